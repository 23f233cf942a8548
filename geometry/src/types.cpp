#include <coverkit/geometry/path.h>
#include <coverkit/geometry/types.h>

#include "error_free.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace coverkit {

Box Workspace::bbox() const {
  Box b;
  bool first = true;
  for (const Ring* r : rings()) {
    for (const Point& p : *r) {
      if (first) {
        b = {p.x, p.y, p.x, p.y};
        first = false;
      }
      if (p.x < b.xmin) b.xmin = p.x;
      if (p.y < b.ymin) b.ymin = p.y;
      if (p.x > b.xmax) b.xmax = p.x;
      if (p.y > b.ymax) b.ymax = p.y;
    }
  }
  return b;
}

std::vector<const Ring*> Workspace::rings() const {
  std::vector<const Ring*> out;
  for (const Region& r : regions) {
    out.push_back(&r.outer);
    for (const Ring& h : r.holes) out.push_back(&h);
  }
  return out;
}

std::size_t Workspace::vertexCount() const {
  std::size_t n = 0;
  for (const Ring* r : rings()) n += r->size();
  return n;
}

namespace {
// Edge i of r crosses p's horizontal to the right of p. Which edges cross the horizontal is decided
// exactly; on which side of p a crossing lies is decided in doubles when it is far from p (margin
// far above double error), exactly otherwise.
bool crossesRight(const Ring& r, std::size_t i, const Point& p, double px, double py) {
  const Point& a = r[i];
  const Point& b = r[(i + 1) % r.size()];
  if ((a.y > p.y) == (b.y > p.y)) return false;
  const double ax = a.x.get_d(), ay = a.y.get_d(), bx = b.x.get_d(), by = b.y.get_d();
  const double xd = ax + (py - ay) * (bx - ax) / (by - ay);
  const double margin = 1e-9 * (1 + std::abs(ax) + std::abs(bx) + std::abs(px));
  if (xd > px + margin) return true;
  if (xd < px - margin) return false;
  return Rational(a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) > p.x;
}
}  // namespace

bool insideRing(const Ring& r, const Point& p) {
  bool in = false;
  const double px = p.x.get_d(), py = p.y.get_d();
  for (std::size_t i = 0; i < r.size(); ++i)
    if (crossesRight(r, i, p, px, py)) in = !in;
  return in;
}

bool insideRing(const Ring& r, const Point& p, const std::vector<std::size_t>& edges) {
  bool in = false;
  const double px = p.x.get_d(), py = p.y.get_d();
  for (std::size_t i : edges)
    if (crossesRight(r, i, p, px, py)) in = !in;
  return in;
}

Rational signedArea2(const Ring& ring) {
  Rational a = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = ring[i];
    const Point& q = ring[(i + 1) % n];
    a += p.x * q.y - q.x * p.y;
  }
  return a;
}

Rational freeArea(const Workspace& w) {
  Rational a = 0;
  for (const Region& r : w.regions) {
    a += abs(signedArea2(r.outer));
    for (const Ring& h : r.holes) a -= abs(signedArea2(h));
  }
  return Rational(a / 2);
}

void normalise(Workspace& w) {
  for (Region& r : w.regions) {
    if (signedArea2(r.outer) < 0) std::reverse(r.outer.begin(), r.outer.end());
    for (Ring& h : r.holes)
      if (signedArea2(h) > 0) std::reverse(h.begin(), h.end());
  }
}

const char* toString(PlanStatus s) {
  switch (s) {
    case PlanStatus::kExactSolution: return "exact_solution";
    case PlanStatus::kPartialCoverage: return "partial_coverage";
    case PlanStatus::kInvalidStart: return "invalid_start";
    case PlanStatus::kNoFreeSpace: return "no_free_space";
    case PlanStatus::kTimeout: return "timeout";
  }
  return "unknown";
}

namespace {
/// An exact sum of doubles: Shewchuk's nonoverlapping expansion (components by increasing
/// magnitude, zeros dropped), so that its sign is its largest component's. `ok` turns false when a
/// product's rounding error could not be represented (underflow) or the expansion outgrows its room.
struct Expansion {
  std::array<double, 48> c{};
  int n = 0;
  bool ok = true;
  void add(double b) {  // Grow-Expansion: TwoSum of b through every component
    if (b == 0) return;
    double q = b;
    int m = 0;
    for (int i = 0; i < n; ++i) {
      double e;
      q = detail::twoSum(q, c[i], e);
      if (e != 0) c[m++] = e;
    }
    if (m == static_cast<int>(c.size())) ok = false;
    else if (q != 0) c[m++] = q;
    n = m;
  }
  void addProduct(double x, double y, double sign) {  // x·y exactly: TwoProduct with fma
    const double p = x * y;
    if (p == 0 ? (x != 0 && y != 0) : std::abs(p) < 0x1p-900) ok = false;
    add(sign * p);
    add(sign * std::fma(x, y, -p));
  }
  int sign() const { return n == 0 ? 0 : (c[n - 1] > 0 ? 1 : -1); }
  double estimate() const {
    double v = 0;
    for (int i = 0; i < n; ++i) v += c[i];
    return v;
  }
  void negate() {
    for (int i = 0; i < n; ++i) c[i] = -c[i];
  }
};

/// The cross (cr) and dot (dt) products of u = from − c and v = to − c exactly, as expansions of
/// doubles (each difference is two doubles by TwoSum, each product two by fma). False where a
/// coordinate is beyond 2^200 or a product underflows: the rationals decide those.
bool exactProducts(const PathSegment& s, Expansion& cr, Expansion& dt) {
  for (double v : {s.from.x, s.from.y, s.to.x, s.to.y, s.center.x, s.center.y})
    if (!(std::abs(v) <= 0x1p200)) return false;
  auto diff = [](double a, double b, std::array<double, 2>& d) { d[0] = detail::twoSum(a, -b, d[1]); };   // a − b = d[0] + d[1]
  std::array<double, 2> ux, uy, vx, vy;
  diff(s.from.x, s.center.x, ux);
  diff(s.from.y, s.center.y, uy);
  diff(s.to.x, s.center.x, vx);
  diff(s.to.y, s.center.y, vy);
  for (double a : ux)
    for (double b : vy) cr.addProduct(a, b, 1);
  for (double a : uy)
    for (double b : vx) cr.addProduct(a, b, -1);
  for (double a : ux)
    for (double b : vx) dt.addProduct(a, b, 1);
  for (double a : uy)
    for (double b : vy) dt.addProduct(a, b, 1);
  return cr.ok && dt.ok;
}

/// |a / b| rounded toward zero, as mpq_get_d gives it, for exact a, b ≠ 0: the largest double q
/// with q·|b| ≤ |a|, found from the estimate by exact signs of |a| − q·|b|. False where q is not
/// well inside the normal doubles or the estimate is more than a few steps off.
bool truncatedRatio(Expansion a, Expansion b, double& q) {
  if (a.sign() < 0) a.negate();
  if (b.sign() < 0) b.negate();
  q = a.estimate() / b.estimate();
  if (!std::isnormal(q) || q > 0x1p900 || q < 0x1p-900) return false;
  auto excess = [&](double t) {  // sign of |a| − t·|b|
    Expansion d = a;
    for (int i = 0; i < b.n; ++i) d.addProduct(t, b.c[i], -1);
    return d.ok ? d.sign() : 2;
  };
  for (int step = 0;; ++step) {
    const int e = excess(q);
    if (e == 2 || step == 4) return false;
    if (e >= 0) break;
    q = std::nextafter(q, 0.0);
  }
  for (int step = 0;; ++step) {
    const double up = std::nextafter(q, HUGE_VAL);
    const int e = excess(up);
    if (e == 2 || step == 4) return false;
    if (e < 0) return true;
    q = up;
  }
}

/// The angle swept by an arc, in [0, 2π]: from == to is a full circle (as the validator and
/// docs/formats.md read it). The angle between u = from − c and v = to − c is taken from the exact
/// cross and dot products (the doubles are exact rationals), so that an arc whose ends differ by
/// less than a double's angle resolution (a near-full circle of radius 1e154) is 2π − tiny, not 0,
/// and nothing overflows for coordinates up to the largest double.
double arcSweep(const PathSegment& s) {
  if (s.from.x == s.to.x && s.from.y == s.to.y) return 2 * M_PI;
  auto fromSigned = [&](double th) {
    if (s.ccw) return th >= 0 ? th : 2 * M_PI + th;
    return th <= 0 ? -th : 2 * M_PI - th;
  };
  // the same angle as the rationals below give, to the bit, from exact sums of doubles (ten times
  // faster: a large plan's metrics ask for every arc's angle several times)
  Expansion ecr, edt;
  double q;
  if (exactProducts(s, ecr, edt)) {
    const int scr = ecr.sign(), sdt = edt.sign();
    if (scr == 0) return fromSigned(sdt >= 0 ? 0 : M_PI);
    if (sdt == 0) return fromSigned(scr > 0 ? M_PI / 2 : -M_PI / 2);
    if (truncatedRatio(ecr, edt, q)) {
      const double t = std::atan(q);
      const double mag = sdt > 0 ? t : M_PI - t;
      return fromSigned(scr > 0 ? mag : -mag);
    }
  }
  const Rational cx = exactFromDouble(s.center.x), cy = exactFromDouble(s.center.y);
  const Rational ux = exactFromDouble(s.from.x) - cx, uy = exactFromDouble(s.from.y) - cy;
  const Rational vx = exactFromDouble(s.to.x) - cx, vy = exactFromDouble(s.to.y) - cy;
  const Rational cr = ux * vy - uy * vx, dt = ux * vx + uy * vy;
  // the signed angle θ ∈ (−π, π] from u to v: atan of the exact ratio, by quadrant; a tiny θ of
  // either sign stays exact to a double's precision (never 2π − tiny rounded to 2π, then to 0)
  double th;
  if (sgn(cr) == 0) th = sgn(dt) >= 0 ? 0 : M_PI;
  else if (sgn(dt) == 0) th = sgn(cr) > 0 ? M_PI / 2 : -M_PI / 2;
  else {
    const double t = std::atan(std::abs(Rational(cr / dt).get_d()));  // in (0, π/2)
    const double mag = sgn(dt) > 0 ? t : M_PI - t;
    th = sgn(cr) > 0 ? mag : -mag;
  }
  return fromSigned(th);
}

/// The part of segment ab inside the box (Liang–Barsky): [t0, t1] ⊆ [0, 1], and its end points.
/// An end on a side of the box is computed from that side (x = side, y on the line through a and b)
/// rather than from t, so that a segment from −1e300 to 1e300 is clipped to the box's own sides.
bool clipLine(PointD a, PointD b, const BoxD& box, double& t0, double& t1, PointD& p0, PointD& p1) {
  t0 = 0;
  t1 = 1;
  int s0 = -1, s1 = -1;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {a.x - box.xmin, box.xmax - a.x, a.y - box.ymin, box.ymax - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0 && t > t0) { t0 = t; s0 = i; }
    if (p[i] > 0 && t < t1) { t1 = t; s1 = i; }
  }
  if (!(t0 <= t1) || !std::isfinite(t0) || !std::isfinite(t1)) return false;
  const double side[4] = {box.xmin, box.xmax, box.ymin, box.ymax};
  auto onSide = [&](int i, double t) -> PointD {
    if (i < 0) return t == 0 ? a : b;
    if (i < 2) return {side[i], std::clamp(a.y + (side[i] - a.x) * (dy / dx), box.ymin, box.ymax)};
    return {std::clamp(a.x + (side[i] - a.y) * (dx / dy), box.xmin, box.xmax), side[i]};
  };
  p0 = onSide(s0, 0);
  p1 = onSide(s1, 1);
  return true;
}
bool inBox(PointD p, const BoxD& b) { return p.x >= b.xmin && p.x <= b.xmax && p.y >= b.ymin && p.y <= b.ymax; }
}  // namespace

double PathSegment::length() const {
  if (kind == Kind::kLine) return std::hypot(to.x - from.x, to.y - from.y);
  double rad = std::hypot(from.x - center.x, from.y - center.y);
  return rad * arcSweep(*this);
}

Path Path::fromPoints(const std::vector<PointD>& pts) {
  Path p;
  if (pts.empty()) return p;
  p.start = pts.front();
  for (std::size_t i = 1; i < pts.size(); ++i) p.segments.push_back(PathSegment::line(pts[i - 1], pts[i]));
  return p;
}

double Path::length() const {
  double l = 0;
  for (const auto& s : segments) l += s.length();
  return l;
}

std::vector<PointD> Path::polyline(double tolerance) const {
  std::vector<PointD> pts{start};
  for (const auto& s : segments) {
    if (s.kind == PathSegment::Kind::kArc) {
      double rad = std::hypot(s.from.x - s.center.x, s.from.y - s.center.y);
      double sweep = arcSweep(s);
      // chord error rad(1 - cos(h/2)) <= tol  =>  h <= 2 acos(1 - tol/rad)
      double h = rad > tolerance ? 2 * std::acos(1 - tolerance / rad) : sweep;
      int n = std::max(1, static_cast<int>(std::ceil(sweep / std::max(h, 1e-9))));
      double a0 = std::atan2(s.from.y - s.center.y, s.from.x - s.center.x);
      for (int i = 1; i < n; ++i) {
        double a = a0 + (s.ccw ? 1 : -1) * sweep * i / n;
        pts.push_back({s.center.x + rad * std::cos(a), s.center.y + rad * std::sin(a)});
      }
    }
    pts.push_back(s.to);
  }
  return pts;
}

std::vector<std::vector<PointD>> Path::polylineWithin(double tolerance, const BoxD& box) const {
  std::vector<std::vector<PointD>> runs;
  std::vector<PointD> run;
  auto close = [&] {
    if (!run.empty()) runs.push_back(std::move(run));
    run.clear();
  };
  auto add = [&](PointD p) {
    if (run.empty() || run.back().x != p.x || run.back().y != p.y) run.push_back(p);
  };
  if (segments.empty()) {
    if (inBox(start, box)) runs.push_back({start});
    return runs;
  }
  for (const auto& s : segments) {
    if (s.kind == PathSegment::Kind::kLine) {
      double t0, t1;
      PointD p0, p1;
      if (!clipLine(s.from, s.to, box, t0, t1, p0, p1)) {
        close();
        continue;
      }
      if (t0 > 0) close();
      add(p0);
      add(p1);
      if (t1 < 1) close();
      continue;
    }
    // an arc: the angular intervals of its circle inside the box, sampled with chord error ≤ tolerance
    const double rad = std::hypot(s.from.x - s.center.x, s.from.y - s.center.y);
    const double sweep = arcSweep(s), dir = s.ccw ? 1 : -1;
    const double a0 = std::atan2(s.from.y - s.center.y, s.from.x - s.center.x);
    if (!(rad > 0) || !std::isfinite(rad)) {
      close();
      continue;
    }
    std::vector<double> cuts{0, sweep};  // parameters u ∈ [0, sweep]: angle a0 + dir·u
    auto cutAt = [&](double angle) {
      double u = dir * (angle - a0);
      u = std::fmod(u, 2 * M_PI);
      if (u < 0) u += 2 * M_PI;
      if (u > 0 && u < sweep) cuts.push_back(u);
    };
    for (double x : {box.xmin, box.xmax}) {
      const double c = (x - s.center.x) / rad;
      if (c >= -1 && c <= 1) { cutAt(std::acos(c)); cutAt(-std::acos(c)); }
    }
    for (double y : {box.ymin, box.ymax}) {
      const double c = (y - s.center.y) / rad;
      if (c >= -1 && c <= 1) { cutAt(std::asin(c)); cutAt(M_PI - std::asin(c)); }
    }
    std::sort(cuts.begin(), cuts.end());
    const double h = rad > tolerance ? 2 * std::acos(1 - tolerance / rad) : 2 * M_PI;
    auto at = [&](double u) { return PointD{s.center.x + rad * std::cos(a0 + dir * u), s.center.y + rad * std::sin(a0 + dir * u)}; };
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const double u0 = cuts[i], u1 = cuts[i + 1];
      if (!inBox(at((u0 + u1) / 2), box)) {
        close();
        continue;
      }
      const long n = std::max(1L, static_cast<long>(std::ceil((u1 - u0) / std::max(h, 1e-9))));
      add(u0 == 0 ? s.from : at(u0));
      for (long k = 1; k < n; ++k) add(at(u0 + (u1 - u0) * static_cast<double>(k) / static_cast<double>(n)));
      add(u1 == sweep ? s.to : at(u1));
    }
    if (!inBox(s.to, box)) close();
  }
  close();
  return runs;
}

}  // namespace coverkit
