// Polygon clipping (contour/clipping.hpp): coordinates beyond the integer lattice Clipper works
// in are refused with a message, whatever the caller checked, never Clipper's own exception.
#include "contour/clipping.hpp"

#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "tests/io/io_test_util.hpp"

namespace sansui::contour {
namespace {

using ::testing::HasSubstr;

TEST(Clipping, CoordinatesOutsideTheLatticeAreAnInputErrorNotClippersException) {
  for (const double huge : {1e16, 1e77, -1e114, std::numeric_limits<double>::quiet_NaN()}) {
    const Ring ring{{0, 0}, {100, 0}, {100, huge}, {0, 100}};
    EXPECT_THAT(test::input_error_of([&] { (void)positive_region(ring); }), HasSubstr("outside the range polygon clipping works in"))
        << huge;
    EXPECT_THAT(test::input_error_of([&] { (void)inflate({ring}, 1.0); }), HasSubstr("outside the range")) << huge;
  }
  // 1e12 m is inside (Clipper's 128-bit range): no error.
  const Ring far{{1e12, 0}, {1e12 + 100, 0}, {1e12 + 100, 100}, {1e12, 100}};
  EXPECT_EQ(positive_region(far).size(), 1u);
}

}  // namespace
}  // namespace sansui::contour
