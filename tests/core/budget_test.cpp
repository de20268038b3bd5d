// The one budget check (core/budget.hpp): memory over the limit is refused with or without force;
// time over the work limit only without it; the message names the estimate, the limit and the
// way out.
#include "core/budget.hpp"

#include <cmath>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/memory.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;

/// Restores the process-wide memory limit a test lowered.
class MemoryLimit {
 public:
  explicit MemoryLimit(std::size_t bytes) { set_memory_limit_bytes(bytes); }
  ~MemoryLimit() { set_memory_limit_bytes(saved_); }
  MemoryLimit(const MemoryLimit&) = delete;
  MemoryLimit& operator=(const MemoryLimit&) = delete;

 private:
  std::size_t saved_ = memory_limit_bytes();
};

std::string refusal(const budget::Cost& cost, bool forced = false) {
  try {
    budget::check(cost, forced);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

budget::Cost cost_of(double bytes, double seconds) {
  budget::Cost cost;
  cost.bytes = bytes;
  cost.seconds = seconds;
  cost.what = "the thing (size 9)";
  cost.smaller = "give a smaller size";
  return cost;
}

TEST(BudgetCheck, MemoryOverTheLimitIsRefusedEvenWhenForced) {
  const MemoryLimit limit(1'000'000'000);
  EXPECT_EQ(refusal(cost_of(1e9, 0.0)), "");
  const std::string expected =
      "the thing (size 9) needs 2 GB, more than the memory limit of 1 GB (raise it with --max-memory GB, or give a smaller size)";
  EXPECT_EQ(refusal(cost_of(2e9, 0.0)), expected);
  EXPECT_EQ(refusal(cost_of(2e9, 0.0), true), expected);
  EXPECT_THAT(refusal(cost_of(std::nan(""), 0.0)), HasSubstr("needs nan GB"));
}

TEST(BudgetCheck, WorkOverTheLimitNeedsForceWhereThereIsOne) {
  EXPECT_EQ(refusal(cost_of(0.0, budget::work_limit_s)), "");
  EXPECT_EQ(refusal(cost_of(0.0, 1260.0)),
            "the thing (size 9) would take about 21 minutes, more than the work limit of 10 minutes: give a smaller size, or pass force "
            "(--force) to run it");
  EXPECT_EQ(refusal(cost_of(0.0, 1260.0), true), "");
  budget::Cost unforceable = cost_of(0.0, 4.0 * 3600.0);
  unforceable.force.clear();
  EXPECT_EQ(refusal(unforceable, true),
            "the thing (size 9) would take about 4 hours, more than the work limit of 10 minutes: give a smaller size");
}

TEST(BudgetCheck, CheckMemoryIsTheBudgetsMemoryCheck) {
  const MemoryLimit limit(1'000'000);
  try {
    check_memory(4.2e6, "world.size 1025");
    ADD_FAILURE() << "not refused";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "world.size 1025 needs 0.0042 GB, more than the memory limit of 0.001 GB (raise it with --max-memory GB)");
  }
}

TEST(BudgetCheck, TimesAndSizesReadAsSentences) {
  EXPECT_EQ(budget::format_seconds(40.0), "40 s");
  EXPECT_EQ(budget::format_seconds(780.0), "13 minutes");
  EXPECT_EQ(budget::format_seconds(1e20), "forever");
  EXPECT_EQ(budget::format_bytes(4.4e12), "4.4 TB");
}

}  // namespace
}  // namespace sansui
