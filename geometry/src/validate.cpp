// The independent validator. Exact: line pieces with CGAL's Cartesian kernel over GMP rationals
// (squared distances are rational), arcs with CORE::Expr (exact square roots). Doubles are used
// only to skip edges that are certainly far away (margin far above double rounding at the piece's
// own magnitude; beyond 1e150 no double filter at all). Between the
// two sits a filter, as in CGAL's filtered kernels: the same distance is bounded from below with
// interval arithmetic (CGAL::Interval_nt, directed rounding, inputs enclosed by to_interval); an
// edge whose lower bound is certainly ≥ r is clear, and only the others are decided exactly. Where
// a branch of the exact computation cannot be decided on intervals, the filter takes the smaller
// of its values (or gives up), so it never says "clear" where the exact test would not.
#include <coverkit/geometry/validate.h>

#include "edge_index.h"
#include "error_free.h"
#include "team.h"
#include <coverkit/geometry/parallel.h>

#include <CGAL/CORE_Expr.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/mpq_class.h>
#include <CGAL/squared_distance_2.h>

#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/cspace.h>

#include <cmath>
#include <limits>
#include <optional>
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
/// Whether p lies closer than R to segment ab; `found` gets the distance (for the message). Squared
/// comparisons, no division: an arc's jump can be shorter than a double resolves (its two ends
/// round to the same doubles), and a division by its length made CORE's filter warn of a possible
/// zero divisor. CORE writes each warning to a file "Core_Diagnostics" in the working directory
/// (thousands in a sweep over seeded worlds) and ends the process when it cannot open it.
bool pointSegBelow(const ExprPoint& p, const ExprPoint& a, const ExprPoint& b, const Expr& R, Expr& found) {
  const ExprPoint ab = sub(b, a), ap = sub(p, a);
  const Expr l2 = dot(ab, ab), s = dot(ap, ab), R2 = R * R;
  if (l2 == 0 || s <= 0 || s >= l2) {   // nearest to an end
    const ExprPoint q = l2 == 0 || s <= 0 ? ap : sub(p, b);
    const Expr d2 = dot(q, q);
    if (!(d2 < R2)) return false;
    found = sqrt(d2);
    return true;
  }
  const Expr c = cross(ab, ap);
  if (!(c * c < R2 * l2)) return false;
  const double len = std::sqrt(l2.doubleValue());   // the message's distance, in doubles
  found = len > 0 ? Expr(std::abs(c.doubleValue()) / len) : sqrt(dot(ap, ap));
  return true;
}
/// Whether segments ab and cd come closer than R: they cross, or an end is closer than R to the
/// other segment. Each candidate is compared with R on its own: comparing two candidates with each
/// other (a min) can compare equal expressions, which CORE decides only at its root-bound precision
/// (seconds for coordinates near 1e150), while a comparison with R is decided as soon as it differs.
bool segSegBelow(const ExprPoint& a, const ExprPoint& b, const ExprPoint& c, const ExprPoint& d, const Expr& R, Expr& found) {
  const int o1 = CGAL::sign(cross(sub(b, a), sub(c, a))), o2 = CGAL::sign(cross(sub(b, a), sub(d, a)));
  const int o3 = CGAL::sign(cross(sub(d, c), sub(a, c))), o4 = CGAL::sign(cross(sub(d, c), sub(b, c)));
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    found = Expr(0);
    return true;
  }
  return pointSegBelow(a, c, d, R, found) || pointSegBelow(b, c, d, R, found) || pointSegBelow(c, a, b, R, found) ||
         pointSegBelow(d, a, b, R, found);
}

/// Beyond this magnitude the double pre-filters (squares of coordinate differences) could overflow
/// and the interval filter's bounds would be infinite: such pieces (an arc about a centre at 1e160,
/// a segment to x = 1e200) skip both filters and are decided by the exact tests alone.
constexpr double kFilterRange = 1e150;
bool filterable(std::initializer_list<double> values) {
  for (double v : values)
    if (!(std::abs(v) <= kFilterRange)) return false;
  return true;
}

// --- the interval filter: lower bounds of the distances the exact code computes -----------------

using I = CGAL::Interval_nt<true>;
struct IPoint {
  I x, y;
};
/// The tightest interval of q; a dyadic q of at most 53 bits (a grid map's coordinates) is a double
/// exactly, read without the general conversion (MPFR's, a few percent of a large validation).
I iv(const Rational& q) {
  const mpz_srcptr num = q.get_num_mpz_t(), den = q.get_den_mpz_t();
  const std::size_t denBits = mpz_sizeinbase(den, 2);
  if (mpz_sizeinbase(num, 2) <= 53 && denBits <= 1000 && mpz_scan1(den, 0) + 1 == denBits) return I(q.get_d());
  return I(CGAL::to_interval(q));
}
IPoint ip(const Point& p) { return {iv(p.x), iv(p.y)}; }

/// Three-valued truth: 0 no, 1 yes, 2 undecided on intervals.
int tri(CGAL::Uncertain<bool> u) { return CGAL::is_certain(u) ? (CGAL::get_certain(u) ? 1 : 0) : 2; }
int triAnd(int a, int b) { return (a == 0 || b == 0) ? 0 : (a == 1 && b == 1 ? 1 : 2); }
int triNot(int a) { return a == 2 ? 2 : 1 - a; }

// The segment filter runs on unprotected intervals (Interval_nt_advanced) under one rounding-mode
// guard per edge: the protected type switches the FPU mode at every operation, which was most of
// the validator's time on large grid maps.
using IA = CGAL::Interval_nt_advanced;
struct IPointA {
  IA x, y;
};
IPointA toAdvanced(const IPoint& p) { return {IA(p.x.inf(), p.x.sup()), IA(p.y.inf(), p.y.sup())}; }
inline IPointA asub(const IPointA& a, const IPointA& b) { return {a.x - b.x, a.y - b.y}; }
inline IA across(const IPointA& a, const IPointA& b) { return a.x * b.y - a.y * b.x; }
inline IA adot(const IPointA& a, const IPointA& b) { return a.x * b.x + a.y * b.y; }
inline IA anorm(const IPointA& a) { return CGAL::sqrt(adot(a, a)); }

/// Whether segments ab and cd, both axis-parallel with ends that are doubles (point intervals), are
/// at least √r2 apart, decided exactly without rationals: 1 yes, 0 no, -1 not decidable this way.
/// Two such segments are boxes, √(gx² + gy²) apart with each gap one subtraction; every step is
/// checked error-free (TwoSum for sums, fma for squares), so a grid map's pieces at exactly r from
/// an obstacle edge, where every interval bound straddles r², need no rational arithmetic. Call in
/// round-to-nearest mode (TwoSum needs it), with r2 a double that is r² exactly. `d2` is then the
/// exact squared distance.
int axisPiecesClear(const IPointA& A, const IPointA& B, const IPointA& C, const IPointA& D, double r2, double& d2) {
  for (const IPointA* p : {&A, &B, &C, &D})
    if (!p->x.is_point() || !p->y.is_point()) return -1;
  const double ax = A.x.inf(), ay = A.y.inf(), bx = B.x.inf(), by = B.y.inf();
  const double cx = C.x.inf(), cy = C.y.inf(), dx = D.x.inf(), dy = D.y.inf();
  if ((ax != bx && ay != by) || (cx != dx && cy != dy)) return -1;
  constexpr double kBig = 0x1p500;
  for (double v : {ax, ay, bx, by, cx, cy, dx, dy})
    if (!(std::abs(v) <= kBig)) return -1;
  // the gap between [lo1, hi1] and [lo2, hi2]: rounding keeps a difference's sign, so the larger
  // of the two differences is the gap when positive; it must then be exact
  auto gap = [&](double lo1, double hi1, double lo2, double hi2, double& g) {
    const double g1 = lo2 - hi1, g2 = lo1 - hi2;
    if (g1 <= 0 && g2 <= 0) {
      g = 0;
      return true;
    }
    return g1 > 0 ? detail::exactSum(lo2, -hi1, g) : detail::exactSum(lo1, -hi2, g);
  };
  double gx, gy, qx, qy;
  if (!gap(std::min(ax, bx), std::max(ax, bx), std::min(cx, dx), std::max(cx, dx), gx) ||
      !gap(std::min(ay, by), std::max(ay, by), std::min(cy, dy), std::max(cy, dy), gy) || !detail::exactProduct(gx, gx, qx) ||
      !detail::exactProduct(gy, gy, qy) || !detail::exactSum(qx, qy, d2))
    return -1;
  return d2 >= r2 ? 1 : 0;
}

/// ≤ the distance from p to segment ab (pointSegBelow); 0 when ab may be degenerate. Call
/// under CGAL::Protect_FPU_rounding<true>.
IA lbPointSeg(const IPointA& p, const IPointA& a, const IPointA& b) {
  const IPointA ab = asub(b, a), ap = asub(p, a);
  const IA l2 = adot(ab, ab);
  if (!CGAL::certainly(l2 > 0)) return IA(0);
  const IA t = adot(ap, ab) / l2;
  if (CGAL::certainly(t <= 0)) return anorm(ap);
  if (CGAL::certainly(t >= 1)) return anorm(asub(p, b));
  return CGAL::abs(across(ab, ap)) / CGAL::sqrt(l2);  // the distance to the line: ≤ every branch
}

/// ≤ the squared distance from p to segment ab; 0 when ab may be degenerate. Squared, so that
/// points given as doubles give exact bounds wherever the products are exact in doubles (a grid's
/// coordinates): a piece at exactly r from an edge is then accepted here, without the exact test.
/// Call under CGAL::Protect_FPU_rounding<true>.
IA lbPointSeg2(const IPointA& p, const IPointA& a, const IPointA& b) {
  const IPointA ab = asub(b, a), ap = asub(p, a);
  const IA l2 = adot(ab, ab);
  if (!CGAL::certainly(l2 > 0)) return IA(0);
  const IA t = adot(ap, ab);
  if (CGAL::certainly(t <= 0)) return adot(ap, ap);
  if (CGAL::certainly(t >= l2)) {
    const IPointA bp = asub(p, b);
    return adot(bp, bp);
  }
  return CGAL::square(across(ab, ap)) / l2;  // to the line: ≤ every branch
}

/// ≤ the (squared, with lbPointSeg2) distance between segments ab and cd from `pointSeg`, a lower
/// bound of a point's to a segment; 0 when they may cross. On either interval type.
template <class Pt, class PointSeg>
auto lbSegSegBy(const Pt& a, const Pt& b, const Pt& c, const Pt& d, PointSeg pointSeg) {
  using N = decltype(a.x);
  auto sameSide = [](const N& u, const N& v) {
    return (CGAL::certainly(u > 0) && CGAL::certainly(v > 0)) || (CGAL::certainly(u < 0) && CGAL::certainly(v < 0));
  };
  auto sub = [](const Pt& u, const Pt& v) { return Pt{u.x - v.x, u.y - v.y}; };
  auto cross = [](const Pt& u, const Pt& v) { return u.x * v.y - u.y * v.x; };
  const N o1 = cross(sub(b, a), sub(c, a)), o2 = cross(sub(b, a), sub(d, a));
  const N o3 = cross(sub(d, c), sub(a, c)), o4 = cross(sub(d, c), sub(b, c));
  if (!sameSide(o1, o2) && !sameSide(o3, o4)) return N(0);
  return CGAL::min(CGAL::min(pointSeg(a, c, d), pointSeg(b, c, d)), CGAL::min(pointSeg(c, a, b), pointSeg(d, a, b)));
}

/// ≤ the squared distance between segments ab and cd. Call under CGAL::Protect_FPU_rounding<true>.
IA lbSegSeg2(const IPointA& a, const IPointA& b, const IPointA& c, const IPointA& d) { return lbSegSegBy(a, b, c, d, lbPointSeg2); }

/// ≤ the distance between segments ab and cd; 0 when they may cross. Call under
/// CGAL::Protect_FPU_rounding<true>.
IA lbSegSeg(const IPointA& a, const IPointA& b, const IPointA& c, const IPointA& d) { return lbSegSegBy(a, b, c, d, lbPointSeg); }

/// The arc of Checker::arc on intervals: ≤ the distance the exact code finds to edge pq. On
/// unprotected intervals, as the segment filter: construct it and call lowerBound under
/// CGAL::Protect_FPU_rounding<true> (one switch of the rounding mode per edge, not per operation).
class ArcFilter {
public:
  ArcFilter(const Point& f, const Point& t, const Point& c, const Rational& rho2, bool ccw)
      : ArcFilter(toAdvanced(ip(f)), toAdvanced(ip(t)), toAdvanced(ip(c)), advanced(iv(rho2)), ccw, f == t) {}
  /// From intervals holding the ends, the centre and ρ²; `full`: f == t exactly.
  ArcFilter(const IPointA& f, const IPointA& t, const IPointA& c, const IA& rho2, bool ccw, bool full)
      : C_(c), F_(f), T_(t), rho2_(rho2), rho_(CGAL::sqrt(rho2_)), full_(full) {
    B_ = asub(T_, C_);
    const IA lenB = anorm(B_);
    Tp_ = {C_.x + B_.x * rho_ / lenB, C_.y + B_.y * rho_ / lenB};
    A_ = asub(F_, C_);
    if (!ccw) std::swap(A_, B_);
    jumpLength_ = anorm(asub(T_, Tp_));
  }
  IA lowerBound(const IPointA& P, const IPointA& Q) const {
    const IPointA d = asub(Q, P), pc = asub(P, C_);
    const IA qa = adot(d, d), qb = 2 * adot(pc, d), qc = adot(pc, pc) - rho2_;
    if (!CGAL::certainly(qa > 0)) return IA(0);
    const IA disc = CGAL::square(qb) - 4 * qa * qc;
    if (!CGAL::certainly(disc < 0)) {
      const IA sq = CGAL::sqrt(disc);
      for (const IA& s : {(-qb - sq) / (2 * qa), (-qb + sq) / (2 * qa)}) {
        if (CGAL::certainly(s < 0) || CGAL::certainly(s > 1)) continue;
        if (inRange(asub({P.x + s * d.x, P.y + s * d.y}, C_)) != 0) return IA(0);  // may meet the arc
      }
    }
    // the jump from Tp to t: where t lies (almost) on the circle it is (almost) a point, and the
    // orientation tests of lbSegSeg cannot decide a degenerate segment; every point of it is
    // within |t − Tp| of Tp, which bounds it then
    const IA jump = CGAL::max(lbSegSeg(Tp_, T_, P, Q), lbPointSeg(Tp_, P, Q) - jumpLength_);
    IA best = CGAL::min(CGAL::min(lbPointSeg(F_, P, Q), lbPointSeg(Tp_, P, Q)), CGAL::min(CGAL::min(pointArc(P), pointArc(Q)), jump));
    const IA s = -adot(pc, d) / qa;
    const IPointA v = asub({P.x + s * d.x, P.y + s * d.y}, C_);
    const IA hd = anorm(v);
    if (triAnd(triAnd(tri(s > 0), tri(s < 1)), triAnd(tri(hd >= rho_), inRange(v))) != 0) best = CGAL::min(best, hd - rho_);
    return best;
  }

private:
  static IA advanced(const I& x) { return IA(x.inf(), x.sup()); }
  int inRange(const IPointA& v) const {
    if (full_) return 1;
    const IA ab = across(A_, B_);
    if (CGAL::certainly(ab > 0)) return triAnd(tri(across(A_, v) >= 0), tri(across(v, B_) >= 0));
    if (CGAL::certainly(ab < 0)) return triNot(triAnd(tri(across(B_, v) > 0), tri(across(v, A_) > 0)));
    return 2;
  }
  /// ≤ pointArcDist: the distance to the circle is ≤ the distance to either end.
  IA pointArc(const IPointA& P) const {
    const IPointA v = asub(P, C_);
    if (inRange(v) != 0) return CGAL::abs(anorm(v) - rho_);
    return CGAL::min(anorm(asub(P, F_)), anorm(asub(P, Tp_)));
  }
  IPointA C_, F_, T_, A_, B_, Tp_;
  IA rho2_, rho_, jumpLength_;
  bool full_;
};

class Checker {
public:
  Checker(const Workspace& w, const Rational& r) : w_(w), r_(r), r2_(r * r), rd_(r.get_d()), index_(w) {
    const Box b = w.bbox();
    scale_ = std::max({1.0, std::abs(b.xmin.get_d()), std::abs(b.xmax.get_d()), std::abs(b.ymin.get_d()),
                       std::abs(b.ymax.get_d())});
  }

  std::size_t exactTests = 0;
  void skipInsideTest() { insideChecked_ = true; }
  void setFiltered(bool on) { filtered_ = on; }

  /// Returns an empty string when clear, else what is wrong.
  std::string segment(const Point& a, const Point& b) {
    return segment({a.x.get_d(), a.y.get_d()}, {b.x.get_d(), b.y.get_d()}, toAdvanced(ip(a)), toAdvanced(ip(b)),
                   [&] { return std::pair<Point, Point>(a, b); });
  }
  /// The same for a piece given by doubles (a path's): their intervals are exact, and the exact
  /// points are made only when an edge needs the exact test.
  std::string segment(PointD a, PointD b) {
    return segment(a, b, IPointA{IA(a.x), IA(a.y)}, IPointA{IA(b.x), IA(b.y)},
                   [&] { return std::pair<Point, Point>(exactPoint(a), exactPoint(b)); });
  }

  /// The same for an arc given by doubles (a path's): decided on doubles and intervals, without
  /// rationals, when its end is certainly on the circle within the tolerance and every nearby edge
  /// passes a filter; otherwise (and for the first piece, which must be tested inside W) the exact
  /// way below. The verdict is the exact way's in both.
  std::string arc(PointD f, PointD t, PointD c, bool ccw) {
    auto exactWay = [&] { return arc(exactPoint(f), exactPoint(t), exactPoint(c), ccw); };
    if (!insideChecked_ || !filtered_ || !filterable({c.x, c.y, f.x, f.y, t.x, t.y}) || (f.x == c.x && f.y == c.y)) return exactWay();
    const IPointA F{IA(f.x), IA(f.y)}, T{IA(t.x), IA(t.y)}, C{IA(c.x), IA(c.y)};
    IA rho2, t2;
    std::optional<ArcFilter> intervals;
    {
      CGAL::Protect_FPU_rounding<true> upward;
      const IPointA u = asub(F, C), v = asub(T, C);
      rho2 = adot(u, u), t2 = adot(v, v);
      // |t2 − ρ²| ≤ ρ²/10⁹ + 10⁻¹⁸, the exact way's test, with enclosures of both constants
      const IA billionth(std::nextafter(1e-9, 0.0), std::nextafter(1e-9, 1.0)), tiny(std::nextafter(1e-18, 0.0), std::nextafter(1e-18, 1.0));
      if (!CGAL::certainly(CGAL::abs(t2 - rho2) <= rho2 * billionth + tiny) || !CGAL::certainly(rho2 > 0)) return exactWay();
      intervals.emplace(F, T, C, rho2, ccw, f.x == t.x && f.y == t.y);
    }
    // the double filter's radius and margin, as the exact way's (the end within |√t2 − ρ| of the circle)
    const double rr = std::sqrt(rho2.inf());
    const double m = rd_ + 1e-7 * scale_ + (std::sqrt(std::max(t2.sup(), rho2.sup())) - std::sqrt(std::min(t2.inf(), rho2.inf()))) +
                     1e-12 * (std::sqrt(rho2.sup()) + std::abs(c.x) + std::abs(c.y));
    bool decided = true;
    index_.query(c.x - rr - m, c.y - rr - m, c.x + rr + m, c.y + rr + m, [&](const detail::IndexedEdge& e) {
      if (decided && !filteredOut(e, c.x, c.y, rr, m, &*intervals)) decided = false;
    });
    return decided ? std::string() : exactWay();
  }

  /// Arc from f about c (radius |f - c|) to the ray through t, ccw or not; then the straight jump
  /// from where the arc meets that ray to t (t lies on the circle only within a relative 1e-9).
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
    const bool full = (f == t);
    // The arc in CORE's exact numbers, made only when some edge passes both filters: most arcs
    // are decided on doubles and intervals, and building these square roots was most of their cost.
    struct ExactArc {
      ExprPoint C, F, T, A, B, Tp;
      Expr rho, R;
    };
    std::optional<ExactArc> exactArc;
    auto exact = [&]() -> const ExactArc& {
      if (exactArc) return *exactArc;
      ExactArc X;
      X.C = ep(c), X.F = ep(f), X.T = ep(t);
      X.rho = sqrt(ex(rho2));
      X.B = sub(X.T, X.C);
      const Expr lenB = sqrt(dot(X.B, X.B));
      X.Tp = {X.C.x + X.B.x * X.rho / lenB, X.C.y + X.B.y * X.rho / lenB};
      X.A = sub(X.F, X.C);
      if (!ccw) std::swap(X.A, X.B);  // a cw arc from f to t is the ccw arc from t to f
      X.R = ex(r_);
      return exactArc.emplace(std::move(X));
    };
    auto inRange = [&](const ExprPoint& v) {
      if (full) return true;
      const ExprPoint &A = exactArc->A, &B = exactArc->B;
      const Expr ab = cross(A, B);
      if (ab > 0) return cross(A, v) >= 0 && cross(v, B) >= 0;
      if (ab < 0) return !(cross(B, v) > 0 && cross(v, A) > 0);
      if (dot(A, B) > 0) return cross(A, v) == 0 && dot(A, v) > 0;  // zero sweep
      return cross(A, v) >= 0;                                       // half circle
    };
    const double cx = c.x.get_d(), cy = c.y.get_d();
    const bool filter = filterable({cx, cy, f.x.get_d(), f.y.get_d(), t.x.get_d(), t.y.get_d()});
    // rr and the margin are finite when filtering; otherwise every edge is tested exactly. The
    // margin covers the jump too: t is within |√t2 − ρ| of the circle.
    const double rr = filter ? std::sqrt(rho2.get_d()) : std::numeric_limits<double>::infinity();
    // and double rounding at the circle's magnitude (hypot of differences near 1e20 is off by ~1e4)
    const double m = filter ? rd_ + 1e-7 * scale_ + std::abs(std::sqrt(t2.get_d()) - rr) +
                                  1e-12 * (rr + std::abs(cx) + std::abs(cy))
                            : 0;
    std::optional<ArcFilter> intervals;
    if (filter && filtered_) {
      CGAL::Protect_FPU_rounding<true> upward;
      intervals.emplace(f, t, c, rho2, ccw);
    }
    std::string bad;
    Expr found;  // the distance that was found below R (for the message)
    auto below = [&](const Expr& d) {
      if (!(d < exactArc->R)) return false;
      found = d;
      return true;
    };
    // the distance from P to the arc is below R (never a min of candidates: see segSegBelow)
    auto pointArcBelow = [&](const ExprPoint& P) {
      const ExactArc& X = *exactArc;
      const ExprPoint v = sub(P, X.C);
      if (inRange(v)) return below(abs(sqrt(dot(v, v)) - X.rho));
      return below(dist(P, X.F)) || below(dist(P, X.Tp));
    };
    const bool jump = t2 != rho2;  // else t is where the arc ends
    // An edge with an end at the arc's centre, as the two edges at the obstacle corner a sweep turns
    // about: the arc and its jump lie at distance exactly ρ (or |t − c|) from that end, so neither
    // filter can decide them, and CORE's square roots took half of Smooth-STC's time. Decided here
    // on rationals: when every direction of the arc (from c) and of the jump makes an angle of at
    // least 90° with the edge, each of their points is nearest to the edge's end c, at distance
    // ≥ min(ρ, |t − c|) ≥ r. That holds when both end directions do and the edge's direction is
    // not inside the arc's angular range (a range leaving the closed half-plane and coming back
    // passes through it). Otherwise the exact test below decides.
    const auto clearOfCornerEdge = [&](const detail::IndexedEdge& e) {
      const Point* other = *e.a == c ? e.b : *e.b == c ? e.a : nullptr;
      if (!other || full || rho2 < r2_ || t2 < r2_) return false;
      const Rational ux = other->x - c.x, uy = other->y - c.y;
      Rational ax = f.x - c.x, ay = f.y - c.y, bx = t.x - c.x, by = t.y - c.y;
      if (!ccw) {
        std::swap(ax, bx);
        std::swap(ay, by);
      }
      auto dot = [](const Rational& x0, const Rational& y0, const Rational& x1, const Rational& y1) { return Rational(x0 * x1 + y0 * y1); };
      auto cross = [](const Rational& x0, const Rational& y0, const Rational& x1, const Rational& y1) { return Rational(x0 * y1 - y0 * x1); };
      if (dot(ax, ay, ux, uy) > 0 || dot(bx, by, ux, uy) > 0) return false;
      const Rational ab = cross(ax, ay, bx, by);
      bool inside;   // the edge's direction within the ccw range from A to B (inRange above)
      if (ab > 0) inside = cross(ax, ay, ux, uy) >= 0 && cross(ux, uy, bx, by) >= 0;
      else if (ab < 0) inside = !(cross(bx, by, ux, uy) > 0 && cross(ux, uy, ax, ay) > 0);
      else if (dot(ax, ay, bx, by) > 0) inside = cross(ax, ay, ux, uy) == 0 && dot(ax, ay, ux, uy) > 0;
      else inside = cross(ax, ay, ux, uy) >= 0;
      return !inside;
    };
    const auto visit = [&](const detail::IndexedEdge& e) {
      if (!bad.empty()) return;
      if (filter && filteredOut(e, cx, cy, rr, m, intervals ? &*intervals : nullptr)) return;
      if (clearOfCornerEdge(e)) return;
      ++exactTests;
      const ExactArc& X = exact();
      const ExprPoint &C = X.C, &F = X.F, &T = X.T, &Tp = X.Tp;
      const Expr &rho = X.rho, &R = X.R;
      const ExprPoint P = ep(*e.a), Q = ep(*e.b);
      // intersection of the segment with the circle inside the arc's range
      ExprPoint d = sub(Q, P), pc = sub(P, C);
      const Expr qa = dot(d, d), qb = 2 * dot(pc, d), qc = dot(pc, pc) - ex(rho2);
      const Expr disc = qb * qb - 4 * qa * qc;
      bool hit = false;
      // No division by qa (an edge ~1e-160 long has a qa that is 0 in doubles, and CORE's filter
      // then warns into a file, see pointSegBelow): s = n / 2qa is compared as n with 2qa, and the
      // point X on the circle is taken as (X − C)·2qa, which inRange (signs only) reads the same.
      if (qa != 0 && disc >= 0) {
        const Expr sq = sqrt(disc), q2 = 2 * qa;
        for (const Expr& n : {-qb - sq, -qb + sq}) {
          if (n < 0 || n > q2) continue;
          if (inRange(ExprPoint{pc.x * q2 + n * d.x, pc.y * q2 + n * d.y})) hit = true;
        }
      }
      bool close = hit;
      if (hit) found = Expr(0);
      close = close || pointSegBelow(F, P, Q, R, found) || pointSegBelow(Tp, P, Q, R, found) || pointArcBelow(P) ||
              pointArcBelow(Q) || (jump && segSegBelow(Tp, T, P, Q, R, found));
      if (!close && qa != 0) {   // the foot H of c on the line, s = n / qa, as w = (H − C)·qa
        const Expr n = -dot(pc, d);
        if (n > 0 && n < qa) {
          const ExprPoint w{pc.x * qa + n * d.x, pc.y * qa + n * d.y};
          const Expr wl = sqrt(dot(w, w));   // |H − C|·qa
          if (wl >= rho * qa && inRange(w) && wl < (rho + R) * qa) {
            close = true;
            const double q = qa.doubleValue();   // the message's distance, in doubles
            found = Expr(q > 0 ? wl.doubleValue() / q - rho.doubleValue() : 0.0);
          }
        }
      }
      if (close) {
        std::ostringstream os;
        os << "disc meets an obstacle along the arc: distance " << found.doubleValue() << " < r = " << rd_;
        bad = os.str();
      }
    };
    if (filter) index_.query(cx - rr - m, cy - rr - m, cx + rr + m, cy + rr + m, visit);
    else
      for (const detail::IndexedEdge& e : index_.edges()) visit(e);
    return bad;
  }

private:
  /// `da`, `db`: the ends as doubles (rounded when the ends are not doubles); `A`, `B`: intervals
  /// holding the exact ends; `exact()`: the exact ends, asked for only when needed.
  template <class ExactEnds>
  std::string segment(PointD da, PointD db, const IPointA& A, const IPointA& B, ExactEnds&& exact) {
    std::optional<std::pair<Point, Point>> ends;
    auto exactEnds = [&]() -> const std::pair<Point, Point>& {
      if (!ends) ends = exact();
      return *ends;
    };
    if (!insideChecked_) {
      insideChecked_ = true;
      if (!strictlyInside(w_, exactEnds().first)) return "starts outside the workspace or on its boundary";
    }
    const double ax = da.x, ay = da.y, bx = db.x, by = db.y;
    // the margin covers double rounding at the piece's own magnitude too (a far end at 1e20)
    const double m = rd_ + 1e-7 * scale_ + 1e-12 * std::max({std::abs(ax), std::abs(ay), std::abs(bx), std::abs(by)});
    const bool filter = filterable({ax, ay, bx, by});
    std::string bad;
    std::optional<KS> s;
    double d2d = 0;
    const detail::IndexedEdge* first = index_.edges().data();
    index_.query(std::min(ax, bx) - m, std::min(ay, by) - m, std::max(ax, bx) + m, std::max(ay, by) + m,
                 [&](const detail::IndexedEdge& e) {
                   if (!bad.empty()) return;
                   if (filter && detail::segSegDist2(ax, ay, bx, by, e.ax, e.ay, e.bx, e.by) > m * m) return;
                   if (filter && filtered_) {
                     const auto& [ea, eb] = edgeIntervals(static_cast<std::size_t>(&e - first));
                     {
                       CGAL::Protect_FPU_rounding<true> upward;
                       if (CGAL::certainly(lbSegSeg2(A, B, ea, eb) >= R2_)) return;
                     }
                     const int axis = R2_.is_point() ? axisPiecesClear(A, B, ea, eb, R2_.inf(), d2d) : -1;
                     if (axis == 1) return;
                     if (axis == 0) {
                       bad = tooNear(d2d, e);
                       return;
                     }
                   }
                   ++exactTests;
                   const auto& [a, b] = exactEnds();
                   if (!s) s.emplace(kp(a), kp(b));
                   KS es(kp(*e.a), kp(*e.b));
                   const mpq_class d2 = (a == b) ? CGAL::squared_distance(kp(a), es) : CGAL::squared_distance(*s, es);
                   if (d2 < r2_) bad = tooNear(d2.get_d(), e);
                 });
    return bad;
  }

  /// The violation of a piece whose squared distance to edge e is d2 < r².
  std::string tooNear(double d2, const detail::IndexedEdge& e) const {
    std::ostringstream os;
    os << "disc meets an obstacle: distance " << std::sqrt(d2) << " < r = " << rd_ << " to boundary edge (" << e.ax << "," << e.ay
       << ")-(" << e.bx << "," << e.by << ")";
    return os.str();
  }

  /// Edge e is certainly at least r from the arc about (cx, cy) of radius about rr: beyond the
  /// annulus rr ± m (doubles, with the margin), or bounded on intervals (`intervals`, if given).
  bool filteredOut(const detail::IndexedEdge& e, double cx, double cy, double rr, double m, const ArcFilter* intervals) {
    const double dc = detail::pointSegDist(cx, cy, e.ax, e.ay, e.bx, e.by);
    const double far = std::max(std::hypot(e.ax - cx, e.ay - cy), std::hypot(e.bx - cx, e.by - cy));
    if (dc > rr + m || far < rr - m) return true;
    if (!intervals) return false;
    const auto& [ea, eb] = edgeIntervals(static_cast<std::size_t>(&e - index_.edges().data()));
    CGAL::Protect_FPU_rounding<true> upward;
    return CGAL::certainly(intervals->lowerBound(ea, eb) >= R_);
  }

  /// The intervals of edge i's ends, converted from the rationals once.
  const std::pair<IPointA, IPointA>& edgeIntervals(std::size_t i) {
    if (edgeI_.empty()) {
      edgeI_.resize(index_.edges().size());
      edgeIReady_.assign(index_.edges().size(), 0);
    }
    if (!edgeIReady_[i]) {
      const detail::IndexedEdge& e = index_.edges()[i];
      edgeI_[i] = {toAdvanced(ip(*e.a)), toAdvanced(ip(*e.b))};
      edgeIReady_[i] = 1;
    }
    return edgeI_[i];
  }

  const Workspace& w_;
  Rational r_, r2_;
  IA R2_ = [this] {
    const I q = iv(r2_);
    return IA(q.inf(), q.sup());
  }();
  IA R_ = [this] {
    const I q = iv(r_);
    return IA(q.inf(), q.sup());
  }();
  std::vector<std::pair<IPointA, IPointA>> edgeI_;
  std::vector<char> edgeIReady_;
  double rd_, scale_ = 1;
  detail::EdgeIndex index_;
  bool insideChecked_ = false;
  bool filtered_ = true;
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
  Impl(const Workspace& w, const Rational& r, bool filtered) : checker(w, r) {
    checker.skipInsideTest();
    checker.setFiltered(filtered);
  }
};
ClearanceChecker::ClearanceChecker(const Workspace& w, const Rational& r, bool filtered)
    : impl_(std::make_unique<Impl>(w, r, filtered)) {}
ClearanceChecker::~ClearanceChecker() = default;
bool ClearanceChecker::clear(const Point& a, const Point& b) { return impl_->checker.segment(a, b).empty(); }
bool ClearanceChecker::clear(PointD a, PointD b) { return impl_->checker.segment(a, b).empty(); }
bool ClearanceChecker::clearArc(PointD from, PointD to, PointD center, bool ccw) {
  return impl_->checker.arc(from, to, center, ccw).empty();
}
bool ClearanceChecker::clearArc(const Point& from, const Point& to, const Point& center, bool ccw) {
  return impl_->checker.arc(from, to, center, ccw).empty();
}

namespace {

/// What validatePaths finds on segments [first, last) of one path, `cur` the point before them.
struct RangeResult {
  std::vector<Violation> violations;   ///< at most maxViolations, in order
  bool valid = true;
  bool stopped = false;                ///< a non-finite coordinate: nothing after it is checked
  std::size_t segmentsChecked = 0, exactTests = 0;
};

RangeResult checkRange(const Problem& problem, const Path& path, int R, std::size_t first, std::size_t last, PointD cur,
                       const ValidationOptions& o) {
  RangeResult res;
  auto add = [&](Violation v) {
    res.valid = false;
    if (res.violations.size() < o.maxViolations) res.violations.push_back(std::move(v));
  };
  const Robot& robot = problem.robots[static_cast<std::size_t>(R)];
  Checker check(problem.workspace, robot.radius);
  if (first > 0) check.skipInsideTest();   // the range holding segment 0 tests the path's first point
  for (std::size_t si = first; si < last; ++si) {
    const PathSegment& s = path.segments[si];
    const int S = static_cast<int>(si);
    ++res.segmentsChecked;
    for (double v : {s.from.x, s.from.y, s.to.x, s.to.y, s.center.x, s.center.y})
      if (!std::isfinite(v)) {
        add({"finite", R, S, "non-finite coordinate"});
        res.stopped = true;
        return res;
      }
    const double gap = std::hypot(s.from.x - cur.x, s.from.y - cur.y);
    if (gap > o.continuityTolerance) {
      add({"continuity", R, S, "gap of " + formatDouble(gap) + " between " + fmt(cur) + " and " + fmt(s.from)});
    } else if (gap > 0) {
      std::string why = check.segment(cur, s.from);
      if (!why.empty()) add({"clearance", R, S, "joint: " + why});
    }
    std::string why = s.kind == PathSegment::Kind::kLine ? check.segment(s.from, s.to)
                                                         : check.arc(s.from, s.to, s.center, s.ccw);
    if (!why.empty()) add({s.kind == PathSegment::Kind::kArc && why.find("circle") != std::string::npos ? "arc" : "clearance", R, S, why});
    if (o.cspace) {
      const bool clear = s.kind == PathSegment::Kind::kLine
                             ? o.cspace->segmentClear(exactPoint(s.from), exactPoint(s.to))
                             : o.cspace->arcClear(exactPoint(s.from), exactPoint(s.to), exactPoint(s.center), s.ccw);
      if (!clear) add({"cspace", R, S, "leaves C-free (r = " + formatDouble(robot.radius.get_d()) + ", eps " + formatDouble(o.cspace->epsilon()) + ")"});
    }
    cur = s.to;
  }
  res.exactTests = check.exactTests;
  return res;
}

}  // namespace

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
  const unsigned cores = detail::threadCount(o.threads);
  for (std::size_t ri = 0; ri < paths.size(); ++ri) {
    const Path& path = paths[ri];
    const Robot& robot = problem.robots[ri];
    const int R = static_cast<int>(ri);
    if (!std::isfinite(path.start.x) || !std::isfinite(path.start.y)) {
      add({"start", R, -1, "start is not finite"});
      continue;
    }
    if (robot.start) {
      const double dx = path.start.x - robot.start->x.get_d(), dy = path.start.y - robot.start->y.get_d();
      if (std::hypot(dx, dy) > o.startTolerance)
        add({"start", R, -1, "path starts at " + fmt(path.start) + ", not at the robot's start"});
    }
    if (path.segments.empty()) {
      Checker check(problem.workspace, robot.radius);
      std::string why = check.segment(path.start, path.start);
      if (!why.empty()) add({"clearance", R, -1, why});
      continue;
    }
    // Ranges of the path checked at once, each with its own checker. The verdict, the violations
    // and their order do not depend on how many: each piece's test is the same, and the ranges'
    // findings are taken in order (the C-space check, whose caches are not shared, stays on one).
    const std::size_t n = path.segments.size();
    const std::size_t ranges = o.cspace ? 1 : std::min<std::size_t>(cores, std::max<std::size_t>(1, n / 4096));
    std::vector<RangeResult> found(ranges);
    auto bound = [&](std::size_t k) { return n * k / ranges; };
    auto run = [&](std::size_t k) {
      const std::size_t first = bound(k);
      found[k] = checkRange(problem, path, R, first, bound(k + 1), first == 0 ? path.start : path.segments[first - 1].to, o);
    };
    detail::parallelFor(ranges, cores, run);
    std::size_t exact = 0;
    for (RangeResult& f : found) {
      rep.segmentsChecked += f.segmentsChecked;
      exact += f.exactTests;
      if (!f.valid) rep.valid = false;
      for (Violation& v : f.violations) add(std::move(v));
      if (f.stopped) return rep;   // a non-finite coordinate ends the validation, as it always did
    }
    rep.exactTests += exact;
  }
  if (detail::needsTeamChecks(problem, paths)) detail::checkTeam(problem, paths, add);
  return rep;
}

}  // namespace coverkit
