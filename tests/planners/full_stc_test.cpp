// Full-STC: same path as STC where nothing is blocked, every reachable free sub-cell elsewhere,
// node doubling and single-sided edges, and paths exactly safe where sub-cell centres are not doubles.
#include "helpers/checkers.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/planners/registry.h>

#include <gtest/gtest.h>

using namespace coverkit;

namespace {

Workspace gridWorld(std::uint64_t seed, int w, int h, double density, const Rational& resolution) {
  datasets::GridMapSpec g;
  g.width = w;
  g.height = h;
  g.density = density;
  g.clustered = seed % 2 == 0;
  g.resolution = resolution;
  g.seed = seed;
  return datasets::gridToWorkspace(datasets::generateGridMap(g), "grid");
}

}  // namespace

TEST(FullStc, ObstacleFreeMapAllThreeGiveTheSameOptimalPath) {
  for (auto [m, n] : std::vector<std::pair<int, int>>{{1, 1}, {2, 3}, {6, 4}, {9, 7}}) {
    const Rational r(1, 5), D = 2 * r;  // D = 0.4: centres are not doubles
    Workspace w;
    Region reg;
    reg.outer = {{0, 0}, {Rational(2 * m) * D, 0}, {Rational(2 * m) * D, Rational(2 * n) * D}, {0, Rational(2 * n) * D}};
    w.regions.push_back(reg);
    const auto ctx = testing_helpers::contextFor(w, r);
    const Plan stc = planners::runPlanner("stc", ctx, {});
    const Plan spiral = planners::runPlanner("spiral_stc", ctx, {});
    const Plan full = planners::runPlanner("full_stc", ctx, {});
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, full));
    EXPECT_EQ(testing_helpers::pathJsonOf(stc), testing_helpers::pathJsonOf(full)) << m << "x" << n;
    EXPECT_EQ(testing_helpers::pathJsonOf(spiral), testing_helpers::pathJsonOf(full)) << m << "x" << n;
    const Metrics mt = computeMetrics(ctx.problem, ctx.cells, full.paths);
    EXPECT_NEAR(mt.length, 4.0 * m * n * D.get_d(), 1e-9);
    EXPECT_EQ(mt.enteredSubcells, static_cast<std::size_t>(4 * m * n));
    EXPECT_LE(mt.revisitedSubcells, 1u);  // the start, on the return
    for (const char* tree : {"bfs", "kruskal_straight"})
      EXPECT_EQ(testing_helpers::pathJsonOf(planners::runPlanner("stc", ctx, {{"tree", tree}})), testing_helpers::pathJsonOf(planners::runPlanner("full_stc", ctx, {{"tree", tree}})))
          << tree;
  }
}

TEST(FullStc, NodeDoublingAndSingleSidedEdges) {
  // Rows top to bottom, one sub-cell a character. Mega-cell (1,1) (columns 2-3, rows 2-3 from the
  // bottom) has only its top-left and bottom-right sub-cells free: two nodes. Partial mega-cells
  // such as (0,0) and (1,2) meet their neighbours through one pair only: single-sided edges.
  const Workspace w = datasets::parseTextGrid(
      "......\n"
      "..#.#.\n"
      "...#..\n"
      "..#...\n"
      "#.##..\n"
      "......\n",
      "doubling.grid");
  const auto ctx = testing_helpers::contextFor(w, Rational(1, 2), Point{Rational(9, 2), Rational(1, 2)});
  for (const char* tree : {"dfs_ccw", "bfs", "kruskal_straight"}) {
    const Plan plan = planners::runPlanner("full_stc", ctx, {{"tree", tree}});
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan)) << tree;
    EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan)) << tree;
    EXPECT_GE(plan.statistics.at("node_doublings"), 1.0) << tree;
    EXPECT_EQ(plan.statistics.at("subcells_left_out"), 0.0);
    EXPECT_EQ(plan.statistics.at("reachable_subcells"), 29.0);
    // the whole free set, where STC gets only the free mega-cells
    EXPECT_EQ(computeMetrics(ctx.problem, ctx.cells, plan.paths).enteredSubcells, 29u);
  }
  EXPECT_LT(computeMetrics(ctx.problem, ctx.cells, planners::runPlanner("stc", ctx, {}).paths).enteredSubcells, 29u);
}

TEST(FullStc, EveryReachableFreeSubcellOnSeededWorlds) {
  // r = 1/4 on a 1/2 grid: every centre is a double, so nothing may be left out
  std::size_t revisits = 0, entered = 0;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    const Workspace w = gridWorld(seed, 20 + static_cast<int>(seed % 5) * 7, 18 + static_cast<int>(seed % 3) * 5, 0.05 * static_cast<double>(seed % 6),
                                  Rational(1, 2));
    const auto ctx = testing_helpers::contextFor(w, Rational(1, 4));
    for (const char* tree : {"dfs_ccw", "bfs", "kruskal_straight"}) {
      const Plan plan = planners::runPlanner("full_stc", ctx, {{"tree", tree}});
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan)) << seed << " " << tree;
      EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan)) << seed << " " << tree;
      EXPECT_EQ(plan.statistics.at("subcells_left_out"), 0.0) << seed;
      const Metrics mt = computeMetrics(ctx.problem, ctx.cells, plan.paths);
      EXPECT_EQ(static_cast<double>(mt.enteredSubcells), plan.statistics.at("reachable_subcells")) << seed;
      revisits += mt.revisitedSubcells;
      entered += mt.enteredSubcells;
    }
  }
  // repeated sub-cells are accepted near obstacles only: well under half of what is covered
  EXPECT_LT(revisits, entered / 2);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {  // polygon worlds: obstacles not on the grid
    datasets::PolygonWorldSpec p;
    p.seed = seed;
    p.count = 10;
    p.shape = static_cast<datasets::ObstacleShape>(seed % 4);
    const auto ctx = testing_helpers::contextFor(datasets::generatePolygonWorld(p), Rational(1, 4));
    const Plan plan = planners::runPlanner("full_stc", ctx, {});
    if (plan.status == PlanStatus::kInvalidStart) continue;
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan)) << seed;
    EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan)) << seed;
  }
}

TEST(FullStc, CentresThatAreNotDoublesStaySafe) {
  // 0.05 m pixels, r = 0.15: sub-cells of 0.3 share their borders with obstacle pixels and their
  // centres are not doubles; the path must still be exactly safe, with moves repaired rather than
  // sub-cells dropped wherever one side is free
  double repaired = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const Workspace w = gridWorld(2 * seed, 400, 300, 0.008 * static_cast<double>(seed), Rational(1, 20));  // clustered
    const auto ctx = testing_helpers::contextFor(w, Rational(3, 20));
    const Plan plan = planners::runPlanner("full_stc", ctx, {});
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan)) << seed;
    EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan)) << seed;
    EXPECT_EQ(plan.status, PlanStatus::kExactSolution);
    repaired += plan.statistics.at("moves_repaired");
    EXPECT_LE(plan.statistics.at("subcells_left_out"), 0.02 * plan.statistics.at("reachable_subcells")) << seed;
    EXPECT_GT(plan.statistics.at("reachable_subcells"), 1000) << seed;
  }
  EXPECT_GT(repaired, 0);  // the case arises, and is handled
}

TEST(FullStc, StartInABlockedSubcellIsAStatus) {
  const Workspace w = datasets::parseTextGrid("....\n....\n...#\n....\n", "t.grid");
  // the start's sub-cell is free but its mega-cell is not: STC refuses, Full-STC plans
  const auto ctx = testing_helpers::contextFor(w, Rational(1, 2), Point{Rational(5, 2), Rational(3, 2)});
  EXPECT_EQ(planners::runPlanner("stc", ctx, {}).status, PlanStatus::kInvalidStart);
  const Plan plan = planners::runPlanner("full_stc", ctx, {});
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
  EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan));
}

TEST(FullStc, BuiltInMaps) {
  for (const char* f : {"rooms.grid", "maze.map", "pillars.wkt", "field_ring.geojson", "office.yaml"}) {
    const Workspace w = datasets::loadMap(std::string(COVERKIT_DATA_DIR) + "/" + f);
    for (const Rational& r : {Rational(1, 10), Rational(1, 4)}) {
      const auto ctx = testing_helpers::contextFor(w, r);
      const Plan plan = planners::runPlanner("full_stc", ctx, {});
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan)) << f;
      EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan)) << f;
    }
  }
}
