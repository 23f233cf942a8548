#include "helpers/checkers.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/path_io.h>
#include <coverkit/planners/registry.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/planners/sensor.h>

#include <gtest/gtest.h>

#include <map>

using namespace coverkit;


TEST(Sensor, AnswersOnlyForTheRobotsCellAndLogsEveryQuestion) {
  graph::GridGraph g(3, 1);
  g.active = {1, 1, 0};
  planners::MegaCellSensor s(g, 0);
  EXPECT_TRUE(s.neighbourFree(0, graph::kEast));
  EXPECT_FALSE(s.neighbourFree(0, graph::kWest));
  EXPECT_THROW(s.neighbourFree(1, graph::kEast), std::logic_error);  // not where the robot is
  s.moveTo(1);
  EXPECT_FALSE(s.neighbourFree(1, graph::kEast));
  EXPECT_THROW(s.moveTo(2), std::logic_error);  // blocked
  EXPECT_EQ(s.log().size(), 3u);
}

TEST(SpiralStc, SamePathAsOfflineStcWithDfsCcwFromEveryQuadrant) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    datasets::GridMapSpec spec;
    spec.width = 30;
    spec.height = 22;
    spec.density = 0.12;
    spec.clustered = seed % 2 == 0;
    spec.seed = seed;
    const Workspace w = datasets::gridToWorkspace(datasets::generateGridMap(spec), "grid");
    const auto base = testing_helpers::contextFor(w, Rational(1, 2));
    // the default start, then the other three quadrants of the same mega-cell
    CellIndex c;
    ASSERT_TRUE(base.cells.locateSub(*base.problem.robots[0].start, c));
    for (int q = 0; q < 4; ++q) {
      const int col = (c.col / 2) * 2 + (q == 1 || q == 2), row = (c.row / 2) * 2 + (q >= 2);
      const auto ctx = testing_helpers::contextFor(w, Rational(1, 2), base.cells.subCenter(col, row));
      const Plan offline = planners::runPlanner("stc", ctx, {{"tree", "dfs_ccw"}});
      const Plan online = planners::runPlanner("spiral_stc", ctx, {});
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, online)) << seed;
      datasets::PathDocument a, b;
      a.paths = offline.paths;
      b.paths = online.paths;
      EXPECT_EQ(datasets::pathJson(a), datasets::pathJson(b)) << "seed " << seed << " quadrant " << q;
      EXPECT_EQ(online.statistics.at("tree_nodes"), offline.statistics.at("tree_nodes"));
      EXPECT_TRUE(testing_helpers::withinGabrielyRimonBound(ctx, online)) << "seed " << seed;
      // local questions only, at most four per mega-cell of the tree
      EXPECT_LE(online.statistics.at("sensor_queries"), 4 * online.statistics.at("tree_nodes"));
    }
  }
}

TEST(SpiralStc, OnlineTreeRulesAskOnlyLocalQuestionsAndCoverTheSameMegaCells) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    datasets::GridMapSpec spec;
    spec.width = 40;
    spec.height = 30;
    spec.density = 0.1;
    spec.clustered = seed % 2 == 0;
    spec.seed = seed;
    const Workspace w = datasets::gridToWorkspace(datasets::generateGridMap(spec), "grid");
    const auto ctx = testing_helpers::contextFor(w, Rational(1, 2));
    const Plan offline = planners::runPlanner("stc", ctx, {});
    for (const char* tree : {"dfs_ccw", "bfs", "kruskal_straight"}) {
      // the sensor throws on any question about a cell the robot is not in: running is the proof
      const Plan online = planners::runPlanner("spiral_stc", ctx, {{"tree", tree}});
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, online)) << seed << " " << tree;
      EXPECT_TRUE(testing_helpers::coversStartComponent(ctx, online)) << seed << " " << tree;
      EXPECT_EQ(online.statistics.at("tree_nodes"), offline.statistics.at("tree_nodes")) << tree;
      EXPECT_LE(online.statistics.at("sensor_queries"), 4 * online.statistics.at("tree_nodes")) << tree;
      // a tree of n mega-cells is walked around in 4n moves, whatever its shape
      EXPECT_EQ(online.statistics.at("subcells_in_tour"), 4 * online.statistics.at("tree_nodes")) << tree;
    }
  }
}

TEST(SpiralStc, LengthWithinTheBoundOnPolygonWorlds) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    datasets::PolygonWorldSpec p;
    p.seed = seed;
    p.count = 12;
    p.shape = static_cast<datasets::ObstacleShape>(seed % 4);
    const auto ctx = testing_helpers::contextFor(datasets::generatePolygonWorld(p), Rational(1, 5));
    for (const char* tree : {"dfs_ccw", "bfs", "kruskal_straight"}) {
      const Plan plan = planners::runPlanner("spiral_stc", ctx, {{"tree", tree}});
      if (plan.status == PlanStatus::kInvalidStart) continue;
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan)) << seed;
      EXPECT_TRUE(testing_helpers::withinGabrielyRimonBound(ctx, plan)) << seed << " " << tree;
    }
  }
}
