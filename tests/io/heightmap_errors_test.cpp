// Bad input for heightmaps, for every format: missing, truncated and corrupt files, NaN, bad
// ranges, unwritable or missing directories. Each gives an InputError naming the file, and a
// failed write leaves no file behind: no heightmap, no sidecar, no ".tmp-" file.
#include <limits>

#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/heightmap_io.hpp"
#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

class HeightmapErrors : public ::testing::TestWithParam<const char*> {
 protected:
  std::string name() const { return std::string("h") + GetParam(); }
};

INSTANTIATE_TEST_SUITE_P(AllFormats, HeightmapErrors, ::testing::Values(".png", ".raw", ".r32", ".tif"),
                         [](const auto& parameter) { return std::string(parameter.param + 1); });

TEST_P(HeightmapErrors, AMissingFileIsNamed) {
  test::TempDir directory("errors-missing");
  const auto path = directory / name();
  EXPECT_EQ(test::input_error_of([&] { io::read_heightmap(path); }), "cannot read " + path.string() + ": No such file or directory");
}

TEST_P(HeightmapErrors, ADirectoryIsNotAHeightmap) {
  test::TempDir directory("errors-directory");
  std::filesystem::create_directory(directory / name());
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / name()); }), HasSubstr(": it is a directory"));
  EXPECT_THAT(test::input_error_of([&] { io::write_heightmap(directory / name(), test::sample_heights(3, 3)); }),
              HasSubstr(": it is a directory"));
}

TEST_P(HeightmapErrors, ATruncatedFileIsAnError) {
  test::TempDir directory("errors-truncated");
  const auto path = directory / name();
  io::write_heightmap(path, test::sample_heights(64, 64, 9));
  test::truncate_file(path, std::filesystem::file_size(path) / 2);
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(path); }), StartsWith("cannot read " + path.string() + ": "));
  test::truncate_file(path, 5);
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(path); }), StartsWith("cannot read " + path.string() + ": "));
}

TEST_P(HeightmapErrors, GarbageIsAnError) {
  test::TempDir directory("errors-garbage");
  const auto path = directory / name();
  test::write_text(path, "this is not a heightmap, just some text of odd length.");
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(path); }), StartsWith("cannot read " + path.string() + ": "));
  test::write_text(path, "");
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(path); }), StartsWith("cannot read " + path.string() + ": "));
}

TEST_P(HeightmapErrors, NaNOrInfinityToWriteLeavesNoFile) {
  test::TempDir directory("errors-nan");
  const auto path = directory / name();
  Heightfield heights = test::sample_heights(8, 8);
  heights(5, 6) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(test::input_error_of([&] { io::write_heightmap(path, heights); }),
            "cannot write " + path.string() + ": sample (5, 6) is nan: heights must be finite numbers");
  heights(5, 6) = -std::numeric_limits<float>::infinity();
  EXPECT_THAT(test::input_error_of([&] { io::write_heightmap(path, heights); }), HasSubstr("sample (5, 6) is -inf"));
  EXPECT_TRUE(test::files_in(directory.path()).empty());
}

TEST_P(HeightmapErrors, AMissingDirectoryLeavesNoFile) {
  test::TempDir directory("errors-nodir");
  const auto path = directory / "missing" / name();
  EXPECT_EQ(test::input_error_of([&] { io::write_heightmap(path, test::sample_heights(3, 3)); }),
            "cannot write " + path.string() + ": directory " + (directory / "missing").string() + " does not exist");
  EXPECT_TRUE(test::files_in(directory.path()).empty());
}

TEST_P(HeightmapErrors, AFileThatCannotBeCreatedLeavesNoFile) {
  // A name longer than the file system allows: the directory is fine, creating the file is not
  // (unlike a read-only directory, this fails for root too). A raw file's ENVI header is created
  // first, a 16-bit PNG's world file first, then the sidecar.
  test::TempDir directory("errors-create");
  const auto path = directory / (std::string(300, 'x') + GetParam());
  const bool raw = GetParam() == std::string(".raw") || GetParam() == std::string(".r32") || GetParam() == std::string(".r16");
  const bool png = GetParam() == std::string(".png");
  const std::string first = raw   ? path.string() + ".hdr"
                            : png ? std::filesystem::path(path).replace_extension(".pgw").string()
                                  : path.string() + ".json";
  EXPECT_EQ(test::input_error_of([&] { io::write_heightmap(path, test::sample_heights(3, 3)); }),
            "cannot write " + first + ": File name too long");
  EXPECT_EQ(test::input_error_of([&] {
              io::write_heightmap(path, test::sample_heights(3, 3), {std::nullopt, {}, false});
            }),
            "cannot write " + path.string() + ": File name too long");
  EXPECT_TRUE(test::files_in(directory.path()).empty());
}

TEST_P(HeightmapErrors, AnUnwritableDirectoryLeavesNoFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may write into read-only directories";
  test::TempDir directory("errors-readonly");
  std::filesystem::permissions(directory.path(), std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  const auto path = directory / name();
  EXPECT_THAT(test::input_error_of([&] { io::write_heightmap(path, test::sample_heights(3, 3)); }), HasSubstr("is not writable"));
  std::filesystem::permissions(directory.path(), std::filesystem::perms::owner_all);
  EXPECT_TRUE(test::files_in(directory.path()).empty());
}

TEST_P(HeightmapErrors, EmptyGridsAndBadCellSizesAreRefused) {
  test::TempDir directory("errors-empty");
  EXPECT_THAT(test::input_error_of([&] { io::write_heightmap(directory / name(), Heightfield()); }), HasSubstr("the heightfield is empty"));
  Heightfield heights = test::sample_heights(3, 3);
  heights.cell_size_m = 0.0;
  EXPECT_THAT(test::input_error_of([&] { io::write_heightmap(directory / name(), heights); }),
              HasSubstr("cell size 0 m is not allowed: it must be > 0"));
  EXPECT_TRUE(test::files_in(directory.path()).empty());
}

TEST(HeightmapErrorsAny, ABadRangeIsRefusedBeforeWriting) {
  test::TempDir directory("errors-range");
  EXPECT_EQ(test::input_error_of([&] {
              io::write_heightmap(directory / "h.png", test::sample_heights(3, 3), {io::HeightRange{5.0, 5.0}});
            }),
            "height range 5,5 m is not allowed: MIN must be below MAX, both finite");
  io::HeightmapReadOptions options;
  options.range = io::HeightRange{1.0, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "h.png", options); }),
              HasSubstr("height range 1,nan m is not allowed"));
  EXPECT_TRUE(test::files_in(directory.path()).empty());
}

TEST(HeightmapErrorsAny, UnknownExtensionsAreNamed) {
  test::TempDir directory("errors-extension");
  EXPECT_EQ(io::heightmap_format_for("a.PNG")->name, "png16");
  EXPECT_EQ(io::heightmap_format_for("a.tiff")->name, "geotiff");
  EXPECT_EQ(io::heightmap_format_for("a.R16")->name, "r16");
  EXPECT_EQ(io::heightmap_format_for("a.jpg"), nullptr);
  EXPECT_EQ(io::heightmap_format_for("a"), nullptr);
  EXPECT_EQ(test::input_error_of([&] { io::write_heightmap(directory / "h.jpg", test::sample_heights(3, 3)); }),
            "cannot write " + (directory / "h.jpg").string() + ": unknown extension '.jpg': heightmaps are .png .raw .r16 .r32 .tif .tiff");
  EXPECT_THAT(test::input_error_of([&] { io::read_heightmap(directory / "h.exr"); }), HasSubstr("unknown extension '.exr'"));
}

TEST(HeightmapErrorsAny, AFailedWriteKeepsTheOldFileAndSidecar) {
  test::TempDir directory("errors-keep");
  const auto path = directory / "h.r32";
  io::write_heightmap(path, test::sample_heights(4, 4, 1));
  const auto before = test::file_bytes(path);
  const auto sidecar_before = test::file_bytes(io::sidecar_path(path));
  Heightfield broken = test::sample_heights(8, 8, 2);
  broken(0, 0) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(test::input_error_of([&] { io::write_heightmap(path, broken); }), "<no InputError>");
  EXPECT_EQ(test::file_bytes(path), before);
  EXPECT_EQ(test::file_bytes(io::sidecar_path(path)), sidecar_before);
  EXPECT_EQ(test::files_in(directory.path()), (std::vector<std::string>{"h.r32", "h.r32.hdr", "h.r32.json"}));
}

}  // namespace
}  // namespace sansui
