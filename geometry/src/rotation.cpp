// Exact rational rotations (decomposition.h).
#include <coverkit/geometry/decomposition.h>

#include <cmath>

namespace coverkit {

double Rotation::degrees() const { return std::atan2(s.get_d(), c.get_d()) * 180 / M_PI; }

Point Rotation::apply(const Point& p) const { return {Rational(c * p.x - s * p.y), Rational(s * p.x + c * p.y)}; }
Point Rotation::inverse(const Point& p) const { return {Rational(c * p.x + s * p.y), Rational(-s * p.x + c * p.y)}; }
PointD Rotation::apply(const PointD& p) const {
  const double cd = c.get_d(), sd = s.get_d();
  return {cd * p.x - sd * p.y, sd * p.x + cd * p.y};
}
PointD Rotation::inverse(const PointD& p) const {
  const double cd = c.get_d(), sd = s.get_d();
  return {cd * p.x + sd * p.y, -sd * p.x + cd * p.y};
}

Rotation Rotation::nearest(double degrees, long maxDenominator) {
  // θ = k·90° + φ, φ in [−45°, 45°]: the quarter turns are exact, φ comes from t ≈ tan(φ/2)
  double d = std::fmod(degrees, 360.0);
  if (d < 0) d += 360;
  const long k = std::lround(d / 90) % 4;
  const double phi = (d - 90.0 * std::lround(d / 90)) * M_PI / 180;
  const double t = std::tan(phi / 2);
  long bestP = 0, bestQ = 1;
  double bestErr = std::abs(t);
  for (long q = 1; q <= std::max(1L, maxDenominator); ++q) {
    const long p = std::lround(t * static_cast<double>(q));
    const double err = std::abs(static_cast<double>(p) / static_cast<double>(q) - t);
    if (err < bestErr) {
      bestErr = err;
      bestP = p;
      bestQ = q;
    }
  }
  const Rational tq = ratio(bestP, bestQ);
  Rotation r;
  r.c = (1 - tq * tq) / (1 + tq * tq);
  r.s = 2 * tq / (1 + tq * tq);
  r.c.canonicalize();
  r.s.canonicalize();
  for (long i = 0; i < k; ++i) {  // a quarter turn: (c, s) ↦ (−s, c)
    Rational nc = -r.s;
    r.s = r.c;
    r.c = nc;
  }
  return r;
}

Workspace rotate(const Workspace& w, const Rotation& r) {
  Workspace out = w;
  for (Region& reg : out.regions) {
    for (Point& p : reg.outer) p = r.apply(p);
    for (Ring& h : reg.holes)
      for (Point& p : h) p = r.apply(p);
  }
  return out;
}

CurveRegion unrotate(const CurveRegion& region, const Rotation& r) {
  if (r.c == 1) return region;
  auto loop = [&](CurveLoop l) {
    for (PathSegment& s : l.pieces) {
      s.from = r.inverse(s.from);
      s.to = r.inverse(s.to);
      if (s.kind == PathSegment::Kind::kArc) s.center = r.inverse(s.center);
    }
    return l;
  };
  CurveRegion out = region;
  out.outer = loop(region.outer);
  for (CurveLoop& h : out.holes) h = loop(h);
  return out;
}

}  // namespace coverkit
