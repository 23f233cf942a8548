#include <coverkit/optimise/turning.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace coverkit;

TEST(Turning, StraightIsZeroAndCornersCost) {
  EXPECT_DOUBLE_EQ(optimise::bendingEnergy({{0, 0}, {1, 0}, {2, 0}}), 0);
  const double right = optimise::bendingEnergy({{0, 0}, {1, 0}, {1, 1}});
  EXPECT_NEAR(right, (M_PI / 2) * (M_PI / 2), 1e-12);
  EXPECT_GT(optimise::bendingEnergy({{0, 0}, {1, 0}, {0, 0.1}}), right);
}
