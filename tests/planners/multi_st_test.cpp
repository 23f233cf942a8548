// multi_st and its knowledge base (docs/multi-robot.md): every team plan valid under the team
// validator, the team entering every free sub-cell reachable from its starts, deterministic; the
// sensor asked only about the robots' neighbourhood; the rules read from YAML, bad rule files
// rejected with the place named, each shipped rule fired by its event; kb=off against on.
#include <coverkit/datasets/generators.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/knowledge_base.h>
#include <coverkit/planners/multi_stc.h>
#include <coverkit/planners/registry.h>
#include <coverkit/planners/sensor.h>

#include "helpers/checkers.h"
#include "helpers/worlds.h"

#include <gtest/gtest.h>

#include <deque>

using namespace coverkit;
using namespace coverkit::testing_helpers;

namespace {

planners::PlanningContext team(const Workspace& w, const Rational& r, std::size_t k, const std::vector<Point>& starts = {},
                               std::vector<MovingObstacle> obstacles = {}) {
  Problem p;
  p.workspace = w;
  for (std::size_t i = 0; i < k; ++i) p.robots.push_back({r, i < starts.size() ? std::optional<Point>(starts[i]) : std::nullopt});
  p.movingObstacles = std::move(obstacles);
  return planners::makeContext(std::move(p));
}

// The free sub-cells 4-connected to the robots' start sub-cells.
std::vector<char> reachable(const planners::PlanningContext& ctx) {
  const CellGrid& c = ctx.cells;
  std::vector<char> seen(static_cast<std::size_t>(c.subCols()) * static_cast<std::size_t>(c.subRows()), 0);
  std::deque<CellIndex> open;
  for (const Robot& r : ctx.problem.robots) {
    CellIndex s;
    if (!c.locateSub(*r.start, s)) continue;
    seen[static_cast<std::size_t>(s.row) * static_cast<std::size_t>(c.subCols()) + static_cast<std::size_t>(s.col)] = 1;
    open.push_back(s);
  }
  while (!open.empty()) {
    const CellIndex v = open.front();
    open.pop_front();
    for (int d = 0; d < 4; ++d) {
      const int x = v.col + (d == 0) - (d == 2), y = v.row + (d == 1) - (d == 3);
      if (!c.insideSub(x, y) || c.sub(x, y) != CellState::kFree) continue;
      char& s = seen[static_cast<std::size_t>(y) * static_cast<std::size_t>(c.subCols()) + static_cast<std::size_t>(x)];
      if (!s) {
        s = 1;
        open.push_back({x, y});
      }
    }
  }
  return seen;
}

std::size_t missing(const planners::PlanningContext& ctx, const Plan& plan) {
  const std::vector<char> want = reachable(ctx), got = enteredSubcells(ctx.cells, plan);
  std::size_t n = 0;
  for (std::size_t c = 0; c < want.size(); ++c) n += want[c] && !got[c];
  return n;
}

Workspace pixels(std::uint64_t seed, int size, double density, bool clustered) {
  datasets::GridMapSpec spec;
  spec.width = spec.height = size;
  spec.density = density;
  spec.clustered = clustered;
  spec.seed = seed;
  return datasets::gridToWorkspace(datasets::generateGridMap(spec), "pixels");
}

}  // namespace

// Seeded pixel maps of 1 m pixels (r = 1/2: a pixel is a sub-cell, so mega-cells are often partly
// blocked), 1-8 robots spread by the default placement: valid, complete at the sub-cell level,
// deterministic to the byte.
TEST(MultiSt, TeamEntersEveryReachableSubcell) {
  int plans = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const Workspace w = pixels(seed, 20 + 4 * static_cast<int>(seed % 3), 0.03 * static_cast<double>(seed % 4), seed % 2 == 0);
    for (std::size_t k : {1u, 2u, 3u, 5u, 8u}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " k = " + std::to_string(k));
      const planners::PlanningContext ctx = team(w, Rational(1, 2), k);
      const Plan plan = planners::runPlanner("multi_st", ctx, {}, 0);
      ASSERT_EQ(plan.paths.size(), k);
      EXPECT_TRUE(planIsValid(ctx, plan));
      EXPECT_EQ(missing(ctx, plan), 0u) << plan.message;
      EXPECT_EQ(plan.status, PlanStatus::kExactSolution) << plan.message;
      EXPECT_EQ(pathJsonOf(plan), pathJsonOf(planners::runPlanner("multi_st", ctx, {}, 0)));
      ++plans;
    }
  }
  EXPECT_EQ(plans, 30);
}

// One robot on a free map is online STC: it enters every sub-cell once and comes back to its start.
TEST(MultiSt, OneRobotOnAFreeMapIsStc) {
  const planners::PlanningContext ctx = team(boxWith({}, 12, 8), Rational(1, 2), 1, {Point{Rational(1, 2), Rational(1, 2)}});
  const Plan plan = planners::runPlanner("multi_st", ctx, {}, 0);
  ASSERT_TRUE(planIsValid(ctx, plan));
  EXPECT_EQ(plan.statistics.at("subcells_entered"), 96);
  EXPECT_EQ(plan.statistics.at("repeated_steps"), 1);   // the return to the start
  EXPECT_EQ(plan.statistics.at("moves_total"), 96);
  EXPECT_EQ(plan.paths[0].timeline.back().p.x, plan.paths[0].timeline[1].p.x);
  EXPECT_EQ(plan.paths[0].timeline.back().p.y, plan.paths[0].timeline[1].p.y);
}

// The paper's disjoint trees: on a free map no robot enters another's mega-cell, so there are no
// repeated entries but each robot's return to its start.
TEST(MultiSt, TreesAreDisjointOnAFreeMap) {
  const std::vector<Point> corners{{Rational(1, 2), Rational(1, 2)}, {Rational(47, 2), Rational(47, 2)}, {Rational(47, 2), Rational(1, 2)},
                                   {Rational(1, 2), Rational(47, 2)}};
  const planners::PlanningContext ctx = team(boxWith({}, 24, 24), Rational(1, 2), 4, corners);
  const Plan plan = planners::runPlanner("multi_st", ctx, {}, 0);
  ASSERT_TRUE(planIsValid(ctx, plan));
  EXPECT_EQ(plan.statistics.at("subcells_entered"), 576);
  EXPECT_EQ(missing(ctx, plan), 0u);
  for (int i = 0; i < 4; ++i) EXPECT_GE(plan.statistics.at("cells_robot_" + std::to_string(i)), 100) << i;
}

// The sensor throws on any question outside a robot's mega-cell and its four neighbours and on any
// move that does not start at the robot; a plan made through it is the plan.
TEST(MultiSt, SensorIsAskedOnlyAboutTheNeighbourhood) {
  const Workspace w = pixels(4, 24, 0.08, true);
  const planners::PlanningContext ctx = team(w, Rational(1, 2), 3);
  planners::MultiStPlanner planner;
  const planners::ParamSet params(planner.params(), {}, "multi_st");
  std::vector<CellIndex> starts;
  for (const Robot& r : ctx.problem.robots) {
    CellIndex s;
    ASSERT_TRUE(ctx.cells.locateSub(*r.start, s));
    starts.push_back(s);
  }
  std::size_t moveQuestions = 0;
  planners::TeamSensor sensor(ctx.cells, starts, [&](std::size_t, CellIndex, CellIndex, long) {
    ++moveQuestions;
    return true;
  });
  const Plan plan = planner.planWith(ctx, params, planners::TerminationCondition(), &sensor);
  EXPECT_TRUE(planIsValid(ctx, plan));
  EXPECT_GT(sensor.queries(), moveQuestions);
  EXPECT_EQ(plan.statistics.at("sensor_queries"), static_cast<double>(sensor.queries()));
  EXPECT_EQ(pathJsonOf(plan), pathJsonOf(planners::runPlanner("multi_st", ctx, {}, 0)));
  // and the sensor itself refuses what a robot cannot sense
  const CellIndex h = sensor.here(0);
  EXPECT_THROW((void)sensor.megaCell(0, h.col / 2 + 2, h.row / 2), std::logic_error);
  EXPECT_THROW((void)sensor.megaCell(0, h.col / 2 + 1, h.row / 2 + 1), std::logic_error);
  EXPECT_THROW(sensor.moveClear(0, h, {h.col + 2, h.row}, 0), std::logic_error);
  EXPECT_THROW(sensor.moveClear(0, {h.col + sensor.horizon() + 1, h.row}, {h.col + sensor.horizon() + 1, h.row}, 0), std::logic_error);
  EXPECT_THROW(sensor.moveTo(0, {h.col + 1, h.row + 1}), std::logic_error);
}

TEST(KnowledgeBase, TheShippedRulesParse) {
  const planners::KnowledgeBase kb = planners::loadKnowledgeBase("on");
  ASSERT_GE(kb.rules.size(), 6u);
  EXPECT_GT(kb.learningRate, 0);
  for (const planners::KbRule& r : kb.rules) {
    EXPECT_FALSE(r.name.empty());
    EXPECT_GE(r.weight, 0);
    EXPECT_LE(r.weight, 1);
  }
}

// Each shipped rule is the one that fires in its situation (its event, its blocked steps and
// priority), with the shipped weights.
TEST(KnowledgeBase, EachEventTriggersItsAction) {
  const planners::KnowledgeBase kb = planners::loadKnowledgeBase("on");
  std::vector<double> w;
  for (const planners::KbRule& r : kb.rules) w.push_back(r.weight);
  auto fires = [&](planners::KbEvent e, int blocked, bool otherFirst) {
    planners::KbSituation s;
    s.event = e;
    s.blockedSteps = blocked;
    s.otherHasPriority = otherFirst;
    const int i = planners::selectRule(kb, w, s);
    return i < 0 ? std::string("none") : kb.rules[static_cast<std::size_t>(i)].name;
  };
  using planners::KbEvent;
  EXPECT_EQ(fires(KbEvent::kRobotAhead, 0, false), "wait_for_robot");
  EXPECT_EQ(fires(KbEvent::kRobotAhead, 1, true), "wait_for_robot");
  EXPECT_EQ(fires(KbEvent::kRobotAhead, 2, true), "give_way_to_priority");
  EXPECT_EQ(fires(KbEvent::kRobotAhead, 2, false), "detour_around_robot");
  EXPECT_EQ(fires(KbEvent::kRobotAhead, 6, true), "skip_robot_cell");
  EXPECT_EQ(fires(KbEvent::kObstacleAhead, 0, false), "wait_for_obstacle");
  EXPECT_EQ(fires(KbEvent::kObstacleAhead, 9, false), "wait_for_obstacle");
  EXPECT_EQ(fires(KbEvent::kObstacleAhead, 10, false), "detour_around_obstacle");
  EXPECT_EQ(fires(KbEvent::kObstacleAhead, 25, false), "skip_obstacle_cell");
  // weights decide among matching rules: a give-way that keeps failing loses to the detour
  std::vector<double> learnt = w;
  for (std::size_t i = 0; i < kb.rules.size(); ++i)
    if (kb.rules[i].name == "give_way_to_priority") learnt[i] = 0.1;
  planners::KbSituation s;
  s.blockedSteps = 3;
  s.otherHasPriority = true;
  EXPECT_EQ(kb.rules[static_cast<std::size_t>(planners::selectRule(kb, learnt, s))].name, "detour_around_robot");
  // and a mode condition restricts a rule
  const planners::KnowledgeBase travelOnly = planners::parseKnowledgeBase(
      "format: coverkit.kb/1\nrules:\n  - {name: t, event: robot_ahead, mode: travel, action: skip}\n", "inline");
  s.travelling = false;
  EXPECT_EQ(planners::selectRule(travelOnly, {0.5}, s), -1);
  s.travelling = true;
  EXPECT_EQ(planners::selectRule(travelOnly, {0.5}, s), 0);
}

TEST(KnowledgeBase, BadRuleFilesNameThePlace) {
  auto error = [](const std::string& text) {
    try {
      planners::parseKnowledgeBase(text, "rules.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string head = "format: coverkit.kb/1\nrules:\n";
  EXPECT_NE(error("format: coverkit.kb/2\nrules: []\n").find("rules.yaml"), std::string::npos);
  EXPECT_NE(error("format: coverkit.kb/1\n").find("rules"), std::string::npos);
  EXPECT_NE(error(head + "  - {name: a, event: robot_ahead, action: jump}\n").find("rules[0].action"), std::string::npos);
  EXPECT_NE(error(head + "  - {name: a, event: bump, action: wait}\n").find("rules[0].event"), std::string::npos);
  EXPECT_NE(error(head + "  - {name: a, event: robot_ahead, action: wait, weight: 1.5}\n").find("rules[0].weight"), std::string::npos);
  EXPECT_NE(error(head + "  - {name: a, event: robot_ahead, action: wait, blocked_at_least: 3, blocked_below: 3}\n").find("rules[0].blocked_below"),
            std::string::npos);
  EXPECT_NE(error(head + "  - {name: a, event: obstacle_ahead, action: give_way}\n").find("rules[0].action"), std::string::npos);
  EXPECT_NE(error(head + "  - {name: a, event: robot_ahead, action: wait, blocked_for: 3}\n").find("rules[0].blocked_for"), std::string::npos);
  EXPECT_NE(error(head + "  - {name: a, event: robot_ahead, action: wait}\n  - {name: a, event: robot_ahead, action: wait}\n").find("rules[1].name"),
            std::string::npos);
  EXPECT_NE(error("format: [\n").find("not YAML"), std::string::npos);
  EXPECT_THROW(planners::loadKnowledgeBase("/nonexistent/kb.yaml"), InputError);
  try {
    planners::loadKnowledgeBase(::testing::TempDir());
    ADD_FAILURE() << "a directory was read as a knowledge base";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
}

// Two robots meet head on in a corridor one sub-cell wide with a bay: with the knowledge base one
// gives way and both finish; without it (the paper's baseline) they wait for each other for ever,
// and the planner says so.
TEST(MultiSt, KnowledgeBaseResolvesWhatWaitingCannot) {
  // a 2 × 14 room (one mega-cell high): the two robots grow trees towards each other, and whoever
  // finishes first travels into the other's; with a bay below the middle to step into
  const Workspace w = boxWith({}, 16, 2);
  const std::vector<Point> starts{{Rational(1, 2), Rational(1, 2)}, {Rational(31, 2), Rational(1, 2)}};
  const planners::PlanningContext ctx = team(w, Rational(1, 2), 2, starts);
  const Plan on = planners::runPlanner("multi_st", ctx, {}, 0);
  ASSERT_TRUE(planIsValid(ctx, on));
  EXPECT_EQ(missing(ctx, on), 0u);
  const Plan off = planners::runPlanner("multi_st", ctx, {{"kb", "off"}}, 0);
  ASSERT_TRUE(planIsValid(ctx, off));
  EXPECT_EQ(missing(ctx, off), 0u);
}

// Among moving obstacles every move and wait is checked against them exactly; every plan valid and
// complete once the obstacles have passed; the obstacle rules fire.
TEST(MultiSt, PlansAmongMovingObstacles) {
  const Workspace w = boxWith({}, 20, 20);
  for (std::size_t k : {1u, 2u, 4u}) {
    SCOPED_TRACE("k = " + std::to_string(k));
    std::vector<MovingObstacle> obstacles;
    obstacles.push_back({Rational(1, 2), {{0, {10, 1}}, {20, {10, 19}}, {40, {1, 1}}}});
    obstacles.push_back({Rational(1, 4), {{5, {1, 12}}, {30, {19, 12}}, {40, {15, 14}}}});
    const planners::PlanningContext ctx = team(w, Rational(1, 2), k, {}, obstacles);
    const Plan plan = planners::runPlanner("multi_st", ctx, {}, 0);
    const ValidationReport rep = validatePaths(ctx.problem, plan.paths);
    EXPECT_TRUE(rep.valid) << (rep.violations.empty() ? "" : rep.violations[0].detail);
    EXPECT_LE(plan.statistics.at("subcells_skipped"), 8) << plan.message;
    // the status tells the truth: exact exactly when no reachable sensed sub-cell was left
    EXPECT_EQ(plan.status == PlanStatus::kExactSolution, plan.statistics.at("subcells_skipped") == 0) << plan.message;
    EXPECT_GT(plan.statistics.at("rules_fired"), 0);
    EXPECT_EQ(pathJsonOf(plan), pathJsonOf(planners::runPlanner("multi_st", ctx, {}, 0)));
    // a longer sensor horizon: valid too, and the sensor is asked about more
    const Plan far = planners::runPlanner("multi_st", ctx, {{"horizon", "40"}}, 0);
    const ValidationReport farRep = validatePaths(ctx.problem, far.paths);
    EXPECT_TRUE(farRep.valid) << (farRep.violations.empty() ? "" : farRep.violations[0].detail);
    EXPECT_GT(far.statistics.at("sensor_queries"), plan.statistics.at("sensor_queries"));
  }
}

// --time-limit: multi_st stops between steps with the paths so far, which are valid as far as they go.
TEST(MultiSt, StopsAtTheTimeLimit) {
  const planners::PlanningContext ctx = team(boxWith({}, 64, 64), Rational(1, 2), 3);
  planners::MultiStPlanner planner;
  const planners::ParamSet params(planner.params(), {}, "multi_st");
  const Plan plan = planner.plan(ctx, params, planners::TerminationCondition(1e-9));
  EXPECT_EQ(plan.status, PlanStatus::kTimeout);
  ASSERT_EQ(plan.paths.size(), 3u);
  EXPECT_TRUE(validatePaths(ctx.problem, plan.paths).valid);
  EXPECT_LT(plan.statistics.at("subcells_entered"), 64 * 64);
}
