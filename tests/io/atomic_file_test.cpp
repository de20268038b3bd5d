// Atomic writes: the file appears whole or not at all; the temporary never stays.
#include "io/atomic_file.hpp"

#include <csignal>

#include <sys/wait.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/binary_file.hpp"
#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

TEST(IoAtomicFile, RenamesTheTemporaryIntoPlace) {
  test::TempDir directory("atomic-ok");
  std::filesystem::path used;
  io::write_atomically(directory / "a.txt", [&](const std::filesystem::path& temporary) {
    used = temporary;
    EXPECT_EQ(temporary.parent_path(), directory.path());  // same file system, so rename is atomic
    test::write_text(temporary, "hello");
  });
  EXPECT_THAT(used.filename().string(), ::testing::StartsWith("a.txt.tmp-"));
  EXPECT_EQ(test::files_in(directory.path()), std::vector<std::string>{"a.txt"});
}

TEST(IoAtomicFile, AFailingWriterLeavesNothingAndKeepsTheOldFile) {
  test::TempDir directory("atomic-fail");
  test::write_text(directory / "a.txt", "old");
  EXPECT_THROW(io::write_atomically(directory / "a.txt",
                                    [&](const std::filesystem::path& temporary) {
                                      test::write_text(temporary, "half");
                                      fail("stop");
                                    }),
               InputError);
  EXPECT_EQ(test::files_in(directory.path()), std::vector<std::string>{"a.txt"});
  EXPECT_EQ(test::file_bytes(directory / "a.txt"), (std::vector<unsigned char>{'o', 'l', 'd'}));
}

TEST(IoAtomicFile, ChecksTheDirectoryFirst) {
  test::TempDir directory("atomic-dir");
  bool called = false;
  const auto path = directory / "no" / "a.txt";
  EXPECT_EQ(test::input_error_of([&] { io::write_atomically(path, [&](const auto&) { called = true; }); }),
            "cannot write " + path.string() + ": directory " + (directory / "no").string() + " does not exist");
  EXPECT_FALSE(called);
  EXPECT_THAT(test::input_error_of([] { io::check_writable(""); }), ::testing::HasSubstr("output path is empty"));
}

TEST(IoAtomicFile, ABatchRenamesEveryFileAtCommitAndNoneBefore) {
  test::TempDir directory("atomic-batch");
  {
    io::OutputBatch batch;
    io::write_atomically(directory / "a.txt", [&](const std::filesystem::path& temporary) { test::write_text(temporary, "a"); });
    io::write_atomically(directory / "b.txt", [&](const std::filesystem::path& temporary) { test::write_text(temporary, "b"); });
    const std::vector<std::string> before = test::files_in(directory.path());
    EXPECT_EQ(before.size(), 2u);
    for (const auto& name : before) EXPECT_THAT(name, ::testing::HasSubstr(".tmp-"));  // nothing under a final name yet
    batch.commit();
  }
  EXPECT_EQ(test::files_in(directory.path()), (std::vector<std::string>{"a.txt", "b.txt"}));
}

TEST(IoAtomicFile, ABatchThatFailsLeavesNoFileAndKeepsTheOldOnes) {
  test::TempDir directory("atomic-batch-fail");
  test::write_text(directory / "a.txt", "old");
  EXPECT_THROW(
      {
        io::OutputBatch batch;
        io::write_atomically(directory / "a.txt", [&](const std::filesystem::path& temporary) { test::write_text(temporary, "new"); });
        io::OutputBatch inner;  // joins the outer batch: its commit does nothing
        io::write_atomically(directory / "b.txt", [&](const std::filesystem::path& temporary) { test::write_text(temporary, "b"); });
        inner.commit();
        io::write_atomically(directory / "c.txt", [&](const std::filesystem::path& temporary) {
          test::write_text(temporary, "half");
          fail("stop");
        });
        batch.commit();
      },
      InputError);
  EXPECT_EQ(test::files_in(directory.path()), std::vector<std::string>{"a.txt"});
  EXPECT_EQ(test::file_bytes(directory / "a.txt"), (std::vector<unsigned char>{'o', 'l', 'd'}));
  // No batch alive any more: writes are renamed at once again.
  io::write_atomically(directory / "d.txt", [&](const std::filesystem::path& temporary) { test::write_text(temporary, "d"); });
  EXPECT_TRUE(std::filesystem::exists(directory / "d.txt"));
}

TEST(IoAtomicFile, AWriteToAFullDeviceNamesThePathAndTheOsError) {
  // /dev/full takes no byte: the same failure as a full disk, without mounting one.
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  EXPECT_EQ(test::input_error_of([] {
              io::detail::OutputFile file("/dev/full", "out/t.r32");
              file.write(std::string(100, 'x'));
              file.close();
            }),
            "cannot write out/t.r32: No space left on device");
}

TEST(IoAtomicFile, SigtermRemovesTheLiveTemporariesThenEndsTheProcess) {
  test::TempDir directory("atomic-signal");
  const auto temporary = directory / "a.txt.tmp-1-0";
  const auto finished = directory / "b.txt";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    io::remove_temporaries_on_signals();
    test::write_text(temporary, "half");
    io::detail::track_temporary(temporary);
    test::write_text(finished, "done");
    io::detail::track_temporary(directory / "b.txt.tmp-1-1");
    io::detail::untrack_temporary(directory / "b.txt.tmp-1-1");  // renamed: not removed
    ::raise(SIGTERM);
    ::_exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_EQ(test::files_in(directory.path()), std::vector<std::string>{"b.txt"});
}

TEST(IoAtomicFile, SigintRemovesAThousandLiveTemporaries) {
  // No fixed number of slots: every live temporary is removed, also after others were freed
  // (their nodes reused for longer and shorter names).
  test::TempDir directory("atomic-signal-many");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    io::remove_temporaries_on_signals();
    for (int k = 0; k < 100; ++k) {
      io::detail::track_temporary(directory / ("gone" + std::to_string(k) + ".tmp-1-0"));
      io::detail::untrack_temporary(directory / ("gone" + std::to_string(k) + ".tmp-1-0"));
    }
    for (int k = 0; k < 1000; ++k) {
      const auto temporary = directory / (std::string(static_cast<std::size_t>(k % 7), 'x') + std::to_string(k) + ".png.tmp-1-0");
      test::write_text(temporary, "half");
      io::detail::track_temporary(temporary);
    }
    test::write_text(directory / "kept.txt", "done");
    ::raise(SIGINT);
    ::_exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGINT);
  EXPECT_EQ(test::files_in(directory.path()), std::vector<std::string>{"kept.txt"});
}

TEST(IoAtomicFile, ASymbolicLinkIsWrittenThroughToItsTarget) {
  test::TempDir directory("atomic-link");
  test::write_text(directory / "target.txt", "old");
  std::filesystem::create_symlink("target.txt", directory / "link.txt");
  io::write_atomically(directory / "link.txt", [](const std::filesystem::path& temporary) { test::write_text(temporary, "new"); });
  EXPECT_TRUE(std::filesystem::is_symlink(directory / "link.txt"));
  const auto bytes = test::file_bytes(directory / "target.txt");
  EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "new");
}

}  // namespace
}  // namespace sansui
