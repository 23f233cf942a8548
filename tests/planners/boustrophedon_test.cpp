// The boustrophedon planner (issue 13): valid on every world (exact validator), covers the start's
// C-free component, follows the sweep direction asked for, reports what it leaves behind gaps
// exactly 2r wide, refuses bad parameters.
#include "helpers/checkers.h"
#include "helpers/worlds.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/planners/registry.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>

using namespace coverkit;

namespace {

Workspace seeded(std::uint64_t seed, int count, datasets::ObstacleShape shape) {
  datasets::PolygonWorldSpec p;
  p.width = 14;
  p.height = 10;
  p.seed = seed;
  p.count = count;
  p.shape = shape;
  return datasets::generatePolygonWorld(p);
}

}  // namespace

TEST(Boustrophedon, ValidAndCoversSeededWorlds) {
  double sum = 0, least = 1;
  int n = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const auto shape = static_cast<datasets::ObstacleShape>(seed % 7);
    const int count = static_cast<int>((seed * 7) % 16);
    const auto ctx = testing_helpers::contextFor(seeded(seed, count, shape), Rational(1, 4));
    for (const char* decomposition : {"boustrophedon", "trapezoidal"}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " " + decomposition);
      const Plan plan = planners::runPlanner("boustrophedon", ctx, {{"decomposition", decomposition}});
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
      EXPECT_EQ(plan.status, PlanStatus::kExactSolution) << plan.message;
      double c = 0;
      EXPECT_TRUE(testing_helpers::coversCFreeComponent(ctx, plan, 0.96, &c));
      sum += c;
      least = std::min(least, c);
      ++n;
    }
  }
  std::cout << n << " plans: mean coverage of the coverable region " << sum / n << ", least " << least << "\n";
  EXPECT_GE(sum / n, 0.99);
}

TEST(Boustrophedon, FollowsArcsAndIsDeterministic) {
  const auto ctx = testing_helpers::contextFor(seeded(5, 6, datasets::ObstacleShape::kDisc), Rational(3, 10));
  const Plan a = planners::runPlanner("boustrophedon", ctx, {});
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, a));
  const auto arcs = std::count_if(a.paths[0].segments.begin(), a.paths[0].segments.end(),
                                  [](const PathSegment& s) { return s.kind == PathSegment::Kind::kArc; });
  EXPECT_GT(arcs, 0);   // the sweep runs along the C-obstacles' arcs
  EXPECT_EQ(testing_helpers::pathJsonOf(a), testing_helpers::pathJsonOf(planners::runPlanner("boustrophedon", ctx, {})));
}

TEST(Boustrophedon, RoundedCornersTurnLessAndLoseNoCoverage) {
  // an open room: the serpentine's U-turns become arcs tangent to the lanes, so the only turns
  // left are where the first side pass meets the lanes and the last side pass
  {
    const auto ctx = testing_helpers::contextFor(seeded(1, 0, datasets::ObstacleShape::kRectangle), Rational(1, 4));
    const Plan rounded = planners::runPlanner("boustrophedon", ctx, {});
    const Plan corners = planners::runPlanner("boustrophedon", ctx, {{"round", "false"}});
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, rounded));
    const Metrics mr = computeMetrics(ctx.problem, ctx.cells, rounded.paths), mc = computeMetrics(ctx.problem, ctx.cells, corners.paths);
    EXPECT_LE(mr.turns, 4u);
    EXPECT_GE(mc.turns, 2 * static_cast<std::size_t>(corners.statistics.at("lanes")) - 2);
  }
  // holes of every shape: fewer turns, every arc checked (valid), and the coverage of the
  // coverable region the same within the metric's certified error
  for (std::uint64_t seed : {2u, 3u, 5u, 6u}) {   // non-convex polygons, stars, discs, mixed
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto shape = static_cast<datasets::ObstacleShape>(seed % 7);
    const auto ctx = testing_helpers::contextFor(seeded(seed, 8, shape), Rational(1, 4));
    const Plan rounded = planners::runPlanner("boustrophedon", ctx, {});
    const Plan corners = planners::runPlanner("boustrophedon", ctx, {{"round", "false"}});
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, rounded));
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, corners));
    double cr = 0, cc = 0;
    EXPECT_TRUE(testing_helpers::coversCFreeComponent(ctx, rounded, 0.97, &cr));
    EXPECT_TRUE(testing_helpers::coversCFreeComponent(ctx, corners, 0.97, &cc));
    EXPECT_GE(cr, cc - 2e-3);
    const Metrics mr = computeMetrics(ctx.problem, ctx.cells, rounded.paths), mc = computeMetrics(ctx.problem, ctx.cells, corners.paths);
    EXPECT_LT(2 * mr.turns, mc.turns);
    EXPECT_LE(rounded.paths[0].length(), corners.paths[0].length());
  }
}

// Cluttered worlds (20 obstacles of 0.5-2 m in 16 m × 16 m) and a larger robot: fewer turns than
// Full-STC and Smooth-STC on every world, where the side passes' and the sweeps' corners and the
// pockets cost the most (docs/decompositions.md, "Beyond these worlds").
TEST(Boustrophedon, TurnsLessThanFullStcAndSmoothStcInClutter) {
  for (std::uint64_t seed : {1u, 2u, 3u})
    for (const Rational& r : {Rational(1, 4), Rational(2, 5)}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " r " + r.get_str());
      const datasets::PolygonWorldSpec p{16, 16, 20, 0.5, 2, datasets::ObstacleShape::kMixed, seed};   // 16 × 16, 20 of 0.5-2
      const auto ctx = testing_helpers::contextFor(datasets::generatePolygonWorld(p), r);
      std::map<std::string, std::size_t> turns;
      for (const char* planner : {"boustrophedon", "full_stc", "smooth_stc"}) {
        const Plan plan = planners::runPlanner(planner, ctx, {});
        ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan)) << planner;
        turns[planner] = computeMetrics(ctx.problem, ctx.cells, plan.paths).turns;
      }
      EXPECT_LT(turns["boustrophedon"], turns["full_stc"]);
      EXPECT_LT(turns["boustrophedon"], turns["smooth_stc"]);
    }
}

// Scanned walls (a generated grid map of 5 cm pixels): every corner of a side pass on a pixel
// step used to come with a connector that went back and forth, and a fillet could leave a piece
// of length 1e-16 whose heading is noise. No piece shorter than 1e-9·r is left between lines, the
// pockets left out are small, and the coverage stays.
TEST(Boustrophedon, OnScannedWallsNoSliversAndPocketsAreSmall) {
  for (std::uint64_t seed : {1u, 2u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const datasets::GridMapSpec g{160, 100, 0.12, true, Rational(1, 20), seed};   // 8 m × 5 m, clustered
    const Workspace w = datasets::gridToWorkspace(datasets::generateGridMap(g), "scan");
    const Rational r(3, 20);
    const auto ctx = testing_helpers::contextFor(w, r);
    const Plan plan = planners::runPlanner("boustrophedon", ctx, {});
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
    const auto& segs = plan.paths[0].segments;
    for (std::size_t i = 1; i + 1 < segs.size(); ++i) {
      if (segs[i].kind == PathSegment::Kind::kLine && segs[i - 1].kind == PathSegment::Kind::kLine) {
        EXPECT_GE(segs[i].length(), 1e-9 * r.get_d()) << "piece " << i;
      }
    }
    EXPECT_LE(plan.statistics.at("pocket_area"), plan.statistics.at("pockets") * r.get_d() * r.get_d() / 16);
    double c = 0;
    EXPECT_TRUE(testing_helpers::coversCFreeComponent(ctx, plan, 0.97, &c));
    const Metrics m = computeMetrics(ctx.problem, ctx.cells, plan.paths);
    std::cout << "seed " << seed << ": coverage " << c << ", turns " << m.turns << ", reversals " << m.reversals << ", pockets "
              << plan.statistics.at("pockets") << "\n";
  }
}

TEST(Boustrophedon, ChainsSweepSeveralCellsAsOneRegion) {
  for (std::uint64_t seed : {2u, 9u}) {
    const auto ctx = testing_helpers::contextFor(seeded(seed, 9, datasets::ObstacleShape::kMixed), Rational(1, 4));
    const Plan chained = planners::runPlanner("boustrophedon", ctx, {});
    const Plan single = planners::runPlanner("boustrophedon", ctx, {{"chains", "false"}});
    for (const Plan* p : {&chained, &single}) {
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, *p));
      EXPECT_EQ(p->status, PlanStatus::kExactSolution) << p->message;
      EXPECT_TRUE(testing_helpers::coversCFreeComponent(ctx, *p, 0.97));
    }
    EXPECT_EQ(single.statistics.at("sweep_regions"), single.statistics.at("cells"));
    EXPECT_LT(chained.statistics.at("sweep_regions"), chained.statistics.at("cells"));
    EXPECT_EQ(chained.statistics.at("cells_in_component"), single.statistics.at("cells_in_component"));
    EXPECT_LE(chained.statistics.at("lanes"), single.statistics.at("lanes"));
  }
}

TEST(Boustrophedon, ItsTurnsPerPhaseAddUpToTheTurnsOfThePath) {
  for (const int deg : {0, 30}) {
    const auto ctx = testing_helpers::contextFor(seeded(3, 8, datasets::ObstacleShape::kMixed), Rational(1, 4));
    const Plan plan = planners::runPlanner("boustrophedon", ctx, {{"direction", std::to_string(deg)}});
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
    double phases = 0;
    for (const char* k : {"turns_transitions", "turns_first_side", "turns_lanes", "turns_last_side"}) phases += plan.statistics.at(k);
    const Metrics m = computeMetrics(ctx.problem, ctx.cells, plan.paths);
    EXPECT_GT(plan.statistics.at("turns_lanes"), 0);
    // in the sweep's own frame (0°) the counts are the same; rotated back (30°), the heading of a
    // connecting piece shorter than 1e-6 is rounding noise, and each of the two joints beside it
    // may count or not
    std::size_t tiny = 0;
    for (const PathSegment& s : plan.paths.at(0).segments) tiny += s.length() < 1e-6;
    if (deg == 0) {
      EXPECT_EQ(phases, static_cast<double>(m.turns));
    } else {
      EXPECT_LE(std::abs(phases - static_cast<double>(m.turns)), 2.0 * static_cast<double>(tiny));
    }
  }
}

TEST(Boustrophedon, SweepsInTheDirectionAskedAndBestIsNoWorse) {
  const auto ctx = testing_helpers::contextFor(seeded(3, 5, datasets::ObstacleShape::kRotatedRectangle), Rational(1, 4));
  const Plan zero = planners::runPlanner("boustrophedon", ctx, {{"direction", "0"}});
  const Plan tilted = planners::runPlanner("boustrophedon", ctx, {{"direction", "30"}});
  const Plan best = planners::runPlanner("boustrophedon", ctx, {{"direction", "best"}});
  for (const Plan* p : {&zero, &tilted, &best}) {
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, *p));
    EXPECT_TRUE(testing_helpers::coversCFreeComponent(ctx, *p, 0.96));
  }
  EXPECT_NEAR(tilted.statistics.at("direction_degrees"), 30, 1e-3);
  EXPECT_GE(best.statistics.at("directions_tried"), 2);
  EXPECT_LE(best.statistics.at("cost"), zero.statistics.at("cost") + 1e-9);
}

TEST(Boustrophedon, ReportsWhatLiesBehindAGapExactly2rWide) {
  // two obstacles leave a gap exactly 2r = 1 wide (y from 1.5 to 2.5) between the halves of the box
  const Workspace w = testing_helpers::boxWith(
      {{{ratio(9, 2), ratio(1, 2)}, {ratio(11, 2), ratio(1, 2)}, {ratio(11, 2), ratio(3, 2)}, {ratio(9, 2), ratio(3, 2)}},
       {{ratio(9, 2), ratio(5, 2)}, {ratio(11, 2), ratio(5, 2)}, {ratio(11, 2), ratio(7, 2)}, {ratio(9, 2), ratio(7, 2)}},
       // a post on the start's side: cells that chains join, so that regions are fewer than cells
       {{ratio(5, 2), ratio(19, 10)}, {ratio(27, 10), ratio(19, 10)}, {ratio(27, 10), ratio(21, 10)}, {ratio(5, 2), ratio(21, 10)}}},
      10, 4);
  const auto ctx = testing_helpers::contextFor(w, Rational(1, 2), Point{1, 2});
  double area = -1;
  for (const char* chains : {"true", "false"}) {   // the cells behind, whatever the regions swept
    const Plan plan = planners::runPlanner("boustrophedon", ctx, {{"chains", chains}});
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
    EXPECT_EQ(plan.status, PlanStatus::kPartialCoverage);
    EXPECT_GT(plan.statistics.at("cells_behind_exact_gaps"), 0);
    EXPECT_GT(plan.statistics.at("area_behind_exact_gaps"), 2);
    if (area >= 0) {
      EXPECT_EQ(plan.statistics.at("area_behind_exact_gaps"), area);
    }
    if (std::string(chains) == "true") {
      EXPECT_LT(plan.statistics.at("sweep_regions"), plan.statistics.at("cells"));
    }
    area = plan.statistics.at("area_behind_exact_gaps");
    for (const PathSegment& s : plan.paths[0].segments) EXPECT_LE(std::max(s.from.x, s.to.x), 5.0);   // stays on its side
  }
}

// Transitions between cells whose shared walls lie on one vertical line with an obstacle's side
// between them, and cells whose interval jumps at a vertical piece of boundary (a corridor with a
// column at its end): every cell is reached (found on the shipped maze at r = 0.4 and on a Moving AI
// maze, where 5 and 14 cells were left).
TEST(Boustrophedon, ReachesEveryCellOfAMaze) {
  const Workspace maze = datasets::loadMap(std::string(COVERKIT_DATA_DIR) + "/maze.map");
  for (const Rational& r : {Rational(2, 5), Rational(31, 100), Rational(1, 4)}) {
    SCOPED_TRACE("r " + r.get_str());
    const auto ctx = testing_helpers::contextFor(maze, r);
    const Plan plan = planners::runPlanner("boustrophedon", ctx, {});
    ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
    EXPECT_EQ(plan.statistics.at("cells_unreached"), 0);
    EXPECT_EQ(plan.statistics.at("sweeps_broken"), 0);
    EXPECT_TRUE(testing_helpers::coversCFreeComponent(ctx, plan, 0.97));
  }
}

TEST(Boustrophedon, RefusesBadParameters) {
  const auto ctx = testing_helpers::contextFor(testing_helpers::boxWith({}), Rational(1, 2));
  for (const auto& kv : std::vector<std::pair<std::string, std::string>>{
           {"direction", "north"}, {"direction", "1e9"}, {"decomposition", "grid"}, {"decomposition", "voronoi"}}) {
    const std::string &k = kv.first, &v = kv.second;   // not a structured binding: clang 14 cannot capture one
    const std::string message = testing_helpers::inputErrorMessage([&] { planners::runPlanner("boustrophedon", ctx, {{k, v}}); });
    EXPECT_NE(message.find(k + "=" + v), std::string::npos) << message;
  }
}
