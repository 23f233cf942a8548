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

template <class XCurve>
PathSegment toSegment(const XCurve& c) {
  const PointD a{CGAL::to_double(c.source().x()), CGAL::to_double(c.source().y())};
  const PointD b{CGAL::to_double(c.target().x()), CGAL::to_double(c.target().y())};
  if (!c.is_circular()) return PathSegment::line(a, b);
  const auto circ = c.supporting_circle();
  return PathSegment::arc(a, b, {CGAL::to_double(circ.center().x()), CGAL::to_double(circ.center().y())},
                          c.orientation() == CGAL::COUNTERCLOCKWISE);
}

}  // namespace coverkit::detail
