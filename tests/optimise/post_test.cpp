// Path post-processing (issue 15): the chain's parsing and its exact re-validation, the `fillet`
// and `smooth` processors on every planner's plans over the contract worlds, and the robot-time
// metrics.
#include "helpers/checkers.h"
#include "helpers/worlds.h"

#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/optimise/processor.h>
#include <coverkit/planners/registry.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <utility>

using namespace coverkit;

namespace {

/// A processor that moves every path's last point far outside the workspace: never valid.
class BrokenProcessor : public optimise::PathProcessor {
public:
  std::string name() const override { return "test_broken"; }
  std::string description() const override { return "test only: a path that leaves the workspace"; }
  std::vector<planners::ParamSpec> params() const override { return {}; }
  Plan process(const Problem&, const Plan& plan, const planners::ParamSet&) const override {
    Plan out = plan;
    for (Path& p : out.paths) p.segments.push_back(PathSegment::line(p.segments.back().to, {1e6, 1e6}));
    out.statistics["moved"] = 1;
    return out;
  }
};

Metrics metricsOf(const planners::PlanningContext& ctx, const Plan& plan, const CSpace* cspace = nullptr) {
  MetricOptions o;
  o.coverable = true;
  o.cspace = cspace;   // its helper C-spaces are built once per world
  return computeMetrics(ctx.problem, ctx.cells, plan.paths, o);
}

}  // namespace

TEST(PostProcessing, StepsParseAndBadOnesAreRefused) {
  const auto s = optimise::parsePostStep("fillet:max_radius=0.3");
  EXPECT_EQ(s.name, "fillet");
  EXPECT_EQ(s.params.at("max_radius"), "0.3");
  EXPECT_TRUE(optimise::parsePostStep("fillet").params.empty());
  for (const char* bad : {"", ":max_radius=1", "fillet:max_radius", "fillet:=1", "fillet:max_radius=1;max_radius=2"})
    EXPECT_NE(testing_helpers::inputErrorMessage([&] { optimise::parsePostStep(bad); }), "") << bad;
  EXPECT_NE(testing_helpers::inputErrorMessage([] { optimise::checkPostSteps({{"no_such_processor", {}}}); }).find("known: fillet"),
            std::string::npos);
  EXPECT_NE(testing_helpers::inputErrorMessage([] { optimise::checkPostSteps({{"fillet", {{"max_radius", "-1"}}}}); }), "");
  EXPECT_NE(testing_helpers::inputErrorMessage([] { optimise::checkPostSteps({{"fillet", {{"radius", "1"}}}}); }), "");
}

TEST(PostProcessing, AnInvalidResultIsRevertedAndReported) {
  auto& reg = optimise::ProcessorRegistry::instance();
  if (!reg.contains("test_broken")) reg.add("test_broken", [] { return std::make_unique<BrokenProcessor>(); });
  const auto ctx = testing_helpers::contextFor(testing_helpers::contractWorlds()[1].second, Rational(1, 4));
  const Plan plan = planners::runPlanner("stc", ctx, {});
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
  const Plan out = optimise::postProcess(ctx.problem, plan, {{"test_broken", {}}, {"fillet", {}}});
  EXPECT_EQ(out.statistics.at("post_test_broken_reverted"), 1);
  EXPECT_EQ(out.statistics.at("post_test_broken_moved"), 1);
  EXPECT_EQ(out.statistics.at("post_fillet_reverted"), 0);
  EXPECT_GT(out.statistics.at("post_fillet_rounded"), 0);
  EXPECT_TRUE(testing_helpers::planIsValid(ctx, out));
}

// The bar: on every planner's plans over the contract worlds, `fillet` and `smooth` keep the
// plan valid (exactly), lose at most 0.5 percentage points of the coverable region and never add
// turning or reversals; `fillet` never adds turns or robot time either, and removes more than half
// of the turns. One test for both processors, so that the plans and their metrics are made once.
namespace {

/// What a processor did over all plans.
struct Tally {
  double worstLoss = 0, turningBefore = 0, turningAfter = 0;
  std::size_t plans = 0, before = 0, after = 0;
  void print(const std::string& processor) const {
    std::cout << processor << ", " << plans << " plans: turns " << before << " -> " << after << ", total turning " << turningBefore << " -> "
              << turningAfter << " deg, worst coverage loss " << worstLoss * 100 << " pp\n";
  }
};

}  // namespace

TEST(PostProcessing, FilletAndSmoothOnEveryPlannerOverTheContractWorlds) {
  Tally fillet, smooth;
  for (const auto& [label, world] : testing_helpers::contractWorlds()) {
    const auto ctx = testing_helpers::contextFor(world, testing_helpers::contractRadius(label));
    const CSpace cspace(ctx.problem.workspace, ctx.problem.robots[0].radius);
    for (const std::string& name : planners::Registry::instance().names()) {
      SCOPED_TRACE(label + " " + name);
      const Plan plan = planners::runPlanner(name, ctx, {});
      if (!succeeded(plan.status)) continue;
      EXPECT_TRUE(testing_helpers::planIsValid(ctx, plan));
      const Metrics m0 = metricsOf(ctx, plan, &cspace);
      if (!m0.hasCoverable) {
        ADD_FAILURE() << "coverable region not computed";
        continue;
      }
      for (const std::string processor : {"fillet", "smooth"}) {
        SCOPED_TRACE(processor);
        const bool fewerTurnsToo = processor == "fillet";
        Tally& t = fewerTurnsToo ? fillet : smooth;
        const Plan out = optimise::postProcess(ctx.problem, plan, {{processor, {}}});
        EXPECT_EQ(out.statistics.at("post_" + processor + "_reverted"), 0);
        EXPECT_TRUE(testing_helpers::planIsValid(ctx, out));
        const Metrics m1 = metricsOf(ctx, out, &cspace);
        if (!m1.hasCoverable) {
          ADD_FAILURE() << "coverable region not computed";
          continue;
        }
        const double loss = m0.coverableCoverage - m1.coverableCoverage;
        t.worstLoss = std::max(t.worstLoss, loss);
        EXPECT_LE(loss, 0.005 + m0.coverableAreaError / m0.coverableArea);
        EXPECT_LE(m1.turningAngleDeg, m0.turningAngleDeg * (1 + 1e-9) + 1e-9);
        EXPECT_LE(m1.reversals, m0.reversals);
        if (fewerTurnsToo) {
          EXPECT_LE(m1.turns, m0.turns);
          EXPECT_LE(m1.robotTime, m0.robotTime * (1 + 1e-9));
        }
        ++t.plans;
        t.before += m0.turns;
        t.after += m1.turns;
        t.turningBefore += m0.turningAngleDeg;
        t.turningAfter += m1.turningAngleDeg;
      }
    }
  }
  fillet.print("fillet");
  smooth.print("smooth");
  EXPECT_LT(fillet.after, fillet.before / 2);
}

// A path that zigzags by 0.05 r about a straight line in an open room: smoothing straightens it
// (total turning down by more than half), clear, the same on every run, and it reports its work.
TEST(PostProcessing, SmoothStraightensAZigzag) {
  const auto ctx = testing_helpers::contextFor(testing_helpers::boxWith({}, 10, 4), Rational(1, 2), Point{1, 2});
  Plan plan;
  plan.status = PlanStatus::kExactSolution;
  Path path;
  path.start = {1, 2};
  PointD at{1, 2};
  for (int i = 1; i <= 40; ++i) {
    const PointD next{1 + 0.2 * i, 2 + (i % 2 ? 0.025 : 0)};
    path.segments.push_back(PathSegment::line(at, next));
    at = next;
  }
  plan.paths = {path};
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
  const Plan out = optimise::postProcess(ctx.problem, plan, {{"smooth", {}}});
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, out));
  EXPECT_EQ(out.statistics.at("post_smooth_reverted"), 0);
  EXPECT_GT(out.statistics.at("post_smooth_iterations"), 0);
  EXPECT_LT(out.statistics.at("post_smooth_cost_after"), out.statistics.at("post_smooth_cost_before"));
  const Metrics m0 = computeMetrics(ctx.problem, ctx.cells, plan.paths), m1 = computeMetrics(ctx.problem, ctx.cells, out.paths);
  EXPECT_LT(m1.turningAngleDeg, m0.turningAngleDeg / 2);
  EXPECT_EQ(testing_helpers::pathJsonOf(out), testing_helpers::pathJsonOf(optimise::postProcess(ctx.problem, plan, {{"smooth", {}}})));
}

// The notch where two arcs of a C-space contour meet (the robot rounding two pixel corners of a
// grid map's staircase wall): `fillet` rounds it too, and as the arcs on either side turn the
// other way and are shortened, the total turning falls (it would stay for two lines).
TEST(PostProcessing, FilletRoundsTheNotchBetweenTwoArcs) {
  const double h = std::sqrt(3.0) / 2;
  const PointD a{2 - h, 4.5}, joint{2.5, 4 + h}, b{3 + h, 4.5};
  const auto ctx = testing_helpers::contextFor(testing_helpers::boxWith({}, 8, 8), Rational(1, 4), Point{exactFromDouble(a.x), exactFromDouble(a.y)});
  Plan plan;
  plan.status = PlanStatus::kExactSolution;
  Path path;
  path.start = a;
  path.segments = {PathSegment::arc(a, joint, {2, 4}, false), PathSegment::arc(joint, b, {3, 4}, false)};
  plan.paths = {path};
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
  const Metrics m0 = computeMetrics(ctx.problem, ctx.cells, plan.paths);
  ASSERT_EQ(m0.turns, 1);   // the notch (60°)
  const Plan out = optimise::postProcess(ctx.problem, plan, {{"fillet", {}}});
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, out));
  EXPECT_EQ(out.statistics.at("post_fillet_rounded"), 1);
  const Metrics m1 = computeMetrics(ctx.problem, ctx.cells, out.paths);
  EXPECT_EQ(m1.turns, 0);
  EXPECT_LT(m1.turningAngleDeg, m0.turningAngleDeg - 1);
  EXPECT_LT(m1.robotTime, m0.robotTime);
}

TEST(RobotTime, LinesCornersAndArcsAsTheModelSays) {
  MetricOptions o;   // v 0.5 m/s, a 0.5 m/s², ω 1.5 rad/s
  Path line;
  line.segments = {PathSegment::line({0, 0}, {4, 0})};
  // accelerate 1 s over 0.25 m, cruise 3.5 m at 0.5 m/s, brake 1 s
  EXPECT_NEAR(robotTraversalTime(line, o), 1 + 7 + 1, 1e-12);
  // where the robot is: 1 s in it has accelerated over 0.25 m, 5 s in it has cruised 2 m more
  EXPECT_NEAR(robotDistanceAt(line, 1, o), 0.25, 1e-12);
  EXPECT_NEAR(robotDistanceAt(line, 5, o), 2.25, 1e-12);
  EXPECT_NEAR(robotDistanceAt(line, 8.5, o), 4 - 0.5 * 0.5 * 0.5 * 0.5, 1e-12);
  EXPECT_EQ(robotDistanceAt(line, 100, o), 4);
  Path shortLine;
  shortLine.segments = {PathSegment::line({0, 0}, {0.125, 0})};
  // never reaches 0.5 m/s: peak sqrt(a L) = 0.25, 2 × 0.5 s
  EXPECT_NEAR(robotTraversalTime(shortLine, o), 1.0, 1e-12);
  Path corner;
  corner.segments = {PathSegment::line({0, 0}, {4, 0}), PathSegment::line({4, 0}, {4, 4})};
  EXPECT_NEAR(robotTraversalTime(corner, o), 2 * 9 + (M_PI / 2) / 1.5, 1e-12);
  EXPECT_EQ(robotDistanceAt(corner, 9 + 0.5, o), 4);   // turning on the spot at the corner
  EXPECT_NEAR(robotDistanceAt(corner, 9 + M_PI / 3 + 1, o), 4.25, 1e-12);
  // the same corner as a quarter circle of radius 0.2 between the lines: no stop; on the arc at most
  // ω ρ = 0.3 m/s, so the robot brakes from 0.5 to 0.3 before it (0.16 m, 0.4 s) and speeds up after
  Path round;
  round.segments = {PathSegment::line({0, 0}, {3.8, 0}), PathSegment::arc({3.8, 0}, {4, 0.2}, {3.8, 0.2}, true),
                    PathSegment::line({4, 0.2}, {4, 4})};
  const double arc = M_PI * 0.2 / 2;
  const double expected = 1 + (3.8 - 0.25 - 0.16) / 0.5 + 0.4 + arc / 0.3 + 0.4 + (3.8 - 0.16 - 0.25) / 0.5 + 1;
  EXPECT_NEAR(robotTraversalTime(round, o), expected, 1e-9);
  EXPECT_LT(robotTraversalTime(round, o), robotTraversalTime(corner, o));
  // reversals and curvature
  Path back;
  back.segments = {PathSegment::line({0, 0}, {1, 0}), PathSegment::line({1, 0}, {0, 0.1}), PathSegment::arc({0, 0.1}, {-0.25, 0.35}, {0, 0.35}, false)};
  Problem problem;
  problem.workspace.regions.push_back({{{-1, -1}, {2, -1}, {2, 2}, {-1, 2}}, {}});
  problem.robots.push_back({Rational(1, 20), Point{0, 0}});
  o.area = false;
  const Metrics m = computeMetrics(problem, classifyCells(problem.workspace, Rational(1, 10)), {back}, o);
  EXPECT_EQ(m.reversals, 1u);
  EXPECT_NEAR(m.maxCurvature, 4, 1e-9);
}
