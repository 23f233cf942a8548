// See team_steps.h.
#include "team_steps.h"

#include <coverkit/geometry/error.h>
#include <coverkit/geometry/validate.h>
#include <coverkit/planners/multi_stc.h>

#include <algorithm>
#include <cmath>
#include <deque>

namespace coverkit::planners {

bool StepTiming::clear(std::size_t robot, PointD a, PointD b, double t0, double t1) const {
  for (std::size_t m = 0; m < problem->movingObstacles.size(); ++m)
    if (!clearOf(robot, m, a, b, t0, t1)) return false;
  return true;
}

bool StepTiming::clearOf(std::size_t robot, std::size_t obstacle, PointD a, PointD b, double t0, double t1) const {
  const MovingObstacle& m = problem->movingObstacles[obstacle];
  return movesClearOf(a, b, t0, t1, m, problem->robots[robot].radius + m.radius);
}

StepTiming makeStepTiming(const PlanningContext& ctx, double step) {
  const CellGrid& cells = ctx.cells;
  StepTiming timing{&ctx.problem, std::vector<double>(static_cast<std::size_t>(cells.subCols())),
                    std::vector<double>(static_cast<std::size_t>(cells.subRows())), step};
  for (int c = 0; c < cells.subCols(); ++c) timing.x[static_cast<std::size_t>(c)] = stcWaypoint(cells, c, 0).x;
  for (int r = 0; r < cells.subRows(); ++r) timing.y[static_cast<std::size_t>(r)] = stcWaypoint(cells, 0, r).y;
  return timing;
}

bool centresAreDoubles(const CellGrid& cells) {
  for (int c = 0; c < cells.subCols(); ++c)
    if (Rational(toDouble(cells.subCenter(c, 0).x)) != cells.subCenter(c, 0).x) return false;
  for (int r = 0; r < cells.subRows(); ++r)
    if (Rational(toDouble(cells.subCenter(0, r).y)) != cells.subCenter(0, r).y) return false;
  return true;
}

void checkTeamGrid(const PlanningContext& ctx, const std::string& planner) {
  const Problem& problem = ctx.problem;
  const std::size_t k = problem.robots.size();
  for (std::size_t i = 1; i < k; ++i)
    if (problem.robots[i].radius != problem.robots[0].radius)
      throw InputError("--radius", "robot " + std::to_string(i), planner + " plans for a team of equal discs");
  if (k < 2) return;
  // Two robots side by side are exactly D apart at sub-cell centres. Where a centre is not a
  // double, STC's rounding (towards the mega-cell's centre, which keeps the disc off the walls)
  // brings the two robots of one mega-cell an ulp nearer than D; with D = 2r no double placement
  // is both clear of walls and 2r from the other robot. So a team needs centres that are doubles,
  // or a sub-cell a little larger than 2r.
  const CellGrid& cells = ctx.cells;
  const bool doubles = centresAreDoubles(cells);
  const Box box = problem.workspace.bbox();
  const double far = std::max({std::abs(box.xmin.get_d()), std::abs(box.xmax.get_d()), std::abs(box.ymin.get_d()), std::abs(box.ymax.get_d()), 1.0});
  const double slack = Rational(cells.subSize() - 2 * problem.robots[0].radius).get_d();
  if (!doubles && !(slack > 8 * (std::nextafter(far, HUGE_VAL) - far)))
    throw InputError(problem.cellSize ? "--cell-size" : "--radius", problem.cellSize ? problem.cellSize->get_str() : problem.robots[0].radius.get_str(),
                     "a team on this grid: its sub-cell centres are not doubles, so two robots side by side would be an ulp nearer "
                     "than 2r; use a radius whose sub-cell centres are doubles (a dyadic one such as 1/4 on a dyadic grid) or a "
                     "--cell-size a little larger than 2r");
}

void writeTimedPaths(const Problem& problem, const StepTiming& timing, const std::vector<std::vector<CellIndex>>& route, Plan& plan) {
  const std::size_t k = route.size();
  const double step = timing.step;
  plan.paths.assign(k, Path{});
  std::size_t totalMoves = 0, most = 0, least = static_cast<std::size_t>(-1), longest = 0;
  for (std::size_t i = 0; i < k; ++i) {
    Path& p = plan.paths[i];
    p.start = {toDouble(problem.robots[i].start->x), toDouble(problem.robots[i].start->y)};
    std::vector<PointD> pts{p.start};
    p.timeline.push_back({0, p.start});
    std::size_t moves = 0;
    for (std::size_t m = 0; m < route[i].size(); ++m) {
      const PointD q = timing.centre(route[i][m]);
      p.timeline.push_back({static_cast<double>(m + 1) * step, q});
      if (m > 0 && !(route[i][m] == route[i][m - 1])) ++moves;
      if (q.x != pts.back().x || q.y != pts.back().y) pts.push_back(q);
    }
    // trailing waits say nothing: the robot stays at its last entry anyway
    while (p.timeline.size() > 1 && p.timeline.back().p.x == p.timeline[p.timeline.size() - 2].p.x &&
           p.timeline.back().p.y == p.timeline[p.timeline.size() - 2].p.y)
      p.timeline.pop_back();
    p.segments = Path::fromPoints(pts).segments;
    totalMoves += moves;
    most = std::max(most, moves);
    least = std::min(least, moves);
    longest = std::max(longest, p.timeline.size() - 1);
  }
  plan.statistics["robots"] = static_cast<double>(k);
  plan.statistics["makespan_steps"] = static_cast<double>(longest);   // the first step: onto the start's centre
  plan.statistics["makespan_s"] = static_cast<double>(longest) * step;
  plan.statistics["moves_total"] = static_cast<double>(totalMoves);
  plan.statistics["moves_most"] = static_cast<double>(most);
  plan.statistics["moves_least"] = static_cast<double>(k ? least : 0);
}

bool everyRobotHasAStart(const Problem& problem, Plan& plan) {
  for (const Robot& r : problem.robots)
    if (!r.start) {
      plan.status = PlanStatus::kNoFreeSpace;
      plan.message = "no free sub-cell for a default start";
      plan.paths.assign(problem.robots.size(), Path{});
      return false;
    }
  return true;
}

void stayAtStarts(const Problem& problem, Plan& plan) {
  const std::size_t k = problem.robots.size();
  plan.paths.assign(k, Path{});
  for (std::size_t i = 0; i < k; ++i) {
    plan.paths[i].start = {toDouble(problem.robots[i].start->x), toDouble(problem.robots[i].start->y)};
    plan.paths[i].timeline = {{0, plan.paths[i].start}};
  }
}

// Sub-cells whose centre stays within r + ρ of an obstacle's last place (blocked for good) are
// neither reachable nor crossed, and a move between neighbouring centres that passes within r + ρ
// of one is no way either (two clear centres beside a parked obstacle can have a blocked move
// between them).
MissedSubcells missedSubcells(const PlanningContext& ctx, const std::vector<Path>& paths) {
  const CellGrid& c = ctx.cells;
  const int cols = c.subCols(), rows = c.subRows();
  auto idx = [&](int x, int y) { return static_cast<std::size_t>(y) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(x); };
  std::vector<char> usable(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows), 0), entered(usable.size(), 0);
  const double r = ctx.problem.robots[0].radius.get_d();
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cols; ++x) {
      if (c.sub(x, y) != CellState::kFree) continue;
      const PointD p = c.subCenterD(x, y);
      bool parked = false;
      for (const MovingObstacle& m : ctx.problem.movingObstacles) {
        const PointD q = m.waypoints.back().p;
        parked = parked || std::hypot(p.x - q.x, p.y - q.y) < r + m.radius.get_d();
      }
      usable[idx(x, y)] = !parked;
    }
  for (const Path& path : paths) {
    auto mark = [&](PointD p) {
      CellIndex s;
      if (c.locateSubD(p, s)) entered[idx(s.col, s.row)] = 1;
    };
    mark(path.start);
    for (const TimedPoint& e : path.timeline) mark(e.p);
  }
  auto moveClear = [&](int x0, int y0, int x1, int y1) {
    const PointD a = c.subCenterD(x0, y0), b = c.subCenterD(x1, y1);
    for (const MovingObstacle& m : ctx.problem.movingObstacles) {
      const PointD q = m.waypoints.back().p;
      const double dx = b.x - a.x, dy = b.y - a.y;
      const double u = std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      if (std::hypot(a.x + u * dx - q.x, a.y + u * dy - q.y) < r + m.radius.get_d()) return false;
    }
    return true;
  };
  // breadth first from the sources (sub-cells, or not located: skipped) over usable sub-cells
  auto count = [&](const std::vector<std::pair<bool, CellIndex>>& sources) {
    std::vector<char> seen(usable.size(), 0);
    std::deque<CellIndex> open;
    for (const auto& [located, s] : sources)
      if (located && !seen[idx(s.col, s.row)]) {
        seen[idx(s.col, s.row)] = 1;
        open.push_back(s);
      }
    std::size_t missed = 0;
    while (!open.empty()) {
      const CellIndex v = open.front();
      open.pop_front();
      missed += usable[idx(v.col, v.row)] && !entered[idx(v.col, v.row)] ? 1 : 0;
      for (int d = 0; d < 4; ++d) {
        const int x = v.col + (d == 0) - (d == 2), y = v.row + (d == 1) - (d == 3);
        if (x < 0 || y < 0 || x >= cols || y >= rows || !usable[idx(x, y)] || seen[idx(x, y)] || !moveClear(v.col, v.row, x, y)) continue;
        seen[idx(x, y)] = 1;
        open.push_back({x, y});
      }
    }
    return missed;
  };
  std::vector<std::pair<bool, CellIndex>> starts, team;
  for (const Robot& robot : ctx.problem.robots) {
    CellIndex s;
    const bool located = c.locateSub(*robot.start, s);
    starts.emplace_back(located, s);
  }
  // where each robot is when the last obstacle stops (the place it reached last by then)
  double stop = 0;
  for (const MovingObstacle& m : ctx.problem.movingObstacles) stop = std::max(stop, m.waypoints.back().t);
  for (const Path& path : paths) {
    PointD at = path.start;
    for (const TimedPoint& e : path.timeline)
      if (e.t <= stop) at = e.p;
    CellIndex s;
    const bool located = c.locateSubD(at, s);
    team.emplace_back(located, s);
  }
  return {count(starts), count(team)};
}


}  // namespace coverkit::planners
