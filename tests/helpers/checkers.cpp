#include "helpers/checkers.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/error.h>

#include <cmath>
#include <sstream>

namespace coverkit::testing_helpers {

std::vector<std::pair<std::string, Workspace>> contractWorlds() {
  std::vector<std::pair<std::string, Workspace>> worlds;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    datasets::GridMapSpec g;
    g.width = 24 + static_cast<int>(seed) * 3;
    g.height = 20;
    g.density = 0.04 * static_cast<double>(seed % 4);
    g.clustered = seed % 2 == 0;
    g.resolution = Rational(1, 10);
    g.seed = seed;
    worlds.emplace_back("grid" + std::to_string(seed), datasets::gridToWorkspace(datasets::generateGridMap(g), "grid"));
    datasets::PolygonWorldSpec p;
    p.seed = seed;
    p.count = 8;
    p.shape = static_cast<datasets::ObstacleShape>(seed % 4);
    worlds.emplace_back("poly" + std::to_string(seed), datasets::generatePolygonWorld(p));
  }
  return worlds;
}

Workspace mixedWorld(std::uint64_t seed, int size, int obstacles) {
  datasets::PolygonWorldSpec s;
  s.width = s.height = size;
  s.count = obstacles;
  s.shape = datasets::ObstacleShape::kMixed;
  s.minSize = 1;
  s.maxSize = 2.5;
  s.seed = seed;
  return datasets::generatePolygonWorld(s);
}

Rational contractRadius(const std::string& label) { return label.rfind("grid", 0) == 0 ? Rational(1, 10) : Rational(1, 4); }

::testing::AssertionResult planIsValid(const planners::PlanningContext& ctx, const Plan& plan) {
  if (!succeeded(plan.status)) return ::testing::AssertionFailure() << "1. plan status " << toString(plan.status) << ": " << plan.message;
  if (plan.paths.size() != ctx.problem.robots.size()) return ::testing::AssertionFailure() << "2. one path per robot expected";
  const ValidationReport rep = validatePaths(ctx.problem, plan.paths);
  if (!rep.valid) {
    auto f = ::testing::AssertionFailure() << "3. validator rejects the plan:";
    for (const auto& v : rep.violations) f << "\n   [" << v.kind << "] robot " << v.robot << " segment " << v.segment << ": " << v.detail;
    return f;
  }
  return ::testing::AssertionSuccess();
}

std::vector<char> enteredSubcells(const CellGrid& cells, const Plan& plan) {
  // independent of the metrics' code path: dense sampling of the polyline
  std::vector<char> seen(cells.subCount(), 0);
  const double D = cells.subSizeD();
  for (const Path& p : plan.paths) {
    CellIndex c0;
    if (cells.locateSubD(p.start, c0)) seen[static_cast<std::size_t>(c0.row) * cells.subCols() + c0.col] = 1;  // a robot that stays put
    const auto pts = p.polyline(D / 100);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      const double len = std::hypot(pts[i + 1].x - pts[i].x, pts[i + 1].y - pts[i].y);
      const int n = std::max(1, static_cast<int>(len / (D / 10)));
      for (int k = 0; k <= n; ++k) {
        CellIndex c;
        if (cells.locateSubD({pts[i].x + (pts[i + 1].x - pts[i].x) * k / n, pts[i].y + (pts[i + 1].y - pts[i].y) * k / n}, c))
          seen[static_cast<std::size_t>(c.row) * cells.subCols() + c.col] = 1;
      }
    }
  }
  return seen;
}

namespace {
/// 4-connected flood fill over sub-cells accepted by `ok`, from `s`.
template <class Ok>
std::vector<char> flood(const CellGrid& cells, CellIndex s, Ok ok) {
  std::vector<char> comp(cells.subCount(), 0);
  if (!ok(s.col, s.row)) return comp;
  std::vector<CellIndex> stack{s};
  comp[static_cast<std::size_t>(s.row) * cells.subCols() + s.col] = 1;
  while (!stack.empty()) {
    const CellIndex v = stack.back();
    stack.pop_back();
    for (auto [dc, dr] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
      const int c = v.col + dc, r = v.row + dr;
      if (!cells.insideSub(c, r) || !ok(c, r)) continue;
      char& m = comp[static_cast<std::size_t>(r) * cells.subCols() + c];
      if (m) continue;
      m = 1;
      stack.push_back({c, r});
    }
  }
  return comp;
}
}  // namespace

::testing::AssertionResult coversCFreeComponent(const planners::PlanningContext& ctx, const Plan& plan, double minimum, double* coverage) {
  MetricOptions o;
  o.coverable = true;
  const Metrics m = computeMetrics(ctx.problem, ctx.cells, plan.paths, o);
  if (!m.hasCoverable) return ::testing::AssertionFailure() << "coverable region not computed: " << m.coverableSkipped;
  // both areas carry error bounds: the most favourable reading
  const double best = (m.coveredArea + m.areaCoverageError * m.freeArea) / std::max(1e-300, m.coverableArea - m.coverableAreaError);
  if (coverage) *coverage = m.coverableCoverage;
  if (best < minimum)
    return ::testing::AssertionFailure() << "covers " << m.coverableCoverage << " of the coverable region (at best " << best << "), below " << minimum;
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult coversWhatItClaims(const planners::PlanningContext& ctx, const Plan& plan, const std::string& coverage) {
  if (coverage == "free_sub_cells") return coversReachableSubcells(ctx, plan);
  if (coverage == "cfree_component") {
    // a plan that reports cells left behind gaps exactly 2r wide claims only the rest (the coverable
    // region counts those cells): its coverage is then checked by the planner's own tests
    const auto it = plan.statistics.find("cells_behind_exact_gaps");
    if (it != plan.statistics.end() && it->second > 0 && plan.status == PlanStatus::kPartialCoverage) return ::testing::AssertionSuccess();
    return coversCFreeComponent(ctx, plan, 0.95);
  }
  return coversStartComponent(ctx, plan);
}

::testing::AssertionResult coversStartComponent(const planners::PlanningContext& ctx, const Plan& plan) {
  const CellGrid& cells = ctx.cells;
  CellIndex s;
  if (!cells.locateSub(*ctx.problem.robots[0].start, s)) return ::testing::AssertionFailure() << "start outside the grid";
  if (cells.mega(s.col / 2, s.row / 2) != CellState::kFree) {
    // a planner that plans without a tree there (Smooth-STC passes the contours from the start,
    // StcSkeleton::planWithoutTree) claims no free mega-cell, only that it passed its component's
    // contours (how much that covers is the planner's own tests'; gaps exactly 2r wide, common on a
    // grid of 0.1 m pixels at r = 0.15, leave parts of the coverable region, as with a tree)
    if (plan.status == PlanStatus::kExactSolution && plan.message.rfind("no free mega-cell at the start", 0) == 0) {
      const auto it = plan.statistics.find("contours_passed");
      if (it != plan.statistics.end() && it->second >= 1) return ::testing::AssertionSuccess();
      return ::testing::AssertionFailure() << "planned without a tree and passed no contour";
    }
    return ::testing::AssertionFailure() << "start mega-cell not free";
  }
  // the sub-cells of the free mega-cells 4-connected to the start's
  const auto comp = flood(cells, s, [&](int c, int r) { return cells.mega(c / 2, r / 2) == CellState::kFree; });
  const auto seen = enteredSubcells(cells, plan);
  std::size_t missing = 0;
  std::ostringstream first;
  for (std::size_t i = 0; i < comp.size(); ++i)
    if (comp[i] && !seen[i] && missing++ == 0) first << "(" << i % cells.subCols() << "," << i / cells.subCols() << ")";
  if (missing) return ::testing::AssertionFailure() << missing << " sub-cells of the start's component not entered, first " << first.str();
  return ::testing::AssertionSuccess();
}

bool squeezedSubcell(const planners::PlanningContext& ctx, CellIndex c) {
  const CellGrid& cells = ctx.cells;
  auto isFree = [&](int q, int r) { return cells.insideSub(q, r) && cells.sub(q, r) == CellState::kFree; };
  // exactly 2r wide between cells that are not free (on both sides of one axis, within the 3×3
  // block around it), at a centre coordinate that is not a double: no double is safe there
  if (cells.subSize() != 2 * ctx.problem.robots[0].radius) return false;
  auto blockedSide = [&](int dc, int dr) {
    for (int k = -1; k <= 1; ++k)
      if (!isFree(c.col + dc + k * dr, c.row + dr + k * dc)) return true;
    return false;
  };
  const Point p = cells.subCenter(c.col, c.row);
  return (exactFromDouble(toDouble(p.x)) != p.x && blockedSide(-1, 0) && blockedSide(1, 0)) ||
         (exactFromDouble(toDouble(p.y)) != p.y && blockedSide(0, -1) && blockedSide(0, 1));
}

::testing::AssertionResult coversReachableSubcells(const planners::PlanningContext& ctx, const Plan& plan) {
  const CellGrid& cells = ctx.cells;
  CellIndex s;
  if (!cells.locateSub(*ctx.problem.robots[0].start, s)) return ::testing::AssertionFailure() << "start outside the grid";
  auto isFree = [&](int c, int r) { return cells.insideSub(c, r) && cells.sub(c, r) == CellState::kFree; };
  auto squeezed = [&](int c, int r) { return squeezedSubcell(ctx, {c, r}); };
  const auto reachable = flood(cells, s, isFree);
  const auto safe = flood(cells, s, [&](int c, int r) { return isFree(c, r) && !squeezed(c, r); });
  const auto seen = enteredSubcells(cells, plan);
  std::size_t missing = 0, excused = 0;
  std::ostringstream first;
  for (std::size_t i = 0; i < reachable.size(); ++i) {
    if (!reachable[i] || seen[i]) continue;
    if (!safe[i]) {
      ++excused;
      continue;
    }
    if (missing++ > 0) continue;
    const int c0 = static_cast<int>(i % static_cast<std::size_t>(cells.subCols())), r0 = static_cast<int>(i / static_cast<std::size_t>(cells.subCols()));
    first << "(" << c0 << "," << r0 << "); around it, top row first (# not free, o not entered, x squeezed):";
    for (int r = r0 + 2; r >= r0 - 2; --r) {
      first << "\n   ";
      for (int c = c0 - 2; c <= c0 + 2; ++c)
        first << (!isFree(c, r) ? '#' : squeezed(c, r) ? 'x' : seen[static_cast<std::size_t>(r) * cells.subCols() + c] ? '.' : 'o');
    }
  }
  if (missing)
    return ::testing::AssertionFailure() << missing << " reachable free sub-cells not entered, first " << first.str();
  const auto it = plan.statistics.find("subcells_left_out");
  if (excused > 0 && (it == plan.statistics.end() || it->second <= 0))
    return ::testing::AssertionFailure() << excused << " squeezed sub-cells not entered but none reported left out";
  return ::testing::AssertionSuccess();
}

/// Gabriely & Rimon's bound: length <= (n + m)·D, n covered D-cells, m covered D-cells on the
/// boundary (4-adjacent to a cell that is not free or to the grid's edge); + 2D for the start's
/// connector.
::testing::AssertionResult withinGabrielyRimonBound(const planners::PlanningContext& ctx, const Plan& plan) {
  const double length = plan.paths[0].length();
  const auto entered = testing_helpers::enteredSubcells(ctx.cells, plan);
  std::size_t n = 0, m = 0;
  for (int r = 0; r < ctx.cells.subRows(); ++r)
    for (int cc = 0; cc < ctx.cells.subCols(); ++cc) {
      if (!entered[static_cast<std::size_t>(r) * ctx.cells.subCols() + cc]) continue;
      ++n;
      bool boundary = false;
      for (auto [dc, dr] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}})
        boundary = boundary || !ctx.cells.insideSub(cc + dc, r + dr) || ctx.cells.sub(cc + dc, r + dr) != CellState::kFree;
      m += boundary;
    }
  const double D = ctx.cells.subSizeD(), bound = static_cast<double>(n + m) * D + 2 * D;
  if (length <= bound) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "length " << length << " > (n + m)·D + 2D = " << bound << " (n " << n << ", m " << m << ")";
}

std::string pathJsonOf(const Plan& plan) {
  datasets::PathDocument d;
  d.paths = plan.paths;
  return datasets::pathJson(d);
}

planners::PlanningContext contextFor(const Workspace& w, const Rational& radius, std::optional<Point> start) {
  Problem p;
  p.workspace = w;
  p.robots.push_back({radius, start});
  return planners::makeContext(p);
}

std::string inputErrorMessage(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace coverkit::testing_helpers
