// multi_stc_balanced and the team's problem checks (docs/multi-robot.md): every team plan valid under
// the team validator, the team entering every sub-cell of the starts' free mega-cells, the makespan
// within what the split promises, deterministic; bad teams rejected with the place named.
#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/planners/registry.h>

#include "helpers/checkers.h"
#include "helpers/worlds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace coverkit;
using namespace coverkit::testing_helpers;

namespace {

planners::PlanningContext team(const Workspace& w, const Rational& r, std::size_t k, const std::vector<Point>& starts = {},
                               std::optional<Rational> cellSize = std::nullopt) {
  Problem p;
  p.workspace = w;
  p.cellSize = cellSize;
  for (std::size_t i = 0; i < k; ++i) p.robots.push_back({r, i < starts.size() ? std::optional<Point>(starts[i]) : std::nullopt});
  return planners::makeContext(std::move(p));
}

/// Disjoint: no sub-cell entered by two robots; together `cells` sub-cells.
void expectDisjointAndWhole(const planners::PlanningContext& ctx, const Plan& plan, double cells) {
  std::vector<int> by(static_cast<std::size_t>(ctx.cells.subCols() * ctx.cells.subRows()), -1);
  for (std::size_t i = 0; i < plan.paths.size(); ++i) {
    Plan one;
    one.paths = {plan.paths[i]};
    const std::vector<char> mine = enteredSubcells(ctx.cells, one);
    for (std::size_t c = 0; c < mine.size(); ++c)
      if (mine[c]) {
        EXPECT_EQ(by[c], -1) << "sub-cell " << c << " entered by robots " << by[c] << " and " << i;
        by[c] = static_cast<int>(i);
      }
  }
  EXPECT_EQ(static_cast<double>(std::count_if(by.begin(), by.end(), [](int o) { return o >= 0; })), cells);
}

}  // namespace

TEST(MultiStc, TeamPlansAreValidCompleteAndBalanced) {
  // the contract's polygon worlds, an open room and seeded grid maps of 1 m pixels (r = 1/2: a pixel
  // is a sub-cell, whose centres are doubles; the contract's 0.1 m grids with r = 1/10 have centres
  // that are not, which the planner refuses for a team, below)
  std::vector<std::pair<std::string, Workspace>> worlds;
  for (auto& [label, w] : contractWorlds())
    if (label.rfind("grid", 0) != 0) worlds.push_back({label, w});
  worlds.push_back({"open", boxWith({})});
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    datasets::GridMapSpec spec;
    spec.width = spec.height = 24;
    spec.density = 0.04 * static_cast<double>(seed);
    spec.clustered = seed != 2;
    spec.seed = seed;
    worlds.push_back({"pixels" + std::to_string(seed), datasets::gridToWorkspace(datasets::generateGridMap(spec), "pixels")});
  }
  int plans = 0;
  for (const auto& [label, w] : worlds) {
    const Rational r = label.rfind("pixels", 0) == 0 ? Rational(1, 2) : contractRadius(label);
    const std::optional<Rational> D;
    // the single robot's tour: what the team must enter between them
    const planners::PlanningContext one = team(w, r, 1, {}, D);
    const Plan stc = planners::runPlanner("stc", one, {}, 0);
    const std::vector<char> want = enteredSubcells(one.cells, stc);
    for (std::size_t k : {1u, 2u, 3u, 5u, 8u}) {
      SCOPED_TRACE(label + " k = " + std::to_string(k));
      const planners::PlanningContext ctx = team(w, r, k, {}, D);
      const Plan plan = planners::runPlanner("multi_stc_balanced", ctx, {}, 0);
      ASSERT_EQ(plan.paths.size(), k);
      EXPECT_TRUE(planIsValid(ctx, plan)) << label << " k = " << k;
      const std::vector<char> got = enteredSubcells(ctx.cells, plan);
      std::size_t missing = 0;
      for (std::size_t c = 0; c < want.size(); ++c) missing += want[c] && !got[c];
      EXPECT_EQ(missing, 0u) << label << " k = " << k;
      // the split: one robot takes the whole tour (one step onto its centre, then a move per cell);
      // a team takes less, whatever the starts (no robot needs more than its stretch's cells and back)
      const double tour = plan.statistics.at("tour_subcells"), makespan = plan.statistics.at("makespan_steps");
      if (k == 1) EXPECT_EQ(makespan, tour) << label;
      else EXPECT_LT(makespan, tour) << label << " k = " << k;
      EXPECT_EQ(pathJsonOf(plan), pathJsonOf(planners::runPlanner("multi_stc_balanced", ctx, {}, 0))) << label;
      ++plans;
    }
  }
  EXPECT_GE(plans, 50);
}

TEST(MultiStc, MoreRobotsFinishSooner) {
  const Workspace w = boxWith({}, 20, 20);
  double previous = 1e300;
  for (std::size_t k : {1u, 2u, 4u, 8u}) {
    const planners::PlanningContext ctx = team(w, Rational(1, 2), k);
    const Plan plan = planners::runPlanner("multi_stc_balanced", ctx, {}, 0);
    ASSERT_TRUE(planIsValid(ctx, plan));
    const double makespan = plan.statistics.at("makespan_s");
    EXPECT_LT(makespan, previous * (k == 1 ? 1.0 : 0.8)) << "k = " << k;
    previous = makespan;
  }
}

TEST(MultiStc, StartsAreSpreadDeterministically) {
  const Workspace w = boxWith({{{4, 4}, {4, 6}, {6, 6}, {6, 4}}});
  const planners::PlanningContext a = team(w, Rational(1, 4), 6), b = team(w, Rational(1, 4), 6);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(*a.problem.robots[i].start, *b.problem.robots[i].start);
    CellIndex c;
    ASSERT_TRUE(a.cells.locateSub(*a.problem.robots[i].start, c));
    EXPECT_EQ(a.cells.mega(c.col / 2, c.row / 2), CellState::kFree);
    for (std::size_t j = 0; j < i; ++j) {
      const Point &p = *a.problem.robots[i].start, &q = *a.problem.robots[j].start;
      EXPECT_GE(Rational((p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y)), Rational(1, 4));
    }
  }
  // a given start stays; the others keep away from it
  const planners::PlanningContext c = team(w, Rational(1, 4), 3, {Point{Rational(9), Rational(9)}});
  EXPECT_EQ(*c.problem.robots[0].start, (Point{Rational(9), Rational(9)}));
  // more robots than room
  EXPECT_NE(inputErrorMessage([&] { team(boxWith({}, 2, 2), Rational(1, 2), 5); }).find("--robots"), std::string::npos);
}

TEST(MultiStc, BadTeamsAreRejected) {
  const Workspace w = boxWith({});
  // two starts nearer than 2r
  EXPECT_NE(inputErrorMessage([&] { team(w, Rational(1, 4), 2, {Point{Rational(1), Rational(1)}, Point{Rational(1), Rational(14, 10)}}); })
                .find("--start: robots 0 and 1: start closer than the sum of their radii"),
            std::string::npos);
  // a moving obstacle that starts on a robot
  Problem p;
  p.workspace = w;
  p.robots.push_back({Rational(1, 4), Point{Rational(1), Rational(1)}});
  p.movingObstacles.push_back({Rational(1, 2), {{0, {1.5, 1.25}}, {10, {9, 9}}}});
  EXPECT_NE(inputErrorMessage([&] { planners::makeContext(p); }).find("dynamic_obstacles[0]: starts on robot 0"), std::string::npos);
  // the same for a default start, one robot or several (an obstacle over the whole room)
  Problem whole;
  whole.workspace = w;
  whole.movingObstacles.push_back({Rational(100), {{5, {5, 5}}}});
  for (std::size_t k : {1u, 3u}) {
    whole.robots.assign(k, Robot{Rational(1, 4), std::nullopt});
    const std::string why = inputErrorMessage([&] { planners::makeContext(whole); });
    EXPECT_TRUE(why.find("dynamic_obstacles[0]: starts on robot 0") != std::string::npos || why.find("clear of the moving obstacles") != std::string::npos)
        << "k = " << k << ": " << why;
  }
  // a single-robot planner refuses a team
  const planners::PlanningContext two = team(w, Rational(1, 4), 2);
  EXPECT_NE(inputErrorMessage([&] { planners::runPlanner("stc", two, {}, 0); }).find("plans for one robot"), std::string::npos);
  // a start in a partially blocked mega-cell: invalid_start, as stc says
  const Workspace holed = boxWith({{{Rational(9, 2), Rational(9, 2)}, {Rational(9, 2), Rational(11, 2)}, {Rational(11, 2), Rational(11, 2)}, {Rational(11, 2), Rational(9, 2)}}});
  const planners::PlanningContext partial = team(holed, Rational(1, 4), 2, {Point{Rational(1), Rational(1)}, Point{Rational(17, 4), Rational(17, 4)}});
  EXPECT_EQ(planners::runPlanner("multi_stc_balanced", partial, {}, 0).status, PlanStatus::kInvalidStart);
  // a grid whose sub-cell centres are not doubles with D = 2r (r = 1/10 or 2/5): without a cell
  // size the team plans on sub-cells a little larger (teamSubCellSize: at most 2^-25 over 2r on this
  // 10 m map), validly with both team planners; a cell size given as 2r is refused with the way out
  for (const Rational& r : {Rational(1, 10), Rational(2, 5)}) {
    const planners::PlanningContext wider = team(w, r, 3);
    EXPECT_GT(wider.cells.subSize(), 2 * r);
    EXPECT_LE(wider.cells.subSize(), 2 * r + Rational(1, 1 << 25));
    for (const char* planner : {"multi_stc_balanced", "multi_st"}) {
      const Plan plan = planners::runPlanner(planner, wider, {}, 0);
      EXPECT_TRUE(planIsValid(wider, plan)) << planner << " r = " << r.get_str();
      EXPECT_EQ(plan.status, PlanStatus::kExactSolution) << planner << " r = " << r.get_str();
    }
    const planners::PlanningContext given = team(w, r, 3, {}, 2 * r);
    EXPECT_NE(inputErrorMessage([&] { planners::runPlanner("multi_stc_balanced", given, {}, 0); }).find("--cell-size a little larger than 2r"),
              std::string::npos);
  }
  // one robot keeps D = 2r (single-robot paths are made safe move by move, docs/stc-family.md)
  EXPECT_EQ(team(w, Rational(1, 10), 1).cells.subSize(), Rational(1, 5));
}

// The regions split (the default on static worlds): each robot's sub-cells are its own, connected
// round its start, their union the whole tour, and the makespan within 1.15 × the ideal (free
// sub-cells / k) steps on obstacle-free maps, for 2 to 24 robots placed farthest apart; 20 robots on
// 50 × 50 and 16 on 24 × 24 need the re-weighted start (1.15 and 1.11 × from the breadth-first one),
// 24 on 24 × 24 its seeded restarts (1.17 × without); on the cluttered grid maps it is no later
// than the travel split.
TEST(MultiStc, RegionsBalanceAnOpenMap) {
  for (int side : {24, 50}) {
    const Workspace w = boxWith({}, side, side);
    const double cells = static_cast<double>(side) * side;
    for (std::size_t k : {2u, 3u, 4u, 8u, 12u, 16u, 20u, 24u}) {
      SCOPED_TRACE("side " + std::to_string(side) + " k = " + std::to_string(k));
      const planners::PlanningContext ctx = team(w, Rational(1, 2), k);
      const Plan plan = planners::runPlanner("multi_stc_balanced", ctx, {}, 0);
      ASSERT_TRUE(planIsValid(ctx, plan));
      EXPECT_EQ(plan.statistics.at("regions"), 1);
      EXPECT_LE(plan.statistics.at("makespan_steps"), 1.15 * cells / static_cast<double>(k));
      expectDisjointAndWhole(ctx, plan, cells);
    }
  }
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    datasets::GridMapSpec spec;
    spec.width = spec.height = 32;
    spec.density = 0.05 * static_cast<double>(seed);
    spec.clustered = true;
    spec.seed = seed;
    const Workspace w = datasets::gridToWorkspace(datasets::generateGridMap(spec), "pixels");
    for (std::size_t k : {2u, 5u, 8u}) {
      const planners::PlanningContext ctx = team(w, Rational(1, 2), k);
      const Plan plan = planners::runPlanner("multi_stc_balanced", ctx, {}, 0);
      const Plan travel = planners::runPlanner("multi_stc_balanced", ctx, {{"regions", "off"}}, 0);
      ASSERT_TRUE(planIsValid(ctx, plan)) << "seed " << seed << " k = " << k;
      EXPECT_LE(plan.statistics.at("makespan_steps"), travel.statistics.at("makespan_steps")) << "seed " << seed << " k = " << k;
    }
  }
}

// Crowded small maps, where regions of whole mega-cells cannot be balanced: an L-shaped room of 64
// mega-cells (r = 1/2; arms 8 m wide) with 13, 20 and 24 robots placed farthest apart took 1.219,
// 1.250 and 1.500 × the ideal with whole mega-cells (20 robots: 1.25 × is the bound for any split
// into whole mega-cells). Regions of sub-cells bring each within 1.15 ×; every plan valid, every
// sub-cell entered by exactly one robot, the same bytes twice; with subcells=off the whole-mega-cell
// split is back. Two robots in one mega-cell (no whole-mega-cell regions exist) get regions too
// (8 robots: 1.375 × with travel, the best split without sub-cell regions there).
TEST(MultiStc, SubcellRegionsBalanceACrowdedRoom) {
  Workspace room;
  room.name = "L";
  Region r;
  r.outer = {{0, 0}, {20, 0}, {20, 8}, {8, 8}, {8, 20}, {0, 20}};
  room.regions.push_back(r);
  normalise(room);
  const double cells = 256;
  for (std::size_t k : {13u, 20u, 24u}) {
    SCOPED_TRACE("k = " + std::to_string(k));
    const planners::PlanningContext ctx = team(room, Rational(1, 2), k);
    const Plan plan = planners::runPlanner("multi_stc_balanced", ctx, {}, 0);
    ASSERT_TRUE(planIsValid(ctx, plan));
    EXPECT_EQ(plan.statistics.at("subcell_regions"), 1);
    EXPECT_EQ(plan.statistics.at("regions"), 1);
    EXPECT_LE(plan.statistics.at("makespan_steps"), 1.15 * cells / static_cast<double>(k));
    expectDisjointAndWhole(ctx, plan, cells);
    EXPECT_EQ(pathJsonOf(plan), pathJsonOf(planners::runPlanner("multi_stc_balanced", ctx, {}, 0)));
    const Plan whole = planners::runPlanner("multi_stc_balanced", ctx, {{"subcells", "off"}}, 0);
    ASSERT_TRUE(planIsValid(ctx, whole));
    EXPECT_EQ(whole.statistics.at("subcell_regions"), 0);
    EXPECT_GT(whole.statistics.at("makespan_steps"), 1.15 * cells / static_cast<double>(k));
  }
  // robots 0 and 1 share the mega-cell [0, 2] x [0, 2] (8 robots: 32 sub-cells each)
  std::vector<Point> starts;
  for (auto [x, y] : std::vector<std::pair<int, int>>{{1, 1}, {3, 1}, {1, 39}, {39, 1}, {9, 9}, {1, 21}, {21, 9}, {13, 29}})
    starts.push_back(Point{Rational(x, 2), Rational(y, 2)});
  const planners::PlanningContext ctx = team(room, Rational(1, 2), 8, starts);
  const Plan plan = planners::runPlanner("multi_stc_balanced", ctx, {}, 0);
  ASSERT_TRUE(planIsValid(ctx, plan));
  EXPECT_EQ(plan.statistics.at("subcell_regions"), 1);
  EXPECT_LE(plan.statistics.at("makespan_steps"), 1.15 * cells / 8);
  expectDisjointAndWhole(ctx, plan, cells);
}

// With travel (the default when regions are off), an obstacle-free map is split evenly: the
// makespan within 1.15 × the ideal (free sub-cells / k) steps for 2 to 16 robots placed farthest
// apart, every plan valid; with travel=off the stretches alone (each robot covering only next to its
// start) are slower.
TEST(MultiStc, TravelBalancesAnOpenMap) {
  const Workspace w = boxWith({}, 50, 50);
  for (std::size_t k : {2u, 4u, 8u, 16u}) {
    const planners::PlanningContext ctx = team(w, Rational(1, 2), k);
    const Plan plan = planners::runPlanner("multi_stc_balanced", ctx, {{"regions", "off"}}, 0);
    ASSERT_TRUE(planIsValid(ctx, plan)) << "k = " << k;
    EXPECT_EQ(plan.statistics.at("travelled"), 1) << "k = " << k;
    EXPECT_LE(plan.statistics.at("makespan_steps"), 1.15 * 2500.0 / static_cast<double>(k)) << "k = " << k;
    const Plan stay = planners::runPlanner("multi_stc_balanced", ctx, {{"travel", "off"}, {"regions", "off"}}, 0);
    ASSERT_TRUE(planIsValid(ctx, stay)) << "k = " << k;
    EXPECT_EQ(stay.statistics.at("travelled"), 0);
    EXPECT_GE(stay.statistics.at("makespan_steps"), plan.statistics.at("makespan_steps"));
  }
}

// Among moving obstacles every step and wait is checked against them exactly, as the validator does:
// the team waits or goes round, and every plan is valid. An obstacle that parks for good on the map
// keeps a few sub-cells out of reach: the plan says so (partial, subcells_skipped) and stays valid.
TEST(MultiStc, PlansAmongMovingObstacles) {
  const Workspace w = boxWith({}, 20, 20);
  for (std::size_t k : {1u, 2u, 4u}) {
    Problem p;
    p.workspace = w;
    p.robots.assign(k, Robot{Rational(1, 2), std::nullopt});
    // one crosses the room and parks in a corner, one sweeps along a row and parks elsewhere, each on
    // a corner of four sub-cells, whose centres are then out of reach for good
    p.movingObstacles.push_back({Rational(1, 2), {{0, {10, 1}}, {20, {10, 19}}, {40, {1, 1}}}});
    p.movingObstacles.push_back({Rational(1, 4), {{5, {1, 12}}, {30, {19, 12}}, {40, {15, 14}}}});
    const planners::PlanningContext ctx = planners::makeContext(p);
    const Plan plan = planners::runPlanner("multi_stc_balanced", ctx, {}, 0);
    ASSERT_TRUE(plan.status == PlanStatus::kExactSolution || plan.status == PlanStatus::kPartialCoverage) << plan.message;
    const ValidationReport rep = validatePaths(ctx.problem, plan.paths);
    EXPECT_TRUE(rep.valid) << "k = " << k << ": " << (rep.violations.empty() ? "" : rep.violations[0].detail);
    EXPECT_EQ(plan.statistics.at("travelled"), 1);
    // each parked obstacle (at a corner of four sub-cells whose centres are √0.5 < r + ρ away) keeps
    // those four out of reach, unless a robot covered them before it arrived
    EXPECT_LE(plan.statistics.at("subcells_skipped"), 8) << "k = " << k;
    EXPECT_EQ(plan.status == PlanStatus::kPartialCoverage, plan.statistics.at("subcells_skipped") > 0);
  }
}

// 16 seeded scenarios among moving obstacles that pass through walls (another generator than
// team-check's: 2-8 robots, 3-10 obstacles of radius 0.2-0.8 at 0.3-2 m/s anywhere in the box,
// r = 1/2 or 1): both team planners' plans valid under the team validator, and every move of a
// timeline between neighbouring sub-cells or a wait (a tour cell left out once made
// multi_stc_balanced jump over it, into a robot parked there; a robot that found no way to its
// piece or no place to park before an obstacle passed made the team stay at its starts).
TEST(MultiStc, SeededScenariosAmongMovingObstaclesAreValid) {
  std::mt19937_64 rng(20261205);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * static_cast<double>(rng() % 1000000) / 1e6; };
  int planned = 0;
  for (int s = 0; s < 16; ++s) {
    const int side = 12 + static_cast<int>(rng() % 13);
    std::vector<Ring> holes;
    for (int b = 0; b < 4; ++b) {   // square blocks on a lattice of 4 m, so they never overlap
      const int x = 4 * static_cast<int>(rng() % static_cast<std::uint64_t>(side / 4 - 1)) + 1, y = 4 * static_cast<int>(rng() % static_cast<std::uint64_t>(side / 4 - 1)) + 1;
      Ring h{{x, y}, {x, y + 2}, {x + 2, y + 2}, {x + 2, y}};
      if (std::none_of(holes.begin(), holes.end(), [&](const Ring& o) { return o[0] == h[0]; })) holes.push_back(h);
    }
    Problem p;
    p.workspace = boxWith(holes, side, side);
    const Rational r = rng() % 2 ? Rational(1) : Rational(1, 2);
    p.robots.assign(2 + rng() % 7, Robot{r, std::nullopt});
    const int obstacles = 3 + static_cast<int>(rng() % 8);
    for (int o = 0; o < obstacles; ++o) {
      MovingObstacle m{exactFromDouble(std::round(uniform(0.2, 0.8) * 100) / 100), {}};
      double t = uniform(1, 5);
      PointD at{uniform(0, side), uniform(0, side)};
      m.waypoints.push_back({t, at});
      for (int w = 1 + static_cast<int>(rng() % 3); w > 0; --w) {
        const PointD next{uniform(0, side), uniform(0, side)};
        t += std::hypot(next.x - at.x, next.y - at.y) / uniform(0.3, 2.0);
        m.waypoints.push_back({t, next});
        at = next;
      }
      p.movingObstacles.push_back(m);
    }
    planners::PlanningContext ctx;
    try {
      ctx = planners::makeContext(p);
    } catch (const InputError&) {
      continue;   // no room for the team clear of the obstacles' first second
    }
    for (const char* planner : {"multi_stc_balanced", "multi_st"}) {
      SCOPED_TRACE(std::string(planner) + " scenario " + std::to_string(s));
      const Plan plan = planners::runPlanner(planner, ctx, {}, 0);
      const ValidationReport rep = validatePaths(ctx.problem, plan.paths);
      EXPECT_TRUE(rep.valid) << plan.message << ": " << (rep.violations.empty() ? "" : rep.violations[0].kind + " " + rep.violations[0].detail);
      const double D = ctx.cells.subSizeD();
      for (const Path& path : plan.paths)
        for (std::size_t e = 2; e < path.timeline.size(); ++e) {
          const double d = std::abs(path.timeline[e].p.x - path.timeline[e - 1].p.x) + std::abs(path.timeline[e].p.y - path.timeline[e - 1].p.y);
          ASSERT_TRUE(d == 0 || std::abs(d - D) < 1e-9 * D) << "a move of " << d << " at t = " << path.timeline[e].t;
        }
    }
    ++planned;
  }
  EXPECT_GE(planned, 13);
}
