// The direct trace of a sweep among axis-parallel edges (axis_sweep.h). No CGAL.
//
// C-free near U is {p : the distance from p to every obstacle edge ≥ r}: its boundary lies on the
// edges' offset segments (each edge moved r towards the free side) and on the quarter circles of
// radius r about the obstacles' convex corners (half circles at the tip of a zero-width spike);
// at a reflex corner the two offset segments cross. The trace:
//  1. candidates: those offsets and arcs that come near U, and U's four sides (counter-clockwise);
//  2. each candidate is cut where it crosses the boundary of another edge's capsule (the points
//     within r of that edge: a rectangle and two discs) and, for offsets and arcs, U's sides; a
//     part is kept where its midpoint is at distance ≥ r from every other edge (and inside U);
//  3. the kept parts, oriented with C-free on their left (offsets along their edge, arcs
//     clockwise, U's sides counter-clockwise), are linked end to start: the contour of U ∩ C-free;
//  4. from the entry (the free point of the base nearest a) the contour is followed back to the
//     base, as CSpace::sweeps does with its exact polygons.
// A midpoint within `tol` of distance r, a part along U's side, a link with no or two successors,
// a loop that never comes back: the trace gives up (false), never guesses.
#include "axis_sweep.h"

#include <coverkit/geometry/rational.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace coverkit::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kAll = std::numeric_limits<double>::infinity();

/// Distance from p to the axis-parallel segment ab (compared with margins only: sqrt, not hypot).
double distToAxisEdge(double px, double py, const AxisEdges::Edge& e) {
  const double x = std::min(std::max(px, std::min(e.ax, e.bx)), std::max(e.ax, e.bx));
  const double y = std::min(std::max(py, std::min(e.ay, e.by)), std::max(e.ay, e.by));
  return std::sqrt((px - x) * (px - x) + (py - y) * (py - y));
}

/// Distance from p to segment ab, any direction.
double distToEdge(double px, double py, const AxisEdges::Edge& e) {
  const double ex = e.bx - e.ax, ey = e.by - e.ay, l2 = ex * ex + ey * ey;
  double t = l2 > 0 ? ((px - e.ax) * ex + (py - e.ay) * ey) / l2 : 0;
  t = std::min(1.0, std::max(0.0, t));
  const double dx = px - e.ax - t * ex, dy = py - e.ay - t * ey;
  return std::sqrt(dx * dx + dy * dy);
}

int sgn(double v) { return (v > 0) - (v < 0); }

/// A piece of C-free's boundary or of U's: a segment a → b, or an arc about c from angle th0,
/// clockwise through `sweep`.
struct Cand {
  bool arc = false;
  double ax = 0, ay = 0, bx = 0, by = 0;  // ends (exact offsets for arcs too)
  double cx = 0, cy = 0, th0 = 0, sweep = 0;
  std::uint32_t g1 = 0, g2 = 0;  // the edges it belongs to (not blockers of it)
  int side = -1;                 // U's side (0 bottom, 1 right, 2 top, 3 left), -1 an offset or arc
  double length(double r) const { return arc ? r * sweep : std::hypot(bx - ax, by - ay); }
};

struct Piece {
  std::size_t cand;
  double t0, t1;
  PointD from, to;
};

}  // namespace

AxisEdges::AxisEdges(const Workspace& w, double cell) : w_(w) {
  const Box b = w.bbox();
  const double xmin = toDouble(b.xmin), ymin = toDouble(b.ymin), xmax = toDouble(b.xmax), ymax = toDouble(b.ymax);
  extent_ = std::max({xmax - xmin, ymax - ymin, 1e-300});
  scale_ = std::max({1.0, std::abs(xmin), std::abs(xmax), std::abs(ymin), std::abs(ymax)});
  x0_ = xmin;
  y0_ = ymin;
  constexpr double kMaxBuckets = 4.0 * 1024 * 1024;
  const double spanX = std::max(xmax - xmin, 1e-300), spanY = std::max(ymax - ymin, 1e-300);
  cell_ = std::max({cell > 0 ? cell : extent_, std::sqrt(2 * spanX * spanY / kMaxBuckets), 2 * std::max(spanX, spanY) / kMaxBuckets});
  nx_ = static_cast<long>(spanX / cell_) + 1;
  ny_ = static_cast<long>(spanY / cell_) + 1;
  buckets_.resize(static_cast<std::size_t>(nx_ * ny_));
  for (const Region& r : w.regions) added_.emplace_back(r.holes.size() + 1, 0);
}

void AxisEdges::addAll() {
  for (std::size_t g = 0; g < w_.regions.size(); ++g)
    for (std::size_t k = 0; k <= w_.regions[g].holes.size(); ++k) addRing(g, k);
}

void AxisEdges::addRing(std::size_t g, std::size_t k) {
  if (added_.at(g).at(k)) return;
  added_[g][k] = 1;
  const Ring& ring = k == 0 ? w_.regions[g].outer : w_.regions[g].holes[k - 1];
  std::vector<const Point*> v;
  for (const Point& p : ring)
    if (v.empty() || !(*v.back() == p)) v.push_back(&p);
  while (v.size() > 1 && *v.front() == *v.back()) v.pop_back();
  const std::size_t n = v.size();
  if (n < 2) return;
  Rational area2(0);
  for (std::size_t i = 0; i < n; ++i) area2 += v[i]->x * v[(i + 1) % n]->y - v[(i + 1) % n]->x * v[i]->y;
  // the obstacle on the right: outside an outer ring, inside a hole
  const bool keep = k == 0 ? area2 > 0 : area2 < 0;
  if (!keep) std::reverse(v.begin(), v.end());
  const auto base = static_cast<std::uint32_t>(edges_.size());
  // the obstacle's corner at v[j] is convex: the ring turns right there, or back
  std::vector<std::uint8_t> convex(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Point &a = *v[(j + n - 1) % n], &b = *v[j], &c = *v[(j + 1) % n];
    const Rational ux = b.x - a.x, uy = b.y - a.y, wx = c.x - b.x, wy = c.y - b.y;
    const Rational cr = ux * wy - uy * wx;
    convex[j] = cr < 0 || (cr == 0 && Rational(ux * wx + uy * wy) < 0);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Point &a = *v[i], &b = *v[(i + 1) % n];
    Edge e{toDouble(a.x), toDouble(a.y), toDouble(b.x), toDouble(b.y), a.x == b.x || a.y == b.y, convex[(i + 1) % n] != 0,
           convex[i] != 0, base + static_cast<std::uint32_t>(i), base + static_cast<std::uint32_t>((i + 1) % n)};
    edges_.push_back(e);
    const long i0 = std::max(0L, static_cast<long>((std::min(e.ax, e.bx) - x0_) / cell_)),
               i1 = std::min(nx_ - 1, static_cast<long>((std::max(e.ax, e.bx) - x0_) / cell_)),
               j0 = std::max(0L, static_cast<long>((std::min(e.ay, e.by) - y0_) / cell_)),
               j1 = std::min(ny_ - 1, static_cast<long>((std::max(e.ay, e.by) - y0_) / cell_));
    for (long j = j0; j <= j1; ++j)
      for (long i2 = i0; i2 <= i1; ++i2) buckets_[static_cast<std::size_t>(j * nx_ + i2)].push_back(e.id);
  }
}

void AxisEdges::query(const BoxD& b, std::vector<const Edge*>& out) const {
  out.clear();
  const long i0 = std::max(0L, static_cast<long>(std::floor((b.xmin - x0_) / cell_))),
             i1 = std::min(nx_ - 1, static_cast<long>(std::floor((b.xmax - x0_) / cell_))),
             j0 = std::max(0L, static_cast<long>(std::floor((b.ymin - y0_) / cell_))),
             j1 = std::min(ny_ - 1, static_cast<long>(std::floor((b.ymax - y0_) / cell_)));
  std::vector<std::uint32_t> ids;
  for (long j = j0; j <= j1; ++j)
    for (long i = i0; i <= i1; ++i)
      for (std::uint32_t id : buckets_[static_cast<std::size_t>(j * nx_ + i)]) {
        const Edge& e = edges_[id];
        if (std::max(e.ax, e.bx) < b.xmin || std::min(e.ax, e.bx) > b.xmax || std::max(e.ay, e.by) < b.ymin ||
            std::min(e.ay, e.by) > b.ymax)
          continue;
        ids.push_back(id);
      }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  for (std::uint32_t id : ids) out.push_back(&edges_[id]);
}

int AxisEdges::inObstacle(double px, double py, double tol) const {
  // the side of p as seen from edge e at e's point nearest p
  auto status = [&](const Edge& e) {
    const double ex = e.bx - e.ax, ey = e.by - e.ay;
    const double t = ((px - e.ax) * ex + (py - e.ay) * ey) / (ex * ex + ey * ey);
    if (t <= 0) return e.convexAtA ? 0 : 1;
    if (t >= 1) return e.convexAtB ? 0 : 1;
    return ex * (py - e.ay) - ey * (px - e.ax) > 0 ? 0 : 1;  // left of a → b: the free side
  };
  std::vector<const Edge*> found;
  for (double rho = cell_;; rho *= 2) {
    query({px - rho, py - rho, px + rho, py + rho}, found);
    double bestD = std::numeric_limits<double>::infinity();
    for (const Edge* e : found) bestD = std::min(bestD, distToEdge(px, py, *e));
    if (bestD <= rho) {
      if (bestD <= tol) return -1;  // on the boundary
      // every edge as near as the nearest (within tol) must tell the same
      int s = -1;
      for (const Edge* e : found) {
        if (distToEdge(px, py, *e) > bestD + tol) continue;
        const int t = status(*e);
        if (s >= 0 && t != s) return -1;
        s = t;
      }
      return s;
    }
    if (rho > 4 * extent_ + 4 * cell_) return -1;
  }
}

bool axisSweep(const AxisEdges& E, double r, const CSpace::SweepRequest& q, CSpace::Sweep& out) {
  const double tol = 1e-9 * E.extent() + 1e-13 * E.scale();
  // U, as CSpace's boxOf: the base [a, d] and `depth` to the right of a → d
  const bool horizontal = q.a.y == q.d.y;
  const Rational dxq = q.d.x - q.a.x, dyq = q.d.y - q.a.y;
  Rational farX = q.a.x, farY = q.a.y;
  if (horizontal) farY += dxq > 0 ? Rational(-q.depth) : q.depth;
  else farX += dyq > 0 ? q.depth : Rational(-q.depth);
  const double ax = toDouble(q.a.x), ay = toDouble(q.a.y), dx = toDouble(q.d.x), dy = toDouble(q.d.y);
  const double fx = toDouble(farX), fy = toDouble(farY);
  const double x0 = std::min({ax, dx, fx}), x1 = std::max({ax, dx, fx}), y0 = std::min({ay, dy, fy}), y1 = std::max({ay, dy, fy});
  if (!(x0 < x1 && y0 < y1)) return false;
  const int baseSide = horizontal ? (ay == y0 ? 0 : 2) : (ax == x0 ? 3 : 1);
  const int farSide = (baseSide + 2) % 4;

  std::vector<const AxisEdges::Edge*> edges;
  const double reach = r + 4 * tol;
  E.query({x0 - reach, y0 - reach, x1 + reach, y1 + reach}, edges);
  if (edges.size() > 256) return false;
  for (const auto* e : edges)
    if (!e->axis) return false;

  // 1. candidates
  std::vector<Cand> cands;
  const double sx[4][4] = {{x0, y0, x1, y0}, {x1, y0, x1, y1}, {x1, y1, x0, y1}, {x0, y1, x0, y0}};
  for (int s = 0; s < 4; ++s) {
    Cand c;
    c.ax = sx[s][0], c.ay = sx[s][1], c.bx = sx[s][2], c.by = sx[s][3];
    c.side = s;
    cands.push_back(c);
  }
  auto nearU = [&](double bx0, double by0, double bx1, double by1) {
    return bx1 >= x0 - tol && bx0 <= x1 + tol && by1 >= y0 - tol && by0 <= y1 + tol;
  };
  for (const auto* e : edges) {
    const double ux = sgn(e->bx - e->ax), uy = sgn(e->by - e->ay), nx = -uy, ny = ux;  // left normal: the free side
    Cand s;
    s.ax = e->ax + r * nx, s.ay = e->ay + r * ny, s.bx = e->bx + r * nx, s.by = e->by + r * ny;
    s.g1 = s.g2 = e->id;
    if (nearU(std::min(s.ax, s.bx), std::min(s.ay, s.by), std::max(s.ax, s.bx), std::max(s.ay, s.by))) cands.push_back(s);
    if (e->convexAtB && nearU(e->bx - r, e->by - r, e->bx + r, e->by + r)) {
      Cand a;
      a.arc = true;
      a.cx = e->bx, a.cy = e->by;
      a.th0 = std::atan2(ny, nx);
      a.ax = s.bx, a.ay = s.by;  // its end and sweep below, from the next edge
      a.g1 = e->id, a.g2 = e->next;
      cands.push_back(a);
    }
  }
  // the arcs' sweeps and ends: the next edge's offset start
  for (Cand& a : cands) {
    if (!a.arc) continue;
    const AxisEdges::Edge* next = nullptr;
    for (const auto* e : edges)
      if (e->id == a.g2) next = e;
    if (!next) return false;  // the next edge starts at the corner, inside the window: never
    const double ux = sgn(next->bx - next->ax), uy = sgn(next->by - next->ay);
    a.bx = a.cx - r * uy, a.by = a.cy + r * ux;
    const double th1 = std::atan2(ux, -uy);
    double sw = a.th0 - th1;
    while (sw <= 0) sw += 2 * kPi;
    while (sw > 2 * kPi) sw -= 2 * kPi;
    a.sweep = sw;  // π/2 at a right turn, π at a reversal
  }

  auto pointAt = [&](const Cand& c, double t) -> PointD {
    if (t <= 0) return {c.ax, c.ay};
    if (t >= 1) return {c.bx, c.by};
    if (!c.arc) return {c.ax + t * (c.bx - c.ax), c.ay + t * (c.by - c.ay)};
    const double th = c.th0 - t * c.sweep;
    return {c.cx + r * std::cos(th), c.cy + r * std::sin(th)};
  };

  // 2. cut and classify. Two curves closer than about 4 tol to touching (1 - cos of the angle
  // at which they would cross below `touch`) are taken to touch, not to cross: a part ending there
  // is then at distance r from the other curve's edge only at its end.
  const double touch = 8 * (tol / r) * (tol / r) + 1e-15;
  std::vector<Piece> pieces;
  std::vector<double> ts;
  std::vector<const AxisEdges::Edge*> blockers;
  for (std::size_t ci = 0; ci < cands.size(); ++ci) {
    const Cand& c = cands[ci];
    const double len = c.length(r);
    if (!(len > tol)) continue;
    ts.assign({0.0, 1.0});
    auto addT = [&](double t) {
      if (t * len > tol && (1 - t) * len > tol) ts.push_back(t);
    };
    // Where the candidate crosses the line x = X (y = Y) at a point whose other coordinate lies in
    // [lo, hi] (a side of a capsule's rectangle, or of U, not its whole line: a crossing of the
    // line beyond the side would only add a cut, which could fall within tol of a true one)
    auto within = [&](double v, double lo, double hi) { return v >= lo - tol && v <= hi + tol; };
    auto crossX = [&](double X, double lo = -kAll, double hi = kAll) {
      if (!c.arc) {
        if (c.ax != c.bx && within(c.ay, lo, hi)) addT((X - c.ax) / (c.bx - c.ax));
        return;
      }
      const double v = (X - c.cx) / r;
      if (std::abs(v) >= 1 - touch) return;  // misses, or touches: no crossing
      for (double th : {std::acos(v), -std::acos(v)}) {
        if (!within(c.cy + r * std::sin(th), lo, hi)) continue;
        double u = c.th0 - th;
        while (u < 0) u += 2 * kPi;
        while (u >= 2 * kPi) u -= 2 * kPi;
        if (u < c.sweep) addT(u / c.sweep);
      }
    };
    auto crossY = [&](double Y, double lo = -kAll, double hi = kAll) {
      if (!c.arc) {
        if (c.ay != c.by && within(c.ax, lo, hi)) addT((Y - c.ay) / (c.by - c.ay));
        return;
      }
      const double v = (Y - c.cy) / r;
      if (std::abs(v) >= 1 - touch) return;
      for (double th : {std::asin(v), kPi - std::asin(v)}) {
        if (!within(c.cx + r * std::cos(th), lo, hi)) continue;
        double u = c.th0 - th;
        while (u < 0) u += 2 * kPi;
        while (u >= 2 * kPi) u -= 2 * kPi;
        if (u < c.sweep) addT(u / c.sweep);
      }
    };
    auto crossCircle = [&](double wx, double wy) {  // radius r about w
      if (!c.arc) {
        // a line that only touches the circle does not cross it
        if (c.ay == c.by) {
          const double h2 = r * r - (c.ay - wy) * (c.ay - wy);
          if (h2 > 2 * touch * r * r) crossX(wx - std::sqrt(h2)), crossX(wx + std::sqrt(h2));
        } else {
          const double h2 = r * r - (c.ax - wx) * (c.ax - wx);
          if (h2 > 2 * touch * r * r) crossY(wy - std::sqrt(h2)), crossY(wy + std::sqrt(h2));
        }
        return;
      }
      const double d = std::hypot(wx - c.cx, wy - c.cy);
      if (!(d > 0) || d >= 2 * r * (1 - touch)) return;
      const double phi = std::atan2(wy - c.cy, wx - c.cx), al = std::acos(d / (2 * r));
      for (double th : {phi - al, phi + al}) {
        double u = c.th0 - th;
        while (u < 0) u += 2 * kPi;
        while (u >= 2 * kPi) u -= 2 * kPi;
        if (u < c.sweep) addT(u / c.sweep);
      }
    };
    const double cx0 = c.arc ? c.cx - r : std::min(c.ax, c.bx), cx1 = c.arc ? c.cx + r : std::max(c.ax, c.bx);
    const double cy0 = c.arc ? c.cy - r : std::min(c.ay, c.by), cy1 = c.arc ? c.cy + r : std::max(c.ay, c.by);
    blockers.clear();
    for (const auto* e : edges) {
      if (c.side < 0 && (e->id == c.g1 || e->id == c.g2)) continue;
      const double ex0 = std::min(e->ax, e->bx) - r, ex1 = std::max(e->ax, e->bx) + r;
      const double ey0 = std::min(e->ay, e->by) - r, ey1 = std::max(e->ay, e->by) + r;
      if (ex1 < cx0 - tol || ex0 > cx1 + tol || ey1 < cy0 - tol || ey0 > cy1 + tol) continue;
      blockers.push_back(e);
      const double lx = std::min(e->ax, e->bx), hx = std::max(e->ax, e->bx), ly = std::min(e->ay, e->by), hy = std::max(e->ay, e->by);
      if (e->ay == e->by) {  // the rectangle [lx, hx] × [y − r, y + r]
        crossX(lx, e->ay - r, e->ay + r), crossX(hx, e->ay - r, e->ay + r), crossY(e->ay - r, lx, hx), crossY(e->ay + r, lx, hx);
      } else {               // [x − r, x + r] × [ly, hy]
        crossY(ly, e->ax - r, e->ax + r), crossY(hy, e->ax - r, e->ax + r), crossX(e->ax - r, ly, hy), crossX(e->ax + r, ly, hy);
      }
      crossCircle(e->ax, e->ay);
      crossCircle(e->bx, e->by);
    }
    if (c.side < 0) crossX(x0, y0, y1), crossX(x1, y0, y1), crossY(y0, x0, x1), crossY(y1, x0, x1);
    std::sort(ts.begin(), ts.end());
    std::size_t m = 1;
    for (std::size_t i = 1; i < ts.size(); ++i)
      if ((ts[i] - ts[m - 1]) * len > tol) ts[m++] = ts[i];
    ts.resize(m);
    ts.back() = 1;
    bool open = false;
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
      const PointD mid = pointAt(c, 0.5 * (ts[i] + ts[i + 1]));
      bool keep = true;
      if (c.side < 0) {
        const double out = std::max({x0 - mid.x, mid.x - x1, y0 - mid.y, mid.y - y1});
        if (out > tol) keep = false;
        else if (out > -tol) return false;  // along U's side
      }
      // within a part no capsule's boundary is crossed, so each edge either covers all of it or
      // none (touching it at most at a point): decided at the midpoint, or, where that lies within
      // tol of distance r (near a touch), at the quarter points. All three within tol: the part
      // runs within tol of the capsule's boundary, kept (it keeps r - tol from that edge, and the
      // slack ε >> tol keeps it clear of the true radius; a part along another one's boundary
      // would give two successors to a link below, where the trace gives up)
      for (std::size_t k = 0; keep && k < blockers.size(); ++k) {
        for (double f : {0.5, 0.25, 0.75}) {
          const PointD p = f == 0.5 ? mid : pointAt(c, ts[i] + f * (ts[i + 1] - ts[i]));
          const double d = distToAxisEdge(p.x, p.y, *blockers[k]);
          if (d < r - tol) keep = false;
          if (d < r - tol || d > r + tol) break;
        }
      }
      if (keep && open && pieces.back().cand == ci) {
        pieces.back().t1 = ts[i + 1];
      } else if (keep) {
        pieces.push_back({ci, ts[i], ts[i + 1], {}, {}});
      }
      open = keep;
    }
  }
  for (Piece& p : pieces) {
    p.from = pointAt(cands[p.cand], p.t0);
    p.to = pointAt(cands[p.cand], p.t1);
  }

  // 3. links: each end meets exactly one start
  const double linkTol = 16 * tol;
  auto succ = [&](std::size_t i) -> long {
    long found = -1;
    for (std::size_t j = 0; j < pieces.size(); ++j) {
      if (std::abs(pieces[j].from.x - pieces[i].to.x) > linkTol || std::abs(pieces[j].from.y - pieces[i].to.y) > linkTol) continue;
      if (found >= 0) return -2;
      found = static_cast<long>(j);
    }
    return found;
  };

  // 4. the entry: the end of the base's free parts nearest a; then around to the base
  // (a free part of U's boundary away from every edge may still lie deep in an obstacle: the
  // base's parts are tested, nearest a first, until one is in free space)
  std::vector<std::pair<double, std::size_t>> baseParts;
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (cands[pieces[i].cand].side == baseSide) baseParts.push_back({std::abs(pieces[i].to.x - ax) + std::abs(pieces[i].to.y - ay), i});
  std::sort(baseParts.begin(), baseParts.end());
  long entry = -1;
  for (const auto& [distance, i] : baseParts) {
    const PointD mid = pointAt(cands[pieces[i].cand], 0.5 * (pieces[i].t0 + pieces[i].t1));
    const int in = E.inObstacle(mid.x, mid.y, tol);
    if (in < 0) return false;
    if (in == 0) {
      entry = static_cast<long>(i);
      break;
    }
  }
  CSpace::Sweep sweep;
  if (entry < 0) {
    out = sweep;  // no point of the base is free
    return true;
  }
  std::vector<std::size_t> loop;
  long cur = succ(static_cast<std::size_t>(entry));
  while (cur != entry) {
    if (cur < 0 || loop.size() > pieces.size()) return false;
    loop.push_back(static_cast<std::size_t>(cur));
    cur = succ(static_cast<std::size_t>(cur));
  }
  PointD exit = pieces[static_cast<std::size_t>(entry)].from;
  while (!loop.empty() && cands[pieces[loop.back()].cand].side == baseSide) {
    exit = pieces[loop.back()].from;
    loop.pop_back();
  }
  sweep.reached = true;
  sweep.entry = pieces[static_cast<std::size_t>(entry)].to;
  sweep.exit = exit;
  // pieces of one support (one line, one circle) in a row become one
  auto support = [&](const Piece& p, double& k0, double& k1) {
    const Cand& c = cands[p.cand];
    if (c.arc) {
      k0 = c.cx, k1 = c.cy;
      return 2;
    }
    const bool hz = c.ay == c.by;
    k0 = hz ? c.ay : c.ax, k1 = 0;
    return hz ? 0 : 1;
  };
  // At a joint the pieces meet within the links' tolerance, normally to the last bits (both ends
  // are the same crossing, computed from either side), and the next piece starts where the last
  // one ends: an axis-parallel line stays exactly so. Where an arc's own end lies further from the
  // joint than 1e-12 of the scale (two cuts within tol of each other were merged), the arc keeps its
  // end, on its circle as the validator asks of an arc to 1e-9 of its radius, and the line moves.
  const double jointTol = 1e-12 * E.scale();
  auto apart = [&](PointD a, PointD b) { return std::abs(a.x - b.x) > jointTol || std::abs(a.y - b.y) > jointTol; };
  int lastKind = -1;
  double lk0 = 0, lk1 = 0;
  for (std::size_t i : loop) {
    const Piece& p = pieces[i];
    const Cand& c = cands[p.cand];
    sweep.farSide = sweep.farSide || c.side == farSide;
    double k0, k1;
    const int kind = support(p, k0, k1);
    if (kind == lastKind && k0 == lk0 && k1 == lk1) {
      sweep.pieces.back().to = p.to;
    } else if (sweep.pieces.empty()) {
      if (c.arc && apart(sweep.entry, p.from)) sweep.entry = p.from;
      sweep.pieces.push_back(c.arc ? PathSegment::arc(sweep.entry, p.to, {c.cx, c.cy}, false) : PathSegment::line(sweep.entry, p.to));
    } else {
      PathSegment& prev = sweep.pieces.back();
      if (c.arc && prev.kind == PathSegment::Kind::kLine && apart(prev.to, p.from)) prev.to = p.from;
      sweep.pieces.push_back(c.arc ? PathSegment::arc(prev.to, p.to, {c.cx, c.cy}, false) : PathSegment::line(prev.to, p.to));
    }
    lastKind = kind, lk0 = k0, lk1 = k1;
  }
  if (!sweep.pieces.empty()) {
    PathSegment& last = sweep.pieces.back();
    if (last.kind == PathSegment::Kind::kArc && apart(last.to, exit)) exit = last.to;
    else last.to = exit;
  }
  sweep.exit = exit;
  const double a0 = horizontal ? ax : ay, d0 = horizontal ? dx : dy;
  sweep.entryT = ((horizontal ? sweep.entry.x : sweep.entry.y) - a0) / (d0 - a0);
  sweep.exitT = ((horizontal ? sweep.exit.x : sweep.exit.y) - a0) / (d0 - a0);
  out = std::move(sweep);
  return true;
}

}  // namespace coverkit::detail
