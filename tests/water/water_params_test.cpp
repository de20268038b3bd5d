#include <set>

#include <gtest/gtest.h>

#include "core/params.hpp"
#include "water/droplets.hpp"
#include "water/flow.hpp"
#include "water/stream_power.hpp"
#include "water/thermal.hpp"

namespace sansui::water {
namespace {

template <class S>
void expect_complete_and_valid() {
  const auto& table = params::table_of<S>();
  EXPECT_EQ(params::covered_fields(table), params::field_count<S>()) << table.section << ": a member without a row";
  for (const auto& row : table.rows) {
    EXPECT_FALSE(row.help.empty()) << table.section << "." << row.key;
    EXPECT_TRUE(!row.unit.empty() || row.unitless || row.kind == params::Kind::integer)
        << table.section << "." << row.key << " has no unit";
  }
  EXPECT_NO_THROW(params::validate(S{}));  // the defaults are allowed
}

TEST(WaterParams, EveryTableCoversItsStructAndAcceptsItsDefaults) {
  expect_complete_and_valid<FlowParams>();
  expect_complete_and_valid<StreamPowerParams>();
  expect_complete_and_valid<ThermalParams>();
  expect_complete_and_valid<DropletParams>();
}

TEST(WaterParams, KeysAreUniqueAcrossTheWaterSections) {
  std::set<std::string> keys;
  const auto add = [&](const auto& table) {
    for (const auto& row : table.rows)
      if (row.key != "sea_level") {
        EXPECT_TRUE(keys.insert(row.key).second) << row.key;
      }
  };
  add(params::table_of<FlowParams>());
  add(params::table_of<StreamPowerParams>());
  add(params::table_of<ThermalParams>());
  add(params::table_of<DropletParams>());
}

}  // namespace
}  // namespace sansui::water
