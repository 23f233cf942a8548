// Metrics that need no CGAL: grid coverage, length, turns, raster area. Formulas: docs/metrics.md.
#include <coverkit/geometry/metrics.h>

#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/validate.h>

#include "edge_index.h"
#include <coverkit/geometry/parallel.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <limits>
#include <optional>
#include <cmath>
#include <unordered_map>

namespace coverkit {

namespace {

double heading(PointD a, PointD b) { return std::atan2(b.y - a.y, b.x - a.x); }
double wrap(double a) {
  while (a > M_PI) a -= 2 * M_PI;
  while (a < -M_PI) a += 2 * M_PI;
  return a;
}
/// Tangent directions at both ends of a piece.
std::pair<double, double> tangents(const PathSegment& s) {
  if (s.kind == PathSegment::Kind::kLine) {
    double h = heading(s.from, s.to);
    return {h, h};
  }
  const double turn = s.ccw ? M_PI / 2 : -M_PI / 2;
  return {heading(s.center, s.from) + turn, heading(s.center, s.to) + turn};
}

/// One piece as the robot drives it: the seconds it first turns on the spot (a corner before it),
/// its length, and its speeds at the start, at most, and at the end.
struct Motion {
  double turn = 0, length = 0, u = 0, peak = 0, w = 0;
};

/// Seconds to drive a motion (after its turn), accelerating and braking at a.
double driveTime(const Motion& m, double a) {
  if (m.length <= 0) return 0;
  const double d1 = (m.peak * m.peak - m.u * m.u) / (2 * a), d2 = (m.peak * m.peak - m.w * m.w) / (2 * a);
  const double cruise = std::max(0.0, m.length - d1 - d2);
  return (m.peak - m.u) / a + (m.peak - m.w) / a + (m.peak > 0 ? cruise / m.peak : 0);
}

/// Distance driven t seconds into a motion's drive (0 ≤ t ≤ driveTime).
double driveDistance(const Motion& m, double a, double t) {
  const double ta = (m.peak - m.u) / a, d1 = (m.peak * m.peak - m.u * m.u) / (2 * a), d2 = (m.peak * m.peak - m.w * m.w) / (2 * a);
  const double cruise = std::max(0.0, m.length - d1 - d2), tc = m.peak > 0 ? cruise / m.peak : 0;
  if (t <= ta) return m.u * t + a * t * t / 2;
  if (t <= ta + tc) return d1 + m.peak * (t - ta);
  const double tau = t - ta - tc;
  return std::min(m.length, d1 + cruise + m.peak * tau - a * tau * tau / 2);
}

/// The path as the robot drives it (robotTraversalTime): per piece its turn before and its speeds.
/// Corners end runs; per run, speeds at the joints from a forward and a backward pass under the
/// acceleration, then per piece the peak: accelerate, cruise at its limit (or peak below it), brake.
std::vector<Motion> motionsOf(const Path& path, const MetricOptions& o) {
  const double tol = o.turnToleranceDeg * M_PI / 180, a = o.aMax;
  std::vector<Motion> out;
  std::vector<double> limit;
  std::size_t runStart = 0;
  auto closeRun = [&] {
    const std::size_t n = out.size() - runStart;
    if (n == 0) return;
    std::vector<double> node(n + 1, 0);
    for (std::size_t k = 1; k < n; ++k) node[k] = std::min(limit[runStart + k - 1], limit[runStart + k]);
    for (std::size_t k = 1; k <= n; ++k) node[k] = std::min(node[k], std::sqrt(node[k - 1] * node[k - 1] + 2 * a * out[runStart + k - 1].length));
    for (std::size_t k = n; k-- > 0;) node[k] = std::min(node[k], std::sqrt(node[k + 1] * node[k + 1] + 2 * a * out[runStart + k].length));
    for (std::size_t k = 0; k < n; ++k) {
      Motion& m = out[runStart + k];
      m.u = node[k];
      m.w = node[k + 1];
      m.peak = std::min(limit[runStart + k], std::sqrt((m.u * m.u + m.w * m.w + 2 * a * m.length) / 2));
    }
    runStart = out.size();
  };
  double prev = 0;
  bool have = false;
  for (const PathSegment& s : path.segments) {
    const double len = s.length();
    if (!(len > 0)) continue;
    const auto [h0, h1] = tangents(s);
    double turn = 0;
    if (have) {
      const double d = std::abs(wrap(h0 - prev));
      if (d > tol) {   // a corner: stop, turn on the spot
        closeRun();
        turn = d / o.omegaMax;
      }
    }
    double v = o.vMax;
    if (s.kind == PathSegment::Kind::kArc) v = std::min(v, o.omegaMax * std::hypot(s.from.x - s.center.x, s.from.y - s.center.y));
    Motion m;
    m.turn = turn;
    m.length = len;
    out.push_back(m);
    limit.push_back(v);
    prev = h1;
    have = true;
  }
  closeRun();
  return out;
}

}  // namespace

double robotTraversalTime(const Path& path, const MetricOptions& o) {
  if (o.vMax <= 0 || o.aMax <= 0 || o.omegaMax <= 0) return 0;
  double t = 0;
  for (const Motion& m : motionsOf(path, o)) t += m.turn + driveTime(m, o.aMax);
  return t;
}

double robotDistanceAt(const Path& path, double seconds, const MetricOptions& o) {
  if (o.vMax <= 0 || o.aMax <= 0 || o.omegaMax <= 0) return 0;
  double t = 0, s = 0;
  for (const Motion& m : motionsOf(path, o)) {
    t += m.turn;
    if (seconds <= t) return s;
    const double drive = driveTime(m, o.aMax);
    if (seconds <= t + drive) return s + driveDistance(m, o.aMax, seconds - t);
    t += drive;
    s += m.length;
  }
  return s;
}

namespace {
/// The timed plan's figures (Metrics::hasTeam and below). A move is a pair of consecutive entries at
/// different places; the moves of all robots are taken in the order of their end times (ties by
/// robot), and one is repeated when the sub-cell of its end was entered before, by any robot (the
/// start's sub-cell counts as entered at t = 0).
void teamFigures(const CellGrid& cells, const std::vector<Path>& paths, Metrics& m) {
  bool timed = false;
  for (const Path& p : paths) timed = timed || !p.timeline.empty();
  if (!timed) return;
  m.hasTeam = true;
  m.robots = paths.size();
  struct Move {
    double t;
    std::size_t robot;
    long cell;   // -1: outside the grid
  };
  auto cellOf = [&](PointD q) -> long {
    CellIndex c;
    return cells.locateSubD(q, c) ? static_cast<long>(c.row) * cells.subCols() + c.col : -1;
  };
  std::vector<Move> moves;
  std::vector<char> entered(cells.subCount(), 0);
  std::vector<std::vector<char>> own(paths.size());
  std::vector<std::size_t> ownCount(paths.size(), 0);
  auto enter = [&](std::size_t robot, long cell) {
    if (cell < 0) return;
    if (own[robot].empty()) own[robot].assign(cells.subCount(), 0);
    char& o = own[robot][static_cast<std::size_t>(cell)];
    if (!o) o = 1, ++ownCount[robot];
  };
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const auto& tl = paths[i].timeline;
    if (tl.empty()) continue;
    m.makespan = std::max(m.makespan, tl.back().t);
    m.sumOfTimes += tl.back().t;
    const long c0 = cellOf(tl.front().p);
    if (c0 >= 0) entered[static_cast<std::size_t>(c0)] = 1;
    enter(i, c0);
    for (std::size_t k = 1; k < tl.size(); ++k)
      if (tl[k].p.x != tl[k - 1].p.x || tl[k].p.y != tl[k - 1].p.y) moves.push_back({tl[k].t, i, cellOf(tl[k].p)});
  }
  std::stable_sort(moves.begin(), moves.end(), [](const Move& a, const Move& b) { return a.t < b.t || (a.t == b.t && a.robot < b.robot); });
  for (const Move& mv : moves) {
    ++m.steps;
    enter(mv.robot, mv.cell);
    if (mv.cell < 0) continue;
    char& e = entered[static_cast<std::size_t>(mv.cell)];
    if (e) ++m.repeatedSteps;
    e = 1;
  }
  const double free = static_cast<double>(m.freeSubcells);
  m.coverageRate = free > 0 ? (static_cast<double>(m.steps) - static_cast<double>(m.repeatedSteps)) / free : 0;
  m.iterationRate = m.steps > 0 ? static_cast<double>(m.repeatedSteps) / static_cast<double>(m.steps) : 0;
  std::size_t sum = 0;
  m.leastCells = ownCount.empty() ? 0 : ownCount.front();
  for (std::size_t c : ownCount) {
    m.mostCells = std::max(m.mostCells, c);
    m.leastCells = std::min(m.leastCells, c);
    sum += c;
  }
  const double mean = ownCount.empty() ? 0 : static_cast<double>(sum) / static_cast<double>(ownCount.size());
  m.balance = mean > 0 ? static_cast<double>(m.mostCells) / mean : 0;
}
}  // namespace

Metrics computeMetrics(const Problem& problem, const CellGrid& cells, const std::vector<Path>& paths,
                       const MetricOptions& o) {
  Metrics m;
  auto t0 = std::chrono::steady_clock::now();
  auto lap = [&](const char* part) {
    const auto t = std::chrono::steady_clock::now();
    m.seconds.emplace_back(part, std::chrono::duration<double>(t - t0).count());
    t0 = t;
  };
  const double D = cells.subSizeD();
  const double r = problem.robots.at(0).radius.get_d();
  // Sub-cells entered by the robot centre: sampling every D/32 along each piece (arcs first
  // flattened to within D/1000); an entry is a change of cell.
  std::vector<std::uint32_t> visits(cells.subCount(), 0);
  std::size_t pieces = 0;
  const Box wb = problem.workspace.bbox();
  const BoxD sampleBox{wb.xmin.get_d() - D, wb.ymin.get_d() - D, wb.xmax.get_d() + D, wb.ymax.get_d() + D};
  for (const Path& p : paths) {
    pieces += p.segments.size();
    m.length += p.length();
    long last = -1;
    auto enterCell = [&](const CellIndex& c) {
      const long k = static_cast<long>(c.row) * cells.subCols() + c.col;
      if (k != last) ++visits[static_cast<std::size_t>(k)];
      last = k;
    };
    auto enter = [&](PointD q) {
      CellIndex c;
      if (!cells.locateSubD(q, c)) { last = -1; return; }
      enterCell(c);
    };
    // only what lies within D of the workspace can enter a sub-cell: sampling is bounded by that part
    for (const std::vector<PointD>& pts : p.polylineWithin(D / 1000, sampleBox)) {
      last = -1;
      enter(pts.front());
      for (std::size_t i = 1; i < pts.size(); ++i) {
        const PointD a = pts[i - 1], b = pts[i];
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        const long n = std::max(1L, static_cast<long>(std::ceil(len / (D / 32))));
        auto sample = [&](long k) {
          const double t = static_cast<double>(k) / static_cast<double>(n);
          return PointD{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        };
        // An axis-parallel piece (most pieces of grid planners): its samples run through one row
        // (column) of cells, and cell indices are monotone in the coordinate, while samples lie less
        // than D apart; so they enter every cell from the first sample's to the last one's in turn,
        // each once. Stepping through those cells gives the same counts without sampling each.
        CellIndex c1, cn;
        if ((a.x == b.x || a.y == b.y) && cells.locateSubD(sample(1), c1) && cells.locateSubD(sample(n), cn)) {
          const bool alongRow = a.y == b.y;
          const int from = alongRow ? c1.col : c1.row, to = alongRow ? cn.col : cn.row, step = to >= from ? 1 : -1;
          for (int v = from;; v += step) {
            enterCell(alongRow ? CellIndex{v, c1.row} : CellIndex{c1.col, v});
            if (v == to) break;
          }
          continue;
        }
        for (long k = 1; k <= n; ++k) enter(sample(k));
      }
    }
    // turns at joints and turning along arcs
    const double tol = o.turnToleranceDeg * M_PI / 180;
    double prev = 0;
    bool have = false;
    for (const PathSegment& s : p.segments) {
      if (s.kind == PathSegment::Kind::kLine && s.from.x == s.to.x && s.from.y == s.to.y) continue;
      auto [h0, h1] = tangents(s);
      if (have) {
        const double d = std::abs(wrap(h0 - prev));
        m.turningAngleDeg += d * 180 / M_PI;
        if (d > tol) ++m.turns;
        if (d > o.reversalDeg * M_PI / 180) ++m.reversals;
      }
      if (s.kind == PathSegment::Kind::kArc) {
        const double rad = std::hypot(s.from.x - s.center.x, s.from.y - s.center.y);
        const double len = s.length();
        if (rad > 0) m.turningAngleDeg += len / rad * 180 / M_PI;
        if (rad > 0 && len > 0) m.maxCurvature = std::max(m.maxCurvature, 1 / rad);
      }
      prev = h1;
      have = true;
    }
  }
  m.segments = pieces;
  for (int row = 0; row < cells.subRows(); ++row)
    for (int col = 0; col < cells.subCols(); ++col) {
      const std::uint32_t v = visits[static_cast<std::size_t>(row) * cells.subCols() + col];
      const bool free = cells.sub(col, row) == CellState::kFree;
      m.freeSubcells += free;
      m.coveredSubcells += free && v > 0;
      m.enteredSubcells += v > 0;
      m.revisitedSubcells += v > 1;
    }
  m.subcellCoverage = m.freeSubcells ? static_cast<double>(m.coveredSubcells) / m.freeSubcells : 0;
  m.overlapRatio = m.enteredSubcells ? static_cast<double>(m.revisitedSubcells) / m.enteredSubcells : 0;
  m.time = o.speed > 0 ? m.length / o.speed : 0;
  for (const Path& p : paths) m.robotTime = std::max(m.robotTime, robotTraversalTime(p, o));

  lap("sub-cells, length, turns");
  if (!o.area) {
    teamFigures(cells, paths, m);
    return m;
  }
  m.hasArea = true;
  m.freeArea = freeArea(problem.workspace).get_d();
  double area = 0;
  // A path the validator accepts sweeps only closure(F): the exact area can skip clipping to F,
  // which is what costs most, so longer paths stay exact.
  const std::size_t limit = std::max(o.exactAreaMaxSegments, o.exactAreaMaxSegmentsClear);
  bool clear = o.pathsKnownClear;
  if (!clear && pieces <= limit && paths.size() == problem.robots.size()) {
    Problem unanchored = problem;  // clearance and continuity only: the start is not a metric's concern
    for (Robot& rb : unanchored.robots) rb.start.reset();
    ValidationOptions vo;
    vo.threads = o.threads;
    clear = validatePaths(unanchored, paths, vo).valid;
  }
  if (pieces <= (clear ? limit : o.exactAreaMaxSegments) &&
      exactCoveredArea(problem.workspace, problem.robots.at(0).radius, paths, area, clear)) {
    m.areaMethod = "exact";
    m.areaCoverageError = 0;
  } else {
    double err = 0;
    area = rasterCoveredArea(problem.workspace, problem.robots.at(0).radius, paths, o.rasterMaxPixels, err, o.threads);
    m.areaMethod = "raster";
    m.areaCoverageError = m.freeArea > 0 ? err / m.freeArea : 0;
  }
  m.coveredArea = area;
  m.areaCoverage = m.freeArea > 0 ? area / m.freeArea : 0;
  double swept = 0;
  for (const Path& p : paths) swept += 2 * r * p.length() + M_PI * r * r;
  m.sweptAreaOverlap = area > 0 ? swept / area - 1 : 0;
  lap("covered area");
  const std::size_t vertices = problem.workspace.vertexCount();
  if (o.coverable && !o.cspace && vertices > o.coverableMaxVertices) {
    m.coverableSkipped = "the workspace has " + std::to_string(vertices) + " vertices, more than " +
                         std::to_string(o.coverableMaxVertices) + " (the C-space would cost minutes)";
  } else if (o.coverable) {
    // the closed convention (cspace.h): the closed C-free components holding the starts, found on
    // the C-space of radius r − δ, so that everything a valid path sweeps lies in the region
    std::vector<Point> starts;
    for (const Path& p : paths) starts.push_back({exactFromDouble(p.start.x), exactFromDouble(p.start.y)});
    double err = 0;
    m.coverableArea = o.cspace ? o.cspace->coverableArea(starts, err, o.threads)
                               : coverableArea(problem.workspace, problem.robots.at(0).radius, starts, err, 1e-6, o.threads);
    m.coverableAreaError = err;
    m.hasCoverable = true;
    m.coverableCoverage = m.coverableArea > 0 ? area / m.coverableArea : 0;
    lap("coverable region");
  }
  teamFigures(cells, paths, m);
  return m;
}

namespace {

/// The squared distance from p to segment ab (doubles; the raster's estimate, never a decision).
inline double pointSegDist2(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / l2, 0.0, 1.0) : 0;
  const double ex = px - (ax + t * dx), ey = py - (ay + t * dy);
  return ex * ex + ey * ey;
}

/// Bucket grid over the path's straight pieces (arcs flattened), for distance queries.
class PieceGrid {
public:
  /// Only the parts of the paths inside [x0, x1] × [y0, y1] (the workspace grown by r) are kept:
  /// nothing outside can cover a point of the workspace.
  PieceGrid(const std::vector<Path>& paths, double flatten, double cell, double x0, double y0, double x1, double y1)
      : x0_(x0), y0_(y0), cell_(cell) {
    nx_ = std::max(1, static_cast<int>(std::ceil((x1 - x0) / cell)) + 1);
    ny_ = std::max(1, static_cast<int>(std::ceil((y1 - y0) / cell)) + 1);
    buckets_.assign(static_cast<std::size_t>(nx_) * ny_, {});
    for (const Path& p : paths)
      for (const std::vector<PointD>& pts : p.polylineWithin(flatten, BoxD{x0, y0, x1, y1})) {
        // consecutive points as pieces; a run of one point is that point alone
        for (std::size_t i = 0; i == 0 || i + 1 < pts.size(); ++i) {
          const PointD a = pts[i], b = pts[std::min(i + 1, pts.size() - 1)];
          const std::size_t k = pieces_.size();
          pieces_.push_back({a.x, a.y, b.x, b.y});
          for (int j = by(std::min(a.y, b.y)); j <= by(std::max(a.y, b.y)); ++j)
            for (int q = bx(std::min(a.x, b.x)); q <= bx(std::max(a.x, b.x)); ++q) buckets_[static_cast<std::size_t>(j) * nx_ + q].push_back(k);
        }
      }
  }
  /// Distance from (x, y) to the path, or a value above `limit` when it is farther than `limit`;
  /// the search stops at the first piece within `enough` (the caller needs no more: the square is
  /// covered). Squared distances inside, one square root at the end.
  double distance(double x, double y, double limit, double enough) const {
    double best = std::numeric_limits<double>::infinity();
    const double enough2 = enough > 0 ? enough * enough : -1;
    for (int j = by(y - limit); j <= by(y + limit); ++j)
      for (int q = bx(x - limit); q <= bx(x + limit); ++q)
        for (std::size_t k : buckets_[static_cast<std::size_t>(j) * nx_ + q]) {
          const auto& s = pieces_[k];
          best = std::min(best, pointSegDist2(x, y, s[0], s[1], s[2], s[3]));
          if (best <= enough2) return std::sqrt(best);
        }
    return std::sqrt(best);
  }

private:
  static int clampIndex(double t, int n) { return !(t > 0) ? 0 : t >= n - 1 ? n - 1 : static_cast<int>(t); }
  int bx(double x) const { return clampIndex((x - x0_) / cell_, nx_); }
  int by(double y) const { return clampIndex((y - y0_) / cell_, ny_); }
  double x0_, y0_, cell_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::array<double, 4>> pieces_;
  std::vector<std::vector<std::size_t>> buckets_;
};

struct Square {
  double cx, cy;
  signed char inside;  // 1 / 0 when known for the whole square's parent, -1 unknown
};

}  // namespace

double rasterCoveredArea(const Workspace& w, const Rational& radius, const std::vector<Path>& paths,
                         std::size_t maxPixels, double& errorBound, unsigned threads) {
  // Squares are classified by their centre's distance d to the path and to W's boundary: a square
  // of half-diagonal e whose centre is farther than e from the boundary lies on one side of it, and
  // it is wholly covered when d <= r - e, wholly uncovered when d > r + e. Uncertain squares are
  // split in four, level by level, while the work stays within a budget; the ones left uncertain
  // count their centre's status and add their whole area to the error bound.
  errorBound = 0;
  const Box b = w.bbox();
  const double r = radius.get_d();
  const double x0 = b.xmin.get_d(), y0 = b.ymin.get_d(), x1 = b.xmax.get_d(), y1 = b.ymax.get_d();
  const double wd = x1 - x0, ht = y1 - y0;
  const std::size_t topPixels = std::max<std::size_t>(1, maxPixels / 4);
  const double h0 = std::max(r / 4, std::sqrt(wd * ht / static_cast<double>(topPixels)));
  const int nx = std::max(1, static_cast<int>(std::ceil(wd / h0))), ny = std::max(1, static_cast<int>(std::ceil(ht / h0)));
  const int maxLevels = 8;
  const double flatten = h0 / std::pow(2.0, maxLevels) / 16;  // arc flattening, added to every margin
  const double slack = flatten + 1e-9 * std::max({1.0, std::abs(x0), std::abs(x1), std::abs(y0), std::abs(y1)});
  const PieceGrid pieces(paths, flatten, std::max(r, h0), x0 - r, y0 - r, x1 + r, y1 + r);
  detail::EdgeIndex edges(w);
  // a query marks the edges it has seen in the index: one index per thread
  auto nearBoundary = [&](detail::EdgeIndex& index, double x, double y, double e) {
    bool near = false;
    index.query(x - e, y - e, x + e, y + e, [&](const detail::IndexedEdge& s) {
      near = near || detail::pointSegDist(x, y, s.ax, s.ay, s.bx, s.by) <= e;
    });
    return near;
  };
  auto insideW = [&](detail::EdgeIndex& index, double x, double y) {  // ray to the right, half-open rule
    bool in = false;
    index.query(x, y, x1 + 1, y, [&](const detail::IndexedEdge& s) {
      if ((s.ay > y) != (s.by > y) && s.ax + (y - s.ay) * (s.bx - s.ax) / (s.by - s.ay) > x) in = !in;
    });
    return in;
  };
  // level 0: pixel centres inside W by row parity
  std::vector<Square> level;
  {
    // each edge listed under the rows whose centre line it may cross (one more row each side for
    // rounding; the crossing test below decides): O(edges + crossings), not rows × edges
    std::vector<std::vector<std::size_t>> rowEdges(static_cast<std::size_t>(ny));
    for (std::size_t k = 0; k < edges.edges().size(); ++k) {
      const auto& e = edges.edges()[k];
      const double lo = (std::min(e.ay, e.by) - y0) / h0 - 0.5, hi = (std::max(e.ay, e.by) - y0) / h0 - 0.5;
      const long j0 = std::max(0L, static_cast<long>(std::floor(std::max(lo, -1.0))) - 1);
      const long j1 = std::min(static_cast<long>(ny) - 1, static_cast<long>(std::ceil(std::min(hi, static_cast<double>(ny)))) + 1);
      for (long j = j0; j <= j1; ++j) rowEdges[static_cast<std::size_t>(j)].push_back(k);
    }
    std::vector<double> xs;
    for (int j = 0; j < ny; ++j) {
      const double cy = y0 + (j + 0.5) * h0;
      xs.clear();
      for (std::size_t k : rowEdges[static_cast<std::size_t>(j)]) {
        const auto& e = edges.edges()[k];
        if ((e.ay > cy) != (e.by > cy)) xs.push_back(e.ax + (cy - e.ay) * (e.bx - e.ax) / (e.by - e.ay));
      }
      std::sort(xs.begin(), xs.end());
      std::size_t q = 0;
      for (int i = 0; i < nx; ++i) {
        const double cx = x0 + (i + 0.5) * h0;
        while (q < xs.size() && xs[q] < cx) ++q;
        level.push_back({cx, cy, static_cast<signed char>(q % 2)});
      }
    }
  }
  double covered = 0, side = h0;
  std::size_t budget = 4 * maxPixels;
  std::vector<Square> next;
  // Each level's squares are split into contiguous runs, one per thread; a run counts its wholly
  // covered and uncertain squares and lists its children in order. Every square of a level adds
  // the same `area`, so adding a run's counts one by one, runs in order, gives the sum a single
  // thread makes, to the bit: the result does not depend on the number of threads.
  struct Run {
    std::vector<Square> next;
    std::size_t covered = 0, uncertain = 0;
  };
  const unsigned threadCount = detail::threadCount(threads);
  std::vector<Run> runs;
  std::vector<detail::EdgeIndex> indices(threadCount - 1, edges);   // parts 1..: their own (a query marks edges in it); part 0: the caller's
  for (int lev = 0;; ++lev) {
    const double e = side * std::sqrt(0.5), area = side * side;
    next.clear();
    const bool last = lev == maxLevels || 4 * level.size() > budget;
    const double q = side / 4;
    auto classify = [&](std::size_t from, std::size_t to, Run& run, detail::EdgeIndex& index) {
      for (std::size_t i = from; i < to; ++i) {
        const Square& s = level[i];
        // below level 0 a known side means the parent square did not meet the boundary
        const bool knownSide = lev > 0 && s.inside >= 0;
        const bool nearB = !knownSide && nearBoundary(index, s.cx, s.cy, e + slack);
        const bool inside = (lev == 0 || knownSide) ? s.inside == 1 : insideW(index, s.cx, s.cy);
        if (!nearB && !inside) continue;
        const double d = pieces.distance(s.cx, s.cy, r + e + slack, nearB ? 0 : r - e - slack);
        if (d > r + e + slack) continue;                                 // wholly uncovered
        if (!nearB && d <= r - e - slack) { ++run.covered; continue; }  // wholly covered
        if (last) {
          run.covered += inside && d <= r;
          ++run.uncertain;
          continue;
        }
        const signed char known = nearB ? -1 : static_cast<signed char>(inside);
        for (double dx : {-q, q})
          for (double dy : {-q, q}) run.next.push_back({s.cx + dx, s.cy + dy, known});
      }
    };
    // threads only for levels worth it (a thread costs tens of microseconds)
    const std::size_t n = level.size(), parts = std::min<std::size_t>(threadCount, std::max<std::size_t>(1, n / 2048));
    runs.assign(parts, Run{});
    detail::parallelFor(parts, threadCount, [&](std::size_t t) {   // part t alone uses its index
      classify(n * t / parts, n * (t + 1) / parts, runs[t], t == 0 ? edges : indices[t - 1]);
    });
    for (Run& run : runs) {
      for (std::size_t k = 0; k < run.covered; ++k) covered += area;
      for (std::size_t k = 0; k < run.uncertain; ++k) errorBound += area;
      next.insert(next.end(), run.next.begin(), run.next.end());
    }
    if (last) break;
    budget -= std::min(budget, next.size());
    level.swap(next);
    side /= 2;
  }
  return covered;
}

}  // namespace coverkit
