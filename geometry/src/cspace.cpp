// C-space of a disc robot with CGAL's approximated offsets (see cspace.h for the contract).
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/error.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/General_polygon_set_2.h>
#include <CGAL/Gps_circle_segment_traits_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/approximated_offset_2.h>

#include "circle_segment_area.h"

#include <algorithm>
#include <cmath>

namespace coverkit {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Traits = CGAL::Gps_circle_segment_traits_2<K>;
using PolygonSet = CGAL::General_polygon_set_2<Traits>;
using CPolygonWithHoles = Traits::General_polygon_with_holes_2;
using CPolygon = Traits::General_polygon_2;
using LinearPolygon = CGAL::Polygon_2<K>;
using LinearPolygonWithHoles = CGAL::Polygon_with_holes_2<K>;

K::FT ft(const Rational& q) { return K::FT(K::FT::ET(q.get_mpq_t())); }

LinearPolygon linear(const Ring& ring, bool ccw) {
  LinearPolygon p;
  for (const Point& v : ring) p.push_back(K::Point_2(ft(v.x), ft(v.y)));
  if (p.is_counterclockwise_oriented() != ccw) p.reverse_orientation();
  return p;
}

/// The same ring as a circle-segment polygon (line segments only).
CPolygon curved(const Ring& ring, bool ccw) {
  const LinearPolygon p = linear(ring, ccw);
  CPolygon out;
  for (auto e = p.edges_begin(); e != p.edges_end(); ++e) out.push_back(Traits::X_monotone_curve_2(e->source(), e->target()));
  return out;
}

CurveLoop loopOf(const CPolygon& pg) {
  CurveLoop l;
  for (auto it = pg.curves_begin(); it != pg.curves_end(); ++it) l.pieces.push_back(detail::toSegment(*it));
  return l;
}

CurveRegion regionOf(const CPolygonWithHoles& pwh) {
  CurveRegion r;
  r.outer = loopOf(pwh.outer_boundary());
  r.area = detail::polygonArea(pwh.outer_boundary());
  for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) {
    r.holes.push_back(loopOf(*h));
    r.area += detail::polygonArea(*h);  // holes are clockwise: negative
  }
  return r;
}

}  // namespace

struct CSpace::Impl {
  Rational radius;
  double eps = 0;
  std::vector<Ring> outers;                  ///< the regions' outer rings (for obstacles())
  std::vector<CPolygonWithHoles> parts;      ///< components of C-free, largest first
  std::vector<PolygonSet> partSets;          ///< one set per component, for point location
  std::vector<double> areas;
};

CSpace::CSpace(const Workspace& w, const Rational& radius, double relativeEps) : impl_(std::make_unique<Impl>()) {
  if (radius <= 0) throw InputError(w.name, "radius", "robot radius must be > 0");
  if (w.regions.empty()) throw InputError(w.name, "workspace", "empty free space");
  impl_->radius = radius;
  for (const Region& reg : w.regions) impl_->outers.push_back(reg.outer);
  const Box b = w.bbox();
  const double extent = std::max(Rational(b.xmax - b.xmin).get_d(), Rational(b.ymax - b.ymin).get_d());
  impl_->eps = relativeEps * std::max(extent, 1e-12);
  const K::FT r = ft(radius);
  // A frame around everything, so that the outside of each region is a bounded polygon with a hole.
  const Rational pad = 4 * radius + 1;
  const Ring frame = {{Rational(b.xmin - pad), Rational(b.ymin - pad)}, {Rational(b.xmax + pad), Rational(b.ymin - pad)},
                      {Rational(b.xmax + pad), Rational(b.ymax + pad)}, {Rational(b.xmin - pad), Rational(b.ymax + pad)}};
  // Each region on its own: the disc in one region never reaches another (they are separated by
  // walls), and the outside of one region contains the others. Regions are disjoint, so their
  // components are simply collected (joining them one by one would cost quadratic time).
  for (const Region& reg : w.regions) {
    // outside of the region: the frame with the region's outer ring as a hole; its offset shrinks
    // the hole by r, which is the region eroded by r
    std::vector<CPolygonWithHoles> cobs;
    const LinearPolygon outerHole = linear(reg.outer, false);
    const LinearPolygonWithHoles outside(linear(frame, true), &outerHole, &outerHole + 1);
    cobs.push_back(CGAL::approximated_offset_2(outside, r, impl_->eps));
    for (const Ring& h : reg.holes) cobs.push_back(CGAL::approximated_offset_2(linear(h, true), r, impl_->eps));
    PolygonSet blocked;
    blocked.join(cobs.begin(), cobs.end());  // one range join: divide and conquer inside CGAL
    PolygonSet regionFree(CPolygonWithHoles(curved(reg.outer, true)));
    regionFree.difference(blocked);
    regionFree.polygons_with_holes(std::back_inserter(impl_->parts));
  }
  for (const auto& p : impl_->parts) {
    double a = detail::polygonArea(p.outer_boundary());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) a += detail::polygonArea(*h);
    impl_->areas.push_back(a);
  }
  // largest first, ties by the outer boundary's first vertex (deterministic)
  std::vector<std::size_t> order(impl_->parts.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return impl_->areas[i] > impl_->areas[j]; });
  std::vector<CPolygonWithHoles> parts;
  std::vector<double> areas;
  for (std::size_t i : order) {
    parts.push_back(impl_->parts[i]);
    areas.push_back(impl_->areas[i]);
  }
  impl_->parts.swap(parts);
  impl_->areas.swap(areas);
  for (const auto& p : impl_->parts) impl_->partSets.emplace_back(p);
}

CSpace::~CSpace() = default;
CSpace::CSpace(CSpace&&) noexcept = default;
CSpace& CSpace::operator=(CSpace&&) noexcept = default;

const Rational& CSpace::radius() const { return impl_->radius; }
double CSpace::epsilon() const { return impl_->eps; }
std::size_t CSpace::componentCount() const { return impl_->parts.size(); }

int CSpace::componentOf(const Point& p) const {
  const Traits::Point_2 q(ft(p.x), ft(p.y));
  for (std::size_t i = 0; i < impl_->partSets.size(); ++i)
    if (impl_->partSets[i].oriented_side(q) != CGAL::ON_NEGATIVE_SIDE) return static_cast<int>(i);
  return -1;
}

double CSpace::area() const {
  double a = 0;
  for (double x : impl_->areas) a += x;
  return a;
}

std::vector<CurveRegion> CSpace::components() const {
  std::vector<CurveRegion> out;
  for (const auto& p : impl_->parts) out.push_back(regionOf(p));
  return out;
}

std::vector<CurveRegion> CSpace::obstacles() const {
  // W's outer boundaries minus C-free; computed on demand (pictures and files only)
  std::vector<CPolygonWithHoles> outers;
  for (const Ring& o : impl_->outers) outers.emplace_back(curved(o, true));
  PolygonSet blocked, free;
  blocked.insert(outers.begin(), outers.end());  // interior-disjoint: no overlay needed
  free.insert(impl_->parts.begin(), impl_->parts.end());
  blocked.difference(free);
  std::vector<CPolygonWithHoles> pw;
  blocked.polygons_with_holes(std::back_inserter(pw));
  std::vector<CurveRegion> out;
  for (const auto& p : pw) out.push_back(regionOf(p));
  return out;
}

}  // namespace coverkit
