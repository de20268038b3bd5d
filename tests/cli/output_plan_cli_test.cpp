// The output plan (issue 30, classes 4, 5 and 7): every file a run would write is checked as a
// whole before any work. Two outputs of one name, an output over another's sidecar or over the
// recipe itself, a NUL in a name, a FIFO, device or symbolic link at an output's place, and a
// recipe file's output outside its folder are refused with one line, exit 2 and no file; and a
// signal during a run of hundreds of temporaries leaves none of them behind.
#include <chrono>
#include <csignal>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <sys/stat.h>
#include <sys/types.h>
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
using ::testing::UnorderedElementsAreArray;

/// A 33x33 midpoint world, and its [[output]] entries: a file name, or NAME|KIND.
std::string scene_with_outputs(const std::vector<std::string>& files) {
  std::string text = "source = \"midpoint\"\n[world]\nsize = 33\n";
  for (const std::string& file : files) {
    const auto bar = file.find('|');
    text += "[[output]]\nfile = \"" + file.substr(0, bar) + "\"\n";
    if (bar != std::string::npos) text += "kind = \"" + file.substr(bar + 1) + "\"\n";
  }
  return text;
}

/// A sidecar whose recipe writes `output_json` (a JSON string, escapes as written).
std::string sidecar_with_output(const std::string& output_json) {
  return R"({"sansui_sidecar": 2, "provenance": {"version": "0.2.0", "recipe": {"sansui_recipe": 4, "source": "midpoint", )"
         R"("world": {"size": 33}, "output": [{"file": )" +
         output_json + "}]}}}\n";
}

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// Exit 2, one line holding `message`, and the directory holding only `left` afterwards.
void expect_refused(const CliResult& r, const std::string& message, const std::filesystem::path& directory,
                    const std::vector<std::string>& left) {
  EXPECT_EQ(r.exit_code, 2) << r.all();
  EXPECT_THAT(r.err, HasSubstr(message));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_THAT(files_in(directory), UnorderedElementsAreArray(left));
}

TEST(OutputPlanCli, TwoOutputsOfOneNameAreRefused) {
  TempDir dir("plan-same-name");
  write(dir / "scene.toml", scene_with_outputs({"a.png", "a.png"}));
  expect_refused(run_cli_line("run scene.toml", dir.path()),
                 "sansui: outputs a.png and a.png (outputs 1 and 2 of the recipe) would write the same file: give each output its own name",
                 dir.path(), {"scene.toml"});
  // Another spelling of the same file.
  write(dir / "scene.toml", scene_with_outputs({"a.png", "./a.png"}));
  expect_refused(run_cli_line("run scene.toml", dir.path()), "outputs a.png and ./a.png", dir.path(), {"scene.toml"});
  // On the command line too.
  expect_refused(run_cli_line("terrain --size 33 -o x.png -o x.png", dir.path()), "outputs x.png and x.png", dir.path(), {"scene.toml"});
}

TEST(OutputPlanCli, AnOutputOverAnotherOutputsSidecarIsRefused) {
  TempDir dir("plan-sidecar");
  // Plant instances may be .csv or .json: p.csv.json is a name an output can have.
  write(dir / "scene.toml", scene_with_outputs({"p.csv", "p.csv.json|plants"}));
  expect_refused(run_cli_line("run scene.toml", dir.path()),
                 "sansui: output p.csv.json would overwrite the sidecar of output p.csv (which rebuilds it): give each output its own name",
                 dir.path(), {"scene.toml"});
  // The ENVI header of a raw heightmap counts too (t.r32.hdr), as do an OBJ's material and texture.
  write(dir / "scene.toml", scene_with_outputs({"t.obj", "t_basecolor.png"}));
  expect_refused(run_cli_line("run scene.toml", dir.path()),
                 "output t_basecolor.png would overwrite the base-colour texture of output t.obj", dir.path(), {"scene.toml"});
}

TEST(OutputPlanCli, ASidecarWhoseOutputIsItselfIsRefusedAndARebuildStillWorks) {
  TempDir dir("plan-itself");
  write(dir / "p.csv.json", sidecar_with_output(R"("p.csv.json", "kind": "plants")"));
  const std::string before = read_text(dir / "p.csv.json");
  expect_refused(run_cli_line("run p.csv.json", dir.path()),
                 "sansui: output p.csv.json would overwrite the recipe this run reads (" + (dir / "p.csv.json").string() + ")", dir.path(),
                 {"p.csv.json"});
  EXPECT_EQ(read_text(dir / "p.csv.json"), before);
  // The usual rebuild rewrites the sidecar it was given, as the sidecar of its output.
  write(dir / "t.png.json", sidecar_with_output(R"("t.png")"));
  const CliResult r = run_cli_line("run t.png.json", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.all();
  EXPECT_TRUE(std::filesystem::exists(dir / "t.png"));
}

TEST(OutputPlanCli, ANulInAnOutputNameIsRefused) {
  TempDir dir("plan-nul");
  write(dir / "x.png.json", sidecar_with_output(R"("a.png\u0000.tif")"));
  expect_refused(run_cli_line("run x.png.json", dir.path()), "output a.png\\x00.tif has a control character (\\x00) in its name",
                 dir.path(), {"x.png.json"});
  write(dir / "scene.toml", scene_with_outputs({"a\\u0007.png"}));
  expect_refused(run_cli_line("run scene.toml", dir.path()), "has a control character (\\x07)", dir.path(), {"x.png.json", "scene.toml"});
}

TEST(OutputPlanCli, AFifoADeviceOrASymbolicLinkAtAnOutputIsRefused) {
  TempDir dir("plan-types");
  ASSERT_EQ(::mkfifo((dir / "f.png").c_str(), 0600), 0);
  expect_refused(run_cli_line("terrain --size 33 -o f.png", dir.path()), "output f.png is a FIFO (named pipe)", dir.path(), {"f.png"});
  // A FIFO at a sidecar's place too.
  ASSERT_EQ(::mkfifo((dir / "g.png.json").c_str(), 0600), 0);
  expect_refused(run_cli_line("terrain --size 33 -o g.png", dir.path()), "the sidecar of output g.png (which rebuilds it) is a FIFO",
                 dir.path(), {"f.png", "g.png.json"});
  std::filesystem::remove(dir / "f.png");
  std::filesystem::remove(dir / "g.png.json");
  // A device, reached through a link that --follow-symlinks follows.
  std::filesystem::create_symlink("/dev/null", dir / "null.png");
  expect_refused(run_cli_line("--follow-symlinks terrain --size 33 -o null.png", dir.path()), "output null.png is a character device",
                 dir.path(), {"null.png"});
  std::filesystem::remove(dir / "null.png");

  write(dir / "target.png", "old");
  std::filesystem::create_symlink("target.png", dir / "link.png");
  expect_refused(run_cli_line("terrain --size 33 -o link.png", dir.path()),
                 "sansui: output link.png is a symbolic link to target.png: writing would replace the link with a file; write another "
                 "name, remove the link, or pass --follow-symlinks to write its target",
                 dir.path(), {"target.png", "link.png"});
  EXPECT_EQ(read_text(dir / "target.png"), "old");
  // --follow-symlinks writes the link's target; the link stays.
  const CliResult r = run_cli_line("--follow-symlinks terrain --size 33 -o link.png", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.all();
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.png"));
  EXPECT_NE(read_text(dir / "target.png"), "old");
  EXPECT_TRUE(std::filesystem::exists(dir / "link.png.json"));
}

TEST(OutputPlanCli, ARecipeFileWritesOnlyInsideItsFolder) {
  TempDir dir("plan-outside");
  std::filesystem::create_directories(dir / "scenes");
  write(dir / "scenes" / "up.toml", scene_with_outputs({"../x.png"}));
  expect_refused(run_cli_line("run scenes/up.toml", dir.path()),
                 "sansui: output ../x.png leaves the recipe's folder (" + (dir / "scenes").string() +
                     "): write a name inside it, use --out-dir DIR, or pass --allow-outside-paths",
                 dir.path(), {"scenes"});
  EXPECT_THAT(files_in(dir / "scenes"), UnorderedElementsAreArray({"up.toml"}));
  // An absolute name in a sidecar someone sent.
  write(dir / "scenes" / "abs.png.json", sidecar_with_output("\"" + (dir / "x.png").string() + "\""));
  expect_refused(run_cli_line("run scenes/abs.png.json", dir.path()), "output " + (dir / "x.png").string() + " leaves the recipe's folder",
                 dir.path(), {"scenes"});
  // The ways out: --allow-outside-paths, --out-dir, -o (names the user typed).
  CliResult r = run_cli_line("run scenes/up.toml --allow-outside-paths", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.all();
  EXPECT_TRUE(std::filesystem::exists(dir / "x.png"));
  r = run_cli_line("run scenes/up.toml --out-dir out", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.all();
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "x.png"));
  r = run_cli_line("run up.toml -o ../y.png", dir.path() / "scenes");
  EXPECT_EQ(r.exit_code, 0) << r.all();
  EXPECT_TRUE(std::filesystem::exists(dir / "y.png"));
  // A directory link in the folder that leads out of it.
  std::filesystem::create_directories(dir / "elsewhere");
  std::filesystem::create_directory_symlink(dir / "elsewhere", dir / "scenes" / "door");
  write(dir / "scenes" / "door.toml", scene_with_outputs({"door/z.png"}));
  expect_refused(run_cli_line("run door.toml", dir.path() / "scenes"), "output door/z.png leaves the recipe's folder", dir / "elsewhere",
                 {});
}

TEST(OutputPlanCli, NamesThatDifferOnlyInCaseGetAWarning) {
  TempDir dir("plan-case");
  write(dir / "scene.toml", scene_with_outputs({"a.png", "A.png"}));
  const CliResult r = run_cli_line("run scene.toml", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.all();
  EXPECT_THAT(r.err, HasSubstr("sansui: warning: output a.png and output A.png differ only in case"));
  EXPECT_TRUE(std::filesystem::exists(dir / "A.png"));
}

/// Starts `sansui ARGS...` in `directory` as a child process; its process id.
pid_t start_in(const std::filesystem::path& directory, const std::vector<std::string>& args) {
  const pid_t child = ::fork();
  if (child == 0) {
    std::vector<char*> argv{const_cast<char*>(sansui::test::cli_path)};
    for (const auto& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    if (::chdir(directory.c_str()) != 0) ::_exit(127);
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    ::execv(sansui::test::cli_path, argv.data());
    ::_exit(127);
  }
  return child;
}

std::size_t temporaries_in(const std::filesystem::path& directory) {
  std::size_t count = 0;
  for (const auto& name : files_in(directory)) count += name.find(".tmp-") != std::string::npos ? 1 : 0;
  return count;
}

/// 200 outputs, each with its sidecar and ENVI header: 600 temporaries held until the batch
/// commits, far more than the 64 the handler's table once held.
void interrupt_a_large_plan(int signal_number, int expected_status) {
  TempDir dir("plan-signal-" + std::to_string(signal_number));
  std::vector<std::string> files;
  for (int k = 0; k < 200; ++k) files.push_back("h" + std::to_string(k) + ".r32");
  write(dir / "scene.toml", scene_with_outputs(files));
  const pid_t child = start_in(dir.path(), {"run", "scene.toml"});
  ASSERT_GT(child, 0);
  // Signalled once more temporaries exist than the old table had slots.
  bool signalled = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < deadline) {
    if (temporaries_in(dir.path()) > 100) {
      ::kill(child, signal_number);
      signalled = true;
      break;
    }
    int status = 0;
    if (::waitpid(child, &status, WNOHANG) == child) GTEST_SKIP() << "the run ended before 100 temporaries were seen";
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  if (!signalled) ::kill(child, SIGKILL);
  ASSERT_TRUE(signalled) << "no temporaries seen in 30 s";
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_EQ(WIFSIGNALED(status) ? 128 + WTERMSIG(status) : WEXITSTATUS(status), expected_status);
  EXPECT_EQ(temporaries_in(dir.path()), 0u) << ::testing::PrintToString(files_in(dir.path()));
}

TEST(OutputPlanCli, SigintDuringARunOfHundredsOfTemporariesLeavesNone) {
  interrupt_a_large_plan(SIGINT, 130);
}

TEST(OutputPlanCli, SigtermDuringARunOfHundredsOfTemporariesLeavesNone) {
  interrupt_a_large_plan(SIGTERM, 143);
}

}  // namespace
}  // namespace sansui::test
