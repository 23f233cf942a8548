// The `smooth` path processor (see smooth.h for the objective and the decisions).
#include <coverkit/optimise/smooth.h>

#include "sweeps.h"

#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/fillet.h>
#include <coverkit/geometry/validate.h>

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace coverkit::optimise {

std::string SmoothProcessor::description() const {
  return "moves the vertices of a path's line stretches (Ceres least squares: second differences, a pull to the plan's "
         "vertices, a clearance barrier), every new piece checked exactly, coverage and total turning kept";
}

std::vector<planners::ParamSpec> SmoothProcessor::params() const {
  return detail::withCoverageGuard({
      {"max_move", planners::ParamType::kDouble, "0.25", "0:10", "the farthest a vertex moves, in robot radii"},
      {"deviation", planners::ParamType::kDouble, "0.1", "0:1000", "the weight of staying at the plan's vertices"},
      {"margin", planners::ParamType::kDouble, "0.02", "0:1", "the barrier's margin beyond r, in robot radii"},
      {"iterations", planners::ParamType::kInt, "50", "1:10000", "Ceres iterations per stretch, at most"}});
}

namespace {

using detail::dist;
using detail::exactOf;
using detail::Sweeps;
using Vec = std::array<double, 2>;


struct Edge {
  double ax, ay, bx, by;
};

/// The workspace's edges (outer rings and holes) in a grid of cell size `cell`.
class Edges {
public:
  Edges(const Workspace& w, double cell) : grid_(cell) {
    for (const Ring* ring : w.rings())
      for (std::size_t i = 0; i < ring->size(); ++i) {
        const Point &a = (*ring)[i], &b = (*ring)[(i + 1) % ring->size()];
        edges_.push_back({a.x.get_d(), a.y.get_d(), b.x.get_d(), b.y.get_d()});
      }
    stamp_.assign(edges_.size(), 0);
    for (std::size_t k = 0; k < edges_.size(); ++k) {
      const Edge& e = edges_[k];
      grid_.add(k, {std::min(e.ax, e.bx), std::min(e.ay, e.by), std::max(e.ax, e.bx), std::max(e.ay, e.by)});
    }
  }
  /// The edges whose cells meet the box of p ± reach (each once, in index order: the same
  /// residuals in the same order on every run).
  std::vector<std::size_t> near(PointD p, double reach) {
    ++now_;
    std::vector<std::size_t> out;
    grid_.any(p, reach, [&](std::size_t k) {
      if (stamp_[k] != now_) {
        stamp_[k] = now_;
        out.push_back(k);
      }
      return false;
    });
    std::sort(out.begin(), out.end());
    return out;
  }
  const Edge& operator[](std::size_t k) const { return edges_[k]; }

private:
  std::vector<Edge> edges_;
  detail::BoxGrid grid_;
  std::vector<unsigned> stamp_;
  unsigned now_ = 0;
};

template <typename T>
T distToEdge(const T* p, const Edge& e) {
  const double dx = e.bx - e.ax, dy = e.by - e.ay, l2 = dx * dx + dy * dy;
  T t = l2 > 0 ? ((p[0] - e.ax) * dx + (p[1] - e.ay) * dy) / l2 : T(0);
  if (t < T(0)) t = T(0);
  if (t > T(1)) t = T(1);
  const T ex = p[0] - (e.ax + t * dx), ey = p[1] - (e.ay + t * dy);
  using std::sqrt;
  return sqrt(ex * ex + ey * ey + 1e-300);
}

struct SecondDifference {
  double scale;
  template <typename T>
  bool operator()(const T* a, const T* b, const T* c, T* res) const {
    res[0] = (a[0] - 2.0 * b[0] + c[0]) * scale;
    res[1] = (a[1] - 2.0 * b[1] + c[1]) * scale;
    return true;
  }
};

struct Deviation {
  Vec at;
  double scale;
  template <typename T>
  bool operator()(const T* q, T* res) const {
    res[0] = (q[0] - at[0]) * scale;
    res[1] = (q[1] - at[1]) * scale;
    return true;
  }
};

/// max(0, need − d(p, e)), p a vertex (b == nullptr) or the middle of a piece.
struct Barrier {
  Edge e;
  double need, scale;
  template <typename T>
  bool operator()(const T* a, const T* b, T* res) const {
    T p[2] = {a[0], a[1]};
    if (b) {
      p[0] = (a[0] + b[0]) * 0.5;
      p[1] = (a[1] + b[1]) * 0.5;
    }
    const T d = distToEdge(p, e);
    res[0] = d < T(need) ? (T(need) - d) * scale : T(0);
    return true;
  }
};
struct VertexBarrier {
  Barrier bar;
  template <typename T>
  bool operator()(const T* a, T* res) const { return bar(a, static_cast<const T*>(nullptr), res); }
};

/// The joints of segs[from, to): their total turning (radians) and how many turn by more than
/// 150° (metrics.h's reversals).
struct Turning {
  double total = 0;
  std::size_t reversals = 0;
};
Turning turningOf(const std::vector<PathSegment>& segs, std::size_t from, std::size_t to) {
  Turning t;
  for (std::size_t i = from; i + 1 < to; ++i) {
    const double a = std::abs(turnAt(segs[i], segs[i + 1]));
    t.total += a;
    t.reversals += a > 150 * M_PI / 180;
  }
  return t;
}

}  // namespace

Plan SmoothProcessor::process(const Problem& problem, const Plan& plan, const planners::ParamSet& params) const {
  Plan out = plan;
  out.statistics.clear();
  std::size_t stretches = 0, vertices = 0, iterations = 0, revertedClearance = 0, revertedCoverage = 0, revertedTurning = 0;
  double costBefore = 0, costAfter = 0;
  const bool keepCoverage = params.flag("keep_coverage");
  const double reach = 1 - params.number("rim");
  for (std::size_t k = 0; k < plan.paths.size(); ++k) {
    const Rational& rq = problem.robots.at(k).radius;
    const double r = rq.get_d();
    ClearanceChecker check(problem.workspace, rq);
    const detail::FreeSpace free(problem.workspace, rq, keepCoverage);
    Edges edges(problem.workspace, r);
    std::vector<PathSegment> segs;
    for (const PathSegment& s : plan.paths[k].segments)
      if (!(s.kind == PathSegment::Kind::kLine && s.from.x == s.to.x && s.from.y == s.to.y)) segs.push_back(s);
    Sweeps sweeps(segs, r);
    const auto isLine = [&](std::size_t i) { return segs[i].kind == PathSegment::Kind::kLine; };
    for (std::size_t a = 0; a < segs.size();) {
      if (!isLine(a)) {
        ++a;
        continue;
      }
      std::size_t b = a;
      while (b < segs.size() && isLine(b)) ++b;   // pieces [a, b): lines; vertices a .. b
      const std::size_t n = b - a;
      std::vector<Vec> q0(n + 1);
      for (std::size_t i = 0; i < n; ++i) q0[i] = {segs[a + i].from.x, segs[a + i].from.y};
      q0[n] = {segs[b - 1].to.x, segs[b - 1].to.y};
      std::vector<bool> fixed(n + 1, false);
      fixed[0] = fixed[n] = true;
      for (std::size_t i = 1; i < n; ++i) fixed[i] = std::abs(turnAt(segs[a + i - 1], segs[a + i])) >= 150 * M_PI / 180;
      const std::size_t movable = static_cast<std::size_t>(std::count(fixed.begin(), fixed.end(), false));
      if (movable == 0) {
        a = b;
        continue;
      }
      ++stretches;
      vertices += movable;
      const std::vector<PathSegment> old(segs.begin() + static_cast<std::ptrdiff_t>(a), segs.begin() + static_cast<std::ptrdiff_t>(b));
      const Turning before = turningOf(segs, a > 0 ? a - 1 : a, std::min(segs.size(), b + 1));
      double margin = params.number("margin") * r, maxMove = params.number("max_move") * r;
      bool kept = false;
      int why = 0;   // 1 clearance, 2 coverage, 3 turning
      for (int attempt = 0; attempt < 8 && !kept; ++attempt) {
        std::vector<Vec> q = q0;
        ceres::Problem prob;
        const double s = 1 / r, wd = std::sqrt(params.number("deviation")) / r, wb2 = 10 / r;
        for (std::size_t i = 0; i <= n; ++i) prob.AddParameterBlock(q[i].data(), 2);
        for (std::size_t i = 1; i < n; ++i)
          prob.AddResidualBlock(new ceres::AutoDiffCostFunction<SecondDifference, 2, 2, 2, 2>(new SecondDifference{s}), nullptr,
                                q[i - 1].data(), q[i].data(), q[i + 1].data());
        for (std::size_t i = 0; i <= n; ++i) {
          if (fixed[i]) {
            prob.SetParameterBlockConstant(q[i].data());
            continue;
          }
          prob.AddResidualBlock(new ceres::AutoDiffCostFunction<Deviation, 2, 2>(new Deviation{q0[i], wd}), nullptr, q[i].data());
          for (std::size_t e : edges.near({q0[i][0], q0[i][1]}, r + margin + maxMove))
            prob.AddResidualBlock(new ceres::AutoDiffCostFunction<VertexBarrier, 1, 2>(new VertexBarrier{{edges[e], r + margin, wb2}}), nullptr,
                                  q[i].data());
        }
        for (std::size_t i = 0; i < n; ++i) {
          if (fixed[i] && fixed[i + 1]) continue;
          const PointD mid{(q0[i][0] + q0[i + 1][0]) / 2, (q0[i][1] + q0[i + 1][1]) / 2};
          const double half = dist({q0[i][0], q0[i][1]}, {q0[i + 1][0], q0[i + 1][1]}) / 2;
          for (std::size_t e : edges.near(mid, r + margin + maxMove + half))
            prob.AddResidualBlock(new ceres::AutoDiffCostFunction<Barrier, 1, 2, 2>(new Barrier{edges[e], r + margin, wb2}), nullptr,
                                  q[i].data(), q[i + 1].data());
        }
        ceres::Solver::Options opt;
        opt.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
        opt.max_num_iterations = static_cast<int>(params.integer("iterations"));
        opt.num_threads = 1;   // the same result on every machine and run
        opt.logging_type = ceres::SILENT;
        opt.minimizer_progress_to_stdout = false;
        ceres::Solver::Summary sum;
        ceres::Solve(opt, &prob, &sum);
        iterations += sum.iterations.size();
        // moves clamped to max_move, the new pieces
        for (std::size_t i = 0; i <= n; ++i) {
          const double dx = q[i][0] - q0[i][0], dy = q[i][1] - q0[i][1], d = std::hypot(dx, dy);
          if (fixed[i] || !std::isfinite(d)) q[i] = q0[i];
          else if (d > maxMove) q[i] = {q0[i][0] + dx * maxMove / d, q0[i][1] + dy * maxMove / d};
        }
        std::vector<PathSegment> now;
        bool degenerate = false;
        for (std::size_t i = 0; i < n; ++i) {
          now.push_back(PathSegment::line({q[i][0], q[i][1]}, {q[i + 1][0], q[i + 1][1]}));
          degenerate = degenerate || q[i] == q[i + 1];
        }
        if (degenerate) {   // two vertices met: a piece without a heading
          why = 3;
          break;
        }
        // a piece that is not clear: its two vertices stay where they were, and the rest is solved
        // again with the margin doubled
        bool clear = true;
        for (std::size_t i = 0; i < n; ++i)
          if ((q[i] != q0[i] || q[i + 1] != q0[i + 1]) && !check.clear(exactOf(now[i].from), exactOf(now[i].to))) {
            clear = false;
            fixed[i] = fixed[i + 1] = true;
          }
        if (!clear) {
          why = 1;
          margin *= 2;
          continue;
        }
        // in place, to measure the turning with the neighbours and the coverage with the rest
        std::vector<PathSegment> trial(segs.begin(), segs.begin() + static_cast<std::ptrdiff_t>(a));
        trial.insert(trial.end(), now.begin(), now.end());
        const std::size_t bNew = trial.size();
        trial.insert(trial.end(), segs.begin() + static_cast<std::ptrdiff_t>(b), segs.end());
        const Turning after = turningOf(trial, a > 0 ? a - 1 : a, std::min(trial.size(), bNew + 1));
        if (after.total > before.total + 1e-9 || after.reversals > before.reversals) {
          why = 3;
          break;   // no smaller move makes it turn less: left as it was
        }
        if (keepCoverage) {
          for (std::size_t i = 0; i < n; ++i) sweeps.replace(a + i, {now[i]});
          bool covered = true;
          for (std::size_t i = 0; i < n; ++i) {
            const PathSegment& o = old[i];
            const double h = headingOf(o, false) + M_PI / 2;
            std::vector<PointD> samples;
            for (double t : {0.0, 0.25, 0.5, 0.75}) {
              const PointD p{o.from.x + t * (o.to.x - o.from.x), o.from.y + t * (o.to.y - o.from.y)};
              for (double side : {-1.0, 1.0})
                for (double f : {reach / 2, reach}) samples.push_back({p.x + side * f * r * std::cos(h), p.y + side * f * r * std::sin(h)});
              if (t == 0.0)
                for (int d = 0; d < 16; ++d) samples.push_back({p.x + reach * r * std::cos(d * M_PI / 8), p.y + reach * r * std::sin(d * M_PI / 8)});
            }
            for (const PointD& sp : samples)
              if (free(sp) && !sweeps.sweeps(sp, r, std::numeric_limits<std::size_t>::max(), std::numeric_limits<std::size_t>::max())) {
                covered = false;   // this piece's vertices stay where they were
                fixed[i] = fixed[i + 1] = true;
                break;
              }
          }
          if (!covered) {
            for (std::size_t i = 0; i < n; ++i) sweeps.replace(a + i, {old[i]});
            why = 2;
            continue;
          }
        }
        kept = true;
        costBefore += sum.initial_cost;
        costAfter += sum.final_cost;
        segs.swap(trial);
        b = bNew;
      }
      if (!kept) {
        revertedClearance += why == 1;
        revertedCoverage += why == 2;
        revertedTurning += why == 3;
      }
      a = b;
    }
    out.paths[k].segments = std::move(segs);
  }
  out.statistics["stretches"] = static_cast<double>(stretches);
  out.statistics["vertices"] = static_cast<double>(vertices);
  out.statistics["iterations"] = static_cast<double>(iterations);
  out.statistics["cost_before"] = costBefore;
  out.statistics["cost_after"] = costAfter;
  out.statistics["stretches_reverted_clearance"] = static_cast<double>(revertedClearance);
  out.statistics["stretches_reverted_coverage"] = static_cast<double>(revertedCoverage);
  out.statistics["stretches_reverted_turning"] = static_cast<double>(revertedTurning);
  return out;
}

}  // namespace coverkit::optimise
