// The file formats are listed once (io/file_formats.hpp): every extension an output kind or a
// reader accepts comes from the list, and the list answers by what a file holds.
#include "io/file_formats.hpp"

#include <algorithm>
#include <set>

#include <gtest/gtest.h>

#include "io/plant_instances.hpp"
#include "io/seed_files.hpp"
#include "scene/output_kinds.hpp"

namespace sansui {
namespace {

std::set<std::string> listed_extensions() {
  std::set<std::string> all;
  for (const io::FileFormat& format : io::file_formats())
    for (std::string_view extension : format.extensions) all.emplace(extension);
  return all;
}

TEST(FileFormats, EveryOutputKindsExtensionIsListed) {
  const std::set<std::string> listed = listed_extensions();
  for (const scene::OutputKindInfo& kind : scene::output_kinds()) {
    for (const std::string& extension : kind.extensions) EXPECT_TRUE(listed.contains(extension)) << kind.name << " " << extension;
    for (const std::string& extension : kind.inferred_from)
      EXPECT_NE(std::ranges::find(kind.extensions, extension), kind.extensions.end()) << kind.name << " " << extension;
  }
}

TEST(FileFormats, OneExtensionIsToldApartByWhatTheFileHolds) {
  ASSERT_NE(io::file_format_for("a.r32", io::FormatData::heights, io::Access::write), nullptr);
  EXPECT_EQ(io::file_format_for("a.r32", io::FormatData::heights, io::Access::write)->name, "r32");
  EXPECT_EQ(io::file_format_for("a.R32", io::FormatData::volume, io::Access::write)->name, "volume_r32");
  EXPECT_EQ(io::file_format_for("a.png", io::FormatData::image, io::Access::write)->name, "png8");
  EXPECT_EQ(io::file_format_for("a.png", io::FormatData::heights, io::Access::write)->name, "png16");
  EXPECT_EQ(io::file_format_for("a.json", io::FormatData::vector, io::Access::read)->name, "geojson");
  EXPECT_EQ(io::file_format_for("a.json", io::FormatData::table, io::Access::write)->name, "json");
  // Read-only and write-only formats answer only their side.
  EXPECT_EQ(io::file_format_for("a.txt", io::FormatData::table, io::Access::write), nullptr);
  EXPECT_EQ(io::file_format_for("a.png", io::FormatData::image, io::Access::read), nullptr);
  EXPECT_EQ(io::file_format_for("a.gltf", io::FormatData::mesh, io::Access::write), nullptr);
}

TEST(FileFormats, ReadersChooseFromTheList) {
  EXPECT_EQ(io::seed_format_for("m.GeoJSON"), io::SeedFormat::geojson);
  EXPECT_EQ(io::seed_format_for("m.json"), io::SeedFormat::geojson);
  EXPECT_EQ(io::seed_format_for("m.svg"), io::SeedFormat::svg);
  EXPECT_EQ(io::seed_format_for("m.csv"), io::SeedFormat::csv);
  EXPECT_EQ(io::seed_format_for("m.txt"), io::SeedFormat::csv);
  EXPECT_EQ(io::seed_format_for("m.png"), std::nullopt);
  EXPECT_EQ(io::plant_format_for("p.csv"), io::PlantFormat::csv);
  EXPECT_EQ(io::plant_format_for("p.JSON"), io::PlantFormat::json);
  EXPECT_EQ(io::plant_format_for("p.txt"), std::nullopt);
  EXPECT_EQ(io::extensions_of({"svg", "png8"}), (std::vector<std::string>{".svg", ".png"}));
}

}  // namespace
}  // namespace sansui
