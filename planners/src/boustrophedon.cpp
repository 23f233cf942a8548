// Boustrophedon coverage on an exact cell decomposition (see boustrophedon.h for the decisions).
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/fillet.h>
#include <coverkit/geometry/validate.h>
#include <coverkit/graph/cell_graph.h>
#include <coverkit/planners/boustrophedon.h>
#include <coverkit/planners/registry.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

namespace coverkit::planners {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

double dist(PointD a, PointD b) { return std::hypot(a.x - b.x, a.y - b.y); }
Point exactOf(PointD p) { return {exactFromDouble(p.x), exactFromDouble(p.y)}; }

double wrapAngle(double a) { return std::remainder(a, 2 * M_PI); }

/// Total turning of a path (radians): heading changes at joints and along arcs.
double turning(const Path& path) {
  double t = 0;
  for (std::size_t i = 0; i < path.segments.size(); ++i) {
    const PathSegment& s = path.segments[i];
    if (s.kind == PathSegment::Kind::kArc) t += std::abs(wrapAngle(headingOf(s, true) - headingOf(s, false)));
    if (i > 0) t += std::abs(turnAt(path.segments[i - 1], s));
  }
  return t;
}

/// Heading changes above 1° (geometry/metrics.h) at the joints of segs[from, to) and where
/// segs[from] meets the segment before it.
double turnsIn(const std::vector<PathSegment>& segs, std::size_t from, std::size_t to) {
  double n = 0;
  const PathSegment* prev = nullptr;
  for (std::size_t i = from > 0 ? from - 1 : 0; i < to; ++i) {
    const PathSegment& s = segs[i];
    if (s.kind == PathSegment::Kind::kLine && s.from.x == s.to.x && s.from.y == s.to.y) continue;
    if (prev && std::abs(turnAt(*prev, s)) > M_PI / 180) ++n;
    prev = &s;
  }
  return n;
}

/// One direction's plan, in the decomposition's frame.
struct FramePlan {
  bool ok = false;
  PlanStatus status = PlanStatus::kExactSolution;
  std::string message;
  Path path;                     ///< in the workspace's frame (rotated back)
  double cost = std::numeric_limits<double>::infinity();
  double degrees = 0;
  std::map<std::string, double> stats;
  double cspaceSeconds = 0, decomposeSeconds = 0, planSeconds = 0;
};

/// The regions a plan sweeps: chains of cells, each cell joined to the next through a vertical wall
/// at its right end (boustrophedon.h). The closed intervals of two such cells overlap on the wall,
/// so every vertical line meets a chain in one interval, and the chain is swept as one cell: its
/// lanes run on across the walls, and it costs one entry, one set of side passes and no lanes
/// doubled at the walls inside it.
class Regions {
public:
  Regions(const CellDecomposition& d, bool chain) : d_(d), of_(d.cells.size(), -1) {
    const std::size_t n = d.cells.size();
    std::vector<int> next(n, -1), prev(n, -1);
    if (chain) {
      // per pair (left cell, right cell) the wall length they share at the left cell's right end
      std::map<std::pair<int, int>, double> shared;
      for (const CellWall& w : d.walls) {
        if (!w.vertical) continue;
        const DecomposedCell &ca = d.cells[static_cast<std::size_t>(w.a)], &cb = d.cells[static_cast<std::size_t>(w.b)];
        if (ca.xmax == w.at && cb.xmin == w.at) shared[{w.a, w.b}] += w.length();
        else if (cb.xmax == w.at && ca.xmin == w.at) shared[{w.b, w.a}] += w.length();
      }
      // cells are sorted by (xmin, ymin): left to right, each takes the free right neighbour it
      // shares the longest wall with
      for (std::size_t a = 0; a < n; ++a) {
        int best = -1;
        double bestLength = 0;
        for (auto it = shared.lower_bound({static_cast<int>(a), -1}); it != shared.end() && it->first.first == static_cast<int>(a); ++it)
          if (prev[static_cast<std::size_t>(it->first.second)] < 0 && it->second > bestLength) {
            best = it->first.second;
            bestLength = it->second;
          }
        if (best < 0) continue;
        next[a] = best;
        prev[static_cast<std::size_t>(best)] = static_cast<int>(a);
      }
    }
    for (std::size_t c = 0; c < n; ++c) {
      if (prev[c] >= 0) continue;
      const int k = static_cast<int>(members_.size());
      members_.emplace_back();
      for (int m = static_cast<int>(c); m >= 0; m = next[static_cast<std::size_t>(m)]) {
        members_.back().push_back(m);
        of_[static_cast<std::size_t>(m)] = k;
      }
    }
  }

  int count() const { return static_cast<int>(members_.size()); }
  int of(int cell) const { return of_[static_cast<std::size_t>(cell)]; }
  const std::vector<int>& cells(int k) const { return members_[static_cast<std::size_t>(k)]; }
  double xmin(int k) const { return d_.cells[static_cast<std::size_t>(cells(k).front())].xmin; }
  double xmax(int k) const { return d_.cells[static_cast<std::size_t>(cells(k).back())].xmax; }
  /// The region fits in a box of w × h (its member cells' extents).
  bool within(int k, double w, double h) const {
    double ylo = std::numeric_limits<double>::infinity(), yhi = -ylo;
    for (int c : cells(k)) {
      ylo = std::min(ylo, d_.cells[static_cast<std::size_t>(c)].ymin);
      yhi = std::max(yhi, d_.cells[static_cast<std::size_t>(c)].ymax);
    }
    return xmax(k) - xmin(k) <= w && yhi - ylo <= h;
  }
  double area(int k) const {
    double a = 0;
    for (int c : cells(k)) a += d_.cells[static_cast<std::size_t>(c)].area;
    return a;
  }
  double ymid(int k) const {
    const DecomposedCell& c = d_.cells[static_cast<std::size_t>(cells(k).front())];
    return (c.ymin + c.ymax) / 2;
  }

  /// The region's interval at x: of the member cell there, or the union of the two that meet at x.
  bool interval(int k, double x, double& lo, double& hi) const {
    bool any = false;
    lo = hi = 0;
    const auto [first, last] = membersOver(k, x, x);
    for (std::size_t q = first; q < last; ++q) {
      const int c = cells(k)[q];
      double l, h;
      if (!d_.interval(c, x, l, h)) continue;
      lo = any ? std::min(lo, l) : l;
      hi = any ? std::max(hi, h) : h;
      any = true;
    }
    return any;
  }

  /// The top (or bottom) of the region over [x0, x1]: the member cells' sides in x order.
  std::vector<SidePiece> side(int k, bool top, double x0, double x1) const {
    std::vector<SidePiece> out;
    const auto [first, last] = membersOver(k, x0, x1);
    for (std::size_t q = first; q < last; ++q) {
      const int c = cells(k)[q];
      const DecomposedCell& cell = d_.cells[static_cast<std::size_t>(c)];
      for (const SidePiece& piece : d_.side(c, top, std::max(x0, cell.xmin), std::min(x1, cell.xmax))) out.push_back(piece);
    }
    return out;
  }

private:
  /// The members whose [xmin, xmax] meets [x0, x1], as an index range: a chain's cells follow each
  /// other left to right, each beginning where the one before ends (binary search on xmax).
  std::pair<std::size_t, std::size_t> membersOver(int k, double x0, double x1) const {
    const std::vector<int>& m = cells(k);
    auto xmaxOf = [&](int c) { return d_.cells[static_cast<std::size_t>(c)].xmax; };
    auto xminOf = [&](int c) { return d_.cells[static_cast<std::size_t>(c)].xmin; };
    std::size_t first = static_cast<std::size_t>(std::lower_bound(m.begin(), m.end(), x0, [&](int c, double x) { return xmaxOf(c) < x; }) - m.begin());
    std::size_t last = first;
    while (last < m.size() && xminOf(m[last]) <= x1) ++last;
    return {first, last};
  }

  const CellDecomposition& d_;
  std::vector<int> of_;
  std::vector<std::vector<int>> members_;
};

class Walker {
public:
  Walker(const Decomposed& d, const Regions& regions, double r)
      : regions_(regions), space_(*d.space), r_(r), wallsOf_(static_cast<std::size_t>(regions.count())) {
    // per pair of regions its longest wall (the first of equal ones), per region the walls to others
    for (const CellWall& w : d.cells.walls) {
      const int ka = regions.of(w.a), kb = regions.of(w.b);
      if (ka == kb) continue;
      const CellWall*& best = longest_[{std::min(ka, kb), std::max(ka, kb)}];
      if (!best || w.length() > best->length()) best = &w;
      wallsOf_[static_cast<std::size_t>(ka)].push_back(&w);
      wallsOf_[static_cast<std::size_t>(kb)].push_back(&w);
    }
  }

  /// Regions of several cells connect through their cells, with `cells` (a walker over single
  /// cells): the interval of a chain jumps at its walls, where splitting a chord in the middle
  /// may never clear a corner.
  void setCellLevel(const Walker* cells) { cellLevel_ = cells; }

  /// From u to v in a region of several cells: through the member cells between theirs.
  bool connectMembers(int k, PointD u, PointD v, std::vector<PathSegment>& out) const {
    const std::vector<int>& m = regions_.cells(k);
    const int i = memberIndexAt(k, u), j = memberIndexAt(k, v);
    if (i < 0 || j < 0) return false;
    std::vector<int> via;
    for (int q = i;; q += j >= i ? 1 : -1) {
      via.push_back(m[static_cast<std::size_t>(q)]);
      if (q == j) break;
    }
    return cellLevel_->throughCells(via, u, v, out);
  }

  /// From u (in cells.front()) to v (in cells.back()) through consecutive neighbouring regions,
  /// from the middle of one shared wall to the next, each piece inside one region.
  bool throughCells(const std::vector<int>& cells, PointD u, PointD v, std::vector<PathSegment>& out) const {
    PointD at = u;
    for (std::size_t q = 0; q + 1 < cells.size(); ++q) {
      const PointD next = door(cells[q], cells[q + 1]);
      if (!connect(cells[q], at, next, out)) return false;
      at = next;
    }
    return connect(cells.back(), at, v, out);
  }

  /// The index (in the region's list) of a member cell holding p (the only one of a region of
  /// one cell), or −1.
  int memberIndexAt(int k, PointD p) const {
    const std::vector<int>& m = regions_.cells(k);
    if (m.size() == 1) return 0;
    if (!cellLevel_) return -1;
    const double tol = 1e-9 * (1 + std::abs(p.x) + std::abs(p.y));
    for (std::size_t q = 0; q < m.size(); ++q) {
      double lo, hi;
      if (cellLevel_->regions_.interval(m[q], p.x, lo, hi) && p.y >= lo - tol && p.y <= hi + tol) return static_cast<int>(q);
    }
    return -1;
  }

  /// The pairs of neighbouring regions.
  std::vector<std::pair<int, int>> neighbours() const {
    std::vector<std::pair<int, int>> out;
    for (const auto& [pair, wall] : longest_) out.push_back(pair);
    return out;
  }

  /// Appends the line u → v when it is clear in the frame's C-free (radius r + μ), exactly.
  bool line(PointD u, PointD v, std::vector<PathSegment>& out) const {
    if (u.x == v.x && u.y == v.y) return true;
    ++checks_;
    if (!space_.segmentClear(exactOf(u), exactOf(v))) return false;
    out.push_back(PathSegment::line(u, v));
    return true;
  }
  /// Appends the arc about c from u to the ray through v (radius |u − c|) when it is clear; `end`
  /// gets the arc's end.
  bool arc(PointD u, PointD v, PointD c, std::vector<PathSegment>& out, PointD& end) const {
    const double rho = dist(u, c), d = dist(v, c);
    if (rho == 0 || d == 0) return false;
    end = {c.x + (v.x - c.x) * rho / d, c.y + (v.y - c.y) * rho / d};
    const bool ccw = (u.x - c.x) * (v.y - c.y) - (u.y - c.y) * (v.x - c.x) > 0;
    ++checks_;
    if (!space_.arcClear(exactOf(u), exactOf(end), exactOf(c), ccw)) return false;
    out.push_back(PathSegment::arc(u, end, c, ccw));
    return true;
  }

  double tau(double lo, double hi) const { return std::min(r_ / 100, (hi - lo) / 4); }

  /// A path from u to v inside `cell` (both in it): the chord, or split at the middle of the
  /// cell's interval halfway in x, recursively; where that fails (an interval that jumps at a
  /// vertical piece of the boundary, so that every split point is on the wrong side of a corner),
  /// through gates at the x of the boundary's vertices instead.
  bool connect(int cell, PointD u, PointD v, std::vector<PathSegment>& out) const {
    if (cellLevel_ && regions_.cells(cell).size() > 1) return connectMembers(cell, u, v, out);
    const std::size_t mark = out.size();
    if (connectSplit(cell, u, v, out)) return true;
    out.resize(mark);
    if (connectGates(cell, u, v, out)) return true;
    out.resize(mark);
    // two points on (nearly) one vertical line, along which an obstacle's side runs (two doors of
    // one wall line): through a point a little inside the cell beside them
    const Extent c = extent(cell);
    const double ym = (u.y + v.y) / 2;
    for (double step = r_ / 100; step < c.xmax - c.xmin; step *= 2)
      for (double side : {-1.0, 1.0}) {
        const PointD p{(u.x + v.x) / 2 + side * step, ym};
        double lo, hi;
        if (p.x < c.xmin || p.x > c.xmax || !regions_.interval(cell, p.x, lo, hi) || p.y <= lo || p.y >= hi) continue;
        if (connectSplit(cell, u, p, out) && connectSplit(cell, p, v, out)) return true;
        out.resize(mark);
      }
    return false;
  }

  bool connectSplit(int cell, PointD u, PointD v, std::vector<PathSegment>& out, int depth = 0) const {
    if (line(u, v, out)) return true;
    if (depth > 18) return false;
    // split halfway in x; two points on one vertical line (two doors on one wall line, where an
    // obstacle may touch it) go through the middle of the cell instead
    const Extent c = extent(cell);
    double xm = (u.x + v.x) / 2;
    if (std::abs(u.x - v.x) <= 1e-9 * (c.xmax - c.xmin)) xm = (c.xmin + c.xmax) / 2;
    double lo, hi;
    if (!regions_.interval(cell, xm, lo, hi)) return false;
    const PointD m{xm, (lo + hi) / 2};
    if ((m.x == u.x && m.y == u.y) || (m.x == v.x && m.y == v.y)) return false;
    return connectSplit(cell, u, m, out, depth + 1) && connectSplit(cell, m, v, out, depth + 1);
  }

  /// Through the gates of a monotone cell: at every x where its boundary has a vertex between u and
  /// v, a point of the interval that both sides of that x share (clamped from the straight line u → v),
  /// the pieces between consecutive gates by connectSplit (the boundary is one curve on each side there).
  bool connectGates(int cell, PointD u, PointD v, std::vector<PathSegment>& out) const {
    std::vector<double> xs;
    for (bool top : {true, false})
      for (const SidePiece& p : regions_.side(cell, top, std::min(u.x, v.x), std::max(u.x, v.x)))
        for (double x : {p.x0, p.x1})
          if (x > std::min(u.x, v.x) && x < std::max(u.x, v.x)) xs.push_back(x);
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    if (v.x < u.x) std::reverse(xs.begin(), xs.end());
    const Extent c = extent(cell);
    const double eps = 1e-7 * (c.xmax - c.xmin);
    PointD at = u;
    for (double x : xs) {
      double l1, h1, l2, h2;
      if (!regions_.interval(cell, x - eps, l1, h1) || !regions_.interval(cell, x + eps, l2, h2)) continue;
      const double glo = std::max(l1, l2), ghi = std::min(h1, h2);
      if (glo > ghi) return false;
      const double m = std::min(r_ / 100, (ghi - glo) / 4);
      const double t = (x - u.x) / (v.x - u.x);
      const PointD gate{x, std::clamp(u.y + t * (v.y - u.y), glo + m, ghi - m)};
      if (!connectSplit(cell, at, gate, out)) return false;
      at = gate;
    }
    return connectSplit(cell, at, v, out);
  }

  /// The point τ inside a side piece at x, along the piece's normal (a parallel line, or a circle
  /// of radius ρ ± τ about the same centre).
  static bool offsetAt(const SidePiece& p, double x, bool top, double t, PointD& out) {
    if (!p.arc) {
      if (p.b == 0) return false;
      out = {x, p.yAt(x) + (top ? -1 : 1) * t * std::hypot(p.a, p.b) / std::abs(p.b)};
      return true;
    }
    const double rho = p.clockwise ? p.rho + t : p.rho - t;
    const double h2 = rho * rho - (x - p.center.x) * (x - p.center.x);
    if (rho <= 0 || h2 < 0) return false;
    out = {x, p.upperHalf ? p.center.y + std::sqrt(h2) : p.center.y - std::sqrt(h2)};
    return true;
  }
  /// The point τ inside the side at the boundary point q of piece p (q on p).
  static PointD offsetOf(const SidePiece& p, PointD q, bool top, double t) {
    if (!p.arc) {
      double nx = p.a, ny = p.b;
      const double len = std::hypot(nx, ny);
      if ((top && ny > 0) || (!top && ny < 0)) {
        nx = -nx;
        ny = -ny;
      }
      return {q.x + t * nx / len, q.y + t * ny / len};
    }
    const double rho = p.clockwise ? p.rho + t : p.rho - t, d = dist(q, p.center);
    return {p.center.x + (q.x - p.center.x) * rho / d, p.center.y + (q.y - p.center.y) * rho / d};
  }

  /// The end of the lane at x on the cell's bottom or top: τ inside the boundary (offsetAt), kept
  /// inside the middle of the interval.
  bool laneEnd(int cell, double x, bool bottom, PointD& out) const {
    double lo, hi;
    if (!regions_.interval(cell, x, lo, hi)) return false;
    const double t = tau(lo, hi), mid = (lo + hi) / 2;
    out = {x, bottom ? lo + t : hi - t};
    for (const SidePiece& p : regions_.side(cell, !bottom, x, x)) {
      PointD q;
      if (x < p.x0 || x > p.x1 || !offsetAt(p, x, !bottom, t, q)) continue;
      if (bottom ? (q.y >= lo && q.y <= mid) : (q.y <= hi && q.y >= mid)) out = q;
      break;
    }
    return true;
  }

  /// From lane end u to lane end v along the cell's top or bottom, τ inside it: lines and arcs
  /// parallel to the boundary's pieces, joined by short lines where two pieces meet at a corner.
  /// Every piece is checked exactly; when one is not clear, chords close to the side instead
  /// (hugChords).
  bool hug(int cell, PointD u, PointD v, bool top, std::vector<PathSegment>& out) const {
    std::vector<PathSegment> tmp;
    if (hugAlong(cell, u, v, top, tmp)) {
      out.insert(out.end(), tmp.begin(), tmp.end());
      return true;
    }
    return hugChords(cell, u, v, top, out);
  }

  /// The lanes of a cell, left to right (boustrophedon.h): their x.
  std::vector<double> lanes(int cell) const {
    const Extent c = extent(cell);
    const double w = c.xmax - c.xmin;
    double lo, hi;
    const double t = regions_.interval(cell, (c.xmin + c.xmax) / 2, lo, hi) ? std::min(r_ / 100, w / 4) : 0;
    const bool leftWall = wallEnd(cell, c.xmin), rightWall = wallEnd(cell, c.xmax);
    const double A = (leftWall ? 0.5 : 0) + (rightWall ? 0.5 : 0);
    const double span = w - t * ((leftWall ? 0 : 1) + (rightWall ? 0 : 1));
    int m = std::max(1, static_cast<int>(std::ceil(span / (2 * r_) + 1 - A - 1e-9)));
    // an odd number, so that the serpentine ends on the side it did not start; but two lanes need
    // no third: the first pass follows one side, the serpentine's one turn the other (boustrophedon.h)
    if (m % 2 == 0 && m != 2) ++m;
    std::vector<double> out;
    if (m - 1 + A <= 0) return {(c.xmin + c.xmax) / 2};
    const double s = span / (m - 1 + A);
    const double x0 = leftWall ? c.xmin + s / 2 : c.xmin + t;
    for (int i = 0; i < m; ++i) out.push_back(x0 + s * i);
    return out;
  }

  /// A reference point of a cell: the middle of its interval at the middle of its extent.
  PointD reference(int cell) const {
    const Extent c = extent(cell);
    const double x = (c.xmin + c.xmax) / 2;
    double lo, hi;
    if (regions_.interval(cell, x, lo, hi)) return {x, (lo + hi) / 2};
    return {x, regions_.ymid(cell)};
  }

  /// The middle of the longest wall between a and b.
  PointD door(int a, int b) const {
    const CellWall* best = longest_.at({std::min(a, b), std::max(a, b)});
    const double mid = (best->lo + best->hi) / 2;
    return best->vertical ? PointD{best->at, mid} : PointD{mid, best->at};
  }

  std::size_t checks() const { return checks_; }

  struct Extent {
    double xmin, xmax;
  };
  Extent extent(int k) const { return {regions_.xmin(k), regions_.xmax(k)}; }

  /// Rounds the joints of segs[from, end) where the heading turns by 1° to 175° and at least one
  /// of the two pieces is a line (roundCorners): an arc of radius r, r/2, ... or r/64, the arc and
  /// both shortened pieces checked exactly; a joint where none is clear keeps its corner. A piece
  /// gives at most half its length to each end, a lane (isLane[i − laneBase]) at most
  /// r(1 − sin α)/cos α, α the angle of the other piece's tangent to the x axis: every point within
  /// r of the part of a lane cut off is then within r of the side pass through the lane's end
  /// (boustrophedon.h), so rounding loses no coverage.
  void roundJoints(std::vector<PathSegment>& segs, std::size_t from, const std::vector<bool>& isLane, std::size_t laneBase = 0) const {
    auto lane = [&](std::size_t i) { return i >= laneBase && i - laneBase < isLane.size() && isLane[i - laneBase]; };
    auto room = [&](std::size_t i, const PathSegment&, const PathSegment& other, bool atEnd) {
      if (!lane(i)) return segs[i].length() / 2;
      const double h = headingOf(other, !atEnd);   // the other piece's tangent at the joint
      const double sa = std::abs(std::sin(h)), ca = std::abs(std::cos(h));
      return ca > 1e-9 ? r_ * (1 - sa) / ca : 0.0;
    };
    auto accept = [&](std::size_t, const PathSegment&, const PathSegment&, const PathSegment& a2, const PathSegment& f, const PathSegment& b2) {
      checks_ += 3;
      return clear(f) && clear(a2) && clear(b2);
    };
    roundCorners(segs, from, {r_, r_ / 64, 0, 1, 175}, room, accept);
  }

  /// Rounds the corners left in segs[from, end) (a side pass's, and those where one part of a
  /// sweep meets the next): a fillet of radius r, r/2, ... down to r/16 whose arc passes within
  /// r/20 of the corner, the arc and both shortened pieces checked exactly. Every point within r
  /// of what the fillet cuts off is within r + r/20 of the arc, so what it gives up is a lens at
  /// most r/20 thick (a side pass's corner is where the disc reaches deepest into a notch of the
  /// boundary). Sharper corners (turning by more than about 115°, where a fillet of r/16 is
  /// farther off) keep their corner.
  void roundSide(std::vector<PathSegment>& segs, std::size_t from) const {
    auto room = [&](std::size_t i, const PathSegment&, const PathSegment&, bool) { return segs[i].length() / 2; };
    auto accept = [&](std::size_t, const PathSegment& cur, const PathSegment&, const PathSegment& a2, const PathSegment& f, const PathSegment& b2) {
      if (dist(cur.to, f.center) - dist(f.from, f.center) > r_ / 20) return false;
      checks_ += 3;
      return clear(f) && clear(a2) && clear(b2);
    };
    roundCorners(segs, from, {r_, r_ / 16, 0, 1, 175, true}, room, accept);
  }

  /// Drops the line pieces of segs[from, end) shorter than 1e-9·r: what a rounded corner leaves of
  /// a piece, or a connector between two legs that meet within rounding. Their heading is
  /// rounding noise, so each made one or two turns of its own. The line before (or else after) one
  /// is stretched over it, checked exactly; where that is not clear the sliver stays. One between
  /// two arcs is left out when under 1e-10 long.
  void dropSlivers(std::vector<PathSegment>& segs, std::size_t from) const {
    if (from > 0) --from;   // the joint with what came before
    const double eps = 1e-9 * r_;
    std::vector<PathSegment> out;   // what replaces segs[from, end): only the tail is rebuilt
    for (std::size_t i = from; i < segs.size(); ++i) {
      const PathSegment& g = segs[i];
      if (g.kind == PathSegment::Kind::kLine && g.length() < eps) {
        if (!out.empty() && out.back().kind == PathSegment::Kind::kLine) {
          const PathSegment c = PathSegment::line(out.back().from, g.to);
          ++checks_;
          if (clear(c)) {
            out.back() = c;
            continue;
          }
        }
        if (i + 1 < segs.size() && segs[i + 1].kind == PathSegment::Kind::kLine) {
          const PathSegment c = PathSegment::line(g.from, segs[i + 1].to);
          ++checks_;
          if (clear(c)) {
            segs[i + 1] = c;
            continue;
          }
        }
        // between two arcs: left out; the gap (under the validator's continuity tolerance, 1e-9)
        // is the sliver itself, which is clear
        if (g.length() < std::min(eps, 1e-10)) continue;
      }
      out.push_back(g);
    }
    segs.resize(from);
    segs.insert(segs.end(), out.begin(), out.end());
  }

  /// A piece clear in the frame's C-free (radius r + μ), exactly.
  bool clear(const PathSegment& g) const {
    if (g.kind == PathSegment::Kind::kLine) return space_.segmentClear(exactOf(g.from), exactOf(g.to));
    return space_.arcClear(exactOf(g.from), exactOf(g.to), exactOf(g.center), g.ccw);
  }

  /// A transition made of line segments, pulled straight: from each point, the farthest later
  /// point of the route that a clear segment reaches (checked exactly), and on from there. Fewer
  /// turns and a shorter way; the route's own segments, already clear, are the fallback.
  void shortcut(std::vector<PathSegment>& route) const {
    if (route.size() < 2) return;
    for (const PathSegment& s : route)
      if (s.kind != PathSegment::Kind::kLine) return;
    std::vector<PointD> pts{route.front().from};
    for (const PathSegment& s : route) pts.push_back(s.to);
    std::vector<PathSegment> out;
    for (std::size_t i = 0; i + 1 < pts.size();) {
      std::size_t j = pts.size() - 1;
      for (; j > i + 1; --j) {
        ++checks_;
        if (space_.segmentClear(exactOf(pts[i]), exactOf(pts[j]))) break;
      }
      if (pts[i].x != pts[j].x || pts[i].y != pts[j].y) out.push_back(PathSegment::line(pts[i], pts[j]));
      i = j;
    }
    route.swap(out);
  }

private:
  /// The cell's end at x is (almost) all wall: its neighbour's lanes sweep beside it.
  bool wallEnd(int cell, double x) const {
    double lo, hi;
    if (!regions_.interval(cell, x, lo, hi) || hi <= lo) return false;
    double walls = 0;
    for (const CellWall* w : wallsOf_[static_cast<std::size_t>(cell)])
      if (w->vertical && std::abs(w->at - x) <= 1e-9 * (1 + std::abs(x))) walls += w->length();
    return walls >= 0.999 * (hi - lo);
  }

  /// The point τ inside piece p at x (offsetAt), or where the circle has no point at that x (near
  /// its x-extreme), along the normal at the boundary point (offsetOf).
  static PointD onOffset(const SidePiece& p, double x, bool top, double t) {
    PointD q;
    if (offsetAt(p, x, top, t, q)) return q;
    return offsetOf(p, {x, p.yAt(x)}, top, t);
  }

  /// The unit direction of a line piece, travelled with x increasing (dir = 1) or decreasing.
  static PointD directionOf(const SidePiece& p, double dir) {
    const double len = std::hypot(p.a, p.b);
    PointD d{p.b / len, -p.a / len};
    if (d.x * dir < 0) d = {-d.x, -d.y};
    return d;
  }

  /// A leg's curve: the line through p along d, or the circle about c of radius R.
  struct Curve {
    bool arc;
    PointD p, d, c;
    double R;
  };
  static Curve offsetCurve(const SidePiece& piece, PointD in, double dir, bool top, double t) {
    if (!piece.arc) return {false, in, directionOf(piece, dir), {}, 0};
    return {true, {}, {}, piece.center, piece.clockwise ? piece.rho + t : piece.rho - t};
  }
  /// The crossing of two curves nearest m (false when they do not cross).
  static bool crossing(const Curve& a, const Curve& b, PointD m, PointD& out) {
    std::vector<PointD> xs;
    auto lineCircle = [&](const Curve& l, const Curve& c) {
      double s0, s1;
      if (!lineCircleCrossings(l.p, l.d, c.c, c.R, s0, s1)) return;
      for (double s : {s0, s1}) xs.push_back({l.p.x + s * l.d.x, l.p.y + s * l.d.y});
    };
    if (!a.arc && !b.arc) {
      const double cross = a.d.x * b.d.y - a.d.y * b.d.x;
      if (std::abs(cross) < 1e-9) return false;
      const PointD w{b.p.x - a.p.x, b.p.y - a.p.y};
      const double s = (w.x * b.d.y - w.y * b.d.x) / cross;
      xs.push_back({a.p.x + s * a.d.x, a.p.y + s * a.d.y});
    } else if (!a.arc) {
      lineCircle(a, b);
    } else if (!b.arc) {
      lineCircle(b, a);
    } else {
      PointD left, right;
      if (!circleCrossings(a.c, a.R, b.c, b.R, left, right)) return false;
      xs = {left, right};
    }
    if (xs.empty()) return false;
    out = xs[0];
    for (const PointD& x : xs)
      if (dist(x, m) < dist(out, m)) out = x;
    return true;
  }

  /// Along the side from u to v, τ inside it: one leg per boundary piece, on the piece's parallel
  /// line or concentric circle, the legs joined where two pieces meet: where the two offset
  /// curves cross, nearest the joint (one corner, as the boundary has), or, where they do not
  /// cross there (or a leg is vertical), at the points τ along the normals at the joint (the same
  /// point where the pieces meet tangentially), by a short line where they differ. Lane ends are
  /// points of these curves (laneEnd), so the walk never steps back along a side.
  bool hugAlong(int cell, PointD u, PointD v, bool top, std::vector<PathSegment>& out) const {
    double lo, hi;
    const double dir = v.x >= u.x ? 1 : -1;
    std::vector<SidePiece> pieces = regions_.side(cell, top, std::min(u.x, v.x), std::max(u.x, v.x));
    if (dir < 0) std::reverse(pieces.begin(), pieces.end());
    struct Leg {
      SidePiece p;
      double xs, xe, t;
      PointD in, out;
    };
    std::vector<Leg> legs;
    for (const SidePiece& p : pieces) {
      const double xs = dir > 0 ? std::max(p.x0, u.x) : std::min(p.x1, u.x);
      const double xe = dir > 0 ? std::min(p.x1, v.x) : std::max(p.x0, v.x);
      if ((xe - xs) * dir <= 0) continue;
      if (!regions_.interval(cell, (xs + xe) / 2, lo, hi)) return false;
      const double t = tau(lo, hi);
      legs.push_back({p, xs, xe, t, onOffset(p, xs, top, t), onOffset(p, xe, top, t)});
    }
    const double tiny = 1e-12 * (1 + std::abs(u.x) + std::abs(u.y));
    for (std::size_t k = 1; k < legs.size(); ++k) {
      Leg &a = legs[k - 1], &b = legs[k];
      a.out = offsetOf(a.p, {b.xs, a.p.yAt(b.xs)}, top, a.t);
      b.in = offsetOf(b.p, {b.xs, b.p.yAt(b.xs)}, top, b.t);
      if (dist(a.out, b.in) <= tiny || (!a.p.arc && a.p.b == 0) || (!b.p.arc && b.p.b == 0)) continue;
      // where the two offset curves cross, nearest the joint: ahead of a's entry and before b's exit
      const PointD m{(a.out.x + b.in.x) / 2, (a.out.y + b.in.y) / 2};
      PointD at;
      if (crossing(offsetCurve(a.p, a.in, dir, top, a.t), offsetCurve(b.p, b.in, dir, top, b.t), m, at) &&
          (at.x - a.in.x) * dir > 0 && (b.out.x - at.x) * dir > 0 && dist(at, m) < 8 * std::max(a.t, b.t) + dist(a.out, b.in))
        a.out = b.in = at;
    }
    PointD cur = u;
    auto follow = [&](const Leg& g) {
      if (dist(cur, g.in) > tiny) {
        if (!line(cur, g.in, out)) return false;
        cur = g.in;
      }
      if (dist(cur, g.out) <= tiny) return true;
      if (!g.p.arc) {
        if (!line(cur, g.out, out)) return false;
        cur = g.out;
        return true;
      }
      PointD end;
      if (!arc(cur, g.out, g.p.center, out, end)) return false;
      cur = end;
      return true;
    };
    for (std::size_t k = 0; k < legs.size(); ++k) {
      const std::size_t mark = out.size();
      const PointD from = cur;
      if (follow(legs[k])) continue;
      // a leg (or the way onto it) that is not clear, where the offset curves of a short piece and
      // its neighbours do not meet as they should: chords close to the side to the leg's end (the
      // end of the whole side for the last leg) instead, the other legs kept
      out.resize(mark);
      cur = from;
      PointD to = v;
      if (k + 1 < legs.size() && !laneEnd(cell, legs[k].xe, !top, to)) return false;
      if (!hugChords(cell, cur, to, top, out)) return false;
      cur = to;
    }
    if (dist(cur, v) > tiny || out.empty() || out.back().kind != PathSegment::Kind::kLine) return line(cur, v, out);
    // v within rounding of the last leg's end: that leg ends at v instead (checked again)
    const PathSegment last = out.back();
    out.pop_back();
    if (line(last.from, v, out)) return true;
    out.push_back(last);
    return line(cur, v, out);
  }

  /// Chords between points τ inside the boundary: a chord is taken when it is clear and passes
  /// within r/20 of the side (sampled at both ends and the middle of every boundary piece between
  /// u and v); otherwise it is split at the sample farthest from it (a spike of C-free the chord
  /// would cut off: the disc would not reach into it). Where that fails, or a chord is not clear,
  /// split at the middle until clear (and from there on without the bound).
  bool hugChords(int cell, PointD u, PointD v, bool top, std::vector<PathSegment>& out, int depth = 0, bool close = true) const {
    if (close && depth <= 12) {
      double worst = r_ / 20;
      PointD split{};
      bool found = false;
      const double lo = std::min(u.x, v.x), hi = std::max(u.x, v.x), dx = v.x - u.x, dy = v.y - u.y, len2 = dx * dx + dy * dy;
      for (const SidePiece& piece : regions_.side(cell, top, lo, hi)) {
        const double a = std::max(lo, piece.x0), b = std::min(hi, piece.x1), e = (b - a) * 1e-3;
        if (b <= a) continue;
        for (double x : {a + e, (a + b) / 2, b - e}) {
          PointD q;
          if (x <= lo || x >= hi || !laneEnd(cell, x, !top, q)) continue;
          const double t = len2 > 0 ? std::clamp(((q.x - u.x) * dx + (q.y - u.y) * dy) / len2, 0.0, 1.0) : 0;
          const double d = std::hypot(q.x - u.x - t * dx, q.y - u.y - t * dy);
          if (d > worst) {
            worst = d;
            split = q;
            found = true;
          }
        }
      }
      const std::size_t mark = out.size();
      if (found && hugChords(cell, u, split, top, out, depth + 1) && hugChords(cell, split, v, top, out, depth + 1)) return true;
      out.resize(mark);   // (a side that jumps at a wall, where the sample's point is beyond a corner)
    }
    if (line(u, v, out)) return true;
    if (depth > 12) return connect(cell, u, v, out);
    const double xm = (u.x + v.x) / 2;
    PointD m;
    if (xm == u.x || xm == v.x || !laneEnd(cell, xm, !top, m)) return connect(cell, u, v, out);
    return hugChords(cell, u, m, top, out, depth + 1, false) && hugChords(cell, m, v, top, out, depth + 1, false);
  }

  const Regions& regions_;
  const Walker* cellLevel_ = nullptr;
  const CSpace& space_;
  double r_;
  std::map<std::pair<int, int>, const CellWall*> longest_;
  std::vector<std::vector<const CellWall*>> wallsOf_;
  mutable std::size_t checks_ = 0;
};

FramePlan planDirection(const Problem& problem, const Rational& rPlan, const std::string& decomposition, double degrees, bool chain,
                        bool rounded, const TerminationCondition& stop) {
  FramePlan fp;
  const double r = problem.robots[0].radius.get_d();
  const Point start = *problem.robots[0].start;
  auto t0 = Clock::now();
  const Decomposed d = runDecomposition(decomposition, {problem.workspace, {{rPlan, std::nullopt}}, std::nullopt, {}},
                                        {{"direction", formatDouble(degrees)}});
  fp.cspaceSeconds = d.cspaceSeconds;
  fp.decomposeSeconds = d.decomposeSeconds;
  t0 = Clock::now();
  const CellDecomposition& cells = d.cells;
  const Rotation& rot = cells.rotation;
  fp.degrees = -rot.degrees();
  fp.stats["cells"] = static_cast<double>(cells.cells.size());
  fp.stats["unwalled_vertices"] = static_cast<double>(cells.unwalledVertices);
  fp.stats["direction_degrees"] = fp.degrees;
  if (cells.cells.empty()) {
    fp.status = PlanStatus::kNoFreeSpace;
    fp.message = "C-free is empty: the robot fits nowhere";
    return fp;
  }
  // the start may lie within μ of C-free's boundary (the default start of a sub-cell exactly 2r
  // wide does): then the path steps from it to a point of the plan's C-free, checked exactly at r
  const Point startFrame = rot.apply(start);
  PointD entry{startFrame.x.get_d(), startFrame.y.get_d()};
  int startCell = cells.locate(startFrame);
  bool stepped = false;
  if (startCell < 0 && segmentClear(problem.workspace, problem.robots[0].radius, start, start)) {
    const double mu = Rational(rPlan - problem.robots[0].radius).get_d();
    for (double step = 2 * mu; step < r && startCell < 0; step *= 4)
      for (int k = 0; k < 16 && startCell < 0; ++k) {
        const double a = k * M_PI / 8;
        const PointD p{entry.x + step * std::cos(a), entry.y + step * std::sin(a)};
        const PointD back = rot.c == 1 ? p : rot.inverse(p);
        const int in = cells.locate(exactOf(p));
        if (in < 0 || !segmentClear(problem.workspace, problem.robots[0].radius, start, exactOf(back))) continue;
        startCell = in;
        entry = p;
        stepped = true;
      }
  }
  if (startCell < 0) {
    fp.status = PlanStatus::kInvalidStart;
    fp.message = "the start is not in C-free (the disc there meets an obstacle or the workspace's boundary)";
    return fp;
  }
  const Regions regions(cells, chain), single(cells, false);
  Walker walk(d, regions, r), cellWalk(d, single, r);
  if (chain) walk.setCellLevel(&cellWalk);
  const std::size_t n = static_cast<std::size_t>(regions.count());
  fp.stats["sweep_regions"] = static_cast<double>(n);
  // the graph of the regions (the order of the sweeps) and of the cells (the transitions)
  auto graphOf = [](const Walker& w, int count) {
    std::vector<PointD> ref(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) ref[static_cast<std::size_t>(k)] = w.reference(k);
    std::vector<graph::WeightedEdge> edges;
    for (const auto& [a, b] : w.neighbours()) {
      const PointD door = w.door(a, b);
      edges.push_back({a, b, dist(ref[static_cast<std::size_t>(a)], door) + dist(door, ref[static_cast<std::size_t>(b)])});
    }
    return graph::CellGraph(count, edges);
  };
  const graph::CellGraph g = graphOf(walk, regions.count());
  const graph::CellGraph gCells = graphOf(cellWalk, single.count());
  const int startCellIndex = startCell;
  startCell = regions.of(startCell);   // from here on, regions

  // order: DFS of the region graph, then 2-opt on shortest-path distances
  std::vector<int> order = g.depthFirstOrder(startCell);
  if (order.size() > 2 && order.size() <= 400) {
    std::map<int, std::vector<double>> distFrom;
    for (int c : order) {
      std::vector<int> pred;
      g.shortestPaths(c, distFrom[c], pred);
    }
    auto D = [&](int a, int b) { return distFrom[a][static_cast<std::size_t>(b)]; };
    bool improved = true;
    for (int pass = 0; improved && pass < 20 && !stop.expired(); ++pass) {
      improved = false;
      for (std::size_t i = 1; i + 1 < order.size(); ++i)
        for (std::size_t j = i + 1; j < order.size(); ++j) {
          // reverse order[i..j]: the open path's last edge has no successor
          const double before = D(order[i - 1], order[i]) + (j + 1 < order.size() ? D(order[j], order[j + 1]) : 0);
          const double after = D(order[i - 1], order[j]) + (j + 1 < order.size() ? D(order[i], order[j + 1]) : 0);
          if (after + 1e-12 < before) {
            std::reverse(order.begin() + static_cast<std::ptrdiff_t>(i), order.begin() + static_cast<std::ptrdiff_t>(j) + 1);
            improved = true;
          }
        }
    }
  }

  std::vector<PathSegment> segs;
  auto cur = [&] { return segs.empty() ? entry : segs.back().to; };
  int here = startCell;
  std::size_t skipped = 0, lanesTotal = 0, unreached = 0, broken = 0, pockets = 0;
  double pocketArea = 0;
  bool timedOut = false;
  std::map<std::string, double> phaseTurns;
  // the end of a part of a sweep that began at segs[from]: its corners and the one with what came
  // before rounded within r/20 (roundSide), slivers dropped, its turns counted
  auto closePart = [&](const char* name, std::size_t from) {
    if (rounded) walk.roundSide(segs, from > 0 ? from - 1 : 0);
    walk.dropSlivers(segs, from);
    phaseTurns[name] += turnsIn(segs, from, segs.size());
  };
  for (std::size_t at = 0; at < order.size(); ++at) {
    const int cell = order[at];
    // a pocket: a region within a box of r/4 × r/4 (a notch of a ragged boundary, a wedge where
    // two C-obstacles nearly meet) is not visited on its own (boustrophedon.h)
    if (at > 0 && regions.within(cell, r / 4, r / 4)) {
      ++pockets;
      pocketArea += regions.area(cell);
      continue;
    }
    if (stop.expired()) {
      timedOut = true;
      break;
    }
    std::vector<double> xs = walk.lanes(cell);
    std::vector<std::pair<PointD, PointD>> lanes;   // (bottom end, top end)
    for (double x : xs) {
      PointD lo, hi;
      if (walk.laneEnd(cell, x, true, lo) && walk.laneEnd(cell, x, false, hi)) lanes.push_back({lo, hi});
    }
    if (lanes.empty()) continue;
    // which end first (left or right) and which side first (the bottom or the top; the first
    // pass runs along that side): the corner nearest the robot, the way out counted too (the
    // sweep ends at the far end, on the side where the serpentine ends; with two lanes back at
    // the first lane), to the next region's reference point
    bool fromRight = false, bottomFirst = true;
    double best = std::numeric_limits<double>::infinity();
    const std::size_t m = lanes.size();
    const bool last = at + 1 == order.size();
    const PointD next = last ? PointD{} : walk.reference(order[at + 1]);
    for (bool fr : {false, true})
      for (bool bf : {true, false}) {
        const auto& l = fr ? lanes.back() : lanes.front();
        const auto& e = m == 2 ? l : (fr ? lanes.front() : lanes.back());
        const bool exitBottom = m % 2 == 0 ? bf : !bf;   // an even count ends on the first side
        double dd = dist(cur(), bf ? l.first : l.second);
        if (!last) dd += dist(exitBottom ? e.first : e.second, next);
        if (dd < best) {
          best = dd;
          fromRight = fr;
          bottomFirst = bf;
        }
      }
    if (fromRight) std::reverse(lanes.begin(), lanes.end());
    auto end = [&](std::size_t i, bool bottom) { return bottom ? lanes[i].first : lanes[i].second; };
    const PointD first = end(0, bottomFirst);
    // get there: through the cells of a shortest path of the cell graph, from the cell the robot
    // is in (one of the region it swept last) to the one of `first`
    auto routeFrom = [&](PointD at, std::vector<PathSegment>& route) {
      const int fromIndex = walk.memberIndexAt(here, at), toIndex = walk.memberIndexAt(cell, first);
      if (fromIndex < 0 || toIndex < 0) return false;
      const int from = regions.cells(here)[static_cast<std::size_t>(fromIndex)], to = regions.cells(cell)[static_cast<std::size_t>(toIndex)];
      const std::vector<int> via = from == to ? std::vector<int>{from} : gCells.shortestPath(from, to);
      return !via.empty() && cellWalk.throughCells(via, at, first, route);
    };
    std::vector<PathSegment> route;
    const std::size_t mark0 = segs.size();
    bool reached = routeFrom(cur(), route);
    // a sweep may end where no split of the chord reaches the door (a corner of a ragged cell):
    // back along the path's last line segments (valid, so valid reversed) and try from there
    for (std::size_t back = 1; !reached && back <= 16 && back <= segs.size(); ++back) {
      const PathSegment& last = segs[segs.size() - back];
      if (last.kind != PathSegment::Kind::kLine) break;
      route.clear();
      for (std::size_t k = 1; k <= back; ++k) {
        const PathSegment& sgm = segs[segs.size() - k];
        route.push_back(PathSegment::line(sgm.to, sgm.from));
      }
      std::vector<PathSegment> onward;
      reached = routeFrom(last.from, onward);
      if (reached) route.insert(route.end(), onward.begin(), onward.end());
    }
    if (!reached) {
      skipped += regions.cells(cell).size();
      unreached += regions.cells(cell).size();
      continue;
    }
    walk.shortcut(route);
    if (rounded) walk.roundJoints(route, 0, {});
    segs.insert(segs.end(), route.begin(), route.end());
    closePart("turns_transitions", mark0);
    std::size_t mark = segs.size();
    // the sweep (boustrophedon.h): along the first side to the far end, the lanes back in a
    // serpentine (an odd number of lanes ends on the other side), along the other side again
    bool ok = true;
    for (std::size_t i = 0; ok && i + 1 < m; ++i) ok = walk.hug(cell, cur(), end(i + 1, bottomFirst), !bottomFirst, segs);
    closePart("turns_first_side", mark);
    mark = segs.size();
    bool atBottom = bottomFirst;
    std::vector<bool> isLane;   // per piece of segs[mark, end): a lane
    for (std::size_t j = m; ok && j-- > 0;) {
      const std::size_t at = segs.size();
      ok = walk.line(cur(), end(j, !atBottom), segs);
      isLane.resize(segs.size() - mark, false);
      if (segs.size() > at) isLane[at - mark] = true;
      atBottom = !atBottom;
      ++lanesTotal;
      // between two lanes: the chord when it is clear (both sides are followed by the side
      // passes already); with two lanes there is no last pass, so the turn follows the side
      if (ok && j > 0) ok = (m != 2 && walk.line(cur(), end(j - 1, atBottom), segs)) || walk.hug(cell, cur(), end(j - 1, atBottom), !atBottom, segs);
    }
    // the serpentine's corners rounded: the side passes sweep what they cut (roundJoints)
    if (ok && rounded) walk.roundJoints(segs, mark, isLane, mark);
    closePart("turns_lanes", mark);
    mark = segs.size();
    if (m != 2)   // two lanes: the serpentine's turn has followed the other side already
      for (std::size_t i = 0; ok && i + 1 < m; ++i) ok = walk.hug(cell, cur(), end(i + 1, atBottom), !atBottom, segs);
    closePart("turns_last_side", mark);
    if (!ok) ++broken;
    if (!ok) skipped += regions.cells(cell).size();   // what was swept before the break stays; its cells count as not done
    here = cell;
  }
  // back to the workspace's frame; the start exactly as given (as a double)
  const PointD startD{start.x.get_d(), start.y.get_d()};
  auto back = [&](PointD p) { return rot.c == 1 ? p : rot.inverse(p); };
  Path path;
  path.start = startD;
  if (stepped) path.segments.push_back(PathSegment::line(startD, back(entry)));
  for (const PathSegment& sg : segs) {
    PathSegment t = sg;
    t.from = back(sg.from);
    t.to = back(sg.to);
    if (sg.kind == PathSegment::Kind::kArc) t.center = back(sg.center);
    if (path.segments.empty() && !stepped) t.from = startD;   // rotated back, the first point is the start
    path.segments.push_back(t);
  }
  fp.path = std::move(path);
  fp.stats["lanes"] = static_cast<double>(lanesTotal);
  for (const auto& [k, v] : phaseTurns) fp.stats[k] = v;
  fp.stats["skipped_cells"] = static_cast<double>(skipped);
  fp.stats["cells_unreached"] = static_cast<double>(unreached);
  fp.stats["sweeps_broken"] = static_cast<double>(broken);
  fp.stats["pockets"] = static_cast<double>(pockets);
  fp.stats["pocket_area"] = pocketArea;
  std::size_t inComponent = 0;
  for (int k : order) inComponent += regions.cells(k).size();
  fp.stats["cells_in_component"] = static_cast<double>(inComponent);
  fp.stats["exact_checks"] = static_cast<double>(walk.checks());
  // components of the plan's C-free joined to the start's only where C-free is pinched to zero
  // width (a gap exactly 2r wide, boustrophedon.h): counted, not crossed
  std::size_t behind = 0;
  double behindArea = 0;
  if (d.space->componentCount() > 1) {
    const int home = cells.cells[static_cast<std::size_t>(startCellIndex)].component;
    const int closedHome = d.space->closedComponentOf(startFrame);
    std::map<int, bool> joined;
    for (std::size_t c = 0; c < cells.cells.size(); ++c) {
      const int k = cells.cells[c].component;
      if (k == home) continue;
      auto it = joined.find(k);
      if (it == joined.end())
        it = joined.emplace(k, closedHome >= 0 && d.space->closedComponentOf(exactOf(cellWalk.reference(static_cast<int>(c)))) == closedHome).first;
      if (it->second) behindArea += cells.cells[c].area;
      behind += it->second;
    }
  }
  fp.stats["cells_behind_exact_gaps"] = static_cast<double>(behind);
  fp.stats["area_behind_exact_gaps"] = behindArea;
  fp.ok = true;
  if (behind > 0 && skipped == 0 && !timedOut) {
    fp.status = PlanStatus::kPartialCoverage;
    fp.message = std::to_string(behind) + " cell(s) of C-free (area " + formatDouble(behindArea) +
                 ") are joined to the start's only through gaps exactly 2r wide, which this planner does not cross";
  }
  if (timedOut) {
    fp.status = PlanStatus::kTimeout;
    fp.message = "time limit reached";
  } else if (skipped > 0) {
    fp.status = PlanStatus::kPartialCoverage;
    fp.message = std::to_string(skipped) + " cell(s) could not be reached or swept";
  }
  fp.cost = fp.path.length() + r * turning(fp.path);
  fp.stats["cost"] = fp.cost;
  fp.planSeconds = since(t0);
  return fp;
}

/// The sweep directions `best` tries: 0°, 90° and the four edge directions (mod 180°) with the most
/// total edge length, to 0.1°.
std::vector<double> candidateDirections(const Workspace& w) {
  std::map<long, double> weight;   // tenths of a degree in [0, 1800)
  for (const Ring* ring : w.rings())
    for (std::size_t i = 0; i < ring->size(); ++i) {
      const Point& a = (*ring)[i];
      const Point& b = (*ring)[(i + 1) % ring->size()];
      const double dx = Rational(b.x - a.x).get_d(), dy = Rational(b.y - a.y).get_d();
      double deg = std::atan2(dy, dx) * 180 / M_PI;
      if (deg < 0) deg += 180;
      long key = std::lround(deg * 10) % 1800;
      weight[key] += std::hypot(dx, dy);
    }
  std::vector<std::pair<double, long>> byWeight;
  for (const auto& [k, wt] : weight) byWeight.push_back({-wt, k});
  std::sort(byWeight.begin(), byWeight.end());
  std::vector<double> out{0, 90};
  for (std::size_t i = 0; i < byWeight.size() && i < 4; ++i) {
    const double deg = static_cast<double>(byWeight[i].second) / 10;
    if (std::find(out.begin(), out.end(), deg) == out.end()) out.push_back(deg);
  }
  return out;
}

}  // namespace

std::string BoustrophedonPlanner::description() const {
  return "boustrophedon coverage (Choset & Pignon) on an exact decomposition of C-free: lanes at spacing <= 2r in each "
         "cell, cells in a DFS + 2-opt order of the cell graph, transitions through the cells";
}

std::vector<ParamSpec> BoustrophedonPlanner::params() const {
  return {{"decomposition", ParamType::kChoice, "boustrophedon", "boustrophedon|trapezoidal", "the decomposition whose cells are swept"},
          {"chains", ParamType::kBool, "true", "true|false",
           "sweep chains of cells joined through vertical walls as one region (one entry, lanes across the walls); false: "
           "every cell on its own, as in the paper"},
          {"round", ParamType::kBool, "true", "true|false",
           "round the serpentine's corners and the transitions' corners with arcs of radius up to r, and the side passes' "
           "corners with arcs that pass within r/20 of them (each checked exactly); false: corners, as in the paper"},
          {"direction", ParamType::kDouble, "0", "-360:360|best",
           "sweep direction in degrees (lanes perpendicular to it), or best: the workspace's main edge directions, 0 and 90 "
           "tried, the least length + r x turning kept"}};
}

Capabilities BoustrophedonPlanner::capabilities() const {
  Capabilities c;
  c.needsCells = false;
  c.output = "lines+arcs";
  c.coverage = "cfree_component";
  return c;
}

Plan BoustrophedonPlanner::plan(const PlanningContext& ctx, const ParamSet& params, const TerminationCondition& stop) {
  Plan plan;
  plan.planner = name();
  const Problem& problem = ctx.problem;
  if (!problem.robots.at(0).start) {
    plan.status = PlanStatus::kNoFreeSpace;
    plan.message = "no start: nothing of the workspace is free for this robot";
    return plan;
  }
  // the margin μ (boustrophedon.h): a power of two, so r + μ stays a short rational
  const Rational& r = problem.robots[0].radius;
  const Box b = problem.workspace.bbox();
  const double extent = std::max(Rational(b.xmax - b.xmin).get_d(), Rational(b.ymax - b.ymin).get_d());
  const double mu = std::max(std::ldexp(r.get_d(), -24), std::ldexp(extent, -40));
  const Rational rPlan = r + exactFromDouble(std::ldexp(1.0, std::ilogb(mu) + 1));
  std::vector<double> directions;
  if (params.text("direction") == "best") directions = candidateDirections(problem.workspace);
  else directions = {params.number("direction")};
  FramePlan best;
  double cspace = 0, decompose = 0, sweep = 0;
  for (double deg : directions) {
    FramePlan fp = planDirection(problem, rPlan, params.text("decomposition"), deg, params.flag("chains"), params.flag("round"), stop);
    cspace += fp.cspaceSeconds;
    decompose += fp.decomposeSeconds;
    sweep += fp.planSeconds;
    if (!best.ok || (fp.ok && (static_cast<int>(fp.status) < static_cast<int>(best.status) ||
                               (fp.status == best.status && fp.cost < best.cost))))
      best = std::move(fp);
  }
  plan.status = best.status;
  plan.message = best.message;
  plan.statistics = best.stats;
  plan.statistics["directions_tried"] = static_cast<double>(directions.size());
  plan.timings = {{"cspace", cspace}, {"decompose", decompose}, {"sweep", sweep}};
  if (best.ok) plan.paths.push_back(std::move(best.path));
  return plan;
}

}  // namespace coverkit::planners
