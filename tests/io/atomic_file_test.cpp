// Atomic writes: the file appears whole or not at all; the temporary never stays.
#include "io/atomic_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace sansui
