// The `fillet` path processor (see fillet.h for the decisions).
#include <coverkit/optimise/fillet.h>

#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/fillet.h>
#include <coverkit/geometry/validate.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace coverkit::optimise {

std::string FilletProcessor::description() const {
  return "replaces each corner by the largest tangent arc of radius <= max_radius x r that keeps exact clearance (and, by "
         "default, everything the corner swept)";
}

std::vector<planners::ParamSpec> FilletProcessor::params() const {
  return {{"max_radius", planners::ParamType::kDouble, "1", "0.001:100", "the largest fillet radius, in robot radii"},
          {"keep_coverage", planners::ParamType::kBool, "true", "true|false",
           "round a corner only as far as what the cut-off corner swept stays swept by the rest of the path (or is not free), "
           "up to a rim of rim x r"},
          {"rim", planners::ParamType::kDouble, "0.04", "0:0.5",
           "keep_coverage: the width of the outer rim of the corner's sweep that a fillet may leave unswept, in robot radii"}};
}

namespace {

Point exactOf(PointD p) { return {exactFromDouble(p.x), exactFromDouble(p.y)}; }
double dist(PointD a, PointD b) { return std::hypot(a.x - b.x, a.y - b.y); }

bool clearPiece(ClearanceChecker& check, const PathSegment& s) {
  if (s.kind == PathSegment::Kind::kLine) return check.clear(exactOf(s.from), exactOf(s.to));
  return check.clearArc(exactOf(s.from), exactOf(s.to), exactOf(s.center), s.ccw);
}

/// Distance from q to a piece (doubles: coverage is measured, not decided, here).
double distToPiece(PointD q, const PathSegment& s) {
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

/// What the rest of a path sweeps, for the coverage guard: the pieces as they are now (slot k holds
/// piece k, or what replaced it: its shortened part and the fillet after it), found through a grid
/// of cell size r over each slot's box (piece k and k + 1 together: a fillet lies in that corner).
class Sweeps {
public:
  Sweeps(const std::vector<PathSegment>& segs, double r) : slots_(segs.size()), cell_(r) {
    for (std::size_t k = 0; k < segs.size(); ++k) {
      slots_[k] = {segs[k]};
      BoxD b = boxOf(segs[k]);
      if (k + 1 < segs.size()) {
        const BoxD c = boxOf(segs[k + 1]);
        b = {std::min(b.xmin, c.xmin), std::min(b.ymin, c.ymin), std::max(b.xmax, c.xmax), std::max(b.ymax, c.ymax)};
      }
      // a slot over more than 64 × 64 cells is checked at every query instead (few: long lanes)
      if (static_cast<double>(key(b.xmax) - key(b.xmin) + 1) * static_cast<double>(key(b.ymax) - key(b.ymin) + 1) > 64 * 64) {
        long_.push_back(k);
        continue;
      }
      for (long i = key(b.xmin); i <= key(b.xmax); ++i)
        for (long j = key(b.ymin); j <= key(b.ymax); ++j) grid_[cellKey(i, j)].push_back(k);
    }
  }
  void replace(std::size_t k, std::vector<PathSegment> now) { slots_[k] = std::move(now); }
  /// Whether some piece of a slot other than `skipA`, `skipB` passes within r of q.
  bool sweeps(PointD q, double r, std::size_t skipA, std::size_t skipB) const {
    auto near = [&](std::size_t k) {
      if (k == skipA || k == skipB) return false;
      for (const PathSegment& s : slots_[k])
        if (distToPiece(q, s) <= r) return true;
      return false;
    };
    for (std::size_t k : long_)
      if (near(k)) return true;
    for (long i = key(q.x - r); i <= key(q.x + r); ++i)
      for (long j = key(q.y - r); j <= key(q.y + r); ++j) {
        const auto it = grid_.find(cellKey(i, j));
        if (it == grid_.end()) continue;
        for (std::size_t k : it->second)
          if (near(k)) return true;
      }
    return false;
  }

private:
  static BoxD boxOf(const PathSegment& s) {
    if (s.kind == PathSegment::Kind::kLine) return {std::min(s.from.x, s.to.x), std::min(s.from.y, s.to.y), std::max(s.from.x, s.to.x), std::max(s.from.y, s.to.y)};
    const double R = dist(s.from, s.center);
    return {s.center.x - R, s.center.y - R, s.center.x + R, s.center.y + R};
  }
  /// The cell of a coordinate, clamped to ±2^40 cells (a cell of r and coordinates up to 10^15).
  long key(double v) const { return static_cast<long>(std::clamp(std::floor(v / cell_), -1099511627776.0, 1099511627776.0)); }
  static unsigned long long cellKey(long i, long j) {
    return (static_cast<unsigned long long>(i) * 0x9E3779B97F4A7C15ULL) ^ static_cast<unsigned long long>(j);
  }
  std::vector<std::vector<PathSegment>> slots_;
  double cell_;
  std::unordered_map<unsigned long long, std::vector<std::size_t>> grid_;
  std::vector<std::size_t> long_;
};

}  // namespace

Plan FilletProcessor::process(const Problem& problem, const Plan& plan, const planners::ParamSet& params) const {
  Plan out = plan;
  out.statistics.clear();
  std::size_t corners = 0, rounded = 0, keptForCoverage = 0;
  double radii = 0;
  const bool keepCoverage = params.flag("keep_coverage");
  const double reach = 1 - params.number("rim");
  for (std::size_t k = 0; k < plan.paths.size(); ++k) {
    const Rational& rq = problem.robots.at(k).radius;
    const double r = rq.get_d(), maxRadius = params.number("max_radius") * r;
    ClearanceChecker check(problem.workspace, rq);
    // free space at sub-cells of r/2 for the guard: a point in a blocked sub-cell needs no sweeping
    // (a partial sub-cell counts as free: the guard errs towards keeping corners); on a map more
    // than 4096 of them across, 1/4096 of its extent
    const Box wb = problem.workspace.bbox();
    const Rational extent = std::max(Rational(wb.xmax - wb.xmin), Rational(wb.ymax - wb.ymin));
    const CellGrid cells = keepCoverage ? classifyCells(problem.workspace, std::max(Rational(rq / 2), Rational(extent / 4096))) : CellGrid();
    auto free = [&](PointD q) {
      CellIndex c;
      return cells.locateSubD(q, c) && cells.sub(c.col, c.row) != CellState::kBlocked;
    };
    std::vector<PathSegment> segs;
    for (const PathSegment& s : plan.paths[k].segments)
      if (!(s.kind == PathSegment::Kind::kLine && s.from.x == s.to.x && s.from.y == s.to.y)) segs.push_back(s);
    if (segs.size() < 2) continue;
    Sweeps rest(segs, r);
    std::vector<bool> refused(segs.size(), false), done(segs.size(), false);
    // the guard: every free point within r of the parts cut off is within r of the new pieces or
    // of the rest of the path, but for an outer rim of rim·r (sampled: around the corner at 1/3,
    // 2/3 and all of (1 − rim)·r in 24 directions, and beside the cut-off parts, at their chords)
    auto keeps = [&](std::size_t i, const PathSegment& cur, const PathSegment& next, const PathSegment& a2, const PathSegment& f,
                     const PathSegment& b2) {
      const PathSegment cut1 = PathSegment::line(a2.to, cur.to);
      const PathSegment cut2 = next.kind == PathSegment::Kind::kLine ? PathSegment::line(next.from, b2.from)
                                                                     : PathSegment::arc(next.from, b2.from, next.center, next.ccw);
      std::vector<PointD> samples;
      const PointD c = cur.to;
      for (int a = 0; a < 24; ++a)
        for (double f3 : {reach / 3, 2 * reach / 3, reach})
          samples.push_back({c.x + f3 * r * std::cos(a * M_PI / 12), c.y + f3 * r * std::sin(a * M_PI / 12)});
      for (const PathSegment* s : {&cut1, &cut2})
        for (double t : {0.25, 0.5, 0.75, 1.0}) {
          const PointD p{s->from.x + t * (s->to.x - s->from.x), s->from.y + t * (s->to.y - s->from.y)};
          const double h = headingOf(*s, false) + M_PI / 2;
          for (double side : {-1.0, 1.0})
            for (double f2 : {reach / 2, reach}) samples.push_back({p.x + side * f2 * r * std::cos(h), p.y + side * f2 * r * std::sin(h)});
        }
      for (const PointD& q : samples) {
        if (std::min(distToPiece(q, cut1), distToPiece(q, cut2)) > r) continue;   // not the cut-off parts' sweep
        if (distToPiece(q, a2) <= r || distToPiece(q, f) <= r || distToPiece(q, b2) <= r) continue;
        if (!free(q) || rest.sweeps(q, r, i, i + 1)) continue;
        return false;
      }
      return true;
    };
    auto accept = [&](std::size_t i, const PathSegment& cur, const PathSegment& next, const PathSegment& a2, const PathSegment& f,
                      const PathSegment& b2) {
      if (keepCoverage && !keeps(i, cur, next, a2, f, b2)) {
        refused[i] = true;
        return false;
      }
      return clearPiece(check, f) && clearPiece(check, a2) && clearPiece(check, b2);
    };
    auto made = [&](std::size_t i, const PathSegment& a2, const PathSegment& f, const PathSegment& b2, double radius) {
      rest.replace(i, {a2, f});
      rest.replace(i + 1, {b2});
      done[i] = true;
      radii += radius / r;
    };
    // a piece gives at most half its length to each end
    const auto room = [&](std::size_t i, const PathSegment&, const PathSegment&, bool) { return segs[i].length() / 2; };
    const FilletCount n = roundCorners(segs, 0, {maxRadius, maxRadius / 1024, 5, 1, 179}, room, accept, made);
    corners += n.corners;
    rounded += n.rounded;
    for (std::size_t i = 0; i < refused.size(); ++i) keptForCoverage += refused[i] && !done[i];
    out.paths[k].segments = std::move(segs);
  }
  out.statistics["corners"] = static_cast<double>(corners);
  out.statistics["rounded"] = static_cast<double>(rounded);
  out.statistics["kept_for_coverage"] = static_cast<double>(keptForCoverage);
  out.statistics["mean_radius_r"] = rounded ? radii / static_cast<double>(rounded) : 0;
  return out;
}

}  // namespace coverkit::optimise
