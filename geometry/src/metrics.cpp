// Metrics that need no CGAL: grid coverage, length, turns, raster area. Formulas: docs/metrics.md.
#include <coverkit/geometry/metrics.h>

#include <coverkit/geometry/validate.h>

#include "edge_index.h"

#include <algorithm>
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

}  // namespace

Metrics computeMetrics(const Problem& problem, const CellGrid& cells, const std::vector<Path>& paths,
                       const MetricOptions& o) {
  Metrics m;
  const double D = cells.subSizeD();
  const double r = problem.robots.at(0).radius.get_d();
  // Sub-cells entered by the robot centre: sampling every D/32 along each piece (arcs first
  // flattened to within D/1000); an entry is a change of cell.
  std::vector<std::uint32_t> visits(cells.subCount(), 0);
  std::size_t pieces = 0;
  for (const Path& p : paths) {
    pieces += p.segments.size();
    m.length += p.length();
    const std::vector<PointD> pts = p.polyline(D / 1000);
    long last = -1;
    auto enter = [&](PointD q) {
      CellIndex c;
      if (!cells.locateSubD(q, c)) { last = -1; return; }
      const long k = static_cast<long>(c.row) * cells.subCols() + c.col;
      if (k != last) ++visits[static_cast<std::size_t>(k)];
      last = k;
    };
    enter(pts.front());
    for (std::size_t i = 1; i < pts.size(); ++i) {
      const double len = std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
      const int n = std::max(1, static_cast<int>(std::ceil(len / (D / 32))));
      for (int k = 1; k <= n; ++k) {
        const double t = static_cast<double>(k) / n;
        enter({pts[i - 1].x + t * (pts[i].x - pts[i - 1].x), pts[i - 1].y + t * (pts[i].y - pts[i - 1].y)});
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
      }
      if (s.kind == PathSegment::Kind::kArc) {
        const double rad = std::hypot(s.from.x - s.center.x, s.from.y - s.center.y);
        if (rad > 0) m.turningAngleDeg += s.length() / rad * 180 / M_PI;
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

  m.freeArea = freeArea(problem.workspace).get_d();
  double area = 0;
  // A path the validator accepts sweeps only closure(F): the exact area can skip clipping to F.
  bool clear = false;
  if (pieces <= o.exactAreaMaxSegments && paths.size() == problem.robots.size()) {
    Problem unanchored = problem;  // clearance and continuity only: the start is not a metric's concern
    for (Robot& rb : unanchored.robots) rb.start.reset();
    clear = validatePaths(unanchored, paths).valid;
  }
  if (pieces <= o.exactAreaMaxSegments &&
      exactCoveredArea(problem.workspace, problem.robots.at(0).radius, paths, area, clear)) {
    m.areaMethod = "exact";
    m.areaCoverageError = 0;
  } else {
    double err = 0;
    area = rasterCoveredArea(problem.workspace, problem.robots.at(0).radius, paths, o.rasterMaxPixels, err);
    m.areaMethod = "raster";
    m.areaCoverageError = m.freeArea > 0 ? err / m.freeArea : 0;
  }
  m.coveredArea = area;
  m.areaCoverage = m.freeArea > 0 ? area / m.freeArea : 0;
  double swept = 0;
  for (const Path& p : paths) swept += 2 * r * p.length() + M_PI * r * r;
  m.sweptAreaOverlap = area > 0 ? swept / area - 1 : 0;
  return m;
}

double rasterCoveredArea(const Workspace& w, const Rational& radius, const std::vector<Path>& paths,
                         std::size_t maxPixels, double& errorBound) {
  const Box b = w.bbox();
  const double r = radius.get_d();
  const double x0 = b.xmin.get_d(), y0 = b.ymin.get_d();
  const double wd = b.xmax.get_d() - x0, ht = b.ymax.get_d() - y0;
  double h = std::max(r / 8, std::sqrt(wd * ht / static_cast<double>(maxPixels)));
  const int nx = std::max(1, static_cast<int>(std::ceil(wd / h))), ny = std::max(1, static_cast<int>(std::ceil(ht / h)));
  const double half = h * std::sqrt(0.5);
  const double flatten = h / 100;  // arcs flattened to within this
  std::vector<float> dist(static_cast<std::size_t>(nx) * ny, std::numeric_limits<float>::infinity());
  std::vector<std::uint8_t> nearBoundary(dist.size(), 0);
  auto pix = [&](double x, double lo) { return static_cast<int>(std::floor((x - lo) / h - 0.5)); };
  auto visitBand = [&](double ax, double ay, double bx, double by, double band, auto&& f) {
    const int i0 = std::max(0, pix(std::min(ax, bx) - band, x0)), i1 = std::min(nx - 1, pix(std::max(ax, bx) + band, x0) + 1);
    const int j0 = std::max(0, pix(std::min(ay, by) - band, y0)), j1 = std::min(ny - 1, pix(std::max(ay, by) + band, y0) + 1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const double cx = x0 + (i + 0.5) * h, cy = y0 + (j + 0.5) * h;
        f(static_cast<std::size_t>(j) * nx + i, detail::pointSegDist(cx, cy, ax, ay, bx, by));
      }
  };
  for (const Path& p : paths) {
    const std::vector<PointD> pts = p.polyline(flatten);
    for (std::size_t i = 0; i + 1 < pts.size() || i == 0; ++i) {
      const PointD a = pts[i], c = i + 1 < pts.size() ? pts[i + 1] : pts[i];
      visitBand(a.x, a.y, c.x, c.y, r + h, [&](std::size_t k, double d) { dist[k] = std::min(dist[k], static_cast<float>(d)); });
      if (pts.size() == 1) break;
    }
  }
  detail::EdgeIndex index(w);
  for (const auto& e : index.edges())
    visitBand(e.ax, e.ay, e.bx, e.by, half, [&](std::size_t k, double d) { if (d <= half * 1.000001) nearBoundary[k] = 1; });
  // inside W by row parity at pixel centres (pixels near the boundary are uncertain anyway)
  std::size_t covered = 0, uncertain = 0;
  std::vector<double> xs;
  const auto& edges = index.edges();
  for (int j = 0; j < ny; ++j) {
    const double cy = y0 + (j + 0.5) * h;
    xs.clear();
    for (const auto& e : edges)
      if ((e.ay > cy) != (e.by > cy)) xs.push_back(e.ax + (cy - e.ay) * (e.bx - e.ax) / (e.by - e.ay));
    std::sort(xs.begin(), xs.end());
    std::size_t q = 0;
    for (int i = 0; i < nx; ++i) {
      const double cx = x0 + (i + 0.5) * h;
      while (q < xs.size() && xs[q] < cx) ++q;
      const bool inside = q % 2 == 1;
      const std::size_t k = static_cast<std::size_t>(j) * nx + i;
      const double d = dist[k];
      const bool sure = !nearBoundary[k] && std::abs(d - r) > half + flatten + 1e-9 * r;
      if (inside && d <= r) ++covered;
      if (!sure && (inside || nearBoundary[k]) && d <= r + half + flatten) ++uncertain;
    }
  }
  errorBound = uncertain * h * h;
  return covered * h * h;
}

}  // namespace coverkit
