// Where between grid points a searched parameter's least G lies
// (montecarlo/records/gap/fit/subgrid.h): the parabola's vertex, and its use on a
// G that is quadratic in the parameter's logarithm.
#include <gtest/gtest.h>

#include <cmath>

#include "montecarlo/records/gap/fit/subgrid.h"

namespace insmc::gap {
namespace {

TEST(Subgrid, TheVertexOfAParabolaThroughThreePointsIsItsMinimum) {
  // y = 2 (x − 0.3)² + 1 at unequal spacing.
  const auto y = [](double x) { return 2 * (x - 0.3) * (x - 0.3) + 1; };
  const double x[3] = {-1.0, 0.0, 2.5};
  const double v[3] = {y(x[0]), y(x[1]), y(x[2])};
  EXPECT_NEAR(parabola_vertex(x, v), 0.3, 1e-12);
}

TEST(Subgrid, APointNotBelowItsChordKeepsTheGridValue) {
  const double x[3] = {0.0, 1.0, 2.0};
  const double flat[3] = {1.0, 1.0, 1.0};
  EXPECT_EQ(parabola_vertex(x, flat), 1.0);
  const double concave[3] = {0.0, 1.0, 0.0};
  EXPECT_EQ(parabola_vertex(x, concave), 1.0);
}

TEST(Subgrid, TheVertexOfAConvexParabolaWithItsLeastInTheMiddleLiesBetweenTheNeighbours) {
  // Any y[1] at or below both neighbours and below the chord: the vertex
  // stays within half a step of the middle point.
  const double x[3] = {0.0, 1.0, 2.0};
  for (double y0 : {0.5, 1.0, 3.0})
    for (double y2 : {0.5, 1.0, 3.0}) {
      const double y[3] = {y0, 0.5, y2};
      const double v = parabola_vertex(x, y);
      EXPECT_GE(v, 0.5 - 1e-12) << y0 << " " << y2;
      EXPECT_LE(v, 1.5 + 1e-12) << y0 << " " << y2;
    }
}

}  // namespace
}  // namespace insmc::gap
