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
      // Gabriely & Rimon's bound: length <= (n + m)·D, n covered D-cells, m covered D-cells on the
      // boundary (4-adjacent to a cell that is not free or to the grid's edge)
      const Metrics mt = computeMetrics(ctx.problem, ctx.cells, online.paths);
      std::size_t m = 0;
      std::vector<char> entered(ctx.cells.subCount(), 0);
      {
        const auto pts = online.paths[0].polyline(0.01);
        for (std::size_t i = 0; i + 1 < pts.size(); ++i)
          for (int k = 0; k <= 20; ++k) {
            CellIndex e;
            if (ctx.cells.locateSubD({pts[i].x + (pts[i + 1].x - pts[i].x) * k / 20, pts[i].y + (pts[i + 1].y - pts[i].y) * k / 20}, e))
              entered[static_cast<std::size_t>(e.row) * ctx.cells.subCols() + e.col] = 1;
          }
      }
      for (int r = 0; r < ctx.cells.subRows(); ++r)
        for (int cc = 0; cc < ctx.cells.subCols(); ++cc) {
          if (!entered[static_cast<std::size_t>(r) * ctx.cells.subCols() + cc]) continue;
          bool boundary = false;
          for (auto [dc, dr] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}})
            boundary = boundary || !ctx.cells.insideSub(cc + dc, r + dr) || ctx.cells.sub(cc + dc, r + dr) != CellState::kFree;
          m += boundary;
        }
      const double D = ctx.cells.subSizeD();
      EXPECT_LE(mt.length, static_cast<double>(mt.enteredSubcells + m) * D + 2 * D) << "seed " << seed;  // + the start's connector
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
