#include "learning/grid_potential.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(GridPotential, IsTheBestTakenValueOfTheStateAndZeroElsewhere) {
  QTable q(3);
  q.set_value(7, 0, -40.0);
  q.add_visit(7, 0);
  q.set_value(7, 1, -10.0);
  q.add_visit(7, 1);
  q.set_value(7, 2, 99.0);  // written but never taken: not a known value of the state
  q.set_value(8, 2, 5.0);   // a row without a taken action
  const GridPotential phi(q);
  EXPECT_EQ(phi(7), -10.0);
  EXPECT_EQ(phi(8), 0.0);
  EXPECT_EQ(phi(9), 0.0);
  EXPECT_DOUBLE_EQ(phi.shaping(9, 7, 0.9), 0.9 * -10.0);
  EXPECT_DOUBLE_EQ(phi.shaping(7, 7, 0.9), -10.0 * (0.9 - 1.0));
}

TEST(GridPotential, WithoutATableItIsZero) {
  const GridPotential phi;
  EXPECT_EQ(phi(0), 0.0);
  EXPECT_EQ(phi.shaping(0, 1, 0.9), 0.0);
}

}  // namespace
}  // namespace crux
