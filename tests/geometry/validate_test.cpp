#include <coverkit/geometry/validate.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace coverkit;

namespace {
Problem corridor() {
  // free corridor [0,10] × [0,1] between walls; robot radius 1/2 fits exactly
  Problem p;
  Region r;
  r.outer = {{0, 0}, {10, 0}, {10, 1}, {0, 1}};
  p.workspace.regions.push_back(r);
  p.workspace.name = "corridor";
  p.robots.push_back({Rational(1, 2), Point{Rational(1), Rational(1, 2)}});
  return p;
}
Path line(const std::vector<PointD>& pts) { return Path::fromPoints(pts); }
}  // namespace

TEST(Validator, TouchingTheWallExactlyIsAllowed) {
  const Problem p = corridor();
  const auto rep = validatePaths(p, {line({{1, 0.5}, {9, 0.5}})});
  EXPECT_TRUE(rep.valid) << (rep.violations.empty() ? "" : rep.violations[0].detail);
}

TEST(Validator, OneUlpIntoTheWallIsCaught) {
  const Problem p = corridor();
  const double y = std::nextafter(0.5, 0.0);
  const auto rep = validatePaths(p, {line({{1, 0.5}, {5, y}})});
  ASSERT_FALSE(rep.valid);
  EXPECT_EQ(rep.violations[0].kind, "clearance");
  EXPECT_EQ(rep.violations[0].segment, 0);
}

TEST(Validator, DiscontinuityAndWrongStart) {
  Problem p = corridor();
  Path path = line({{1, 0.5}, {3, 0.5}});
  path.segments.push_back(PathSegment::line({4, 0.5}, {5, 0.5}));
  auto rep = validatePaths(p, {path});
  ASSERT_FALSE(rep.valid);
  EXPECT_EQ(rep.violations[0].kind, "continuity");
  EXPECT_EQ(rep.violations[0].segment, 1);
  p.robots[0].start = Point{Rational(2), Rational(1, 2)};
  rep = validatePaths(p, {line({{1, 0.5}, {3, 0.5}})});
  ASSERT_FALSE(rep.valid);
  EXPECT_EQ(rep.violations[0].kind, "start");
}

TEST(Validator, PathThroughAHoleIsCaught) {
  Problem p;
  Region r;
  r.outer = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  r.holes.push_back({{4, 4}, {4, 6}, {6, 6}, {6, 4}});
  p.workspace.regions.push_back(r);
  p.robots.push_back({Rational(1, 4), Point{Rational(1), Rational(5)}});
  EXPECT_FALSE(validatePaths(p, {line({{1, 5}, {9, 5}})}).valid);
  EXPECT_TRUE(validatePaths(p, {line({{1, 5}, {1, 3.75}, {9, 3.75}})}).valid);    // distance exactly 1/4
  EXPECT_FALSE(validatePaths(p, {line({{1, 5}, {1, 3.8}, {9, 3.8}})}).valid);     // 0.2 < 1/4
}

TEST(Validator, ArcsAreCheckedExactly) {
  Problem p;
  Region r;
  r.outer = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  r.holes.push_back({{4, 4}, {4, 6}, {6, 6}, {6, 4}});
  p.workspace.regions.push_back(r);
  p.robots.push_back({Rational(1, 2), Point{Rational(8), Rational(5)}});
  // half circle of radius 3 about (5,5) from (8,5) ccw to (2,5): passes (5,8); the square's corner
  // (6,6) is at distance 3 - sqrt(2) ≈ 1.59 > 1/2 from the circle; clear.
  Path ok;
  ok.start = {8, 5};
  ok.segments.push_back(PathSegment::arc({8, 5}, {2, 5}, {5, 5}, true));
  EXPECT_TRUE(validatePaths(p, {ok}).valid);
  // radius 1.5: the corner (6,6) is 1.5 - sqrt(2) ≈ 0.086 away: hits
  p.robots[0].start = Point{Rational(13, 2), Rational(5)};
  Path bad;
  bad.start = {6.5, 5};
  bad.segments.push_back(PathSegment::arc({6.5, 5}, {3.5, 5}, {5, 5}, true));
  EXPECT_FALSE(validatePaths(p, {bad}).valid);
  // the same arc clockwise goes below the square: also hits (symmetry), and a cw arc of radius 3 is clear
  Path cw;
  cw.start = {8, 5};
  cw.segments.push_back(PathSegment::arc({8, 5}, {2, 5}, {5, 5}, false));
  p.robots[0].start = Point{Rational(8), Rational(5)};
  EXPECT_TRUE(validatePaths(p, {cw}).valid);
  // an end point off the circle is reported
  Path off;
  off.start = {8, 5};
  off.segments.push_back(PathSegment::arc({8, 5}, {2, 5.5}, {5, 5}, true));
  const auto rep = validatePaths(p, {off});
  ASSERT_FALSE(rep.valid);
  EXPECT_EQ(rep.violations[0].kind, "arc");
}

TEST(Validator, SegmentClearPredicate) {
  const Problem p = corridor();
  EXPECT_TRUE(segmentClear(p.workspace, Rational(1, 2), {Rational(1), Rational(1, 2)}, {Rational(9), Rational(1, 2)}));
  EXPECT_FALSE(segmentClear(p.workspace, Rational(1, 2), {Rational(1), Rational(1, 2)}, {Rational(9), Rational(2, 5)}));
}

// The interval filter in front of the exact tests must never change a verdict. Pieces are placed
// at r·(1 + e) from obstacle edges and vertices whose coordinates are not doubles, with e down to
// 1e-15 (where doubles cannot decide), and every verdict is compared with the unfiltered checker;
// some arcs end a little off their circle, with the short jump the checker adds there; arcs are
// also given as doubles (ClearanceChecker::clearArc on PointD, what planners and the validator use).
TEST(Validator, IntervalFilterNeverChangesAVerdict) {
  Workspace w;
  Region reg;
  reg.outer = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  reg.holes.push_back({{Rational(10, 3), Rational(22, 7)}, {Rational(20, 3), Rational(37, 9)}, {Rational(21, 5), Rational(78, 11)}});
  // a square turned by atan(3/4): rational vertices
  reg.holes.push_back({{Rational(7), Rational(1)}, {Rational(39, 5), Rational(8, 5)}, {Rational(36, 5), Rational(12, 5)}, {Rational(32, 5), Rational(9, 5)}});
  w.regions.push_back(reg);
  const Rational r(3, 10);
  ClearanceChecker fast(w, r), exact(w, r, false);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  const double eps[] = {-1e-3, -1e-13, -1e-15, 0, 1e-15, 1e-13, 1e-3};
  auto P = [](double x, double y) { return Point{exactFromDouble(x), exactFromDouble(y)}; };
  int clear = 0, blocked = 0;
  for (const auto& hole : reg.holes) {
    const std::size_t n = hole.size();
    for (int trial = 0; trial < 140; ++trial) {
      const std::size_t i = rng() % n;
      const double ax = hole[i].x.get_d(), ay = hole[i].y.get_d(), bx = hole[(i + 1) % n].x.get_d(),
                   by = hole[(i + 1) % n].y.get_d();
      const double e = eps[rng() % 7], rho = 0.3 * (1 + e);
      bool a = false, b = false;
      if (trial % 2 == 0) {  // a segment beside edge i, parallel or slanted
        const double len = std::hypot(bx - ax, by - ay), nx = (by - ay) / len, ny = -(bx - ax) / len;  // outward for cw holes
        const double t = u(rng), s = u(rng) * 0.8, tilt = (rng() % 2) ? 0 : (u(rng) - 0.5) * 1e-9;
        const double x0 = ax + t * (bx - ax) + rho * nx, y0 = ay + t * (by - ay) + rho * ny;
        const double x1 = x0 + s * (bx - ax) / len + tilt * nx, y1 = y0 + s * (by - ay) / len + tilt * ny;
        a = fast.clear(P(x0, y0), P(x1, y1));
        b = exact.clear(P(x0, y0), P(x1, y1));
      } else {  // an arc about vertex i
        // the end off the circle by up to 4e-10 of ρ in a third of them: a jump the filter bounds
        const double a0 = u(rng) * 2 * M_PI, a1 = a0 + (u(rng) - 0.5) * 2 * M_PI, off = rho * (1 + (trial % 3 == 1 ? 4e-10 : 0));
        const PointD fd{ax + rho * std::cos(a0), ay + rho * std::sin(a0)}, td{ax + off * std::cos(a1), ay + off * std::sin(a1)};
        const Point f = P(fd.x, fd.y), to = P(td.x, td.y);
        const bool ccw = rng() % 2;
        a = fast.clearArc(f, to, P(ax, ay), ccw);
        b = exact.clearArc(f, to, P(ax, ay), ccw);
        // the same arc as doubles (a path's), decided on intervals where they suffice
        ASSERT_EQ(fast.clearArc(fd, td, PointD{ax, ay}, ccw), b) << "trial " << trial << " e = " << e << ", doubles";
      }
      ASSERT_EQ(a, b) << "trial " << trial << " e = " << e;
      (a ? clear : blocked) += 1;
    }
  }
  EXPECT_GT(clear, 20);
  EXPECT_GT(blocked, 20);
}

// A path's pieces come as doubles: the validator bounds their squared distances on intervals
// without converting them to rationals first. On a grid map the pieces run at exactly r from the
// obstacle edges (Full-STC beside a blocked pixel), where those bounds are exact: the verdict must
// still be the exact test's, at r and one ulp either side, for lines along, across and slanted.
TEST(Validator, PiecesAsDoublesAtExactlyRGetTheExactTestsVerdict) {
  Workspace w;
  Region reg;
  reg.outer = {{0, 0}, {20, 0}, {20, 20}, {0, 20}};
  for (int k = 0; k < 4; ++k) {   // unit pixels blocked, cw holes
    const Rational x(3 + 4 * k), y(5 + 3 * k);
    reg.holes.push_back({{x, y}, {x, y + 1}, {x + 1, y + 1}, {x + 1, y}});
  }
  w.regions.push_back(reg);
  Problem p;
  p.workspace = w;
  p.robots.push_back({Rational(1, 2), std::nullopt});
  ClearanceChecker exact(w, Rational(1, 2), false);
  auto P = [](PointD q) { return Point{exactFromDouble(q.x), exactFromDouble(q.y)}; };
  std::mt19937 rng(11);
  int clear = 0, blocked = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const auto& hole = reg.holes[static_cast<std::size_t>(rng() % 4)];
    const double hx = hole[0].x.get_d(), hy = hole[0].y.get_d();
    const double off[] = {std::nextafter(0.5, 0.0), 0.5, std::nextafter(0.5, 1.0), 0.25, 1.5};
    const double d = off[rng() % 5];
    const double along0 = hx - 3 + static_cast<double>(rng() % 8) * 0.5, along1 = along0 + 0.5 + static_cast<double>(rng() % 6);
    PointD a, b;
    const double diag[] = {0.25, 0.375, std::nextafter(0.375, 0.0), 0.5};
    switch (rng() % 5) {
      case 4: a = b = {hx - diag[rng() % 4], hy - diag[rng() % 4]}; break;   // a point off the corner (both gaps)
      case 0: a = {along0, hy - d}; b = {along1, hy - d}; break;                 // below, along the bottom edge
      case 1: a = {hx + 1 + d, hy - 2 + along0 - hx}; b = {hx + 1 + d, hy - 2 + along1 - hx}; break;  // right side
      case 2: a = {hx - d, hy - 2}; b = {hx - d - 1e-9, hy + 3}; break;          // left, slightly slanted
      default: a = {hx - d, hy + 0.5}; b = {hx - d, hy + 0.5}; break;            // a point
    }
    const bool byExact = exact.clear(P(a), P(b));
    const ValidationReport rep = validatePaths(p, {line({a, b})});
    ASSERT_EQ(rep.valid, byExact) << "trial " << trial << " (" << a.x << "," << a.y << ")-(" << b.x << "," << b.y << ")";
    (byExact ? clear : blocked) += 1;
  }
  EXPECT_GT(clear, 100);
  EXPECT_GT(blocked, 100);
}

// A long path is checked in ranges on several threads: the report (verdict, every violation in
// order, the counts) must be the one of a single thread, with faults in several ranges, a gap, and
// a non-finite coordinate that ends the validation.
TEST(Validator, ThreadsGiveTheSameReport) {
  const Problem p = corridor();
  std::vector<PointD> pts;
  for (int i = 0; i < 24000; ++i) pts.push_back({1 + 8.0 * (i % 2), 0.5});   // along the corridor and back
  Path path = Path::fromPoints(pts);
  for (std::size_t k : {100u, 7000u, 15001u, 23000u}) path.segments[k].to.y = 0.4;   // into the wall
  for (std::size_t k : {101u, 7001u, 15002u, 23001u}) path.segments[k].from.y = 0.4;
  path.segments[12000].from.x += 1e-3;                                                   // a gap
  auto report = [&](const Path& q, unsigned threads) {
    ValidationOptions o;
    o.threads = threads;
    o.maxViolations = 7;
    return validatePaths(p, {q}, o);
  };
  auto same = [](const ValidationReport& a, const ValidationReport& b) {
    EXPECT_EQ(a.valid, b.valid);
    EXPECT_EQ(a.segmentsChecked, b.segmentsChecked);
    EXPECT_EQ(a.exactTests, b.exactTests);
    ASSERT_EQ(a.violations.size(), b.violations.size());
    for (std::size_t i = 0; i < a.violations.size(); ++i) {
      EXPECT_EQ(a.violations[i].kind, b.violations[i].kind);
      EXPECT_EQ(a.violations[i].segment, b.violations[i].segment);
      EXPECT_EQ(a.violations[i].detail, b.violations[i].detail);
    }
  };
  const ValidationReport one = report(path, 1);
  ASSERT_FALSE(one.valid);
  EXPECT_EQ(one.violations.size(), 7u);   // capped, in path order
  EXPECT_EQ(one.violations.front().segment, 100);
  same(one, report(path, 2));
  same(one, report(path, 3));
  Path broken = path;
  broken.segments[18000].to.x = std::numeric_limits<double>::quiet_NaN();
  const ValidationReport stopped = report(broken, 1);
  EXPECT_EQ(stopped.segmentsChecked, 18001u);
  same(stopped, report(broken, 2));
  same(stopped, report(broken, 4));
}

// Arcs about an obstacle's corner, as Smooth-STC's sweeps turn: the two edges at the corner are at
// distance exactly ρ from every point of the arc whose direction makes at least 90° with them, and
// are decided on rationals without the exact square-root test. Verdicts worked out by hand.
TEST(Validator, ArcsAboutAnObstacleCornerAreDecidedByTheirDirections) {
  Workspace w;
  Region reg;
  reg.outer = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  reg.holes.push_back({{4, 4}, {4, 6}, {6, 6}, {6, 4}});   // corner c = (6, 6): edges down and left
  w.regions.push_back(reg);
  const Rational r(1, 2);
  auto P = [](const char* x, const char* y) { return Point{Rational(x), Rational(y)}; };
  const Point c = P("6", "6");
  struct Case {
    Point from, to;
    bool ccw, clear;
    const char* what;
  };
  const Case cases[] = {
      {P("13/2", "6"), P("6", "13/2"), true, true, "the outer quarter, ρ = r: touches both edges' lines at its ends"},
      {P("6", "13/2"), P("13/2", "6"), false, true, "the same quarter clockwise"},
      {P("63/10", "32/5"), P("6", "13/2"), true, true, "inside the quarter, from (3/5, 4/5)·r"},
      {P("162/25", "293/50"), P("6", "13/2"), true, false, "from 16° below: 0.48 from the right edge"},
      {P("6", "13/2"), P("13/2", "6"), true, false, "the long way round (270°)"},
      {P("822/125", "729/125"), P("6", "33/5"), true, true, "ρ = 0.6 from 16° below: 0.576 from the edge (the exact test)"},
      {P("159/25", "138/25"), P("6", "33/5"), true, false, "ρ = 0.6 from 53° below: 0.36 from the edge"},
  };
  ClearanceChecker fast(w, r), exact(w, r, false);
  for (const Case& k : cases) {
    EXPECT_EQ(fast.clearArc(k.from, k.to, c, k.ccw), k.clear) << k.what;
    EXPECT_EQ(exact.clearArc(k.from, k.to, c, k.ccw), k.clear) << k.what;
  }
}
