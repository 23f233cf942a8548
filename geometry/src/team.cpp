// The team checks of the validator (docs/multi-robot.md): timelines, robots against robots and
// robots against moving obstacles, exactly. No CGAL: positions and times are doubles read as the
// exact rationals they hold, and every verdict is decided on rationals (gmpxx) after a filter in
// doubles whose margin is far above their rounding.
//
// Decisions:
//  * a timeline starts at t = 0 at the path's start, its times strictly increase, and each move
//    (between consecutive entries) stays on one piece of the path's polyline (its start, the pieces'
//    ends, and the gaps the continuity tolerance accepts), forward; it ends at the path's end. So
//    the timeline moves only where the static check has cleared the disc, and the team checks need
//    not repeat it. Arcs are not timed: a timed path is made of lines.
//  * before t = 0 nothing is checked; after its last entry a robot stays where it is, and a moving
//    obstacle stays at its first waypoint before that one's time and at its last one after: the checks
//    run to the latest time of all and the positions held there.
//  * robots i and j must stay at least r_i + r_j apart, a robot and an obstacle of radius ρ at least
//    r + ρ: touching is allowed, as touching a wall is.
#include "team.h"

#include <coverkit/geometry/rational.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace coverkit {

namespace {
/// The place at time t on the move from entry a to entry b (a.t ≤ t ≤ b.t), in doubles.
PointD between(const TimedPoint& a, const TimedPoint& b, double t) {
  const double f = (t - a.t) / (b.t - a.t);
  return {a.p.x + f * (b.p.x - a.p.x), a.p.y + f * (b.p.y - a.p.y)};
}
/// The first entry after time t (entries held before the first and after the last, t inside).
std::vector<TimedPoint>::const_iterator entryAfter(const std::vector<TimedPoint>& e, double t) {
  return std::upper_bound(e.begin(), e.end(), t, [](double v, const TimedPoint& w) { return v < w.t; });
}
}  // namespace

PointD MovingObstacle::at(double t) const {
  if (waypoints.empty()) return {0, 0};
  if (t <= waypoints.front().t) return waypoints.front().p;
  if (t >= waypoints.back().t) return waypoints.back().p;
  const auto it = entryAfter(waypoints, t);
  return between(*(it - 1), *it, t);
}

namespace detail {

namespace {

using Q = Rational;
struct QPoint {
  Q x, y;
};
QPoint exact(PointD p) { return {exactFromDouble(p.x), exactFromDouble(p.y)}; }

std::string fmtT(double t) {
  std::ostringstream os;
  os.precision(17);
  os << t;
  return os.str();
}

/// A piecewise-linear motion in time: its entries, held before the first and after the last.
struct Motion {
  const std::vector<TimedPoint>* entries = nullptr;
  PointD at(double t, std::size_t& hint) const {
    const auto& e = *entries;
    if (t <= e.front().t) return e.front().p;
    if (t >= e.back().t) return e.back().p;
    while (hint + 1 < e.size() && e[hint + 1].t <= t) ++hint;
    return between(e[hint], e[hint + 1], t);
  }
  /// The exact place at time t (t itself read exactly).
  QPoint exactAt(double t) const {
    const auto& e = *entries;
    if (t <= e.front().t) return exact(e.front().p);
    if (t >= e.back().t) return exact(e.back().p);
    const auto it = entryAfter(e, t);
    const TimedPoint &b = *it, &a = *(it - 1);
    const QPoint A = exact(a.p), B = exact(b.p);
    const Q f = (exactFromDouble(t) - exactFromDouble(a.t)) / (exactFromDouble(b.t) - exactFromDouble(a.t));
    return {A.x + f * (B.x - A.x), A.y + f * (B.y - A.y)};
  }
};

/// min over s ∈ [0, 1] of |D0 + s·W|², exactly.
Q closestSquared(const QPoint& D0, const QPoint& W) {
  const Q ww = W.x * W.x + W.y * W.y;
  Q s = 0;
  if (sgn(ww) > 0) {
    s = -(D0.x * W.x + D0.y * W.y) / ww;
    if (s < 0) s = 0;
    if (s > 1) s = 1;
  }
  const Q dx = D0.x + s * W.x, dy = D0.y + s * W.y;
  return dx * dx + dy * dy;
}

/// The same in doubles (the filter).
double closestSquaredD(double dx0, double dy0, double wx, double wy) {
  const double ww = wx * wx + wy * wy;
  double s = ww > 0 ? -(dx0 * wx + dy0 * wy) / ww : 0;
  s = std::min(1.0, std::max(0.0, s));
  const double dx = dx0 + s * wx, dy = dy0 + s * wy;
  return dx * dx + dy * dy;
}

/// The first instant interval over which motions a and b come closer than `minDist` (exactly), or
/// false. `scale` bounds the coordinates' magnitude for the filter's margin.
/// Only the instants in [lo, hi] count (both included; the default: all of them).
bool firstApproach(const Motion& a, const Motion& b, const Q& minDist, double scale, double& t0, double& t1, double& dist,
                   double lo = -HUGE_VAL, double hi = HUGE_VAL) {
  std::vector<double> times;
  times.reserve(a.entries->size() + b.entries->size() + 2);
  for (const auto* m : {&a, &b})
    for (const TimedPoint& e : *m->entries)
      if (e.t >= lo && e.t <= hi) times.push_back(e.t);
  for (double t : {lo, hi})
    if (std::isfinite(t)) times.push_back(t);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  const Q min2 = minDist * minDist;
  const double md = minDist.get_d();
  // a squared distance this far above min² in doubles is certainly above it exactly: the positions
  // are within a few ulps of scale of the exact ones
  const double margin = 1e-9 * (md * md + scale * scale);
  std::size_t ha = 0, hb = 0;
  PointD pa = a.at(times.front(), ha), pb = b.at(times.front(), hb);
  auto decide = [&](double ta, double tb, PointD qa0, PointD qb0, PointD qa1, PointD qb1) {
    const double d2 = closestSquaredD(qa0.x - qb0.x, qa0.y - qb0.y, (qa1.x - qa0.x) - (qb1.x - qb0.x), (qa1.y - qa0.y) - (qb1.y - qb0.y));
    if (d2 > md * md + margin) return true;
    const QPoint A0 = a.exactAt(ta), B0 = b.exactAt(ta), A1 = a.exactAt(tb), B1 = b.exactAt(tb);
    const Q e2 = closestSquared({A0.x - B0.x, A0.y - B0.y}, {(A1.x - A0.x) - (B1.x - B0.x), (A1.y - A0.y) - (B1.y - B0.y)});
    if (e2 >= min2) return true;
    t0 = ta, t1 = tb, dist = std::sqrt(e2.get_d());
    return false;
  };
  if (times.size() == 1) return !decide(times[0], times[0], pa, pb, pa, pb);
  for (std::size_t k = 0; k + 1 < times.size(); ++k) {
    const PointD qa = a.at(times[k + 1], ha), qb = b.at(times[k + 1], hb);
    if (!decide(times[k], times[k + 1], pa, pb, qa, qb)) return true;
    pa = qa, pb = qb;
  }
  return false;
}

/// Whether q lies on segment [a, b] (exactly): collinear, and within its box.
bool onSegment(PointD a, PointD b, PointD q) {
  if (q.x < std::min(a.x, b.x) || q.x > std::max(a.x, b.x) || q.y < std::min(a.y, b.y) || q.y > std::max(a.y, b.y)) return false;
  if ((a.x == b.x && q.x == a.x) || (a.y == b.y && q.y == a.y)) return true;   // axis-parallel: the box decides
  const QPoint A = exact(a), B = exact(b), P = exact(q);
  return sgn((B.x - A.x) * (P.y - A.y) - (B.y - A.y) * (P.x - A.x)) == 0;
}

/// The timeline's own checks (see the file's comment); "" when it is well formed and follows the path.
std::string timelineProblem(const Path& path, int& at) {
  const auto& tl = path.timeline;
  at = -1;
  if (tl.empty()) return "no timeline: every robot of a team, and every robot among moving obstacles, needs one";
  for (std::size_t i = 0; i < tl.size(); ++i) {
    at = static_cast<int>(i);
    if (!std::isfinite(tl[i].t) || !std::isfinite(tl[i].p.x) || !std::isfinite(tl[i].p.y)) return "timeline entry " + std::to_string(i) + " is not finite";
    if (i == 0 && tl[i].t != 0) return "timeline starts at t = " + fmtT(tl[i].t) + ", not at 0";
    if (i > 0 && !(tl[i].t > tl[i - 1].t)) return "timeline entry " + std::to_string(i) + ": time " + fmtT(tl[i].t) + " does not increase";
  }
  for (const PathSegment& s : path.segments)
    if (s.kind != PathSegment::Kind::kLine) {
      at = -1;
      return "a timed path is made of lines: arcs are not timed";
    }
  // the polyline the path's pieces make: its start, each piece's ends (a gap accepted by the
  // continuity tolerance is a piece of its own)
  std::vector<PointD> poly{path.start};
  for (const PathSegment& s : path.segments) {
    if (s.from.x != poly.back().x || s.from.y != poly.back().y) poly.push_back(s.from);
    if (s.to.x != poly.back().x || s.to.y != poly.back().y) poly.push_back(s.to);
  }
  at = 0;
  if (tl[0].p.x != path.start.x || tl[0].p.y != path.start.y) return "timeline starts at another place than the path";
  std::size_t k = 0;       // the robot is on poly's piece k → k + 1 (or at its end)
  PointD cur = path.start;
  for (std::size_t i = 1; i < tl.size(); ++i) {
    at = static_cast<int>(i);
    const PointD q = tl[i].p;
    if (q.x == cur.x && q.y == cur.y) continue;   // a wait
    if (k + 1 >= poly.size()) return "timeline entry " + std::to_string(i) + " moves on after the path's end";
    const PointD b = poly[k + 1];
    // forward on the current piece: between cur and its end (collinear with the piece)
    if (!onSegment(cur, b, q) || !onSegment(poly[k], b, q))
      return "timeline entry " + std::to_string(i) + " leaves the path (not on its piece " + std::to_string(k) + ", forward)";
    cur = q;
    if (q.x == b.x && q.y == b.y) ++k;
  }
  at = static_cast<int>(tl.size()) - 1;
  if (k + 1 < poly.size()) return "timeline ends before the path does (on its piece " + std::to_string(k) + ")";
  return "";
}

}  // namespace

}  // namespace detail

bool movesClearOf(PointD a, PointD b, double t0, double t1, const MovingObstacle& m, const Rational& minDist) {
  if (m.waypoints.empty()) return true;
  // held from t0 on: one entry (a Motion holds it before and after)
  const std::vector<TimedPoint> robot = std::isfinite(t1) ? std::vector<TimedPoint>{{t0, a}, {t1, b}} : std::vector<TimedPoint>{{t0, a}};
  double scale = 1;
  for (const PointD& p : {a, b}) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
  for (const TimedPoint& e : m.waypoints) scale = std::max({scale, std::abs(e.p.x), std::abs(e.p.y)});
  double u0, u1, d;
  return !detail::firstApproach({&robot}, {&m.waypoints}, minDist, scale, u0, u1, d, t0, t1);
}

namespace detail {

bool needsTeamChecks(const Problem& problem, const std::vector<Path>& paths) {
  if (paths.size() > 1 || !problem.movingObstacles.empty()) return true;
  for (const Path& p : paths)
    if (!p.timeline.empty()) return true;
  return false;
}

void checkTeam(const Problem& problem, const std::vector<Path>& paths, const std::function<void(Violation)>& add) {
  std::vector<char> timed(paths.size(), 0);
  double scale = 1;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    int at = -1;
    const std::string why = timelineProblem(paths[i], at);
    if (!why.empty()) add({"timeline", static_cast<int>(i), at, why});
    else timed[i] = 1;
    for (const TimedPoint& e : paths[i].timeline) scale = std::max({scale, std::abs(e.p.x), std::abs(e.p.y)});
  }
  for (std::size_t o = 0; o < problem.movingObstacles.size(); ++o) {
    const MovingObstacle& m = problem.movingObstacles[o];
    for (const TimedPoint& e : m.waypoints) scale = std::max({scale, std::abs(e.p.x), std::abs(e.p.y)});
  }
  // robots against robots, pairs in order
  for (std::size_t i = 0; i < paths.size(); ++i)
    for (std::size_t j = i + 1; j < paths.size(); ++j) {
      if (!timed[i] || !timed[j]) continue;
      const Q minDist = problem.robots[i].radius + problem.robots[j].radius;
      double t0, t1, d;
      if (firstApproach({&paths[i].timeline}, {&paths[j].timeline}, minDist, scale, t0, t1, d))
        add({"robot_robot", static_cast<int>(i), -1,
             "robots " + std::to_string(i) + " and " + std::to_string(j) + " come within " + fmtT(d) + " < " + fmtT(minDist.get_d()) +
                 " of each other between t = " + fmtT(t0) + " and t = " + fmtT(t1)});
    }
  // robots against moving obstacles
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (!timed[i]) continue;
    for (std::size_t o = 0; o < problem.movingObstacles.size(); ++o) {
      const MovingObstacle& m = problem.movingObstacles[o];
      const Q minDist = problem.robots[i].radius + m.radius;
      double t0, t1, d;
      if (firstApproach({&paths[i].timeline}, {&m.waypoints}, minDist, scale, t0, t1, d))
        add({"robot_obstacle", static_cast<int>(i), -1,
             "robot " + std::to_string(i) + " comes within " + fmtT(d) + " < " + fmtT(minDist.get_d()) + " of moving obstacle " +
                 std::to_string(o) + " between t = " + fmtT(t0) + " and t = " + fmtT(t1)});
    }
  }
}

}  // namespace detail
}  // namespace coverkit
