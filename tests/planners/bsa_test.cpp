// BSA with A* backtracking: the filling rules, backtracking points, complete coverage.
#include "helpers/checkers.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/planners/registry.h>

#include <gtest/gtest.h>

using namespace coverkit;

namespace {
planners::PlanningContext openGrid(int w, int h, Point start) {
  std::string text;
  for (int r = 0; r < h; ++r) text += std::string(static_cast<std::size_t>(w), '.') + "\n";
  return testing_helpers::contextFor(datasets::parseTextGrid(text, "open.grid"), Rational(1, 2), start);
}
const Point kCorner{Rational(1, 2), Rational(1, 2)};
}  // namespace

TEST(Bsa, ZigzagFromACornerOfAnOpenMapIsOneBoustrophedonWithoutBacktracking) {
  const auto ctx = openGrid(9, 7, kCorner);
  const Plan plan = planners::runPlanner("bsa_zigzag", ctx, {});
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
  EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan));
  EXPECT_EQ(plan.statistics.at("backtracks"), 0.0);
  EXPECT_EQ(plan.statistics.at("filling_moves"), 9.0 * 7 - 1);  // every cell once
  const Metrics m = computeMetrics(ctx.problem, ctx.cells, plan.paths);
  EXPECT_NEAR(m.length, 9.0 * 7 - 1, 1e-9);
  EXPECT_EQ(m.turns, 2u * (9 - 1));  // two turns between lanes (columns)
}

TEST(Bsa, SpiralFromACornerOfAnOpenMapSpiralsInwardWithoutBacktracking) {
  // start at the bottom-left corner heading east with the wall on the right: RLS = left keeps
  // turning inwards only when the left is free, so it follows the boundary and spirals in
  const auto ctx = openGrid(8, 6, kCorner);
  const Plan plan = planners::runPlanner("bsa_spiral", ctx, {{"side", "right"}});
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
  EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan));
  EXPECT_EQ(plan.statistics.at("backtracks"), 0.0);
  EXPECT_EQ(plan.statistics.at("filling_moves"), 8.0 * 6 - 1);
}

TEST(Bsa, BacktracksToLeftBehindCellsAndCoversEverything) {
  // a U-shaped obstacle open to the bottom: the cells in it and behind it are reached by backtracking
  const Workspace w = datasets::parseTextGrid(
      "..........\n"
      "..........\n"
      "...####...\n"
      "...#..#...\n"
      "...#..#...\n"
      "..........\n",
      "split.grid");
  const auto ctx = testing_helpers::contextFor(w, Rational(1, 2), kCorner);
  for (const char* p : {"bsa_spiral", "bsa_zigzag"}) {
    const Plan plan = planners::runPlanner(p, ctx, {});
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan)) << p;
    EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan)) << p;
    EXPECT_GE(plan.statistics.at("backtracks"), 1.0) << p;
    EXPECT_GE(plan.statistics.at("backtracking_points"), plan.statistics.at("backtracks")) << p;
    EXPECT_EQ(plan.statistics.at("covered_cells"), 60.0 - 8.0) << p;  // the pocket inside the U is reachable from below
  }
}

TEST(Bsa, CompleteValidAndDeterministicOnSeededMaps) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    datasets::GridMapSpec g;
    g.width = g.height = 30;
    g.density = 0.05 + 0.02 * static_cast<double>(seed % 5);
    g.clustered = seed % 2 == 0;
    g.seed = seed;
    const auto ctx = testing_helpers::contextFor(datasets::gridToWorkspace(datasets::generateGridMap(g), "grid"), Rational(1, 2));
    for (const char* p : {"bsa_spiral", "bsa_zigzag"}) {
      const Plan plan = planners::runPlanner(p, ctx, {});
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan)) << p << " " << seed;
      EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan)) << p << " " << seed;
      // every filling move enters a new cell; backtracking travel may sweep new cells on its way
      EXPECT_GE(plan.statistics.at("covered_cells"), plan.statistics.at("filling_moves") + 1) << p;
      EXPECT_LE(plan.statistics.at("covered_cells"), plan.statistics.at("filling_moves") + 1 + plan.statistics.at("travel_moves")) << p;
    }
  }
}
