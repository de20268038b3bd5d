// Outputs that survive faults (issue 15 items 6, 7, 9): a full disk, an unwritable directory, a
// process killed or interrupted mid-write, a later output that fails, an output over an input.
// Whatever happens, a file under its final name is complete, and no temporary NAME.tmp-PID-N is
// left behind, except after kill -9 (nothing can run then), which later runs ignore.
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <thread>

#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/cli/cli_runner.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

using ::testing::HasSubstr;

/// A tmpfs of `size` mounted on `directory` for one test, unmounted when it ends (also when an
/// assertion fails). Mounting needs root (CI runs as root); otherwise mounted() is false.
class SmallDisk {
 public:
  SmallDisk(const std::filesystem::path& directory, const std::string& size) : directory_(directory) {
    std::filesystem::create_directories(directory);
    mounted_ = ::mount("tmpfs", directory.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0;
    if (!mounted_) reason_ = std::strerror(errno);
  }
  ~SmallDisk() {
    if (mounted_) ::umount2(directory_.c_str(), MNT_DETACH);
  }
  SmallDisk(const SmallDisk&) = delete;
  SmallDisk& operator=(const SmallDisk&) = delete;
  bool mounted() const { return mounted_; }
  const std::string& reason() const { return reason_; }
  /// Fills the disk to the last byte (a file that is not counted as an output).
  void fill() const {
    std::ofstream filler(directory_ / "filler", std::ios::binary);
    const std::string block(4096, 'x');
    while (filler.write(block.data(), static_cast<std::streamsize>(block.size()))) {}
  }

 private:
  std::filesystem::path directory_;
  bool mounted_ = false;
  std::string reason_;
};

/// Runs `sansui ARGS` with every temporary name its outputs `full` (and their sidecars) can be
/// written under already a symbolic link to /dev/full, which fails every write with ENOSPC as
/// a full disk does: the fallback where a tmpfs cannot be mounted (not root). The process id in
/// the names is the shell's, which `exec` hands on to env and then sansui.
CliResult run_cli_on_dev_full(const std::vector<std::filesystem::path>& full, const std::vector<std::string>& args,
                              const std::filesystem::path& scratch) {
  std::string line;
  for (const auto& path : full)
    for (const std::string& name : {path.string(), path.string() + ".json"})
      for (int k = 0; k < 8; ++k) line += "ln -s /dev/full '" + name + ".tmp-'$$'-" + std::to_string(k) + "' && ";
  line += "exec env -u DISPLAY -u WAYLAND_DISPLAY '" + std::string(sansui::test::cli_path) + "'";
  for (const auto& arg : args) line += " '" + arg + "'";
  line += " < /dev/null > '" + (scratch / "out").string() + "' 2> '" + (scratch / "err").string() + "'";
  const int status = std::system(line.c_str());
  CliResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(scratch / "out");
  result.err = read_text(scratch / "err");
  std::filesystem::remove(scratch / "out");
  std::filesystem::remove(scratch / "err");
  // The links sansui did not use (it removes those it wrote to).
  for (const auto& path : full)
    for (const auto& entry : std::filesystem::directory_iterator(path.parent_path()))
      if (entry.is_symlink() && std::filesystem::read_symlink(entry.path()) == "/dev/full") std::filesystem::remove(entry.path());
  return result;
}

/// Files in `directory` except the filler.
std::vector<std::string> outputs_in(const std::filesystem::path& directory) {
  std::vector<std::string> names = files_in(directory);
  std::erase(names, "filler");
  std::sort(names.begin(), names.end());
  return names;
}

bool is_temporary(const std::string& name) {
  return name.find(".tmp-") != std::string::npos;
}

/// A small DEM to read: a 129^2 terrain with its sidecar.
std::filesystem::path small_dem(const TempDir& dir, const std::string& name, const std::string& seed = "1") {
  const auto path = dir / name;
  const CliResult r = run_cli({"terrain", "--size", "129", "--seed", seed, "-o", path.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return path;
}

/// A full-disk failure: exit 2, one line naming the file and the OS error, nothing in `directory`.
void expect_disk_full(const CliResult& r, const std::filesystem::path& file, const std::filesystem::path& directory) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  // The message names the file that failed: the output, its sidecar (written first) or a file
  // beside it (an OBJ's NAME.mtl and NAME_basecolor.png).
  const std::string start = "sansui: cannot write " + (file.parent_path() / file.stem()).string();
  const bool named = r.err.starts_with(start) && r.err.ends_with(": No space left on device\n");
  EXPECT_TRUE(named) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(outputs_in(directory).empty()) << ::testing::PrintToString(outputs_in(directory));
}

TEST(WriteFaultsCli, AFullDiskEndsWithTheOsErrorAndNoFile) {
  TempDir dir("faults-full");
  const auto disk_dir = dir / "disk";
  const SmallDisk disk(disk_dir, "1m");
  if (!disk.mounted()) {
    // Not root: the same failures through /dev/full (each output's temporaries are links to it).
    const auto dem = small_dem(dir, "dem.r32");
    const auto other = small_dem(dir, "other.r32", "2");
    for (const char* name : {"t.r32", "t.png", "t.tif", "t.raw", "t.obj", "t.glb"}) {
      const auto path = disk_dir / name;
      expect_disk_full(run_cli_on_dev_full({path}, {"terrain", "--size", "129", "-o", path.string()}, dir.path()), path, disk_dir);
    }
    const auto json = disk_dir / "c.json";
    expect_disk_full(run_cli_on_dev_full({json}, {"compare", dem.string(), other.string(), "--json", json.string()}, dir.path()), json,
                     disk_dir);
    const auto map = disk_dir / "m.svg";
    expect_disk_full(run_cli_on_dev_full({map}, {"compare", dem.string(), other.string(), "--map-real", map.string()}, dir.path()), map,
                     disk_dir);
    return;
  }
  // 1025^2 float32 samples are 4 MiB: the disk fills in the middle of the heightmap (uneroded: a
  // write fault needs no erosion, which takes most of the time under the sanitizers).
  const auto r32 = disk_dir / "t.r32";
  expect_disk_full(run_cli({"terrain", "--size", "1025", "--no-erode", "-o", r32.string()}), r32, disk_dir);

  // With the disk full to the last byte, every format fails the same way, small files included.
  const auto dem = small_dem(dir, "dem.r32");
  const auto other = small_dem(dir, "other.r32", "2");
  disk.fill();
  for (const char* name : {"t.png", "t.tif", "t.raw", "t.obj", "t.glb"}) {
    const auto path = disk_dir / name;
    expect_disk_full(run_cli({"terrain", "--size", "129", "-o", path.string()}), path, disk_dir);
  }
  const auto json = disk_dir / "c.json";
  expect_disk_full(run_cli({"compare", dem.string(), other.string(), "--json", json.string()}), json, disk_dir);
  const auto map = disk_dir / "m.svg";
  expect_disk_full(run_cli({"compare", dem.string(), other.string(), "--map-real", map.string()}), map, disk_dir);
  const auto picture = disk_dir / "m.png";
  expect_disk_full(run_cli({"compare", dem.string(), other.string(), "--map-real", picture.string()}), picture, disk_dir);
}

TEST(WriteFaultsCli, WhenALaterOutputFailsNoOutputOfTheCommandIsWritten) {
  TempDir dir("faults-later");
  const auto disk_dir = dir / "disk";
  const SmallDisk disk(disk_dir, "1m");
  const auto a = dir / "a.png";
  const auto b = disk_dir / "b.r32";
  const std::vector<std::string> args{"terrain", "--size", "1025", "--no-erode", "-o", a.string(), "-o", b.string()};
  // Not root: b's temporaries are links to /dev/full instead of files on a full tmpfs.
  const CliResult r = disk.mounted() ? run_cli(args) : run_cli_on_dev_full({b}, args, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("cannot write " + b.string() + ": No space left on device"));
  EXPECT_TRUE(outputs_in(disk_dir).empty()) << ::testing::PrintToString(outputs_in(disk_dir));
  std::vector<std::string> left = files_in(dir.path());
  std::erase(left, "disk");
  EXPECT_TRUE(left.empty()) << ::testing::PrintToString(left);  // neither a.png nor its sidecar nor a temporary
}

TEST(WriteFaultsCli, AnUnwritableDirectoryIsNamedBeforeAnyWork) {
  TempDir dir("faults-readonly");
  const auto locked = dir / "locked";
  std::filesystem::create_directories(locked);
  std::filesystem::permissions(locked, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec |
                                           std::filesystem::perms::group_read | std::filesystem::perms::group_exec |
                                           std::filesystem::perms::others_read | std::filesystem::perms::others_exec);
  const auto out = locked / "t.r32";
  std::string prefix;
  if (::geteuid() == 0) {  // root writes anywhere: run as nobody
    if (std::system("runuser -u nobody -- true > /dev/null 2>&1") != 0) GTEST_SKIP() << "running as root without runuser: cannot test";
    // A build in a private folder (mktemp -d makes them 0700) is out of nobody's reach.
    if (std::system(("runuser -u nobody -- test -x '" + std::string(sansui::test::cli_path) + "' > /dev/null 2>&1").c_str()) != 0)
      GTEST_SKIP() << "nobody cannot run " << sansui::test::cli_path << " (a parent folder is private): cannot test";
    prefix = "runuser -u nobody -- ";
  }
  // run_cli_line puts `env ... sansui` after the prefix: runuser runs env, env runs sansui.
  const std::string line = "terrain --size 129 -o '" + out.string() + "'";
  const std::string command =
      prefix + "env -u DISPLAY '" + std::string(sansui::test::cli_path) + "' " + line + " < /dev/null 2> '" + (dir / "err").string() + "'";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string err = read_text(dir / "err");
  EXPECT_THAT(err, HasSubstr("cannot write " + out.string() + ": directory " + locked.string() + " is not writable (Permission denied)"))
      << err;
  EXPECT_TRUE(files_in(locked).empty());
}

/// Starts `sansui ARGS...` as a child process (stdout and stderr to /dev/null); its process id.
pid_t start_cli(const std::vector<std::string>& args) {
  const pid_t child = ::fork();
  if (child == 0) {
    std::vector<char*> argv{const_cast<char*>(sansui::test::cli_path)};
    for (const auto& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    ::execv(sansui::test::cli_path, argv.data());
    ::_exit(127);
  }
  return child;
}

/// Waits until a temporary file appears in `directory` (the write has begun) or the child has
/// ended; true if one appeared while it still runs. A child still running at the deadline is
/// killed and reaped, so that a skipped test leaves no process behind to load the machine.
bool wait_for_temporary(const std::filesystem::path& directory, pid_t child) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    for (const auto& name : files_in(directory))
      if (is_temporary(name)) return true;
    if (::waitpid(child, &status, WNOHANG) == child) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(child, SIGKILL);
  ::waitpid(child, &status, 0);
  return false;
}

/// The exit status a shell reports for a child: its code, or 128 + the signal that ended it.
int shell_status(pid_t child) {
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : WEXITSTATUS(status);
}

/// A large write with several outputs, so that the signal comes while temporaries exist. Uneroded:
/// the terrain takes a fraction of a second and the writes a second or more, where the eroded
/// default took 25 s (Release) and over the 120 s wait under the sanitizers before its first write.
std::vector<std::string> large_write(const TempDir& dir) {
  return {"terrain", "--size",
          "4097",    "--no-erode",
          "-o",      (dir / "t.r32").string(),
          "-o",      (dir / "t.png").string(),
          "-o",      (dir / "t.tif").string()};
}

void interrupt_mid_write(int signal_number, int expected_status) {
  TempDir dir("faults-signal-" + std::to_string(signal_number));
  const pid_t child = start_cli(large_write(dir));
  ASSERT_GT(child, 0);
  if (!wait_for_temporary(dir.path(), child))
    GTEST_SKIP() << "no temporary file was seen while the command ran (it ended first, or wrote nothing in 120 s)";
  ::kill(child, signal_number);
  EXPECT_EQ(shell_status(child), expected_status);
  EXPECT_TRUE(files_in(dir.path()).empty()) << ::testing::PrintToString(files_in(dir.path()));  // no temporary, no output
}

TEST(WriteFaultsCli, SigintMidWriteRemovesTheTemporariesAndExits130) {
  interrupt_mid_write(SIGINT, 130);
}

TEST(WriteFaultsCli, SigtermMidWriteRemovesTheTemporariesAndExits143) {
  interrupt_mid_write(SIGTERM, 143);
}

TEST(WriteFaultsCli, KillDashNineLeavesNoFinalFileAndTheNextRunIgnoresTheStaleTemporary) {
  TempDir dir("faults-kill");
  const pid_t child = start_cli(large_write(dir));
  ASSERT_GT(child, 0);
  if (!wait_for_temporary(dir.path(), child))
    GTEST_SKIP() << "no temporary file was seen while the command ran (it ended first, or wrote nothing in 120 s)";
  ::kill(child, SIGKILL);
  EXPECT_EQ(shell_status(child), 128 + SIGKILL);
  std::vector<std::string> stale = files_in(dir.path());
  for (const auto& name : stale) EXPECT_TRUE(is_temporary(name)) << name << " appeared under its final name";
  EXPECT_FALSE(stale.empty());

  // The next run writes the same names: complete files, the killed run's temporaries untouched.
  const CliResult r = run_cli({"terrain", "--size", "129", "-o", (dir / "t.r32").string(), "-o", (dir / "t.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(std::filesystem::file_size(dir / "t.r32"), 129u * 129u * 4u);
  for (const auto& name : stale) EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
}

TEST(WriteFaultsCli, AnOutputOverAnInputIsRefusedBeforeAnyWork) {
  TempDir dir("faults-input");
  const auto dem = small_dem(dir, "t.png");
  const std::string before = read_text(dem);
  const std::string sidecar_before = read_text(dir / "t.png.json");
  const auto refused = [&](const std::vector<std::string>& args, const std::filesystem::path& input) {
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_THAT(r.err, HasSubstr("would overwrite " + input.string()));
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  };
  // A map of the compared DEM written over it; by another spelling; through a hard link.
  refused({"compare", dem.string(), dem.string(), "--map-real", dem.string()}, dem);
  refused({"compare", dem.string(), dem.string(), "--map-real", (dir / "." / "t.png").string()}, dem);
  std::filesystem::create_hard_link(dem, dir / "link.png");
  refused({"compare", (dir / "link.png").string(), (dir / "link.png").string(), "--map-generated", dem.string()}, dir / "link.png");
  // Over the input's sidecar.
  refused({"compare", dem.string(), dem.string(), "--json", (dir / "t.png.json").string()}, dir / "t.png.json");
  // The case: refused too (a comparison is .json).
  EXPECT_EQ(run_cli({"compare", dem.string(), dem.string(), "--json", dem.string()}).exit_code, 2);
  EXPECT_EQ(read_text(dem), before);
  EXPECT_EQ(read_text(dir / "t.png.json"), sidecar_before);
  std::vector<std::string> left = files_in(dir.path());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"link.png", "t.pgw", "t.png", "t.png.aux.xml", "t.png.json"}));
}

}  // namespace
}  // namespace sansui::test
