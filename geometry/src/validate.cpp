// The independent validator. Exact: line pieces with CGAL's Cartesian kernel over GMP rationals
// (squared distances are rational), arcs with CORE::Expr (exact square roots). Doubles are used
// only to skip edges that are certainly far away (margin far above double rounding).
#include <coverkit/geometry/validate.h>

#include "edge_index.h"

#include <CGAL/CORE_Expr.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/mpq_class.h>
#include <CGAL/squared_distance_2.h>

#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/cspace.h>

#include <cmath>
#include <sstream>

namespace coverkit {

namespace {

using K = CGAL::Simple_cartesian<mpq_class>;
using KP = K::Point_2;
using KS = K::Segment_2;
using Expr = CORE::Expr;

KP kp(const Point& p) { return KP(p.x, p.y); }
Point exactPoint(PointD p) { return {exactFromDouble(p.x), exactFromDouble(p.y)}; }

struct ExprPoint {
  Expr x, y;
};
Expr ex(const Rational& q) { return Expr(CORE::BigRat(q.get_mpq_t())); }
ExprPoint ep(const Point& p) { return {ex(p.x), ex(p.y)}; }
Expr cross(const ExprPoint& a, const ExprPoint& b) { return a.x * b.y - a.y * b.x; }
Expr dot(const ExprPoint& a, const ExprPoint& b) { return a.x * b.x + a.y * b.y; }
ExprPoint sub(const ExprPoint& a, const ExprPoint& b) { return {a.x - b.x, a.y - b.y}; }
Expr dist(const ExprPoint& a, const ExprPoint& b) {
  ExprPoint d = sub(a, b);
  return sqrt(dot(d, d));
}
Expr pointSegDistance(const ExprPoint& p, const ExprPoint& a, const ExprPoint& b) {
  ExprPoint ab = sub(b, a), ap = sub(p, a);
  Expr l2 = dot(ab, ab);
  if (l2 == 0) return dist(p, a);
  Expr t = dot(ap, ab) / l2;
  if (t <= 0) return dist(p, a);
  if (t >= 1) return dist(p, b);
  return abs(cross(ab, ap)) / sqrt(l2);
}

class Checker {
public:
  Checker(const Workspace& w, const Rational& r) : w_(w), r_(r), r2_(r * r), rd_(r.get_d()), index_(w) {
    const Box b = w.bbox();
    scale_ = std::max({1.0, std::abs(b.xmin.get_d()), std::abs(b.xmax.get_d()), std::abs(b.ymin.get_d()),
                       std::abs(b.ymax.get_d())});
  }

  std::size_t exactTests = 0;
  void skipInsideTest() { insideChecked_ = true; }

  /// Returns an empty string when clear, else what is wrong.
  std::string segment(const Point& a, const Point& b) {
    if (!insideChecked_) {
      insideChecked_ = true;
      if (!strictlyInside(w_, a)) return "starts outside the workspace or on its boundary";
    }
    const double ax = a.x.get_d(), ay = a.y.get_d(), bx = b.x.get_d(), by = b.y.get_d();
    const double m = rd_ + 1e-7 * scale_;
    std::string bad;
    KS s(kp(a), kp(b));
    index_.query(std::min(ax, bx) - m, std::min(ay, by) - m, std::max(ax, bx) + m, std::max(ay, by) + m,
                 [&](const detail::IndexedEdge& e) {
                   if (!bad.empty()) return;
                   if (detail::segSegDist(ax, ay, bx, by, e.ax, e.ay, e.bx, e.by) > m) return;
                   ++exactTests;
                   KS es(kp(*e.a), kp(*e.b));
                   const mpq_class d2 = (a == b) ? CGAL::squared_distance(kp(a), es) : CGAL::squared_distance(s, es);
                   if (d2 < r2_) {
                     std::ostringstream os;
                     os << "disc meets an obstacle: distance " << std::sqrt(d2.get_d()) << " < r = " << rd_
                        << " to boundary edge (" << e.ax << "," << e.ay << ")-(" << e.bx << "," << e.by << ")";
                     bad = os.str();
                   }
                 });
    return bad;
  }

  /// Arc from f about c (radius |f - c|) to the ray through t, ccw or not; then the jump to t.
  std::string arc(const Point& f, const Point& t, const Point& c, bool ccw) {
    if (!insideChecked_) {
      insideChecked_ = true;
      if (!strictlyInside(w_, f)) return "starts outside the workspace or on its boundary";
    }
    const Rational rho2 = (f.x - c.x) * (f.x - c.x) + (f.y - c.y) * (f.y - c.y);
    const Rational t2 = (t.x - c.x) * (t.x - c.x) + (t.y - c.y) * (t.y - c.y);
    if (rho2 == 0) return "arc of zero radius";
    if (abs(Rational(t2 - rho2)) > Rational(rho2) * Rational(1, 1000000000) + Rational("1/1000000000000000000"))
      return "arc end is not on the arc's circle";
    const ExprPoint C = ep(c), F = ep(f), T = ep(t);
    const Expr rho = sqrt(ex(rho2));
    ExprPoint B = sub(T, C);
    const Expr lenB = sqrt(dot(B, B));
    const ExprPoint Tp{C.x + B.x * rho / lenB, C.y + B.y * rho / lenB};
    ExprPoint A = sub(F, C);
    if (!ccw) std::swap(A, B);  // a cw arc from f to t is the ccw arc from t to f
    const bool full = (f == t);
    auto inRange = [&](const ExprPoint& v) {
      if (full) return true;
      const Expr ab = cross(A, B);
      if (ab > 0) return cross(A, v) >= 0 && cross(v, B) >= 0;
      if (ab < 0) return !(cross(B, v) > 0 && cross(v, A) > 0);
      if (dot(A, B) > 0) return cross(A, v) == 0 && dot(A, v) > 0;  // zero sweep
      return cross(A, v) >= 0;                                       // half circle
    };
    const double cx = c.x.get_d(), cy = c.y.get_d(), rr = std::sqrt(rho2.get_d());
    const double m = rd_ + 1e-7 * scale_;
    const Expr R = ex(r_);
    std::string bad;
    auto pointArcDist = [&](const ExprPoint& P) -> Expr {
      ExprPoint v = sub(P, C);
      if (inRange(v)) return abs(sqrt(dot(v, v)) - rho);
      return std::min(dist(P, F), dist(P, Tp));
    };
    index_.query(cx - rr - m, cy - rr - m, cx + rr + m, cy + rr + m, [&](const detail::IndexedEdge& e) {
      if (!bad.empty()) return;
      // double filter: distance from the edge to the full circle's annulus
      const double dc = detail::pointSegDist(cx, cy, e.ax, e.ay, e.bx, e.by);
      const double far = std::max(std::hypot(e.ax - cx, e.ay - cy), std::hypot(e.bx - cx, e.by - cy));
      if (dc > rr + m || far < rr - m) return;
      ++exactTests;
      const ExprPoint P = ep(*e.a), Q = ep(*e.b);
      // intersection of the segment with the circle inside the arc's range
      ExprPoint d = sub(Q, P), pc = sub(P, C);
      const Expr qa = dot(d, d), qb = 2 * dot(pc, d), qc = dot(pc, pc) - ex(rho2);
      const Expr disc = qb * qb - 4 * qa * qc;
      bool hit = false;
      if (qa != 0 && disc >= 0) {
        const Expr sq = sqrt(disc);
        for (const Expr& s : {(-qb - sq) / (2 * qa), (-qb + sq) / (2 * qa)}) {
          if (s < 0 || s > 1) continue;
          ExprPoint X{P.x + s * d.x, P.y + s * d.y};
          if (inRange(sub(X, C))) hit = true;
        }
      }
      Expr best = hit ? Expr(0) : std::min({pointSegDistance(F, P, Q), pointSegDistance(Tp, P, Q), pointArcDist(P),
                                            pointArcDist(Q), pointSegDistance(T, P, Q)});
      if (!hit && qa != 0) {
        const Expr s = -dot(pc, d) / qa;  // foot of c on the line
        if (s > 0 && s < 1) {
          ExprPoint H{P.x + s * d.x, P.y + s * d.y};
          ExprPoint v = sub(H, C);
          const Expr hd = sqrt(dot(v, v));
          if (hd >= rho && inRange(v)) best = std::min(best, hd - rho);
        }
      }
      if (best < R) {
        std::ostringstream os;
        os << "disc meets an obstacle along the arc: distance " << best.doubleValue() << " < r = " << rd_;
        bad = os.str();
      }
    });
    return bad;
  }

private:
  const Workspace& w_;
  Rational r_, r2_;
  double rd_, scale_ = 1;
  detail::EdgeIndex index_;
  bool insideChecked_ = false;
};

std::string fmt(PointD p) {
  std::ostringstream os;
  os.precision(17);
  os << "(" << p.x << "," << p.y << ")";
  return os.str();
}

}  // namespace

bool segmentClear(const Workspace& w, const Rational& r, const Point& a, const Point& b) {
  Checker c(w, r);
  return c.segment(a, b).empty();
}

struct ClearanceChecker::Impl {
  Checker checker;
  Impl(const Workspace& w, const Rational& r) : checker(w, r) { checker.skipInsideTest(); }
};
ClearanceChecker::ClearanceChecker(const Workspace& w, const Rational& r) : impl_(std::make_unique<Impl>(w, r)) {}
ClearanceChecker::~ClearanceChecker() = default;
bool ClearanceChecker::clear(const Point& a, const Point& b) { return impl_->checker.segment(a, b).empty(); }
bool ClearanceChecker::clearArc(const Point& from, const Point& to, const Point& center, bool ccw) {
  return impl_->checker.arc(from, to, center, ccw).empty();
}

ValidationReport validatePaths(const Problem& problem, const std::vector<Path>& paths, const ValidationOptions& o) {
  ValidationReport rep;
  auto add = [&](Violation v) {
    rep.valid = false;
    if (rep.violations.size() < o.maxViolations) rep.violations.push_back(std::move(v));
  };
  if (paths.size() != problem.robots.size()) {
    add({"robots", -1, -1, "plan has " + std::to_string(paths.size()) + " paths for " +
                              std::to_string(problem.robots.size()) + " robots"});
    return rep;
  }
  for (std::size_t ri = 0; ri < paths.size(); ++ri) {
    const Path& path = paths[ri];
    const Robot& robot = problem.robots[ri];
    const int R = static_cast<int>(ri);
    Checker check(problem.workspace, robot.radius);
    if (!std::isfinite(path.start.x) || !std::isfinite(path.start.y)) {
      add({"start", R, -1, "start is not finite"});
      continue;
    }
    if (robot.start) {
      const double dx = path.start.x - robot.start->x.get_d(), dy = path.start.y - robot.start->y.get_d();
      if (std::hypot(dx, dy) > o.startTolerance)
        add({"start", R, -1, "path starts at " + fmt(path.start) + ", not at the robot's start"});
    }
    PointD cur = path.start;
    if (path.segments.empty()) {
      std::string why = check.segment(exactPoint(cur), exactPoint(cur));
      if (!why.empty()) add({"clearance", R, -1, why});
      continue;
    }
    for (std::size_t si = 0; si < path.segments.size(); ++si) {
      const PathSegment& s = path.segments[si];
      const int S = static_cast<int>(si);
      ++rep.segmentsChecked;
      for (double v : {s.from.x, s.from.y, s.to.x, s.to.y, s.center.x, s.center.y})
        if (!std::isfinite(v)) {
          add({"finite", R, S, "non-finite coordinate"});
          return rep;
        }
      const double gap = std::hypot(s.from.x - cur.x, s.from.y - cur.y);
      if (gap > o.continuityTolerance) {
        add({"continuity", R, S, "gap of " + formatDouble(gap) + " between " + fmt(cur) + " and " + fmt(s.from)});
      } else if (gap > 0) {
        std::string why = check.segment(exactPoint(cur), exactPoint(s.from));
        if (!why.empty()) add({"clearance", R, S, "joint: " + why});
      }
      std::string why = s.kind == PathSegment::Kind::kLine
                            ? check.segment(exactPoint(s.from), exactPoint(s.to))
                            : check.arc(exactPoint(s.from), exactPoint(s.to), exactPoint(s.center), s.ccw);
      if (!why.empty()) add({s.kind == PathSegment::Kind::kArc && why.find("circle") != std::string::npos ? "arc" : "clearance",
                             R, S, why});
      if (o.cspace) {
        const bool clear = s.kind == PathSegment::Kind::kLine
                               ? o.cspace->segmentClear(exactPoint(s.from), exactPoint(s.to))
                               : o.cspace->arcClear(exactPoint(s.from), exactPoint(s.to), exactPoint(s.center), s.ccw);
        if (!clear) add({"cspace", R, S, "leaves C-free (r = " + formatDouble(robot.radius.get_d()) + ", eps " + formatDouble(o.cspace->epsilon()) + ")"});
      }
      cur = s.to;
    }
    rep.exactTests += check.exactTests;
  }
  return rep;
}

}  // namespace coverkit
