// The validator's team checks: timelines, robots against robots and against moving obstacles, in
// time, exactly (docs/multi-robot.md).
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/validate.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace coverkit;

namespace {

Problem room(int robots, Rational r = Rational(1, 4)) {
  Problem p;
  Region reg;
  reg.outer = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  p.workspace.regions.push_back(reg);
  for (int i = 0; i < robots; ++i) p.robots.push_back({r, std::nullopt});
  return p;
}

/// A line path through `pts`, timed: pts[k] reached at times[k].
Path timed(const std::vector<PointD>& pts, const std::vector<double>& times) {
  Path p = Path::fromPoints(pts);
  for (std::size_t k = 0; k < pts.size(); ++k) p.timeline.push_back({times[k], pts[k]});
  return p;
}

bool has(const ValidationReport& r, const std::string& kind) {
  for (const Violation& v : r.violations)
    if (v.kind == kind) return true;
  return false;
}

}  // namespace

TEST(Team, CrossingAtTheSameTimeIsCaughtWaitingIsNot) {
  const Problem p = room(2);
  // robot 0 along y = 5 from x = 1 to 9, robot 1 along x = 5 from y = 1 to 9: both at (5, 5) at t = 4
  const Path a = timed({{1, 5}, {9, 5}}, {0, 8});
  const Path b = timed({{5, 1}, {5, 9}}, {0, 8});
  const ValidationReport bad = validatePaths(p, {a, b});
  ASSERT_FALSE(bad.valid);
  EXPECT_TRUE(has(bad, "robot_robot"));
  // robot 1 waits at its start until robot 0 is past: (5, 1) … robot 0 at x ≥ 5.5 from t = 4.5
  const Path late = timed({{5, 1}, {5, 1}, {5, 9}}, {0, 4.5, 12.5});
  Path lateFixed = Path::fromPoints({{5, 1}, {5, 9}});
  lateFixed.timeline = late.timeline;
  const ValidationReport ok = validatePaths(p, {a, lateFixed});
  EXPECT_TRUE(ok.valid) << (ok.violations.empty() ? "" : ok.violations[0].detail);
}

TEST(Team, TheClosestApproachBetweenTimesIsFound) {
  // head on along parallel lanes 0.4 apart (< 2r = 0.5): far apart at every entry, closest at t = 2
  const Problem p = room(2);
  const Path a = timed({{1, 1}, {5, 1}}, {0, 4});
  const Path b = timed({{5, 1.4}, {1, 1.4}}, {0, 4});
  const ValidationReport r = validatePaths(p, {a, b});
  ASSERT_FALSE(r.valid);
  ASSERT_TRUE(has(r, "robot_robot"));
  // the same lanes exactly 2r apart: touching is allowed; one ulp nearer is not
  const Path b2 = timed({{5, 1.5}, {1, 1.5}}, {0, 4});
  EXPECT_TRUE(validatePaths(p, {a, b2}).valid);
  const double y = std::nextafter(1.5, 0.0);
  const Path b3 = timed({{5, y}, {1, y}}, {0, 4});
  EXPECT_TRUE(has(validatePaths(p, {a, b3}), "robot_robot"));
}

TEST(Team, RobotsOfDifferentSizesAndParkedRobots) {
  Problem p = room(2);
  p.robots[1].radius = Rational(1, 2);
  // robot 0 ends at (3, 3) at t = 2 and stays; robot 1 passes (3, 3.7) at t = 10: 0.7 < 0.75
  const Path a = timed({{1, 3}, {3, 3}}, {0, 2});
  const Path b = timed({{1, 3.7}, {9, 3.7}}, {0, 20});
  EXPECT_TRUE(has(validatePaths(p, {a, b}), "robot_robot"));
  const Path c = timed({{1, 3.75}, {9, 3.75}}, {0, 20});
  EXPECT_FALSE(has(validatePaths(p, {a, c}), "robot_robot"));
}

TEST(Team, TimelinesMustFollowTheirPaths) {
  const Problem p = room(1);
  Problem team = room(2);
  const Path other = timed({{8, 8}, {8, 9}}, {0, 1});
  auto why = [&](const Path& x) {
    const ValidationReport r = validatePaths(team, {x, other});
    for (const Violation& v : r.violations)
      if (v.kind == "timeline") return v.detail;
    return std::string();
  };
  Path path = Path::fromPoints({{1, 1}, {5, 1}, {5, 4}});
  // none: a team needs one per robot
  EXPECT_NE(why(path).find("no timeline"), std::string::npos);
  // along the path, with a wait and a stop in the middle of a piece: fine
  path.timeline = {{0, {1, 1}}, {1, {3, 1}}, {2, {3, 1}}, {3, {5, 1}}, {4, {5, 4}}};
  EXPECT_EQ(why(path), "");
  EXPECT_TRUE(validatePaths(p, {path}).valid);   // a timed single robot is checked the same way
  Path q = path;
  q.timeline[0].t = 0.5;
  EXPECT_NE(why(q).find("not at 0"), std::string::npos);
  q = path;
  q.timeline[2].t = 1;
  EXPECT_NE(why(q).find("does not increase"), std::string::npos);
  q = path;
  q.timeline[1].p = {3, 1.5};   // off the piece
  EXPECT_NE(why(q).find("leaves the path"), std::string::npos);
  q = path;
  q.timeline[1].p = {5, 2};   // across the corner in one move
  EXPECT_NE(why(q).find("leaves the path"), std::string::npos);
  q = path;
  q.timeline = {{0, {1, 1}}, {1, {3, 1}}, {2, {2, 1}}};   // backwards
  EXPECT_NE(why(q).find("leaves the path"), std::string::npos);
  q = path;
  q.timeline.pop_back();
  EXPECT_NE(why(q).find("ends before the path"), std::string::npos);
  q = path;
  q.timeline.push_back({5, {5, 5}});
  EXPECT_NE(why(q).find("after the path's end"), std::string::npos);
  q = path;
  q.timeline[3].t = std::nan("");
  EXPECT_NE(why(q).find("not finite"), std::string::npos);
  Path arc;
  arc.start = {2, 1};
  arc.segments.push_back(PathSegment::arc({2, 1}, {1, 2}, {1, 1}, true));
  arc.timeline = {{0, {2, 1}}, {1, {1, 2}}};
  EXPECT_NE(why(arc).find("arcs are not timed"), std::string::npos);
  // a slanted piece: exactly on it, and one ulp off it
  Path slant = Path::fromPoints({{1, 1}, {4, 2.5}});
  slant.timeline = {{0, {1, 1}}, {1, {3, 2}}, {2, {4, 2.5}}};
  EXPECT_EQ(why(slant), "");
  slant.timeline[1].p.y = std::nextafter(2.0, 3.0);
  EXPECT_NE(why(slant).find("leaves the path"), std::string::npos);
}

TEST(Team, MovingObstacles) {
  Problem p = room(1);
  MovingObstacle m;
  m.radius = Rational(1, 4);
  m.waypoints = {{2, {5, 9}}, {10, {5, 1}}};   // down x = 5 from t = 2 (at (5, 9) before), at (5, 5) at t = 6
  p.movingObstacles.push_back(m);
  const Path a = timed({{1, 5}, {9, 5}}, {0, 8});   // at (5, 5) at t = 4: the obstacle is at (5, 7)
  const ValidationReport early = validatePaths(p, {a});
  EXPECT_TRUE(early.valid) << (early.violations.empty() ? "" : early.violations[0].detail);
  const Path b = timed({{1, 5}, {9, 5}}, {0, 12});   // at (5, 5) at t = 6, with the obstacle
  const ValidationReport hit = validatePaths(p, {b});
  ASSERT_FALSE(hit.valid);
  EXPECT_EQ(hit.violations[0].kind, "robot_obstacle");
  // held after its last waypoint: a robot parked on its way later is hit; one that stops 0.5 from
  // where it ends (= r + ρ) is not, nor one it passes at exactly 0.5
  const Path parked = timed({{1, 1}, {5, 1}}, {0, 1});
  EXPECT_FALSE(validatePaths(p, {parked}).valid);
  const Path beside = timed({{1, 1.5}, {4.5, 1.5}}, {0, 1});
  const Path besideSide = timed({{1, 1}, {4.5, 1}}, {0, 1});
  EXPECT_TRUE(validatePaths(p, {besideSide}).valid);
  EXPECT_TRUE(validatePaths(p, {beside}).valid);
  // an untimed robot among moving obstacles is a timeline violation
  EXPECT_FALSE(validatePaths(p, {Path::fromPoints({{1, 1}, {2, 1}})}).valid);
}

// Whatever the validator accepts, sampling every 1/64 s finds no instant at which two robots are
// nearer than 2r; and it rejects every pair that sampling finds nearer than 2r - 1e-9.
TEST(Team, AgreesWithDenseSampling) {
  const Problem p = room(2);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> coord(4, 36);   // quarters of the room's 1 … 9
  int accepted = 0, rejected = 0;
  for (int trial = 0; trial < 300; ++trial) {
    auto walk = [&] {
      std::vector<PointD> pts{{coord(rng) / 4.0, coord(rng) / 4.0}};
      std::vector<double> ts{0};
      for (int k = 0; k < 3; ++k) {
        const PointD last = pts.back();
        pts.push_back(rng() % 2 ? PointD{coord(rng) / 4.0, last.y} : PointD{last.x, coord(rng) / 4.0});
        ts.push_back(ts.back() + 1 + rng() % 8);
      }
      return timed(pts, ts);
    };
    const Path a = walk(), b = walk();
    if (a.start.x == b.start.x && a.start.y == b.start.y) continue;
    const bool ok = !has(validatePaths(p, {a, b}), "robot_robot");
    double minD = 1e300;
    for (double t = 0; t <= 40; t += 1.0 / 64) {
      auto at = [&](const Path& x) {
        MovingObstacle m{Rational(0), x.timeline};
        return m.at(t);
      };
      const PointD pa = at(a), pb = at(b);
      minD = std::min(minD, std::hypot(pa.x - pb.x, pa.y - pb.y));
    }
    if (ok) EXPECT_GE(minD, 0.5 - 1e-12) << "trial " << trial;
    if (minD < 0.5 - 1e-9) EXPECT_FALSE(ok) << "trial " << trial;
    (ok ? accepted : rejected) += 1;
  }
  EXPECT_GT(accepted, 30);
  EXPECT_GT(rejected, 30);
}

// A timed plan's figures: moves, repeated moves (into a sub-cell any robot entered before, the starts'
// counting from t = 0), the Multi-ST paper's coverage and iteration rates, makespan, sum of times and
// balance; an untimed plan has none of them.
TEST(Team, MetricsOfATimedPlan) {
  const Problem p = room(2);
  const CellGrid cells = classifyCells(p.workspace, Rational(1, 2));
  const Path a = timed({{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.25}}, {0, 0.1, 0.2});
  Path b = timed({{5.25, 5.25}, {5.25, 5.75}}, {0, 0.1});
  b.timeline.insert(b.timeline.begin() + 1, TimedPoint{0.05, {5.25, 5.25}});   // a wait is no move
  const Metrics m = computeMetrics(p, cells, {a, b});
  ASSERT_TRUE(m.hasTeam);
  EXPECT_EQ(m.robots, 2u);
  EXPECT_EQ(m.steps, 3u);
  EXPECT_EQ(m.repeatedSteps, 1u);
  EXPECT_DOUBLE_EQ(m.coverageRate, 2.0 / 400);
  EXPECT_DOUBLE_EQ(m.iterationRate, 1.0 / 3);
  EXPECT_EQ(m.makespan, 0.2);
  EXPECT_DOUBLE_EQ(m.sumOfTimes, 0.3);
  EXPECT_EQ(m.mostCells, 2u);
  EXPECT_EQ(m.leastCells, 2u);
  EXPECT_EQ(m.balance, 1.0);
  EXPECT_FALSE(computeMetrics(room(1), cells, {Path::fromPoints({{0.25, 0.25}, {0.75, 0.25}})}).hasTeam);
}
