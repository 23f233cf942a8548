#include "helpers/checkers.h"

#include <cmath>
#include <sstream>

namespace coverkit::testing_helpers {

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

::testing::AssertionResult coversStartComponent(const planners::PlanningContext& ctx, const Plan& plan) {
  const CellGrid& cells = ctx.cells;
  CellIndex s;
  if (!cells.locateSub(*ctx.problem.robots[0].start, s)) return ::testing::AssertionFailure() << "start outside the grid";
  const int mc = cells.megaCols(), mr = cells.megaRows();
  std::vector<char> comp(static_cast<std::size_t>(mc) * mr, 0);
  std::vector<int> stack{(s.row / 2) * mc + s.col / 2};
  if (cells.mega(s.col / 2, s.row / 2) != CellState::kFree) return ::testing::AssertionFailure() << "start mega-cell not free";
  comp[static_cast<std::size_t>(stack[0])] = 1;
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    const int c = v % mc, r = v / mc;
    const int nb[4][2] = {{c + 1, r}, {c - 1, r}, {c, r + 1}, {c, r - 1}};
    for (auto& n : nb) {
      if (!cells.insideMega(n[0], n[1]) || cells.mega(n[0], n[1]) != CellState::kFree) continue;
      const int u = n[1] * mc + n[0];
      if (comp[static_cast<std::size_t>(u)]) continue;
      comp[static_cast<std::size_t>(u)] = 1;
      stack.push_back(u);
    }
  }
  // entered sub-cells from the path's polyline (independent of the metrics' code path: dense sampling)
  std::vector<char> seen(cells.subCount(), 0);
  const double D = cells.subSizeD();
  for (const Path& p : plan.paths) {
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
  std::size_t missing = 0;
  std::ostringstream first;
  for (int r = 0; r < cells.subRows(); ++r)
    for (int c = 0; c < cells.subCols(); ++c)
      if (comp[static_cast<std::size_t>(r / 2) * mc + c / 2] && !seen[static_cast<std::size_t>(r) * cells.subCols() + c]) {
        if (missing++ == 0) first << "(" << c << "," << r << ")";
      }
  if (missing) return ::testing::AssertionFailure() << missing << " sub-cells of the start's component not entered, first " << first.str();
  return ::testing::AssertionSuccess();
}

planners::PlanningContext contextFor(const Workspace& w, const Rational& radius, std::optional<Point> start) {
  Problem p;
  p.workspace = w;
  p.robots.push_back({radius, start});
  return planners::makeContext(p);
}

}  // namespace coverkit::testing_helpers
