#pragma once
// Private: area of general polygons bounded by CGAL circle-segment curves, and their conversion to
// coverkit's double curves. Used by area_exact.cpp and cspace.cpp (both include CGAL already).
#include <coverkit/geometry/path.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/General_polygon_set_2.h>
#include <CGAL/Gps_circle_segment_traits_2.h>

#include <cmath>

namespace coverkit::detail {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Traits = CGAL::Gps_circle_segment_traits_2<K>;
using PolygonSet = CGAL::General_polygon_set_2<Traits>;
using CPolygon = Traits::General_polygon_2;
using CPolygonWithHoles = Traits::General_polygon_with_holes_2;

/// A coverkit rational as the kernel's exact number (no rounding).
inline K::FT ft(const Rational& q) { return K::FT(K::FT::ET(q.get_mpq_t())); }

/// Twice the signed area contribution of one x-monotone curve (Green's theorem).
template <class XCurve>
double curveArea2(const XCurve& c) {
  const double sx = CGAL::to_double(c.source().x()), sy = CGAL::to_double(c.source().y());
  const double tx = CGAL::to_double(c.target().x()), ty = CGAL::to_double(c.target().y());
  double a = sx * ty - tx * sy;  // chord (shoelace, doubled)
  if (c.is_circular()) {
    const auto circ = c.supporting_circle();
    const double cx = CGAL::to_double(circ.center().x()), cy = CGAL::to_double(circ.center().y());
    const double r2 = CGAL::to_double(circ.squared_radius());
    const double ux = sx - cx, uy = sy - cy, vx = tx - cx, vy = ty - cy;
    const bool ccw = c.orientation() == CGAL::COUNTERCLOCKWISE;
    double theta = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);  // (-π, π]
    if (!ccw) theta = -theta;
    if (theta < 0) theta += 2 * M_PI;
    const double seg = r2 * (theta - std::sin(theta));  // doubled circular-segment area
    a += ccw ? seg : -seg;
  }
  return a;
}

template <class Polygon>
double polygonArea(const Polygon& pg) {
  double a = 0;
  for (auto it = pg.curves_begin(); it != pg.curves_end(); ++it) a += curveArea2(*it);
  return a / 2;
}

/// The double of an exact number from its exact value. CGAL::to_double of a lazy number is the
/// middle of its interval, which is tighter once something has asked for the exact value: the same
/// point can give two doubles a few units in the last place apart, depending on what was computed
/// before. Sweeps built from different pieces (CSpace::localSweeps, on any number of threads) must
/// give the same doubles, so they are rounded from the exact value.
inline double stableDouble(const K::FT& x) {
  const auto& i = x.approx();
  if (i.inf() == i.sup()) return i.inf();  // an interval that is one double encloses exactly that
  CGAL::exact(x);
  return CGAL::to_double(x);
}
/// The same for a coordinate a0 + a1·√root of the circle-segment traits.
template <class CoordNT>
double stableDouble(const CoordNT& x) {
  const double a0 = stableDouble(x.a0());
  return x.is_extended() ? a0 + stableDouble(x.a1()) * std::sqrt(stableDouble(x.root())) : a0;
}

/// A curve as a path piece in doubles; `stable`: rounded from the exact values (stableDouble).
template <class XCurve>
PathSegment toSegment(const XCurve& c, bool stable = false) {
  auto d = [stable](const auto& v) { return stable ? stableDouble(v) : CGAL::to_double(v); };
  const PointD a{d(c.source().x()), d(c.source().y())};
  const PointD b{d(c.target().x()), d(c.target().y())};
  if (!c.is_circular()) return PathSegment::line(a, b);
  const auto circ = c.supporting_circle();
  return PathSegment::arc(a, b, {d(circ.center().x()), d(circ.center().y())}, c.orientation() == CGAL::COUNTERCLOCKWISE);
}

}  // namespace coverkit::detail
