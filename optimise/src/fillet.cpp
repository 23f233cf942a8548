// The `fillet` path processor (see fillet.h for the decisions).
#include <coverkit/optimise/fillet.h>

#include "sweeps.h"

#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/fillet.h>
#include <coverkit/geometry/validate.h>

#include <algorithm>
#include <cmath>

namespace coverkit::optimise {

std::string FilletProcessor::description() const {
  return "replaces each corner by the largest tangent arc of radius <= max_radius x r that keeps exact clearance (and, by "
         "default, everything the corner swept)";
}

std::vector<planners::ParamSpec> FilletProcessor::params() const {
  return detail::withCoverageGuard({{"max_radius", planners::ParamType::kDouble, "1", "0.001:100", "the largest fillet radius, in robot radii"}});
}

namespace {

using detail::dist;
using detail::distToPiece;
using detail::exactOf;
using detail::Sweeps;


/// The point a fraction t of the way along a piece, and the heading there.
PointD pointOn(const PathSegment& s, double t) {
  if (s.kind == PathSegment::Kind::kLine) return {s.from.x + t * (s.to.x - s.from.x), s.from.y + t * (s.to.y - s.from.y)};
  const double a0 = std::atan2(s.from.y - s.center.y, s.from.x - s.center.x), rho = dist(s.from, s.center);
  double sweep = std::remainder(std::atan2(s.to.y - s.center.y, s.to.x - s.center.x) - a0, 2 * M_PI);
  if (s.ccw && sweep < 0) sweep += 2 * M_PI;
  if (!s.ccw && sweep > 0) sweep -= 2 * M_PI;
  const double a = a0 + t * sweep;
  return {s.center.x + rho * std::cos(a), s.center.y + rho * std::sin(a)};
}
double headingAt(const PathSegment& s, double t) {
  if (s.kind == PathSegment::Kind::kLine) return headingOf(s, false);
  const PointD p = pointOn(s, t);
  return std::atan2(p.y - s.center.y, p.x - s.center.x) + (s.ccw ? M_PI / 2 : -M_PI / 2);
}

bool clearPiece(ClearanceChecker& check, const PathSegment& s) {
  if (s.kind == PathSegment::Kind::kLine) return check.clear(exactOf(s.from), exactOf(s.to));
  return check.clearArc(exactOf(s.from), exactOf(s.to), exactOf(s.center), s.ccw);
}

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
    const detail::FreeSpace free(problem.workspace, rq, keepCoverage);
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
      const PathSegment cut1 = cur.kind == PathSegment::Kind::kLine ? PathSegment::line(a2.to, cur.to)
                                                                    : PathSegment::arc(a2.to, cur.to, cur.center, cur.ccw);
      const PathSegment cut2 = next.kind == PathSegment::Kind::kLine ? PathSegment::line(next.from, b2.from)
                                                                     : PathSegment::arc(next.from, b2.from, next.center, next.ccw);
      std::vector<PointD> samples;
      const PointD c = cur.to;
      for (int a = 0; a < 24; ++a)
        for (double f3 : {reach / 3, 2 * reach / 3, reach})
          samples.push_back({c.x + f3 * r * std::cos(a * M_PI / 12), c.y + f3 * r * std::sin(a * M_PI / 12)});
      for (const PathSegment* s : {&cut1, &cut2})
        for (double t : {0.25, 0.5, 0.75, 1.0}) {
          const PointD p = pointOn(*s, t);
          const double h = headingAt(*s, t) + M_PI / 2;
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
    const FilletCount n = roundCorners(segs, 0, {maxRadius, maxRadius / 1024, 5, 1, 179, true}, room, accept, made);
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
