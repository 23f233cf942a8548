#pragma once
// What the path processors (fillet, smooth) share: what a path sweeps, in doubles, for their
// coverage guards (coverage is measured, not decided, there; clearance is decided exactly), a
// grid of boxes to find pieces and edges near a point, and the guard's parameters.
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/path.h>
#include <coverkit/planners/planner.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace coverkit::optimise::detail {

inline double dist(PointD a, PointD b) { return std::hypot(a.x - b.x, a.y - b.y); }
/// A double point as the exact point it is (for the exact clearance tests).
inline Point exactOf(PointD p) { return {exactFromDouble(p.x), exactFromDouble(p.y)}; }

/// Distance from q to a piece (doubles: coverage is measured, not decided, here).
inline double distToPiece(PointD q, const PathSegment& s) {
  if (s.kind == PathSegment::Kind::kLine) {
    const double dx = s.to.x - s.from.x, dy = s.to.y - s.from.y, l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((q.x - s.from.x) * dx + (q.y - s.from.y) * dy) / l2, 0.0, 1.0) : 0;
    return std::hypot(q.x - s.from.x - t * dx, q.y - s.from.y - t * dy);
  }
  const double R = dist(s.from, s.center);
  const double a0 = std::atan2(s.from.y - s.center.y, s.from.x - s.center.x), a1 = std::atan2(s.to.y - s.center.y, s.to.x - s.center.x);
  const double aq = std::atan2(q.y - s.center.y, q.x - s.center.x);
  auto ccwFrom = [](double a, double b) { return std::fmod(std::fmod(b - a, 2 * M_PI) + 2 * M_PI, 2 * M_PI); };
  const bool within = s.ccw ? ccwFrom(a0, aq) <= ccwFrom(a0, a1) : ccwFrom(aq, a0) <= ccwFrom(a1, a0);
  if (within) return std::abs(dist(q, s.center) - R);
  return std::min(dist(q, s.from), dist(q, s.to));
}

/// Items with boxes in a grid of square cells (a hash map of the cells that hold any); an item over
/// more than 64 × 64 cells is kept apart and offered to every query (few: long lanes, walls).
class BoxGrid {
public:
  explicit BoxGrid(double cell) : cell_(cell) {}
  void add(std::size_t item, const BoxD& b) {
    if (static_cast<double>(key(b.xmax) - key(b.xmin) + 1) * static_cast<double>(key(b.ymax) - key(b.ymin) + 1) > 64 * 64) {
      large_.push_back(item);
      return;
    }
    for (long i = key(b.xmin); i <= key(b.xmax); ++i)
      for (long j = key(b.ymin); j <= key(b.ymax); ++j) cells_[cellKey(i, j)].push_back(item);
  }
  /// f(item) for the large items, then for those of the cells that meet the box p ± reach (an item
  /// may come more than once), until f returns true; whether it did.
  template <class F>
  bool any(PointD p, double reach, F&& f) const {
    for (std::size_t k : large_)
      if (f(k)) return true;
    for (long i = key(p.x - reach); i <= key(p.x + reach); ++i)
      for (long j = key(p.y - reach); j <= key(p.y + reach); ++j) {
        const auto it = cells_.find(cellKey(i, j));
        if (it == cells_.end()) continue;
        for (std::size_t k : it->second)
          if (f(k)) return true;
      }
    return false;
  }

private:
  /// The cell of a coordinate, clamped to ±2^40 cells (a cell of r and coordinates up to 10^15).
  long key(double v) const { return static_cast<long>(std::clamp(std::floor(v / cell_), -1099511627776.0, 1099511627776.0)); }
  static unsigned long long cellKey(long i, long j) {
    return (static_cast<unsigned long long>(i) * 0x9E3779B97F4A7C15ULL) ^ static_cast<unsigned long long>(j);
  }
  double cell_;
  std::unordered_map<unsigned long long, std::vector<std::size_t>> cells_;
  std::vector<std::size_t> large_;
};

/// What the rest of a path sweeps, for the coverage guard: the pieces as they are now (slot k holds
/// piece k, or what replaced it: its shortened part and the fillet after it), found through a grid
/// of cell size r over each slot's box (piece k and k + 1 together: a fillet lies in that corner).
class Sweeps {
public:
  Sweeps(const std::vector<PathSegment>& segs, double r) : slots_(segs.size()), grid_(r) {
    for (std::size_t k = 0; k < segs.size(); ++k) {
      slots_[k] = {segs[k]};
      BoxD b = boxOf(segs[k]);
      if (k + 1 < segs.size()) {
        const BoxD c = boxOf(segs[k + 1]);
        b = {std::min(b.xmin, c.xmin), std::min(b.ymin, c.ymin), std::max(b.xmax, c.xmax), std::max(b.ymax, c.ymax)};
      }
      grid_.add(k, b);
    }
  }
  void replace(std::size_t k, std::vector<PathSegment> now) { slots_[k] = std::move(now); }
  /// Whether some piece of a slot other than `skipA`, `skipB` passes within r of q.
  bool sweeps(PointD q, double r, std::size_t skipA, std::size_t skipB) const {
    return grid_.any(q, r, [&](std::size_t k) {
      if (k == skipA || k == skipB) return false;
      for (const PathSegment& s : slots_[k])
        if (distToPiece(q, s) <= r) return true;
      return false;
    });
  }

private:
  static BoxD boxOf(const PathSegment& s) {
    if (s.kind == PathSegment::Kind::kLine) return {std::min(s.from.x, s.to.x), std::min(s.from.y, s.to.y), std::max(s.from.x, s.to.x), std::max(s.from.y, s.to.y)};
    const double R = dist(s.from, s.center);
    return {s.center.x - R, s.center.y - R, s.center.x + R, s.center.y + R};
  }
  std::vector<std::vector<PathSegment>> slots_;
  BoxGrid grid_;
};

/// A processor's own parameters followed by the coverage guard's (keep_coverage, rim), which the
/// processors that have a guard share.
inline std::vector<planners::ParamSpec> withCoverageGuard(std::vector<planners::ParamSpec> own) {
  own.push_back({"keep_coverage", planners::ParamType::kBool, "true", "true|false",
                 "change the path only as far as what the old pieces swept stays swept by the path (or is not free), up to a rim "
                 "of rim x r"});
  own.push_back({"rim", planners::ParamType::kDouble, "0.04", "0:0.5",
                 "keep_coverage: the width of the outer rim of the old sweep that may be left unswept, in robot radii"});
  return own;
}

/// Free space for the guard: the workspace's sub-cells of r/2 (at least 1/4096 of the map's extent);
/// a point in a blocked sub-cell needs no sweeping, a partial sub-cell counts as free (the guard errs
/// towards keeping the path). Off: nothing is classified.
class FreeSpace {
public:
  FreeSpace(const Workspace& w, const Rational& r, bool on) {
    if (!on) return;
    const Box b = w.bbox();
    const Rational extent = std::max(Rational(b.xmax - b.xmin), Rational(b.ymax - b.ymin));
    cells_ = classifyCells(w, std::max(Rational(r / 2), Rational(extent / 4096)));
  }
  bool operator()(PointD q) const {
    CellIndex c;
    return cells_.locateSubD(q, c) && cells_.sub(c.col, c.row) != CellState::kBlocked;
  }

private:
  CellGrid cells_;
};

}  // namespace coverkit::optimise::detail
