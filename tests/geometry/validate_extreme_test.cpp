// The validator's verdict must be exact for every finite input: lines and arcs whose ends or
// centres lie from 1e0 to 1e300 away (issue 12's false "valid" verdicts), checked against an
// independent computation written here in plain doubles with margins (cases the doubles cannot
// decide are skipped and counted).
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/rational.h>
#include <coverkit/geometry/validate.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <random>

using namespace coverkit;

namespace {

/// The world: a 10 × 10 room with a 2 × 2 hole in its middle.
Problem room(double r) {
  Problem p;
  Region reg;
  reg.outer = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  reg.holes.push_back({{4, 4}, {4, 6}, {6, 6}, {6, 4}});
  p.workspace.regions.push_back(reg);
  p.workspace.name = "room";
  p.robots.push_back({exactFromDouble(r), std::nullopt});
  return p;
}

Path single(PathSegment s) {
  Path p;
  p.start = s.from;
  p.segments.push_back(s);
  return p;
}

bool valid(const Problem& p, const Path& path) { return validatePaths(p, {path}).valid; }

// ---- the independent computation: distances to the room's eight edges in doubles ----------------
const double kEdges[8][4] = {{0, 0, 10, 0}, {10, 0, 10, 10}, {10, 10, 0, 10}, {0, 10, 0, 0},
                             {4, 4, 4, 6},  {4, 6, 6, 6},    {6, 6, 6, 4},    {6, 4, 4, 4}};
double pointSeg(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / l2, 0.0, 1.0) : 0;
  return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}
bool insideRoom(double x, double y) { return x > 0 && x < 10 && y > 0 && y < 10 && !(x >= 4 && x <= 6 && y >= 4 && y <= 6); }
/// The least distance from a point to the room's boundary, and whether it is in the free space.
double clearance(double x, double y) {
  double d = 1e300;
  for (const auto& e : kEdges) d = std::min(d, pointSeg(x, y, e[0], e[1], e[2], e[3]));
  return insideRoom(x, y) ? d : -d;
}

/// Verdict of a segment inside the room by dense sampling: 1 valid, 0 invalid, -1 undecided.
int sampledVerdict(const std::vector<std::pair<double, double>>& pts, double r, double step) {
  double least = 1e300;
  for (const auto& [x, y] : pts) least = std::min(least, clearance(x, y));
  if (least < r - step) return 0;
  if (least > r + step) return 1;
  return -1;
}

}  // namespace

TEST(ValidatorExtreme, ArcAboutAFarCentreTheLongWayIsInvalid) {
  // the case: from (1, 1) to (1, 1.5) about (X, 1), counter-clockwise: the long way round
  const Problem p = room(0.25);
  for (double X : {1e150, 1e160, 1e200, 1e300, 1e308}) {
    EXPECT_FALSE(valid(p, single(PathSegment::arc({1, 1}, {1, 1.5}, {X, 1}, true)))) << X;
    // clockwise it is the short way: a straight-looking step up, inside the room
    EXPECT_TRUE(valid(p, single(PathSegment::arc({1, 1}, {1, 1.5}, {X, 1}, false)))) << X;
    // and the same mirrored (centre far to the left and below)
    EXPECT_FALSE(valid(p, single(PathSegment::arc({9, 1}, {9, 1.5}, {-X, 1}, false)))) << X;
    EXPECT_TRUE(valid(p, single(PathSegment::arc({9, 1}, {9, 1.5}, {-X, 1}, true)))) << X;
  }
}

TEST(ValidatorExtreme, SegmentToAFarPointIsInvalid) {
  const Problem p = room(0.25);
  for (double x : {7.1e9, 7.2e9, 3e9, 1e12, 1e19, 1e100, 1e300, 1.7e308}) {
    EXPECT_FALSE(valid(p, Path::fromPoints({{1, 1}, {x, 1}}))) << x;
    EXPECT_FALSE(valid(p, Path::fromPoints({{1, 1}, {-x, 1}}))) << x;
    EXPECT_FALSE(valid(p, Path::fromPoints({{1, 1}, {1, x}}))) << x;
    EXPECT_FALSE(valid(p, Path::fromPoints({{x, 1}, {1, 1}}))) << x;   // starts outside
    // the second piece leaves: the first is fine
    EXPECT_FALSE(valid(p, Path::fromPoints({{1, 1}, {2, 1}, {x, x}}))) << x;
  }
}

TEST(ValidatorExtreme, NearFullCircleOfAHugeRadiusIsInvalidAndLong) {
  // ends one double apart on a circle of radius 2e154: counter-clockwise from below to above the
  // start is almost the whole circle
  const Problem p = room(0.25);
  const double R = 2e154;
  const PathSegment s = PathSegment::arc({1, 1}, {1, std::nextafter(1.0, 2.0)}, {1 + R, 1}, false);
  // cw from angle π toward angle π − tiny is the short way; ccw is the long way
  const PathSegment longWay = PathSegment::arc({1, 1}, {1, std::nextafter(1.0, 2.0)}, {1 + R, 1}, true);
  EXPECT_TRUE(valid(p, single(s)));
  EXPECT_FALSE(valid(p, single(longWay)));
  EXPECT_GT(longWay.length(), 6.28 * R);
  EXPECT_LT(s.length(), 1e-9);
  // a full circle (from == to) is 2π long, as the validator reads it
  EXPECT_NEAR(PathSegment::arc({1, 1}, {1, 1}, {2, 1}, true).length(), 2 * M_PI, 1e-12);
}

TEST(ValidatorExtreme, MetricsOfAHugeArcAreBoundedByWhatLiesInTheWorkspace) {
  // an arc of radius 1e7 (and 1e12) used to sample every D/32 along its whole length
  const Problem p = room(0.25);
  const CellGrid cells = classifyCells(p.workspace, Rational(1, 2));
  for (double R : {1e7, 1e12, 1e100}) {
    const Path path = single(PathSegment::arc({1, 1}, {1, 1.5}, {1 + R, 1}, true));
    const auto t0 = std::chrono::steady_clock::now();
    MetricOptions o;
    const Metrics m = computeMetrics(p, cells, {path}, o);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_GT(m.length, 6 * R);
    EXPECT_GE(m.subcellCoverage, 0);
    EXPECT_LE(m.subcellCoverage, 1);
    EXPECT_LE(m.areaCoverage, 1 + m.areaCoverageError + 1e-9);
    // not a speed assertion: a record of what it took (a hang would time the test out)
    RecordProperty("seconds_R" + std::to_string(static_cast<int>(std::log10(R))), std::to_string(seconds));
  }
}

TEST(ValidatorExtreme, PolylineWithinKeepsOnlyWhatIsInTheBox) {
  const BoxD box{0, 0, 10, 10};
  // a line through the box from far away: clipped to its part inside
  Path line = Path::fromPoints({{-1e300, 5}, {1e300, 5}});
  auto runs = line.polylineWithin(0.01, box);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_DOUBLE_EQ(runs[0].front().x, 0);
  EXPECT_DOUBLE_EQ(runs[0].back().x, 10);
  // a circle of radius 4 about (5, 5) lies inside: sampled within the tolerance, closed
  Path circle = single(PathSegment::arc({9, 5}, {9, 5}, {5, 5}, true));
  runs = circle.polylineWithin(1e-3, box);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_GT(runs[0].size(), 50u);
  for (const PointD& q : runs[0]) EXPECT_NEAR(std::hypot(q.x - 5, q.y - 5), 4, 1e-9);
  // a circle of radius 6 about (5, 5) leaves the box four times: four runs inside
  Path big = single(PathSegment::arc({11, 5}, {11, 5}, {5, 5}, true));
  runs = big.polylineWithin(1e-3, box);
  EXPECT_EQ(runs.size(), 4u);
  for (const auto& run : runs)
    for (const PointD& q : run) {
      EXPECT_GE(q.x, -1e-9);
      EXPECT_LE(q.x, 10 + 1e-9);
      EXPECT_GE(q.y, -1e-9);
      EXPECT_LE(q.y, 10 + 1e-9);
    }
  // a huge arc: only its part in the box is sampled (a few points, not 10^12)
  Path huge = single(PathSegment::arc({1, 1}, {1, 1.5}, {1e12, 1}, true));
  std::size_t points = 0;
  for (const auto& run : huge.polylineWithin(1e-3, box)) points += run.size();
  EXPECT_LT(points, 100000u);
}

/// Property: random lines and arcs with ends and centres 10^0 … 10^300 away, in both directions,
/// against the independent verdict. Far pieces must be invalid (they leave the 10 × 10 room); near
/// ones are decided by dense sampling with a margin.
TEST(ValidatorExtreme, PropertyFarLinesAndArcsAgreeWithAnIndependentVerdict) {
  const double r = 0.25;
  const Problem p = room(r);
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> inside(0.6, 9.4), angle(0, 2 * M_PI);
  int checked = 0, skipped = 0;
  for (int e = 0; e <= 300; e += 4) {
    const double far = std::pow(10.0, e);
    for (int rep = 0; rep < 3; ++rep) {
      // a start with clearance > r
      double fx, fy;
      do {
        fx = inside(rng);
        fy = inside(rng);
      } while (clearance(fx, fy) <= r + 0.05);
      const double th = angle(rng);
      // ---- a line from the start to a point `far` away, and back
      {
        const double qx = fx + far * std::cos(th), qy = fy + far * std::sin(th);
        int expect;
        if (far >= 20) expect = 0;  // leaves the room
        else {
          std::vector<std::pair<double, double>> pts;
          for (int k = 0; k <= 4000; ++k) pts.emplace_back(fx + (qx - fx) * k / 4000.0, fy + (qy - fy) * k / 4000.0);
          expect = sampledVerdict(pts, r, far / 4000 + 1e-9);
        }
        if (expect < 0) ++skipped;
        else {
          EXPECT_EQ(valid(p, Path::fromPoints({{fx, fy}, {qx, qy}})), expect == 1) << "line to 1e" << e << " at " << th;
          EXPECT_EQ(valid(p, Path::fromPoints({{qx, qy}, {fx, fy}})), expect == 1 && far < 20 && clearance(qx, qy) > r)
              << "line from 1e" << e;
          ++checked;
        }
      }
      // ---- an arc from the start to a nearby end, about a centre `far` away on the bisector
      {
        double tx, ty;
        do {
          const double a = angle(rng);
          tx = fx + 0.5 * std::cos(a);
          ty = fy + 0.5 * std::sin(a);
        } while (clearance(tx, ty) <= r + 0.05);
        const double mx = (fx + tx) / 2, my = (fy + ty) / 2, len = std::hypot(tx - fx, ty - fy);
        const double nx = -(ty - fy) / len, ny = (tx - fx) / len;  // left normal of F → T
        for (int side : {1, -1}) {
          const double cx = mx + side * far * nx, cy = my + side * far * ny;
          // the centre on the left of F → T: counter-clockwise from F to T is the short way
          for (bool ccw : {true, false}) {
            const bool shortWay = (side == 1) == ccw;
            int expect;
            if (far >= 100) {
              if (!shortWay) expect = 0;  // round a circle of radius ≥ 100: leaves the room
              else {
                // within the sagitta len²/(8·far) of the chord
                std::vector<std::pair<double, double>> pts;
                for (int k = 0; k <= 1000; ++k) pts.emplace_back(fx + (tx - fx) * k / 1000.0, fy + (ty - fy) * k / 1000.0);
                expect = sampledVerdict(pts, r, len * len / (8 * far) + len / 1000 + 1e-9);
              }
            } else {
              const double rho = std::hypot(fx - cx, fy - cy), a0 = std::atan2(fy - cy, fx - cx), a1 = std::atan2(ty - cy, tx - cx);
              double sweep = ccw ? a1 - a0 : a0 - a1;
              while (sweep < 0) sweep += 2 * M_PI;
              std::vector<std::pair<double, double>> pts;
              const int n = 20000;
              for (int k = 0; k <= n; ++k) {
                const double a = a0 + (ccw ? 1 : -1) * sweep * k / n;
                pts.emplace_back(cx + rho * std::cos(a), cy + rho * std::sin(a));
              }
              expect = sampledVerdict(pts, r, rho * sweep / n + 1e-6);
            }
            if (expect < 0) {
              ++skipped;
              continue;
            }
            EXPECT_EQ(valid(p, single(PathSegment::arc({fx, fy}, {tx, ty}, {cx, cy}, ccw))), expect == 1)
                << "arc about a centre 1e" << e << " away, side " << side << (ccw ? " ccw" : " cw") << std::setprecision(17)
                << ": from " << fx << "," << fy << " to " << tx << "," << ty << " about " << cx << "," << cy;
            // the reverse direction: from T back to F is the same set of points
            EXPECT_EQ(valid(p, single(PathSegment::arc({tx, ty}, {fx, fy}, {cx, cy}, !ccw))), expect == 1)
                << "reversed arc about a centre 1e" << e << " away";
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 5 * skipped);
  RecordProperty("checked", checked);
  RecordProperty("skipped", skipped);
}

namespace {
/// An arc's swept angle from exact rationals, as the library defined it before its doubles fast
/// path: the signed angle from the exact cross and dot products, atan of their ratio truncated.
double sweepFromRationals(const PathSegment& s) {
  if (s.from.x == s.to.x && s.from.y == s.to.y) return 2 * M_PI;
  const Rational cx = exactFromDouble(s.center.x), cy = exactFromDouble(s.center.y);
  const Rational ux = exactFromDouble(s.from.x) - cx, uy = exactFromDouble(s.from.y) - cy;
  const Rational vx = exactFromDouble(s.to.x) - cx, vy = exactFromDouble(s.to.y) - cy;
  const Rational cr = ux * vy - uy * vx, dt = ux * vx + uy * vy;
  double th;
  if (sgn(cr) == 0) th = sgn(dt) >= 0 ? 0 : M_PI;
  else if (sgn(dt) == 0) th = sgn(cr) > 0 ? M_PI / 2 : -M_PI / 2;
  else {
    const double t = std::atan(std::abs(Rational(cr / dt).get_d()));
    th = sgn(cr) > 0 ? (sgn(dt) > 0 ? t : M_PI - t) : -(sgn(dt) > 0 ? t : M_PI - t);
  }
  if (s.ccw) return th >= 0 ? th : 2 * M_PI + th;
  return th <= 0 ? -th : 2 * M_PI - th;
}
}  // namespace

TEST(ValidatorExtreme, ArcLengthInDoublesIsTheExactAnglesToTheBit) {
  // grid-map arcs (ends and centres on multiples of 2^-k, where doubles give the products exactly),
  // arbitrary doubles (where they do not) and huge and tiny magnitudes: the length is the rational
  // computation's to the bit, the angle truncated exactly as mpq_get_d truncates
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> small(-4000, 4000), shift(0, 6), sign(0, 1);
  std::uniform_real_distribution<double> any(-1e3, 1e3), expo(-300, 300);
  int checked = 0;
  for (int i = 0; i < 20000; ++i) {
    PointD c, a, b;
    const int kind = i % 4;
    auto pick = [&]() -> double {
      if (kind == 0) return std::ldexp(small(rng), -shift(rng));
      if (kind == 1) return any(rng);
      if (kind == 2) return (sign(rng) ? 1 : -1) * std::pow(10.0, expo(rng));
      return 0.05 * small(rng);   // a 0.05 m map's coordinates
    };
    c = {pick(), pick()};
    a = {pick(), pick()};
    b = {pick(), pick()};
    if (kind == 0 && i % 8 == 0) b = {c.x - (a.y - c.y), c.y + (a.x - c.x)};   // a quarter turn exactly
    if (kind == 0 && i % 16 == 4) b = {2 * c.x - a.x, 2 * c.y - a.y};          // a half turn exactly
    for (bool ccw : {true, false}) {
      const PathSegment s = PathSegment::arc(a, b, c, ccw);
      const double rad = std::hypot(a.x - c.x, a.y - c.y);
      if (!std::isfinite(rad)) continue;
      const double want = rad * sweepFromRationals(s);
      ASSERT_EQ(s.length(), want) << std::setprecision(17) << "arc (" << a.x << "," << a.y << ") -> (" << b.x << ","
                                  << b.y << ") about (" << c.x << "," << c.y << ")" << (ccw ? " ccw" : " cw");
      ++checked;
    }
  }
  EXPECT_GT(checked, 30000);
}
