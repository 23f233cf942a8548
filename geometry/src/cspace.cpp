// C-space of a disc robot with CGAL's approximated offsets (see cspace.h for the contract).
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/sampling.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/General_polygon_set_2.h>
#include <CGAL/Gps_circle_segment_traits_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Polygon_triangulation_decomposition_2.h>
#include <CGAL/approximated_offset_2.h>

#include "axis_sweep.h"
#include "circle_segment_area.h"
#include "cspace_access.h"
#include <coverkit/geometry/parallel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace coverkit {

namespace {

using detail::CPolygon;
using detail::CPolygonWithHoles;
using detail::ft;
using detail::K;
using detail::PolygonSet;
using detail::Traits;
using LinearPolygon = CGAL::Polygon_2<K>;
using LinearPolygonWithHoles = CGAL::Polygon_with_holes_2<K>;

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

Rational exactOf(const K::FT& x) { return Rational(CGAL::exact(x)); }

/// A unit vector of rational coordinates near the angle `psi`: tan of the half angle, relative to
/// the nearest axis, rounded to a multiple of 2^-bits (the classic rational parametrisation of the
/// circle), then turned by that axis's quarter turns. Exactly of length 1.
std::pair<Rational, Rational> rationalUnit(double psi, int bits) {
  const long q = std::lround(psi / M_PI_2);
  const double t = std::tan((psi - static_cast<double>(q) * M_PI_2) / 2);  // |t| <= tan(π/8) + rounding
  Rational tq(static_cast<long>(std::llround(std::ldexp(t, bits))));
  tq /= Rational(mpz_class(1) << bits);
  const Rational den = 1 + tq * tq, c = (1 - tq * tq) / den, s = 2 * tq / den;
  switch (((q % 4) + 4) % 4) {
    case 0: return {c, s};
    case 1: return {-s, c};
    case 2: return {-c, -s};
    default: return {s, -c};
  }
}

/// The offset of a strictly convex polygon by a disc, built directly (no arrangement), or false when
/// the construction below cannot be certified (the caller then uses approximated_offset_2).
/// Decision (issue 14): approximated_offset_2 computes a convolution cycle and then the union of its
/// interior with an arrangement of its own for every polygon: 40 % of the C-space of 1,000 convex
/// obstacles. And its eps does not bound the distance of its pieces from the exact offset (up to
/// 93 × eps measured: cspace.h). For a convex polygon the cycle is already the boundary, so it is
/// built here directly, with pieces of the same kinds (rational points, exact arcs, outside the
/// exact offset) that stay within eps of it:
///  - around each vertex v an exact arc of radius r between rational points v + r·u of the circle (u
///    a rational unit vector from the rational parametrisation of the circle), which stops just
///    short of the two edges' normals (the exact arc would end on them, at irrational points);
///  - over an edge a→b, the two tangents of those circles at a + r·u₁ and b + r·u₂, where u₁ lies
///    just before the edge's outward normal and u₂ just after it: they meet at a rational point above
///    the exact offset edge (a roof).
/// The roof's top lies about L·δ/2 + r·δ²/2 above the exact edge for angles δ: they are at most
/// eps / (16·L) and sqrt(eps / (16·r)) (so within eps / 10 of it, rounding of the angles included),
/// and a quarter of the smallest turn, so that every arc keeps a positive span. Each side (u₁ before
/// n, u₂ after it, each arc counter-clockwise) is checked exactly. Edges parallel to an axis have a rational unit normal: offset exactly, one segment.
/// Consecutive pieces share their end point's representation: the Boolean operations then see one
/// point, not two equal ones that only an exact comparison tells apart.
bool convexOffset(const LinearPolygon& p, const Rational& r, double eps, CPolygonWithHoles& out) {
  // the vertices, counter-clockwise, without collinear ones
  std::vector<std::pair<Rational, Rational>> v;
  {
    std::vector<std::pair<Rational, Rational>> all;
    for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it) all.emplace_back(exactOf(it->x()), exactOf(it->y()));
    const std::size_t n = all.size();
    for (std::size_t i = 0; i < n; ++i) {
      const auto &a = all[(i + n - 1) % n], &b = all[i], &c = all[(i + 1) % n];
      const int o = sgn((b.first - a.first) * (c.second - a.second) - (b.second - a.second) * (c.first - a.first));
      if (o < 0) return false;  // not convex
      if (o > 0) v.push_back(b);
    }
  }
  const std::size_t n = v.size();
  if (n < 3 || r <= 0 || !(eps > 0)) return false;
  std::vector<double> angle(n);  // of the outward normal (dy, −dx)
  for (std::size_t i = 0; i < n; ++i) {
    const auto &a = v[i], &b = v[(i + 1) % n];
    angle[i] = std::atan2(Rational(a.first - b.first).get_d(), Rational(b.second - a.second).get_d());
  }
  const double rd = r.get_d();
  double turnBound = 0.1;
  for (std::size_t i = 0; i < n; ++i) {
    double turn = angle[(i + 1) % n] - angle[i];
    while (turn <= 0) turn += 2 * M_PI;
    turnBound = std::min(turnBound, turn / 4);
  }
  struct Edge {
    std::pair<Rational, Rational> before, after;  // unit vectors just before and just after the normal
    bool axis = false;
  };
  std::vector<Edge> edges(n);
  for (std::size_t i = 0; i < n; ++i) {
    Edge& e = edges[i];
    const auto &a = v[i], &b = v[(i + 1) % n];
    const Rational nx = b.second - a.second, ny = a.first - b.first;
    if (sgn(nx) == 0 || sgn(ny) == 0) {
      e.axis = true;
      e.before = e.after = {Rational(sgn(nx)), Rational(sgn(ny))};
      continue;
    }
    const double len = std::hypot(nx.get_d(), ny.get_d());
    const double delta = std::min({turnBound, eps / (16 * len), std::sqrt(eps / (16 * rd))});
    if (!(delta > 1e-17)) return false;
    const int bits = static_cast<int>(std::ceil(std::log2(8 / delta)));
    if (bits > 62) return false;
    e.before = rationalUnit(angle[i] - delta, bits);
    e.after = rationalUnit(angle[i] + delta, bits);
    auto side = [&](const std::pair<Rational, Rational>& u) { return sgn(nx * u.second - ny * u.first); };
    if (side(e.before) >= 0 || side(e.after) <= 0) return false;  // rounding put one on the wrong side
  }
  for (std::size_t i = 0; i < n; ++i) {  // every arc turns counter-clockwise by less than a half turn
    const auto &u = edges[(i + n - 1) % n].after, &w = edges[i].before;
    if (sgn(u.first * w.second - u.second * w.first) <= 0) return false;
  }
  // The loop's corners in order, and the piece that leaves each: a segment, or an arc about a vertex
  // (split at its leftmost or rightmost point, so that every arc is x-monotone).
  struct Corner {
    Rational x, y;
    int arcAbout = -1;  // the vertex the piece leaving this corner turns about, or -1: a segment
  };
  std::vector<Corner> corners;
  auto add = [&](const Rational& x, const Rational& y, int arc) { corners.push_back({x, y, arc}); };
  for (std::size_t i = 0; i < n; ++i) {
    const Edge &prev = edges[(i + n - 1) % n], &e = edges[i];
    const auto &a = v[i], &b = v[(i + 1) % n];
    const auto &u = prev.after, &w = e.before;
    add(a.first + r * u.first, a.second + r * u.second, static_cast<int>(i));
    if (sgn(u.second) < 0 && sgn(w.second) > 0) add(a.first + r, a.second, static_cast<int>(i));        // rightmost point
    else if (sgn(u.second) > 0 && sgn(w.second) < 0) add(a.first - r, a.second, static_cast<int>(i));   // leftmost point
    add(a.first + r * w.first, a.second + r * w.second, -1);
    if (e.axis) continue;  // straight on to the next arc's start
    // the roof's top: the tangent at a + r·u₁ is u₁·x = u₁·a + r, the one at b + r·u₂ is u₂·x = u₂·b + r
    const auto &u1 = e.before, &u2 = e.after;
    const Rational c1 = u1.first * a.first + u1.second * a.second + r, c2 = u2.first * b.first + u2.second * b.second + r;
    const Rational det = u1.first * u2.second - u1.second * u2.first;  // > 0: u₂ after u₁
    add((c1 * u2.second - c2 * u1.second) / det, (u1.first * c2 - u2.first * c1) / det, -1);
  }
  std::vector<K::Point_2> kp;
  std::vector<Traits::Point_2> tp;
  for (const Corner& c : corners) {
    kp.emplace_back(ft(c.x), ft(c.y));
    tp.emplace_back(kp.back().x(), kp.back().y());
  }
  const K::FT r2 = ft(r * r);
  CPolygon loop;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const std::size_t next = (k + 1) % corners.size();
    if (corners[k].arcAbout < 0) {
      loop.push_back(Traits::X_monotone_curve_2(K::Line_2(kp[k], kp[next]), tp[k], tp[next]));
    } else {
      const auto& c = v[static_cast<std::size_t>(corners[k].arcAbout)];
      const K::Circle_2 circle(K::Point_2(ft(c.first), ft(c.second)), r2, CGAL::COUNTERCLOCKWISE);
      loop.push_back(Traits::X_monotone_curve_2(circle, tp[k], tp[next], CGAL::COUNTERCLOCKWISE));
    }
  }
  out = CPolygonWithHoles(loop);
  return true;
}

/// Offsets of a polygon (with holes) whose union is its approximated offset. Small polygons are
/// offset whole (convolution); large ones are triangulated first and every triangle is offset on
/// its own, so that the caller's single range join unites them: the convolution of a large
/// non-convex polygon grows quadratically (docs/performance.md: a 10,000-vertex star).
/// Every loop of the polygon closes (each curve ends where the next begins). CGAL's
/// approximated_offset_2 returns a loop that does not close for some small convex polygons (a
/// 24-gon disc of radius 0.26 at r = 0.2, at every eps tried); the Boolean operations then drop the
/// obstacle silently under NDEBUG, and plans crossed it (the validator caught them).
bool closedLoops(const CPolygonWithHoles& p) {
  auto closed = [](const CPolygon& g) {
    auto it = g.curves_begin();
    if (it == g.curves_end()) return false;
    auto prev = it;
    for (++it; it != g.curves_end(); prev = it, ++it)
      if (!(prev->target() == it->source())) return false;
    return g.curves_begin()->source() == prev->target();
  };
  if (!closed(p.outer_boundary())) return false;
  for (auto h = p.holes_begin(); h != p.holes_end(); ++h)
    if (!closed(*h)) return false;
  return true;
}

/// With `near`, only the triangles of a large polygon whose box comes within `reach` of `near` are
/// offset (a triangle's offset lies within its box grown by r and CGAL's approximation, below
/// `reach`); small polygons are offset whole as without it, so every piece is one the whole
/// construction makes.
template <class Polygon>
void offsetPieces(const Polygon& p, std::size_t vertices, const K::FT& r, double eps, std::vector<CPolygonWithHoles>& out,
                  const BoxD* near = nullptr, double reach = 0) {
  constexpr std::size_t kWhole = 2000;
  if constexpr (std::is_same_v<Polygon, LinearPolygon>) {
    CPolygonWithHoles direct;
    if (convexOffset(p, exactOf(r), eps, direct)) {
      out.push_back(std::move(direct));
      return;
    }
  }
  if (vertices <= kWhole) {
    CPolygonWithHoles whole = CGAL::approximated_offset_2(p, r, eps);
    if (closedLoops(whole)) {
      out.push_back(std::move(whole));
      return;
    }
  }
  std::vector<LinearPolygon> triangles;
  CGAL::Polygon_triangulation_decomposition_2<K> decompose;
  decompose(p, std::back_inserter(triangles));
  for (const LinearPolygon& t : triangles) {
    if (near) {
      const CGAL::Bbox_2 b = t.bbox();
      if (b.xmin() > near->xmax + reach || b.xmax() < near->xmin - reach || b.ymin() > near->ymax + reach ||
          b.ymax() < near->ymin - reach)
        continue;
    }
    out.push_back(CGAL::approximated_offset_2(t, r, eps));
  }
}

/// The approximation bound: `relativeEps` of the workspace's extent.
double epsilonOf(const Workspace& w, double relativeEps) {
  const Box b = w.bbox();
  const double extent = std::max(Rational(b.xmax - b.xmin).get_d(), Rational(b.ymax - b.ymin).get_d());
  return relativeEps * std::max(extent, 1e-12);
}

/// A frame around the workspace's box, so that the outside of each region is a bounded polygon
/// with a hole.
Ring frameOf(const Workspace& w, const Rational& radius) {
  const Box b = w.bbox();
  const Rational pad = 4 * radius + 1;
  return {{Rational(b.xmin - pad), Rational(b.ymin - pad)}, {Rational(b.xmax + pad), Rational(b.ymin - pad)},
          {Rational(b.xmax + pad), Rational(b.ymax + pad)}, {Rational(b.xmin - pad), Rational(b.ymax + pad)}};
}

/// The C-obstacle pieces of ring k of a region: k = 0 the outside of the region (the frame with
/// the region's outer ring as a hole; its offset shrinks the hole by r, which erodes the region),
/// k >= 1 hole k - 1. Their union with the other rings' pieces is the complement of the region's
/// C-free within the frame. Each call makes its own exact numbers (threads share none).
void ringOffsets(const Region& reg, std::size_t k, const Ring& frame, const Rational& radius, double eps,
                 std::vector<CPolygonWithHoles>& out, const BoxD* near = nullptr, double reach = 0) {
  const K::FT r = ft(radius);
  if (k == 0) {
    const LinearPolygon outerHole = linear(reg.outer, false);
    const LinearPolygonWithHoles outside(linear(frame, true), &outerHole, &outerHole + 1);
    offsetPieces(outside, reg.outer.size() + 4, r, eps, out, near, reach);
  } else {
    const Ring& h = reg.holes[k - 1];
    offsetPieces(linear(h, true), h.size(), r, eps, out, near, reach);
  }
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
  Workspace workspace;                       ///< kept for obstacles() and coverableArea()
  double relativeEps = 1e-6;
  /// C-free as one set, kept alive for zone walks over its arrangement (built on first use; the
  /// arrangement refers to the set's traits, so the set itself is kept, not a copy).
  std::unique_ptr<PolygonSet> zoneSet;
  PolygonSet::Arrangement_2& arr() {
    if (!zoneSet) {
      zoneSet = std::make_unique<PolygonSet>();
      zoneSet->insert(parts.begin(), parts.end());
    }
    return zoneSet->arrangement();
  }
  /// Every face the curve's interior passes through is in C-free.
  bool curveClear(const Traits::X_monotone_curve_2& cv) {
    using Arr = PolygonSet::Arrangement_2;
    std::vector<boost::variant<Arr::Vertex_handle, Arr::Halfedge_handle, Arr::Face_handle>> cells;
    CGAL::zone(arr(), cv, std::back_inserter(cells));
    for (const auto& c : cells)
      if (const auto* f = boost::get<Arr::Face_handle>(&c))
        if (!(*f)->contained()) return false;
    return true;
  }
  /// C-free as one set for CSpace::sweeps (built on first use).
  std::unique_ptr<PolygonSet> sweepSet;
  std::vector<CPolygonWithHoles> parts;      ///< components of C-free, largest first
  /// One set per component, for point location: built on the first query (many C-spaces never get
  /// one), once, also when queries come from several threads.
  std::vector<PolygonSet> partSets;
  std::once_flag partSetsBuilt;
  const std::vector<PolygonSet>& locator() {
    std::call_once(partSetsBuilt, [&] {
      for (const auto& p : parts) partSets.emplace_back(p);
    });
    return partSets;
  }
  std::vector<double> areas;
  /// The closed convention's helpers (cspace.h), built on first use: radius r − δ and 2r − 2δ.
  std::unique_ptr<CSpace> joined, inner;
  double delta = 0, epsPrime = 0;
  std::map<std::vector<int>, std::pair<double, double>> coverable;  ///< components → (area, error)
};

CSpace::CSpace(const Workspace& w, const Rational& radius, double relativeEps, unsigned threads) : impl_(std::make_unique<Impl>()) {
  if (radius < 0) throw InputError(w.name, "radius", "robot radius must be >= 0");
  if (w.regions.empty()) throw InputError(w.name, "workspace", "empty free space");
  checkWorkspace(w);  // CGAL's preconditions are not input validation
  impl_->radius = radius;
  impl_->workspace = w;
  impl_->relativeEps = relativeEps;
  impl_->eps = epsilonOf(w, relativeEps);
  const Ring frame = frameOf(w, radius);
  // Each region on its own: the disc in one region never reaches another (they are separated by
  // walls), and the outside of one region contains the others. Regions are disjoint, so their
  // components are simply collected (joining them one by one would cost quadratic time).
  if (radius == 0) {  // a point robot: C-free is W itself (the command line rejects r = 0)
    for (const Region& reg : w.regions) {
      std::vector<CPolygon> holes;
      for (const Ring& h : reg.holes) holes.push_back(curved(h, false));
      impl_->parts.emplace_back(curved(reg.outer, true), holes.begin(), holes.end());
    }
  }
  // The offsets, one per obstacle ring, are independent: computed on `threads` threads, each from
  // its own exact numbers (no lazy number is shared between threads), and joined in ring order, so
  // C-free is the same, to the bit, for any number of threads.
  const double eps = impl_->eps;
  for (const Region& reg : w.regions) {
    if (radius == 0) break;
    // job k: ringOffsets' ring k (0 the outside of the region, k >= 1 hole k - 1)
    const std::size_t jobs = reg.holes.size() + 1;
    std::vector<std::vector<CPolygonWithHoles>> offsets(jobs);
    detail::parallelFor(jobs, threads, [&](std::size_t k) { ringOffsets(reg, k, frame, radius, eps, offsets[k]); });
    std::vector<CPolygonWithHoles> cobs;
    std::size_t count = 0;
    for (const std::vector<CPolygonWithHoles>& o : offsets) count += o.size();
    cobs.reserve(count);  // a polygon's holes are a std::deque, whose move may throw: growing would copy
    for (std::vector<CPolygonWithHoles>& o : offsets)
      for (CPolygonWithHoles& q : o) cobs.push_back(std::move(q));
    PolygonSet blocked;
    // One range join: CGAL merges the polygons' arrangements by divide and conquer, sweeping k of
    // them at once; its default k = 5 sweeps the curves of the union up to log5(n) times. k = 64
    // made the C-space of 1,000 convex obstacles 15-20 % faster (docs/performance.md).
    constexpr unsigned kJoinFanIn = 64;
    blocked.join(cobs.begin(), cobs.end(), kJoinFanIn);
    // The outside's offset covers the frame beyond the region, so what the join leaves uncovered
    // within the frame is the region's C-free: the complement (no sweep: every face of the
    // arrangement changes sides), without its one unbounded face beyond the frame.
    blocked.complement();
    std::vector<CPolygonWithHoles> freeParts;
    blocked.polygons_with_holes(std::back_inserter(freeParts));
    for (CPolygonWithHoles& q : freeParts)
      if (!q.is_unbounded()) impl_->parts.push_back(std::move(q));
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
  parts.reserve(order.size());  // moved, not copied, also when growing (see cobs above)
  for (std::size_t i : order) {
    parts.push_back(std::move(impl_->parts[i]));
    areas.push_back(impl_->areas[i]);
  }
  impl_->parts.swap(parts);
  impl_->areas.swap(areas);
}

const std::vector<CPolygonWithHoles>& detail::CSpaceAccess::parts(const CSpace& s) { return s.impl_->parts; }

CSpace::~CSpace() = default;
CSpace::CSpace(CSpace&&) noexcept = default;
CSpace& CSpace::operator=(CSpace&&) noexcept = default;

const Rational& CSpace::radius() const { return impl_->radius; }
double CSpace::epsilon() const { return impl_->eps; }
std::size_t CSpace::componentCount() const { return impl_->parts.size(); }

int CSpace::componentOf(const Point& p) const {
  const Traits::Point_2 q(ft(p.x), ft(p.y));
  const std::vector<PolygonSet>& sets = impl_->locator();
  for (std::size_t i = 0; i < sets.size(); ++i)
    if (sets[i].oriented_side(q) != CGAL::ON_NEGATIVE_SIDE) return static_cast<int>(i);
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
  for (const Region& reg : impl_->workspace.regions) outers.emplace_back(curved(reg.outer, true));
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

bool CSpace::segmentClear(const Point& a, const Point& b) const {
  if (!contains(a) || !contains(b)) return false;
  if (a == b) return true;
  return impl_->curveClear(Traits::X_monotone_curve_2(K::Point_2(ft(a.x), ft(a.y)), K::Point_2(ft(b.x), ft(b.y))));
}

bool CSpace::arcClear(const Point& from, const Point& to, const Point& center, bool ccw) const {
  if (!contains(from)) return false;
  const Rational rho2 = (from.x - center.x) * (from.x - center.x) + (from.y - center.y) * (from.y - center.y);
  const Rational d2 = (to.x - center.x) * (to.x - center.x) + (to.y - center.y) * (to.y - center.y);
  if (rho2 == 0 || d2 == 0) return from == to && contains(from);
  const K::Circle_2 circle(K::Point_2(ft(center.x), ft(center.y)), ft(rho2), ccw ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE);
  Traits::Curve_2 curve;
  if (from == to) {
    curve = Traits::Curve_2(circle);
  } else {
    // the end: the ray through `to` meets the circle at center + (to − center)·sqrt(rho2 / d2)
    const Rational q = rho2 / d2;
    const Traits::Point_2 end(Traits::CoordNT(ft(center.x), ft(Rational(to.x - center.x)), ft(q)),
                              Traits::CoordNT(ft(center.y), ft(Rational(to.y - center.y)), ft(q)));
    curve = Traits::Curve_2(circle, Traits::Point_2(ft(from.x), ft(from.y)), end);
  }
  Traits traits;
  std::vector<boost::variant<Traits::Point_2, Traits::X_monotone_curve_2>> parts;
  traits.make_x_monotone_2_object()(curve, std::back_inserter(parts));
  for (const auto& v : parts)
    if (const auto* xc = boost::get<Traits::X_monotone_curve_2>(&v))
      if (!impl_->curveClear(*xc)) return false;
  return true;
}

namespace {

/// The closed convention's helper C-spaces (cspace.h): radius r − δ (connectivity, the region K)
/// and 2r − 2δ (K's part farther than r from K's boundary), with eps' = min(eps, r/64), δ = 4·eps'.
struct ClosedHelpers {
  std::unique_ptr<CSpace> joined, inner;
  double delta = 0, epsPrime = 0;
};

/// `threads` (0: every core): with more than one, the two helpers are built at once.
ClosedHelpers closedHelpers(const Workspace& w, const Rational& r, double relativeEps, bool wantInner, unsigned threads = 1) {
  ClosedHelpers h;
  const Box b = w.bbox();
  const double extent = std::max(std::max(Rational(b.xmax - b.xmin).get_d(), Rational(b.ymax - b.ymin).get_d()), 1e-12);
  Rational delta = 0;
  double relEps = relativeEps;
  if (r > 0) {
    h.epsPrime = std::min(relativeEps * extent, r.get_d() / 64);
    relEps = h.epsPrime / extent;
    delta = 4 * exactFromDouble(h.epsPrime);  // > the helpers' eps (relEps·extent rounds within an ulp of eps')
    h.delta = delta.get_d();
  }
  // each C-space is built from the shared, read-only workspace into its own objects: the two at once
  // when there are threads for both, each on one, else each on all there are
  const unsigned cores = detail::threadCount(threads), each = wantInner && cores > 1 ? 1 : cores;
  detail::parallelFor(wantInner ? 2 : 1, cores, [&](std::size_t k) {
    if (k == 0) h.joined = std::make_unique<CSpace>(w, Rational(r - delta), relEps, each);
    else h.inner = std::make_unique<CSpace>(w, Rational(2 * r - 2 * delta), relEps, each);
  });
  return h;
}

double loopLength(const CurveLoop& l) {
  double len = 0;
  for (const PathSegment& s : l.pieces) len += s.length();
  return len;
}

/// The components of `joined` holding the starts, sorted, without repeats.
std::vector<int> startComponents(const CSpace& joined, const std::vector<Point>& starts) {
  std::vector<int> ks;
  for (const Point& s : starts) {
    const int k = joined.componentOf(s);
    if (k >= 0 && std::find(ks.begin(), ks.end(), k) == ks.end()) ks.push_back(k);
  }
  std::sort(ks.begin(), ks.end());
  return ks;
}

/// coverableArea (cspace.h) from the helpers, for the components `ks` of `joined`.
double coverableFrom(const Workspace& w, const Rational& r, const CSpace& joined, const CSpace& innerSpace, double delta,
                     double epsPrime, const std::vector<int>& ks, double& errorBound, unsigned threads) {
  errorBound = 0;
  if (ks.empty()) return 0;
  auto inK = [&](int k) { return std::find(ks.begin(), ks.end(), k) != ks.end(); };
  // K's part farther than r from its boundary: components of the C-space of radius 2r − 2δ lying in
  // K (their points are >= 2r − 2δ > r − δ + eps' from any obstacle, inside K's interior: one vertex
  // tells which component holds them)
  double inner = 0, perimeter = 0;
  for (const CurveRegion& c : innerSpace.components()) {
    if (c.outer.pieces.empty()) continue;
    const PointD v = c.outer.pieces.front().from;
    if (!inK(joined.componentOf({exactFromDouble(v.x), exactFromDouble(v.y)}))) continue;
    inner += c.area;
    perimeter += loopLength(c.outer);
    for (const CurveLoop& l : c.holes) perimeter += loopLength(l);
  }
  // F ∩ (∂K ⊕ disc(r)), rasterised with its bound
  std::vector<Path> loops;
  const std::vector<CurveRegion> comps = joined.components();
  auto add = [&](const CurveLoop& l) {
    if (l.pieces.empty()) return;
    Path p;
    p.start = l.pieces.front().from;
    p.segments = l.pieces;
    loops.push_back(std::move(p));
  };
  for (int k : ks) {
    add(comps[static_cast<std::size_t>(k)].outer);
    for (const CurveLoop& l : comps[static_cast<std::size_t>(k)].holes) add(l);
  }
  const double band = rasterCoveredArea(w, r, loops, 4'000'000, errorBound, threads);
  // the two parts overlap where a point of the first lies within r of ∂K: within δ + eps' of its
  // own boundary (an inner band; its boundary arcs have radius 2r − 2δ, so the band is at most
  // width × perimeter × (1 + width / (2r − 2δ)))
  const double width = delta + epsPrime, rin = 2 * r.get_d() - 2 * delta;
  if (rin > 0) errorBound += width * perimeter * (1 + width / rin);
  return inner + band;
}

}  // namespace

double coverableArea(const Workspace& w, const Rational& radius, const std::vector<Point>& starts, double& errorBound,
                     double relativeEps, unsigned threads) {
  errorBound = 0;
  if (radius < 0) throw InputError(w.name, "radius", "robot radius must be >= 0");
  const ClosedHelpers h = closedHelpers(w, radius, relativeEps, true, threads);
  return coverableFrom(w, radius, *h.joined, *h.inner, h.delta, h.epsPrime, startComponents(*h.joined, starts), errorBound, threads);
}

int CSpace::closedComponentOf(const Point& p) const {
  if (!impl_->joined) {
    ClosedHelpers h = closedHelpers(impl_->workspace, impl_->radius, impl_->relativeEps, false);
    impl_->joined = std::move(h.joined);
    impl_->delta = h.delta;
    impl_->epsPrime = h.epsPrime;
  }
  return impl_->joined->componentOf(p);
}

double CSpace::closedMargin() const {
  if (!impl_->joined) closedComponentOf(Point{impl_->workspace.regions.front().outer.front()});
  return impl_->delta;
}

double CSpace::coverableArea(const std::vector<Point>& starts, double& errorBound, unsigned threads) const {
  if (!impl_->inner) {
    ClosedHelpers h = closedHelpers(impl_->workspace, impl_->radius, impl_->relativeEps, true, threads);
    impl_->joined = std::move(h.joined);
    impl_->inner = std::move(h.inner);
    impl_->delta = h.delta;
    impl_->epsPrime = h.epsPrime;
  }
  // the same components give the same region: kept (plans of several planners on one C-space)
  const std::vector<int> ks = startComponents(*impl_->joined, starts);
  auto it = impl_->coverable.find(ks);
  if (it == impl_->coverable.end()) {
    double err = 0;
    const double a = coverableFrom(impl_->workspace, impl_->radius, *impl_->joined, *impl_->inner, impl_->delta, impl_->epsPrime, ks, err, threads);
    it = impl_->coverable.emplace(ks, std::make_pair(a, err)).first;
  }
  errorBound = it->second.second;
  return it->second.first;
}

std::vector<CSpace::SampledComponent> CSpace::sampledComponents(double tolerance) const {
  // radius r + 4·eps: its C-free lies in the exact C-free of radius r with room to spare for the
  // approximation and for rounding, and gaps exactly 2r wide no longer pinch it to a point
  const CSpace grown(impl_->workspace, Rational(impl_->radius + 4 * exactFromDouble(impl_->eps)), impl_->relativeEps);
  const std::vector<CurveRegion> comps = grown.components();
  std::vector<SampledRegion> sampled = sampleFreeRegions(comps, impl_->workspace, impl_->radius, tolerance);
  std::vector<SampledComponent> out;
  for (std::size_t i = 0; i < comps.size(); ++i) {
    if (sampled[i].outer.empty() || comps[i].outer.pieces.empty()) continue;
    const PointD v = comps[i].outer.pieces.front().from;  // > r from the obstacles: inside one component
    out.push_back({componentOf({exactFromDouble(v.x), exactFromDouble(v.y)}), std::move(sampled[i])});
  }
  return out;
}

CellState CSpaceCells::mega(int col, int row) const {
  const CellState a = subState(2 * col, 2 * row), b = subState(2 * col + 1, 2 * row), c = subState(2 * col, 2 * row + 1),
                  d = subState(2 * col + 1, 2 * row + 1);
  if (a == b && b == c && c == d && a != CellState::kPartial) return a;
  return CellState::kPartial;
}

const CSpaceCells::MegaContour* CSpaceCells::contour(int col, int row) const {
  auto it = std::lower_bound(contours.begin(), contours.end(), std::make_pair(row, col),
                             [](const MegaContour& m, const std::pair<int, int>& k) { return std::make_pair(m.row, m.col) < k; });
  return it != contours.end() && it->col == col && it->row == row ? &*it : nullptr;
}

namespace {

struct Clipper {
  const CellGrid& grid;
  bool wantContours;
  CSpaceCells& out;

  CPolygon box(int c0, int r0, int c1, int r1) const {  // sub-cell index range [c0, c1) × [r0, r1)
    const Rational& D = grid.subSize();
    const Rational x0 = grid.originX() + D * c0, x1 = grid.originX() + D * c1;
    const Rational y0 = grid.originY() + D * r0, y1 = grid.originY() + D * r1;
    return curved({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, true);
  }
  void fill(int c0, int r0, int c1, int r1, CellState s) {
    for (int r = r0; r < r1; ++r)
      for (int c = c0; c < c1; ++c) out.sub[static_cast<std::size_t>(r) * out.subCols + c] = s;
  }
  /// S is C-free ∩ the range's box. Ranges are in mega-cells: [m0, m1) × [n0, n1).
  void recurse(const PolygonSet& S, int m0, int n0, int m1, int n1) {
    if (S.is_empty()) return fill(2 * m0, 2 * n0, 2 * m1, 2 * n1, CellState::kBlocked);
    PolygonSet rest(CPolygonWithHoles(box(2 * m0, 2 * n0, 2 * m1, 2 * n1)));
    rest.difference(S);
    if (rest.is_empty()) return fill(2 * m0, 2 * n0, 2 * m1, 2 * n1, CellState::kFree);
    if (m1 - m0 == 1 && n1 - n0 == 1) return megaCell(S, m0, n0);
    const int mm = m1 - m0 > 1 ? (m0 + m1) / 2 : m1, nm = n1 - n0 > 1 ? (n0 + n1) / 2 : n1;
    for (auto [a0, a1] : {std::pair{m0, mm}, std::pair{mm, m1}})
      for (auto [b0, b1] : {std::pair{n0, nm}, std::pair{nm, n1}}) {
        if (a0 >= a1 || b0 >= b1) continue;
        PolygonSet part(CPolygonWithHoles(box(2 * a0, 2 * b0, 2 * a1, 2 * b1)));
        part.intersection(S);
        recurse(part, a0, b0, a1, b1);
      }
  }
  void megaCell(const PolygonSet& S, int m, int n) {
    for (int dr = 0; dr < 2; ++dr)
      for (int dc = 0; dc < 2; ++dc) {
        const int c = 2 * m + dc, r = 2 * n + dr;
        PolygonSet part(CPolygonWithHoles(box(c, r, c + 1, r + 1)));
        part.intersection(S);
        CellState st = CellState::kPartial;
        if (part.is_empty()) st = CellState::kBlocked;
        else {
          PolygonSet rest(CPolygonWithHoles(box(c, r, c + 1, r + 1)));
          rest.difference(part);
          if (rest.is_empty()) st = CellState::kFree;
        }
        out.sub[static_cast<std::size_t>(r) * out.subCols + c] = st;
      }
    if (!wantContours) return;
    CSpaceCells::MegaContour mc;
    mc.col = m;
    mc.row = n;
    std::vector<CPolygonWithHoles> pw;
    S.polygons_with_holes(std::back_inserter(pw));
    const Rational& D = grid.subSize();
    const K::FT x0 = ft(grid.originX() + 2 * D * m), x1 = ft(grid.originX() + 2 * D * (m + 1));
    const K::FT y0 = ft(grid.originY() + 2 * D * n), y1 = ft(grid.originY() + 2 * D * (n + 1));
    auto onBorder = [&](const Traits::X_monotone_curve_2& cv) {
      if (cv.is_circular()) return false;
      const auto &a = cv.source(), &b = cv.target();
      auto same = [](const auto& u, const K::FT& v) { return CGAL::compare(u, Traits::CoordNT(v)) == CGAL::EQUAL; };
      return (same(a.x(), x0) && same(b.x(), x0)) || (same(a.x(), x1) && same(b.x(), x1)) || (same(a.y(), y0) && same(b.y(), y0)) ||
             (same(a.y(), y1) && same(b.y(), y1));
    };
    auto chainsOf = [&](const CPolygon& loop) {
      std::vector<Traits::X_monotone_curve_2> cs(loop.curves_begin(), loop.curves_end());
      const std::size_t n = cs.size();
      std::size_t start = n;  // first curve after a border curve
      for (std::size_t i = 0; i < n; ++i)
        if (onBorder(cs[i]) && !onBorder(cs[(i + 1) % n])) { start = (i + 1) % n; break; }
      if (start == n) {  // no border curve: the loop is wholly inside (or wholly the border)
        if (n > 0 && !onBorder(cs[0])) {
          CSpaceCells::Chain ch;
          ch.closed = true;
          for (const auto& cv : cs) ch.pieces.push_back(detail::toSegment(cv));
          mc.chains.push_back(std::move(ch));
        }
        return;
      }
      CSpaceCells::Chain ch;
      for (std::size_t k = 0; k < n; ++k) {
        const auto& cv = cs[(start + k) % n];
        if (onBorder(cv)) {
          if (!ch.pieces.empty()) {
            ch.entry = ch.pieces.front().from;
            ch.exit = ch.pieces.back().to;
            mc.chains.push_back(std::move(ch));
            ch = CSpaceCells::Chain();
          }
          continue;
        }
        ch.pieces.push_back(detail::toSegment(cv));
      }
      if (!ch.pieces.empty()) {
        ch.entry = ch.pieces.front().from;
        ch.exit = ch.pieces.back().to;
        mc.chains.push_back(std::move(ch));
      }
    };
    for (const auto& p : pw) {
      mc.pieces.push_back(regionOf(p));
      chainsOf(p.outer_boundary());
      for (auto h = p.holes_begin(); h != p.holes_end(); ++h) chainsOf(*h);
    }
    out.contours.push_back(std::move(mc));
  }
};

}  // namespace

CSpaceCells CSpace::classify(const CellGrid& grid, bool contours) const {
  CSpaceCells out;
  out.subCols = grid.subCols();
  out.subRows = grid.subRows();
  out.sub.assign(static_cast<std::size_t>(out.subCols) * out.subRows, CellState::kBlocked);
  if (grid.megaCount() == 0) return out;
  Clipper clip{grid, contours, out};
  PolygonSet S;
  S.insert(impl_->parts.begin(), impl_->parts.end());
  PolygonSet all(CPolygonWithHoles(clip.box(0, 0, grid.subCols(), grid.subRows())));
  S.intersection(all);
  clip.recurse(S, 0, 0, grid.megaCols(), grid.megaRows());
  std::sort(out.contours.begin(), out.contours.end(),
            [](const auto& a, const auto& b) { return std::make_pair(a.row, a.col) < std::make_pair(b.row, b.col); });
  return out;
}

}  // namespace coverkit

namespace coverkit {

namespace {

using XCurve = detail::Traits::X_monotone_curve_2;

struct SweepBox {
  Rational x0, y0, x1, y1;
};

SweepBox boxOf(const CSpace::SweepRequest& q) {
  // the base is axis-parallel; the right of a → d is (dy, −dx) / |d − a|
  const Rational dx = q.d.x - q.a.x, dy = q.d.y - q.a.y;
  Point far1 = q.a, far2 = q.d;
  if (dx != 0) {  // horizontal: the right is −y when going +x
    const Rational off = dx > 0 ? Rational(-q.depth) : Rational(q.depth);
    far1.y += off;
    far2.y += off;
  } else {
    const Rational off = dy > 0 ? Rational(q.depth) : Rational(-q.depth);
    far1.x += off;
    far2.x += off;
  }
  SweepBox b{q.a.x, q.a.y, q.a.x, q.a.y};
  for (const Point& p : {q.d, far1, far2}) {
    if (p.x < b.x0) b.x0 = p.x;
    if (p.x > b.x1) b.x1 = p.x;
    if (p.y < b.y0) b.y0 = p.y;
    if (p.y > b.y1) b.y1 = p.y;
  }
  return b;
}

CPolygonWithHoles boxPolygon(const SweepBox& b) {
  return CPolygonWithHoles(curved({{b.x0, b.y0}, {b.x1, b.y0}, {b.x1, b.y1}, {b.x0, b.y1}}, true));
}

/// Consecutive pieces of one circle (or one line) become one piece.
void appendMerged(std::vector<PathSegment>& out, std::vector<XCurve>& run) {
  if (run.empty()) return;
  PathSegment s = detail::toSegment(run.front(), true);
  s.to = detail::toSegment(run.back(), true).to;
  out.push_back(s);
  run.clear();
}

bool sameSupport(const XCurve& u, const XCurve& v) {
  if (u.is_circular() != v.is_circular()) return false;
  if (u.is_circular())
    return u.orientation() == v.orientation() && u.supporting_circle().center() == v.supporting_circle().center() &&
           u.supporting_circle().squared_radius() == v.supporting_circle().squared_radius();
  return u.supporting_line() == v.supporting_line();
}

/// The sweep of request q from U ∩ C-free (`pw`, its polygons).
CSpace::Sweep sweepOf(const std::vector<CPolygonWithHoles>& pw, const CSpace::SweepRequest& q) {
  CSpace::Sweep out;
  const bool horizontal = q.a.y == q.d.y;
  const K::FT line = ft(horizontal ? q.a.y : q.a.x);
  const int sign = horizontal ? (q.d.x > q.a.x ? 1 : -1) : (q.d.y > q.a.y ? 1 : -1);
  using CoordNT = detail::Traits::CoordNT;
  auto onBase = [&](const XCurve& cv) {
    if (cv.is_circular()) return false;
    const CoordNT L(line);
    return horizontal ? (CGAL::compare(cv.source().y(), L) == CGAL::EQUAL && CGAL::compare(cv.target().y(), L) == CGAL::EQUAL)
                      : (CGAL::compare(cv.source().x(), L) == CGAL::EQUAL && CGAL::compare(cv.target().x(), L) == CGAL::EQUAL);
  };
  auto along = [&](const detail::Traits::Point_2& p) -> const CoordNT& { return horizontal ? p.x() : p.y(); };
  // the side of U opposite the base: the right of a → d is −y going +x, +x going +y
  const K::FT farLine = ft(horizontal ? Rational(q.a.y + (sign > 0 ? Rational(-q.depth) : q.depth))
                                      : Rational(q.a.x + (sign > 0 ? q.depth : Rational(-q.depth))));
  auto onFar = [&](const XCurve& cv) {
    if (cv.is_circular()) return false;
    const CoordNT L(farLine);
    return horizontal ? (CGAL::compare(cv.source().y(), L) == CGAL::EQUAL && CGAL::compare(cv.target().y(), L) == CGAL::EQUAL)
                      : (CGAL::compare(cv.source().x(), L) == CGAL::EQUAL && CGAL::compare(cv.target().x(), L) == CGAL::EQUAL);
  };
  // the entry: among the targets of base curves (the boundary runs along the base from d towards
  // a), the one nearest a
  std::vector<std::vector<XCurve>> loops;
  int bestLoop = -1;
  std::size_t bestCurve = 0;
  for (const auto& p : pw) {
    loops.emplace_back(p.outer_boundary().curves_begin(), p.outer_boundary().curves_end());
    const auto& cs = loops.back();
    for (std::size_t i = 0; i < cs.size(); ++i) {
      if (!onBase(cs[i])) continue;
      if (bestLoop >= 0) {
        const auto c = CGAL::compare(along(cs[i].target()), along(loops[static_cast<std::size_t>(bestLoop)][bestCurve].target()));
        if (!((sign > 0 && c == CGAL::SMALLER) || (sign < 0 && c == CGAL::LARGER))) continue;
      }
      bestLoop = static_cast<int>(loops.size()) - 1;
      bestCurve = i;
    }
  }
  if (bestLoop < 0) return out;
  const auto& cs = loops[static_cast<std::size_t>(bestLoop)];
  const std::size_t n = cs.size();
  std::size_t first = bestCurve;  // the first curve of the base run that ends at the entry
  while (onBase(cs[(first + n - 1) % n]) && (first + n - 1) % n != bestCurve) first = (first + n - 1) % n;
  out.reached = true;
  std::vector<XCurve> run;
  for (std::size_t k = (bestCurve + 1) % n; k != first; k = (k + 1) % n) {
    out.farSide = out.farSide || onFar(cs[k]);
    if (!run.empty() && !sameSupport(run.back(), cs[k])) appendMerged(out.pieces, run);
    run.push_back(cs[k]);
  }
  appendMerged(out.pieces, run);
  const double a0 = horizontal ? q.a.x.get_d() : q.a.y.get_d(), d0 = horizontal ? q.d.x.get_d() : q.d.y.get_d();
  auto toD = [](const detail::Traits::Point_2& p) { return PointD{detail::stableDouble(p.x()), detail::stableDouble(p.y())}; };
  out.entry = toD(cs[bestCurve].target());
  out.exit = toD(cs[first].source());
  out.entryT = ((horizontal ? out.entry.x : out.entry.y) - a0) / (d0 - a0);
  out.exitT = ((horizontal ? out.exit.x : out.exit.y) - a0) / (d0 - a0);
  return out;
}

CSpace::Sweep sweepOne(const PolygonSet& S, const CSpace::SweepRequest& q) {
  PolygonSet Q(boxPolygon(boxOf(q)));
  Q.intersection(S);
  std::vector<CPolygonWithHoles> pw;
  Q.polygons_with_holes(std::back_inserter(pw));
  return sweepOf(pw, q);
}

void sweepGroup(const PolygonSet& S, const std::vector<CSpace::SweepRequest>& requests, const std::vector<SweepBox>& boxes,
                std::vector<std::size_t>& group, std::vector<CSpace::Sweep>& out) {
  if (group.size() <= 2) {
    for (std::size_t i : group) out[i] = sweepOne(S, requests[i]);
    return;
  }
  SweepBox all = boxes[group.front()];
  for (std::size_t i : group) {
    const SweepBox& b = boxes[i];
    all = {std::min(all.x0, b.x0), std::min(all.y0, b.y0), std::max(all.x1, b.x1), std::max(all.y1, b.y1)};
  }
  const bool alongX = Rational(all.x1 - all.x0) >= Rational(all.y1 - all.y0);
  auto key = [&](std::size_t i) {
    const SweepBox& b = boxes[i];
    return std::make_pair(alongX ? Rational(b.x0 + b.x1).get_d() : Rational(b.y0 + b.y1).get_d(), i);
  };
  const auto mid = group.begin() + static_cast<std::ptrdiff_t>(group.size() / 2);
  std::nth_element(group.begin(), mid, group.end(), [&](std::size_t i, std::size_t j) { return key(i) < key(j); });
  for (int half = 0; half < 2; ++half) {
    std::vector<std::size_t> part(half == 0 ? group.begin() : mid, half == 0 ? mid : group.end());
    SweepBox b = boxes[part.front()];
    for (std::size_t i : part) {
      const SweepBox& c = boxes[i];
      b = {std::min(b.x0, c.x0), std::min(b.y0, c.y0), std::max(b.x1, c.x1), std::max(b.y1, c.y1)};
    }
    PolygonSet clipped(boxPolygon(b));
    clipped.intersection(S);
    sweepGroup(clipped, requests, boxes, part, out);
  }
}

/// The C-obstacles near a box of the plane, for sweeps there without the whole C-space: the
/// pieces of the rings that may come within reach of the box (ringOffsets, so exactly the pieces
/// the CSpace constructor joins), those with many curves or a wide box cut into tiles of about
/// `cell`, indexed by a grid of buckets of side `cell`. Rings are added all at once (addAllNear)
/// or one by one as a robot learns them (addRing; its regions with addRegion).
class LocalObstacles {
public:
  LocalObstacles(const Workspace& w, const Rational& radius, double eps, const BoxD& near, double cell)
      : w_(w), radius_(radius), eps_(eps), near_(near), cell_(cell), frame_(frameOf(w, radius)), slot_(w.regions.size(), -1),
        added_(w.regions.size()) {
    // An offset lies within r and the approximation's rise of its ring; the rise is below r
    // (CGAL's tangents over an arc of radius r; eps for convex obstacles), and every piece's box
    // is checked against this reach below: a piece beyond it would be missed by the other boxes'
    // obstacles, so it stops the computation instead of giving a wrong sweep.
    reach_ = 2 * radius.get_d() + 1000 * eps;
    pad_ = 1e-9 * std::max({1.0, std::abs(near.xmin), std::abs(near.xmax), std::abs(near.ymin), std::abs(near.ymax)});
    x0_ = near.xmin - reach_;
    y0_ = near.ymin - reach_;
    // at most about 4 million buckets (two vectors each: under 200 MB), however small the cells
    constexpr double kMaxBuckets = 4.0 * 1024 * 1024;
    const double spanX = near.xmax + reach_ - x0_, spanY = near.ymax + reach_ - y0_;
    cell_ = std::max({cell_, std::sqrt(2 * spanX * spanY / kMaxBuckets), 2 * std::max(spanX, spanY) / kMaxBuckets});
    nx_ = static_cast<long>(spanX / cell_) + 1;
    ny_ = static_cast<long>(spanY / cell_) + 1;
    pieceAt_.resize(static_cast<std::size_t>(nx_ * ny_));
    regionAt_.resize(static_cast<std::size_t>(nx_ * ny_));
    for (std::size_t g = 0; g < w.regions.size(); ++g) added_[g].assign(w.regions[g].holes.size() + 1, 0);
  }

  /// Every region and ring that may come within reach of `near`.
  void addAllNear() {
    for (std::size_t g = 0; g < w_.regions.size(); ++g) {
      if (!overlaps(ringBox(w_.regions[g].outer), near_, pad_)) continue;
      addRegion(g);
      for (std::size_t k = 0; k <= w_.regions[g].holes.size(); ++k)
        if (k == 0 || overlaps(ringBox(w_.regions[g].holes[k - 1]), near_, reach_)) addRing(g, k);
    }
  }

  /// Region g takes part in the queries (its C-free inside its outer ring's box, minus the pieces
  /// of its rings added so far).
  void addRegion(std::size_t g) {
    if (slot_.at(g) >= 0) return;
    const BoxD outer = ringBox(w_.regions[g].outer);
    // the region's C-free lies inside its outer ring's box; outside it and beyond reach of `near`
    // no query looks, so big pieces are clipped to both before they are cut
    const BoxD wide{near_.xmin - reach_, near_.ymin - reach_, near_.xmax + reach_, near_.ymax + reach_};
    const SweepBox clip{exactFromDouble(std::max(outer.xmin, wide.xmin)), exactFromDouble(std::max(outer.ymin, wide.ymin)),
                        exactFromDouble(std::min(outer.xmax, wide.xmax)), exactFromDouble(std::min(outer.ymax, wide.ymax))};
    slot_[g] = static_cast<int>(regions_.size());
    regions_.push_back({clip, !(clip.x0 < clip.x1 && clip.y0 < clip.y1)});
    if (!regions_.back().empty) addTo(regionAt_, {clip.x0.get_d(), clip.y0.get_d(), clip.x1.get_d(), clip.y1.get_d()}, static_cast<std::uint32_t>(slot_[g]));
  }

  /// The pieces of ring k of region g (0: the outside of the region, k >= 1: hole k - 1), once.
  void addRing(std::size_t g, std::size_t k) {
    addRegion(g);
    if (added_[g].at(k)) return;
    added_[g][k] = 1;
    const Region& reg = w_.regions[g];
    const Clip& region = regions_[static_cast<std::size_t>(slot_[g])];
    if (region.empty) return;
    const BoxD rb = k == 0 ? ringBox(reg.outer) : ringBox(reg.holes[k - 1]);
    std::vector<CPolygonWithHoles> offsets;
    ringOffsets(reg, k, frame_, radius_, eps_, offsets, &near_, reach_);
    std::vector<CPolygonWithHoles> kept;
    BoxD all{};
    for (CPolygonWithHoles& o : offsets) {
      const BoxD ob = polygonBox(o);
      if (k > 0 && !inside(ob, rb, reach_)) throw std::logic_error("CSpace::localSweeps: an obstacle's offset reaches beyond 2r");
      if (!overlaps(ob, near_, reach_)) continue;
      all = kept.empty() ? ob : BoxD{std::min(all.xmin, ob.xmin), std::min(all.ymin, ob.ymin), std::max(all.xmax, ob.xmax), std::max(all.ymax, ob.ymax)};
      kept.push_back(std::move(o));
    }
    if (kept.empty()) return;
    const SweepBox& clip = region.clip;
    const SweepBox start{std::max(clip.x0, Rational(exactFromDouble(all.xmin - pad_))), std::max(clip.y0, Rational(exactFromDouble(all.ymin - pad_))),
                         std::min(clip.x1, Rational(exactFromDouble(all.xmax + pad_))), std::min(clip.y1, Rational(exactFromDouble(all.ymax + pad_)))};
    if (!(start.x0 < start.x1 && start.y0 < start.y1)) return;
    // a large ring comes as the offsets of its triangles, which overlap (long thin ones fan out
    // to the frame's corners): joined first, as the whole C-space joins them, then cut
    PolygonSet ring;
    if (kept.size() == 1) {
      ring = PolygonSet(kept.front());
    } else {
      constexpr unsigned kJoinFanIn = 64;
      ring.join(kept.begin(), kept.end(), kJoinFanIn);
    }
    cut(std::move(ring), start, static_cast<std::size_t>(slot_[g]));
  }

  /// U ∩ C-free for the box of a request inside `near`, as polygons.
  std::vector<CPolygonWithHoles> freeIn(const SweepBox& box) const {
    const BoxD b{box.x0.get_d(), box.y0.get_d(), box.x1.get_d(), box.y1.get_d()};
    std::vector<std::uint32_t> regs = lookUp(b, regionAt_), ids = lookUp(b, pieceAt_);
    std::vector<CPolygonWithHoles> out;
    for (std::uint32_t g : regs) {
      const SweepBox& c = regions_[g].clip;
      const SweepBox part{std::max(box.x0, c.x0), std::max(box.y0, c.y0), std::min(box.x1, c.x1), std::min(box.y1, c.y1)};
      if (!(part.x0 < part.x1 && part.y0 < part.y1)) continue;
      std::vector<const CPolygonWithHoles*> near;
      for (std::uint32_t i : ids)
        if (pieces_[i].region == g && overlaps(pieces_[i].box, b, pad_)) near.push_back(&pieces_[i].poly);
      PolygonSet Q(boxPolygon(part));
      if (near.size() == 1) {
        Q.difference(*near.front());
      } else if (!near.empty()) {
        PolygonSet blocked;
        std::vector<CPolygonWithHoles> ps;
        ps.reserve(near.size());
        for (const CPolygonWithHoles* p : near) ps.push_back(*p);
        blocked.join(ps.begin(), ps.end());
        Q.difference(blocked);
      }
      Q.polygons_with_holes(std::back_inserter(out));
    }
    return out;
  }

private:
  struct Piece {
    CPolygonWithHoles poly;
    BoxD box;
    std::size_t region;
  };
  struct Clip {
    SweepBox clip;
    bool empty;   ///< the region's box is beyond reach of `near`
  };

  static BoxD ringBox(const Ring& ring) {
    BoxD b{ring.front().x.get_d(), ring.front().y.get_d(), ring.front().x.get_d(), ring.front().y.get_d()};
    for (const Point& p : ring) {
      const double x = p.x.get_d(), y = p.y.get_d();
      b = {std::min(b.xmin, x), std::min(b.ymin, y), std::max(b.xmax, x), std::max(b.ymax, y)};
    }
    return b;
  }
  static BoxD polygonBox(const CPolygonWithHoles& p) {
    CGAL::Bbox_2 b;
    for (auto it = p.outer_boundary().curves_begin(); it != p.outer_boundary().curves_end(); ++it) b += it->bbox();
    return {b.xmin(), b.ymin(), b.xmax(), b.ymax()};
  }
  static bool overlaps(const BoxD& a, const BoxD& b, double pad) {
    return a.xmin <= b.xmax + pad && b.xmin <= a.xmax + pad && a.ymin <= b.ymax + pad && b.ymin <= a.ymax + pad;
  }
  static bool inside(const BoxD& a, const BoxD& b, double pad) {
    return a.xmin >= b.xmin - pad && a.xmax <= b.xmax + pad && a.ymin >= b.ymin - pad && a.ymax <= b.ymax + pad;
  }

  /// Pieces with many curves or a box wider than a few cells are cut in halves (exact clips)
  /// until they are small or their box is one cell; empty parts are dropped. The thresholds were
  /// measured on Smooth-STC's clustered grid maps (BM_SmoothStcVsStc, 10^3 and 10^4 mega-cells):
  /// 128 curves and 4 cells took 77 and 803 ms, 32 and 2 took 102 and 1,060 ms, 16 and 2 100 and
  /// 1,055 ms, 64 and 8 90 and 873 ms, 256 and 4 76 and 928 ms.
  void cut(PolygonSet&& set, const SweepBox& box, std::size_t region) {
    constexpr std::size_t kCurves = 128;
    constexpr double kSpan = 4;
    if (set.is_empty()) return;
    const double w = Rational(box.x1 - box.x0).get_d(), h = Rational(box.y1 - box.y0).get_d();
    std::vector<CPolygonWithHoles> pw;
    if ((set.arrangement().number_of_edges() <= kCurves && std::max(w, h) <= kSpan * cell_) || std::max(w, h) <= cell_) {
      set.polygons_with_holes(std::back_inserter(pw));
      for (CPolygonWithHoles& p : pw) {
        const BoxD b = polygonBox(p);
        pieces_.push_back({std::move(p), b, region});
        addTo(pieceAt_, b, static_cast<std::uint32_t>(pieces_.size() - 1));
      }
      return;
    }
    const bool alongX = w >= h;
    const Rational mid = alongX ? Rational((box.x0 + box.x1) / 2) : Rational((box.y0 + box.y1) / 2);
    const SweepBox halves[2] = {alongX ? SweepBox{box.x0, box.y0, mid, box.y1} : SweepBox{box.x0, box.y0, box.x1, mid},
                                alongX ? SweepBox{mid, box.y0, box.x1, box.y1} : SweepBox{box.x0, mid, box.x1, box.y1}};
    for (const SweepBox& half : halves) {
      PolygonSet part(boxPolygon(half));
      part.intersection(set);
      cut(std::move(part), half, region);
    }
  }

  long bucket(double v, double origin, long n) const {
    return std::min(n - 1, std::max(0L, static_cast<long>(std::floor((v - origin) / cell_))));
  }
  void addTo(std::vector<std::vector<std::uint32_t>>& at, const BoxD& b, std::uint32_t id) const {
    const long bx0 = bucket(b.xmin - pad_, x0_, nx_), bx1 = bucket(b.xmax + pad_, x0_, nx_);
    const long by0 = bucket(b.ymin - pad_, y0_, ny_), by1 = bucket(b.ymax + pad_, y0_, ny_);
    for (long by = by0; by <= by1; ++by)
      for (long bx = bx0; bx <= bx1; ++bx) at[static_cast<std::size_t>(by * nx_ + bx)].push_back(id);
  }
  std::vector<std::uint32_t> lookUp(const BoxD& b, const std::vector<std::vector<std::uint32_t>>& at) const {
    std::vector<std::uint32_t> out;
    const long bx0 = bucket(b.xmin - pad_, x0_, nx_), bx1 = bucket(b.xmax + pad_, x0_, nx_);
    const long by0 = bucket(b.ymin - pad_, y0_, ny_), by1 = bucket(b.ymax + pad_, y0_, ny_);
    for (long by = by0; by <= by1; ++by)
      for (long bx = bx0; bx <= bx1; ++bx) {
        const auto& ids = at[static_cast<std::size_t>(by * nx_ + bx)];
        out.insert(out.end(), ids.begin(), ids.end());
      }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  const Workspace& w_;
  Rational radius_;
  double eps_;
  BoxD near_;
  double cell_, reach_ = 0, pad_ = 0, x0_ = 0, y0_ = 0;
  long nx_ = 1, ny_ = 1;
  Ring frame_;
  std::vector<int> slot_;                              ///< region → its entry in regions_, or -1
  std::vector<std::vector<std::uint8_t>> added_;       ///< region, ring → its pieces are in
  std::vector<Clip> regions_;
  std::vector<Piece> pieces_;
  std::vector<std::vector<std::uint32_t>> pieceAt_, regionAt_;   ///< bucket → pieces, regions
};

/// The box of a sweep request, or std::invalid_argument (naming `who`) for a base that is not
/// axis-parallel, is empty, or has no depth.
void checkRequest(const CSpace::SweepRequest& q, const char* who) {
  if (q.depth <= 0 || (q.a.x != q.d.x && q.a.y != q.d.y) || q.a == q.d)
    throw std::invalid_argument(std::string(who) + ": the base must be axis-parallel, non-empty, with depth > 0");
}
SweepBox checkedBox(const CSpace::SweepRequest& q, const char* who) {
  checkRequest(q, who);
  return boxOf(q);
}

/// What the sweeps without a CSpace need of their input (the CSpace constructor checks the same);
/// the rings (checkWorkspace, which CGAL's preconditions need) only with `rings`.
void checkSweepInput(const Workspace& w, const Rational& radius, bool rings = true) {
  if (radius <= 0) throw InputError(w.name, "radius", "robot radius must be > 0 for sweeps");
  if (w.regions.empty()) throw InputError(w.name, "workspace", "empty free space");
  if (rings) checkWorkspace(w);  // CGAL's preconditions are not input validation
}

}  // namespace

std::vector<CSpace::Sweep> CSpace::sweeps(const std::vector<SweepRequest>& requests) const {
  std::vector<Sweep> out(requests.size());
  if (requests.empty()) return out;
  std::vector<SweepBox> boxes;
  for (const SweepRequest& q : requests) boxes.push_back(checkedBox(q, "CSpace::sweeps"));
  if (!impl_->sweepSet) {
    impl_->sweepSet = std::make_unique<PolygonSet>();
    impl_->sweepSet->insert(impl_->parts.begin(), impl_->parts.end());
  }
  const PolygonSet& S = *impl_->sweepSet;
  std::vector<std::size_t> group(requests.size());
  for (std::size_t i = 0; i < group.size(); ++i) group[i] = i;
  sweepGroup(S, requests, boxes, group, out);
  return out;
}

std::vector<CSpace::Sweep> CSpace::localSweeps(const Workspace& w, const Rational& radius, const std::vector<SweepRequest>& requests,
                                               double relativeEps, unsigned threads, bool trace) {
  std::vector<Sweep> out(requests.size());
  if (requests.empty()) return out;
  checkSweepInput(w, radius, false);  // the rings below, once a request needs the exact way
  // each box's longer side and the sum of its x ends (the double of the exact values, as boxOf's
  // box gives them), without making the boxes: the trace needs none, the exact way makes its own
  std::vector<double> sides, centre;
  sides.reserve(requests.size());
  centre.reserve(requests.size());
  for (const SweepRequest& q : requests) {
    checkRequest(q, "CSpace::localSweeps");
    if (q.a.y == q.d.y) {   // horizontal: x from a to d, depth along y
      sides.push_back(std::max(Rational(abs(q.d.x - q.a.x)), q.depth).get_d());
      centre.push_back(Rational(q.a.x + q.d.x).get_d());
    } else {                // vertical: depth along x, to the right of a → d
      sides.push_back(std::max(Rational(abs(q.d.y - q.a.y)), q.depth).get_d());
      centre.push_back(Rational(2 * q.a.x + (q.d.y > q.a.y ? q.depth : Rational(-q.depth))).get_d());
    }
  }
  // buckets about as large as the usual request (a mega-cell for Smooth-STC)
  std::nth_element(sides.begin(), sides.begin() + static_cast<std::ptrdiff_t>(sides.size() / 2), sides.end());
  const double cell = sides[sides.size() / 2];
  const double eps = epsilonOf(w, relativeEps);
  // Requests in strips along x, one strip per thread. The direct trace first (its edges shared
  // read-only by the strips); the requests it leaves get the exact Boolean operations, each strip
  // building its own obstacles from its own exact numbers (threads share none). Both ways give
  // each request's sweep whatever the strips.
  std::vector<std::size_t> order(requests.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return centre[i] < centre[j]; });
  if (trace) {
    detail::AxisEdges edges(w, cell);
    edges.addAll();
    const double rd = toDouble(radius);
    const std::size_t strips = std::min<std::size_t>(detail::threadCount(threads), order.size());
    detail::parallelFor(strips, threads, [&](std::size_t k) {
      for (std::size_t j = order.size() * k / strips; j < order.size() * (k + 1) / strips; ++j)
        out[order[j]].traced = detail::axisSweep(edges, rd, requests[order[j]], out[order[j]]);
    });
    order.erase(std::remove_if(order.begin(), order.end(), [&](std::size_t i) { return out[i].traced; }), order.end());
    if (order.empty()) return out;
  }
  checkWorkspace(w);
  std::vector<SweepBox> boxes;   // boxes[j]: request order[j]'s
  boxes.reserve(order.size());
  for (std::size_t i : order) boxes.push_back(boxOf(requests[i]));
  const std::size_t strips = std::min<std::size_t>(detail::threadCount(threads), order.size());
  detail::parallelFor(strips, threads, [&](std::size_t k) {
    const std::size_t from = order.size() * k / strips, to = order.size() * (k + 1) / strips;
    BoxD near{boxes[from].x0.get_d(), boxes[from].y0.get_d(), boxes[from].x1.get_d(), boxes[from].y1.get_d()};
    for (std::size_t j = from; j < to; ++j) {
      const SweepBox& b = boxes[j];
      near = {std::min(near.xmin, b.x0.get_d()), std::min(near.ymin, b.y0.get_d()), std::max(near.xmax, b.x1.get_d()),
              std::max(near.ymax, b.y1.get_d())};
    }
    LocalObstacles obstacles(w, radius, eps, near, cell);
    obstacles.addAllNear();
    for (std::size_t j = from; j < to; ++j) out[order[j]] = sweepOf(obstacles.freeIn(boxes[j]), requests[order[j]]);
  });
  return out;
}

struct OnlineSweeper::Impl {
  Impl(const Workspace& w, const Rational& radius, double cell, double relativeEps, bool trace)
      : workspace(w), radius(radius), cell(cell), eps(epsilonOf(w, relativeEps)), rd(toDouble(radius)) {
    if (trace) edges.emplace(w, cell);
  }
  static BoxD boxOfWorkspace(const Workspace& w) {
    const Box b = w.bbox();
    return {b.xmin.get_d(), b.ymin.get_d(), b.xmax.get_d(), b.ymax.get_d()};
  }
  /// The exact pieces of the rings added so far, made when a request first needs them.
  LocalObstacles& exact() {
    if (!obstacles) {
      if (edges) checkWorkspace(workspace);   // CGAL's preconditions (the constructor checked them untraced)
      obstacles.emplace(workspace, radius, eps, boxOfWorkspace(workspace), cell);
      for (std::size_t g : regions) obstacles->addRegion(g);
      for (const auto& [g, k] : rings) obstacles->addRing(g, k);
    }
    return *obstacles;
  }
  const Workspace& workspace;   ///< the rings' source (the caller's); only those added are read
  Rational radius;
  double cell, eps, rd;
  std::vector<std::size_t> regions;                    ///< added, in order
  std::vector<std::pair<std::size_t, std::size_t>> rings;
  std::optional<LocalObstacles> obstacles;
  std::optional<detail::AxisEdges> edges;   ///< the added rings' edges for the direct trace
};

OnlineSweeper::OnlineSweeper(const Workspace& w, const Rational& radius, double cell, double relativeEps, bool trace) {
  if (!(cell > 0)) throw std::invalid_argument("OnlineSweeper: the bucket size must be > 0");
  checkSweepInput(w, radius, !trace);   // traced, the rings are checked once a request needs the exact way
  impl_ = std::make_unique<Impl>(w, radius, cell, relativeEps, trace);
}
OnlineSweeper::~OnlineSweeper() = default;

void OnlineSweeper::addRegion(std::size_t region) {
  if (region >= impl_->workspace.regions.size()) throw std::invalid_argument("OnlineSweeper::addRegion: no such region");
  impl_->regions.push_back(region);
  if (impl_->obstacles) impl_->obstacles->addRegion(region);
}

void OnlineSweeper::addRing(std::size_t region, std::size_t ring) {
  if (region >= impl_->workspace.regions.size() || ring > impl_->workspace.regions[region].holes.size())
    throw std::invalid_argument("OnlineSweeper::addRing: no such ring");
  impl_->rings.emplace_back(region, ring);
  if (impl_->obstacles) impl_->obstacles->addRing(region, ring);
  if (impl_->edges) impl_->edges->addRing(region, ring);
}

CSpace::Sweep OnlineSweeper::sweep(const CSpace::SweepRequest& q) const {
  checkRequest(q, "OnlineSweeper::sweep");
  CSpace::Sweep s;
  if (impl_->edges && detail::axisSweep(*impl_->edges, impl_->rd, q, s)) {
    s.traced = true;
    return s;
  }
  return sweepOf(impl_->exact().freeIn(boxOf(q)), q);
}

}  // namespace coverkit
