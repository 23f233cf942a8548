// Exact validation of polygon input, before any geometry (CGAL's preconditions are assertions,
// not input validation).
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/types.h>

#include "edge_index.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace coverkit {

namespace {

/// A vertex with its coordinates rounded to doubles once (mpq_get_d divides: costly in a hot loop).
struct V {
  const Point* p;
  double x, y;
};
V vd(const Point& p) { return {&p, p.x.get_d(), p.y.get_d()}; }

/// Sign of the orientation of (a, b, c). A static double filter first: the coordinates rounded to
/// doubles are each within 2^-52 |x| ≤ δM of the exact ones (M the largest magnitude), so the
/// computed determinant is within about 40 δ M² of the exact one (differences, products, one more
/// subtraction); a value beyond 64 δ M² has the exact sign. Otherwise, and for non-finite doubles,
/// the exact rational determinant decides.
int orient(const V& a, const V& b, const V& c) {
  if (c.p == a.p || c.p == b.p || a.p == b.p) return 0;  // a shared vertex of two edges
  const double det = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  const double M = std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y), std::abs(c.x), std::abs(c.y)});
  const double bound = 64 * 0x1p-52 * M * M;
  if (std::isfinite(bound) && std::abs(det) > bound) return det > 0 ? 1 : -1;
  const Point &pa = *a.p, &pb = *b.p, &pc = *c.p;
  const Rational v = (pb.x - pa.x) * (pc.y - pa.y) - (pb.y - pa.y) * (pc.x - pa.x);
  return sgn(v);
}
bool onSegment(const Point& a, const Point& b, const Point& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}
/// 0: disjoint, 1: touch only at a shared endpoint, 2: any other contact.
int contact(const V& va, const V& vb, const V& vc, const V& vd) {
  const int o1 = orient(va, vb, vc), o2 = orient(va, vb, vd), o3 = orient(vc, vd, va), o4 = orient(vc, vd, vb);
  const Point &a = *va.p, &b = *vb.p, &c = *vc.p, &d = *vd.p;
  bool meet = false;
  if (o1 * o2 < 0 && o3 * o4 < 0) return 2;
  if (o1 == 0 && onSegment(a, b, c)) meet = true;
  if (o2 == 0 && onSegment(a, b, d)) meet = true;
  if (o3 == 0 && onSegment(c, d, a)) meet = true;
  if (o4 == 0 && onSegment(c, d, b)) meet = true;
  if (!meet) return 0;
  // collinear overlap or a vertex on the other's interior is more than an endpoint touch
  const bool shared = a == c || a == d || b == c || b == d;
  if (!shared) return 2;
  if (o1 == 0 && o2 == 0) {  // collinear: overlapping beyond the shared point?
    const Point& s = (a == c || a == d) ? a : b;
    const Point& e1 = (s == a) ? b : a;
    const Point& e2 = (s == c) ? d : c;
    // same direction from s means overlap
    if (sgn(Rational((e1.x - s.x) * (e2.x - s.x) + (e1.y - s.y) * (e2.y - s.y))) > 0) return 2;
  }
  // one segment's far end on the other segment's interior
  if (o1 == 0 && !(c == a || c == b) && onSegment(a, b, c)) return 2;
  if (o2 == 0 && !(d == a || d == b) && onSegment(a, b, d)) return 2;
  if (o3 == 0 && !(a == c || a == d) && onSegment(c, d, a)) return 2;
  if (o4 == 0 && !(b == c || b == d) && onSegment(c, d, b)) return 2;
  return 1;
}

std::string where(std::size_t region, int hole, std::size_t vertex) {
  std::ostringstream os;
  os << "polygon " << region + 1 << (hole < 0 ? std::string(" outer ring") : " hole " + std::to_string(hole + 1))
     << " vertex " << vertex + 1;
  return os.str();
}


}  // namespace

/// Workspace coordinates are bounded so that a path's doubles resolve the map: at 1e15 a double's
/// spacing is 0.125 map units. Beyond, planning is meaningless and pictures, exports and the double
/// filters would overflow; the readers refuse such maps (a WKT with 1e400, a GeoJSON with 1e300).
static const Rational kMaxCoordinate("1000000000000000");

void checkWorkspace(const Workspace& w) {
  if (w.regions.empty()) throw InputError(w.name, "workspace", "no polygon: the free space is empty");
  struct E {
    V a, b;
    std::size_t region;
    int hole;
    std::size_t idx;
    double x0, y0, x1, y1;
  };
  std::vector<E> edges;
  for (std::size_t ri = 0; ri < w.regions.size(); ++ri) {
    const Region& reg = w.regions[ri];
    for (int h = -1; h < static_cast<int>(reg.holes.size()); ++h) {
      const Ring& ring = h < 0 ? reg.outer : reg.holes[static_cast<std::size_t>(h)];
      if (ring.size() < 3) throw InputError(w.name, where(ri, h, 0), "ring has fewer than 3 distinct vertices");
      for (std::size_t i = 0; i < ring.size(); ++i)
        if (abs(ring[i].x) > kMaxCoordinate || abs(ring[i].y) > kMaxCoordinate)
          throw InputError(w.name, where(ri, h, i), "coordinate beyond ±1e15 (paths are written in doubles, which "
                                                    "cannot hold positions at the map's scale out there)");
      for (std::size_t i = 0; i < ring.size(); ++i)
        if (ring[i] == ring[(i + 1) % ring.size()])
          throw InputError(w.name, where(ri, h, i), "repeated vertex");
      bool collinear = true;
      for (std::size_t i = 2; i < ring.size() && collinear; ++i) collinear = orient(vd(ring[0]), vd(ring[1]), vd(ring[i])) == 0;
      if (collinear) throw InputError(w.name, where(ri, h, 0), "ring has zero area (all vertices on one line)");
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const V a = vd(ring[i]), b = vd(ring[(i + 1) % ring.size()]);
        edges.push_back({a, b, ri, h, i, std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)});
      }
    }
  }
  // Sweep over x with sorted edges: candidate pairs whose x-ranges overlap, then exact tests.
  std::vector<std::size_t> order(edges.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return edges[i].x0 < edges[j].x0; });
  const double eps = 1e-9;
  std::vector<std::size_t> active;
  for (std::size_t oi = 0; oi < order.size(); ++oi) {
    const E& e = edges[order[oi]];
    active.erase(std::remove_if(active.begin(), active.end(), [&](std::size_t k) { return edges[k].x1 < e.x0 - eps * (1 + std::abs(e.x0)); }),
                 active.end());
    for (std::size_t k : active) {
      const E& f = edges[k];
      if (f.y1 < e.y0 - eps * (1 + std::abs(e.y0)) || e.y1 < f.y0 - eps * (1 + std::abs(f.y0))) continue;
      const int c = contact(e.a, e.b, f.a, f.b);
      if (c == 0) continue;
      const bool sameRing = e.region == f.region && e.hole == f.hole;
      if (c == 1) {
        if (sameRing) {
          // adjacent edges share a vertex; other edges of one ring may not touch
          const std::size_t n = e.hole < 0 ? w.regions[e.region].outer.size() : w.regions[e.region].holes[static_cast<std::size_t>(e.hole)].size();
          const bool adjacent = (e.idx + 1) % n == f.idx || (f.idx + 1) % n == e.idx;
          if (adjacent) continue;
        } else {
          continue;  // rings of a polygon may touch at a vertex
        }
      }
      throw InputError(w.name, where(e.region, e.hole, e.idx),
                       sameRing ? "self-intersecting ring (edge " + std::to_string(e.idx + 1) + " meets edge " + std::to_string(f.idx + 1) + ")"
                                : "rings intersect (" + where(f.region, f.hole, f.idx) + ")");
    }
    active.push_back(order[oi]);
  }
  // Holes inside their outer ring, not inside another hole; polygons not inside each other. Rings
  // do not cross (checked above), so one point per ring decides; double bounding boxes (with a
  // margin) skip the rings that cannot contain it.
  struct RingBox {
    double x0, y0, x1, y1;
    bool may(const PointD& p) const {  // p rounded to doubles once by the caller (a division each)
      const double e = 1e-9 * (1 + std::abs(p.x) + std::abs(p.y));
      return p.x >= x0 - e && p.x <= x1 + e && p.y >= y0 - e && p.y <= y1 + e;
    }
  };
  auto boxOf = [](const Ring& r) {
    RingBox b{1e300, 1e300, -1e300, -1e300};
    for (const Point& p : r) {
      const double x = p.x.get_d(), y = p.y.get_d();
      b = {std::min(b.x0, x), std::min(b.y0, y), std::max(b.x1, x), std::max(b.y1, y)};
    }
    return b;
  };
  // The parity test of a point against an outer ring reads only the ring's edges that the bucket
  // grid lists on the ray to its right (edge_index.h): every hole of a scan is tested against its
  // outer ring, which may have tens of thousands of edges.
  detail::EdgeIndex index(w);
  std::vector<std::size_t> crossing;
  auto insideOuter = [&](std::size_t ri, const Point& p, const PointD& pd, double xmax) {
    const Ring& ring = w.regions[ri].outer;
    const Point* first = ring.data();
    const double e = 1e-9 * (1 + std::abs(pd.x) + std::abs(pd.y));
    crossing.clear();
    index.query(pd.x - e, pd.y - e, xmax + e, pd.y + e, [&](const detail::IndexedEdge& s) {
      if (s.a >= first && s.a < first + ring.size()) crossing.push_back(static_cast<std::size_t>(s.a - first));
    });
    return insideRing(ring, p, crossing);
  };
  std::vector<RingBox> outerBox;
  std::vector<std::vector<RingBox>> holeBoxes(w.regions.size());
  for (std::size_t ri = 0; ri < w.regions.size(); ++ri) {
    outerBox.push_back(boxOf(w.regions[ri].outer));
    for (const Ring& h : w.regions[ri].holes) holeBoxes[ri].push_back(boxOf(h));
  }
  for (std::size_t ri = 0; ri < w.regions.size(); ++ri) {
    const Region& reg = w.regions[ri];
    const std::vector<RingBox>& holeBox = holeBoxes[ri];
    for (std::size_t h = 0; h < reg.holes.size(); ++h) {
      // the midpoint of an edge is on no other ring (rings meet only at vertices)
      const Point m{Rational((reg.holes[h][0].x + reg.holes[h][1].x) / 2), Rational((reg.holes[h][0].y + reg.holes[h][1].y) / 2)};
      const PointD md{m.x.get_d(), m.y.get_d()};
      if (!outerBox[ri].may(md) || !insideOuter(ri, m, md, outerBox[ri].x1))
        throw InputError(w.name, where(ri, static_cast<int>(h), 0), "hole is outside its outer ring");
      for (std::size_t h2 = 0; h2 < reg.holes.size(); ++h2)
        if (h2 != h && holeBox[h2].may(md) && insideRing(reg.holes[h2], m))
          throw InputError(w.name, where(ri, static_cast<int>(h), 0), "hole lies inside hole " + std::to_string(h2 + 1));
    }
    const Point m{Rational((reg.outer[0].x + reg.outer[1].x) / 2), Rational((reg.outer[0].y + reg.outer[1].y) / 2)};
    const PointD md{m.x.get_d(), m.y.get_d()};
    for (std::size_t rj = 0; rj < w.regions.size(); ++rj) {
      if (rj == ri || !outerBox[rj].may(md) || !insideOuter(rj, m, md, outerBox[rj].x1)) continue;
      bool inHole = false;
      for (std::size_t h = 0; h < w.regions[rj].holes.size() && !inHole; ++h)
        inHole = holeBoxes[rj][h].may(md) && insideRing(w.regions[rj].holes[h], m);
      if (!inHole) throw InputError(w.name, where(ri, -1, 0), "polygon overlaps polygon " + std::to_string(rj + 1));
    }
  }
}

}  // namespace coverkit
