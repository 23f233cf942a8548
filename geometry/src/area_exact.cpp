// Exact covered area: F ∩ (path ⊕ disc(r)) built with CGAL's Boolean operations on circle-segment
// curves (Epeck). The set is exact; its area is a sum over exact curves evaluated in double at the
// end (an area with π in it has no rational value).
//
// Limitation, by construction: a stadium's straight sides are offset by r along the unit normal,
// which is rational only for axis-parallel or Pythagorean directions (3,4,5 ...). Circle-segment
// curves need rational lines, so paths with other directions, or with arcs (the annulus of an arc
// of irrational radius has an irrational squared radius), are left to the raster estimate.
#include <coverkit/geometry/metrics.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/General_polygon_set_2.h>
#include <CGAL/Gps_circle_segment_traits_2.h>

#include "circle_segment_area.h"

#include <cmath>
#include <list>

namespace coverkit {

namespace {

using detail::ft;
using detail::K;
using detail::PolygonSet;
using detail::Traits;
using Polygon = detail::CPolygon;
using PolygonWithHoles = detail::CPolygonWithHoles;
using Curve = Traits::Curve_2;
using XCurve = Traits::X_monotone_curve_2;
using KPoint = K::Point_2;
Traits::Point_2 opt(const KPoint& p) { return Traits::Point_2(p.x(), p.y()); }
KPoint kpt(const Rational& x, const Rational& y) { return KPoint(ft(x), ft(y)); }

void appendCurve(const Curve& c, Polygon& pg) {
  Traits traits;
  std::list<boost::variant<Traits::Point_2, XCurve>> parts;
  traits.make_x_monotone_2_object()(c, std::back_inserter(parts));
  for (auto& v : parts)
    if (auto* xc = boost::get<XCurve>(&v)) pg.push_back(*xc);
}

bool rationalSqrt(const Rational& q, Rational& out) {
  if (q < 0) return false;
  if (!mpz_perfect_square_p(q.get_num_mpz_t()) || !mpz_perfect_square_p(q.get_den_mpz_t())) return false;
  mpz_class n, d;
  mpz_sqrt(n.get_mpz_t(), q.get_num_mpz_t());
  mpz_sqrt(d.get_mpz_t(), q.get_den_mpz_t());
  out = Rational(n, d);
  out.canonicalize();
  return true;
}

Polygon disc(const Rational& cx, const Rational& cy, const Rational& r) {
  Polygon pg;
  appendCurve(Curve(K::Circle_2(kpt(cx, cy), ft(r * r), CGAL::COUNTERCLOCKWISE)), pg);
  return pg;
}

/// Stadium of [a, b] ⊕ disc(r) when the unit direction is rational; false otherwise.
bool stadium(const Point& a, const Point& b, const Rational& r, Polygon& pg) {
  if (a == b) {
    pg = disc(a.x, a.y, r);
    return true;
  }
  const Rational dx = b.x - a.x, dy = b.y - a.y;
  Rational len;
  if (!rationalSqrt(Rational(dx * dx + dy * dy), len)) return false;
  const Rational nx = -dy / len * r, ny = dx / len * r;  // left normal · r
  const KPoint a1 = kpt(a.x - nx, a.y - ny), b1 = kpt(b.x - nx, b.y - ny);  // right side
  const KPoint b2 = kpt(b.x + nx, b.y + ny), a2 = kpt(a.x + nx, a.y + ny);  // left side
  const auto r2 = ft(r * r);
  pg = Polygon();
  appendCurve(Curve(a1, b1), pg);
  appendCurve(Curve(K::Circle_2(kpt(b.x, b.y), r2, CGAL::COUNTERCLOCKWISE), opt(b1), opt(b2)), pg);
  appendCurve(Curve(b2, a2), pg);
  appendCurve(Curve(K::Circle_2(kpt(a.x, a.y), r2, CGAL::COUNTERCLOCKWISE), opt(a2), opt(a1)), pg);
  return true;
}

Polygon ringPolygon(const Ring& ring, bool wantCcw) {
  Ring r = ring;
  const bool ccw = signedArea2(r) > 0;
  if (ccw != wantCcw) std::reverse(r.begin(), r.end());
  Polygon pg;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point& p = r[i];
    const Point& q = r[(i + 1) % r.size()];
    appendCurve(Curve(kpt(p.x, p.y), kpt(q.x, q.y)), pg);
  }
  return pg;
}

}  // namespace

bool exactCoveredArea(const Workspace& w, const Rational& r, const std::vector<Path>& paths, double& area, bool pathIsClear) {
  std::vector<Polygon> pieces;
  for (const Path& p : paths) {
    Point cur{exactFromDouble(p.start.x), exactFromDouble(p.start.y)};
    Polygon pg;
    if (p.segments.empty()) pieces.push_back(disc(cur.x, cur.y, r));
    for (const PathSegment& s : p.segments) {
      if (s.kind != PathSegment::Kind::kLine) return false;
      const Point a{exactFromDouble(s.from.x), exactFromDouble(s.from.y)};
      const Point b{exactFromDouble(s.to.x), exactFromDouble(s.to.y)};
      if (!(a == cur)) {
        if (!stadium(cur, a, r, pg)) return false;
        pieces.push_back(pg);
      }
      if (!stadium(a, b, r, pg)) return false;
      pieces.push_back(pg);
      cur = b;
    }
  }
  PolygonSet swept;
  swept.join(pieces.begin(), pieces.end());
  if (!pathIsClear) {
    PolygonSet free;
    for (const Region& reg : w.regions) {
      std::vector<Polygon> holes;
      for (const Ring& h : reg.holes) holes.push_back(ringPolygon(h, false));
      free.join(PolygonWithHoles(ringPolygon(reg.outer, true), holes.begin(), holes.end()));
    }
    swept.intersection(free);
  }
  std::vector<PolygonWithHoles> out;
  swept.polygons_with_holes(std::back_inserter(out));
  area = 0;
  for (const PolygonWithHoles& pwh : out) {
    area += detail::polygonArea(pwh.outer_boundary());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) area += detail::polygonArea(*h);  // holes are clockwise
  }
  return true;
}

}  // namespace coverkit
