// TRACC. See tracc.h for the reference and the decisions.
#include <coverkit/graph/grid_search.h>
#include <coverkit/planners/sensor.h>
#include <coverkit/planners/tracc.h>

#include "walk_path.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>

namespace coverkit::planners {

namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

std::string TraccPlanner::description() const {
  return "TRACC (Thiayarajan & Balaji 2012), online: senses the four neighbour cells, follows a boustrophedon flow "
         "over the sub-cells, detours by A* around cells known to be unsafe, reports unsafe and enclosed cells";
}

std::vector<ParamSpec> TraccPlanner::params() const {
  return {{"flow", ParamType::kChoice, "rows", "rows|columns",
           "the boustrophedon flow path: along rows (the paper's Fig. 2) or along columns"}};
}

Capabilities TraccPlanner::capabilities() const {
  Capabilities c;
  c.online = true;
  c.coverage = "free_sub_cells";
  return c;
}

Plan TraccPlanner::plan(const PlanningContext& ctx, const ParamSet& params, const TerminationCondition& stop) {
  Plan plan;
  plan.planner = name();
  Point start;
  CellIndex s;
  if (!beginOnCells(ctx, name(), true, plan, start, s)) return plan;
  // Sub-cells squeezed to exactly 2r at a centre that is not a double cannot be crossed by any
  // double path (walk_path.h): the run is made again with them blocked, as the STC family does.
  withoutUnplaceableCells(ctx, s, plan, [&](const PlanningContext& c) {
    std::vector<CellIndex> unsafeCells;
    plan.timings.clear();
    runOnce(c, s, params, stop, plan, unsafeCells);
    return unsafeCells;
  });
  return plan;
}

void TraccPlanner::runOnce(const PlanningContext& ctx, CellIndex s, const ParamSet& params, const TerminationCondition& stop, Plan& plan,
                           std::vector<CellIndex>& unsafeCells) const {
  const CellGrid& cells = ctx.cells;
  const Point startPoint = *ctx.problem.robots.at(0).start;
  auto t0 = Clock::now();
  const int cols = cells.subCols(), rows = cells.subRows();
  const std::size_t n = static_cast<std::size_t>(cols) * rows;
  auto id = [&](CellIndex c) { return c.row * cols + c.col; };
  auto cellOf = [&](int v) { return CellIndex{v % cols, v / cols}; };
  enum : std::uint8_t { kUnknown = 0, kSafe = 1, kUnsafe = 2 };
  std::vector<std::uint8_t> known(n, kUnknown), unreachable(n, 0);
  std::vector<std::uint32_t> entries(n, 0);
  CellSensor sensor(cells, s);
  std::vector<CellIndex> walk;
  auto arrive = [&](CellIndex c) {
    walk.push_back(c);
    ++entries[static_cast<std::size_t>(id(c))];
    for (int d = 0; d < 4; ++d) {
      const int nc = c.col + graph::kDx[d], nr = c.row + graph::kDy[d];
      if (nc < 0 || nr < 0 || nc >= cols || nr >= rows) continue;
      std::uint8_t& k = known[static_cast<std::size_t>(nr * cols + nc)];
      if (k == kUnknown) k = sensor.neighbourFree(c, d) ? kSafe : kUnsafe;
    }
  };
  auto moveTo = [&](CellIndex c) {
    sensor.moveTo(c);
    arrive(c);
  };
  known[static_cast<std::size_t>(id(s))] = kSafe;
  arrive(s);

  // the cells that meet the map's bounding box: the grid is padded to whole mega-cells, and the
  // padding (outside W) is neither in the flow nor in the report
  const Box box = ctx.problem.workspace.bbox();
  auto cellsIn = [&](const Rational& extent) {
    const Rational q = extent / cells.subSize();
    mpz_class whole = q.get_num() / q.get_den();
    if (whole * q.get_den() != q.get_num()) whole += 1;  // ceil for positive q
    return static_cast<int>(whole.get_si());
  };
  const int boxCols = std::min(cols, cellsIn(box.xmax - cells.originX())), boxRows = std::min(rows, cellsIn(box.ymax - cells.originY()));
  // the flow: boustrophedon over every row (or column), from the start's place in it onwards
  const bool byRows = params.text("flow") == "rows";
  std::vector<int> flow;
  flow.reserve(static_cast<std::size_t>(boxCols) * static_cast<std::size_t>(boxRows));
  const int lines = byRows ? boxRows : boxCols, along = byRows ? boxCols : boxRows;
  for (int l = 0; l < lines; ++l)
    for (int k = 0; k < along; ++k) {
      const int a = (l % 2 == 0) ? k : along - 1 - k;
      flow.push_back(byRows ? l * cols + a : a * cols + l);
    }
  const std::size_t at = static_cast<std::size_t>(std::find(flow.begin(), flow.end(), id(s)) - flow.begin());
  const std::size_t nFlow = flow.size();

  graph::GridAStar astar(cols, rows, false);
  std::vector<int> explored;
  std::size_t detours = 0, replans = 0;
  bool timedOut = false;
  for (std::size_t k = 1; k < nFlow && !timedOut; ++k) {
    const int f = flow[(at + k) % nFlow];
    const auto fu = static_cast<std::size_t>(f);
    if (entries[fu] || known[fu] == kUnsafe || unreachable[fu]) continue;
    const CellIndex here = sensor.here(), target = cellOf(f);
    if (known[fu] == kSafe && std::abs(here.col - target.col) + std::abs(here.row - target.row) == 1) {
      moveTo(target);
      continue;
    }
    // a detour (or the way to a flow cell that is not next to the robot)
    ++detours;
    while (!timedOut) {
      timedOut = stop.expired();
      // the search starts at the target: a failure has explored exactly the target's side
      const std::vector<int> path =
          astar.search(id(sensor.here()), f, [&](int v) { return known[static_cast<std::size_t>(v)] != kUnsafe; }, explored);
      if (path.empty()) {  // the target's side does not reach the robot: mark it once
        for (int v : explored) unreachable[static_cast<std::size_t>(v)] = 1;
        break;
      }
      bool blocked = false;
      for (std::size_t i = 1; i < path.size(); ++i) {
        if (known[static_cast<std::size_t>(path[i])] == kUnsafe) {  // sensed on the way: plan again
          blocked = true;
          ++replans;
          break;
        }
        moveTo(cellOf(path[i]));
      }
      if (!blocked || known[fu] == kUnsafe) break;
    }
  }
  // STEP2 of Table 2: every unchecked cell with a safe neighbour is visited. With a flow over every
  // row there is none left (a safe cell is reachable, so it was entered and its neighbours sensed);
  // the loop stays as the paper's end phase and its count is reported.
  std::size_t endVisits = 0;
  for (std::size_t v = 0; v < n && !timedOut; ++v) {
    if (known[v] != kUnknown) continue;
    const CellIndex c = cellOf(static_cast<int>(v));
    for (int d = 0; d < 4; ++d) {
      const int nc = c.col + graph::kDx[d], nr = c.row + graph::kDy[d];
      if (nc < 0 || nr < 0 || nc >= cols || nr >= rows || known[static_cast<std::size_t>(nr * cols + nc)] != kSafe) continue;
      const std::vector<int> path = astar.search(id(sensor.here()), nr * cols + nc, [&](int u) { return known[static_cast<std::size_t>(u)] == kSafe; }, explored);
      for (std::size_t i = 1; i < path.size(); ++i) moveTo(cellOf(path[i]));
      ++endVisits;
      break;
    }
  }
  plan.timings.emplace_back("walk", std::chrono::duration<double>(Clock::now() - t0).count());

  // the end report, over the cells that meet the map's bounding box
  std::size_t unsafe = 0, unchecked = 0, covered = 0, overlapped = 0, unreachedFree = 0;
  for (std::size_t v = 0; v < n; ++v) {
    covered += entries[v] > 0;
    overlapped += entries[v] > 1;
    unreachedFree += entries[v] == 0 && cells.sub(static_cast<int>(v % static_cast<std::size_t>(cols)), static_cast<int>(v / static_cast<std::size_t>(cols))) == CellState::kFree;
    if (static_cast<int>(v % static_cast<std::size_t>(cols)) >= boxCols || static_cast<int>(v / static_cast<std::size_t>(cols)) >= boxRows) continue;
    unsafe += known[v] == kUnsafe;
    unchecked += known[v] == kUnknown;
  }
  plan.statistics["unsafe_cells"] = static_cast<double>(unsafe);
  plan.statistics["unchecked_cells"] = static_cast<double>(unchecked);
  plan.statistics["covered_cells"] = static_cast<double>(covered);
  plan.statistics["end_phase_visits"] = static_cast<double>(endVisits);
  plan.statistics["unreached_free_cells"] = static_cast<double>(unreachedFree);  // ground truth: enclosed free cells
  plan.statistics["redundancy_rate"] = covered ? 100.0 * static_cast<double>(overlapped) / static_cast<double>(covered) : 0.0;
  plan.statistics["detours"] = static_cast<double>(detours);
  plan.statistics["replans"] = static_cast<double>(replans);
  plan.statistics["astar_expansions"] = static_cast<double>(astar.expansions);
  plan.statistics["sensor_queries"] = static_cast<double>(sensor.log().size());
  plan.statistics["start_col"] = s.col;
  plan.statistics["start_row"] = s.row;
  plan.statistics["end_col"] = sensor.here().col;
  plan.statistics["end_row"] = sensor.here().row;

  auto t1 = Clock::now();
  PlacedWalk placed = placeWalk(ctx, walk, startPoint, false);
  unsafeCells = placed.unsafeCells;
  plan.timings.emplace_back("path", std::chrono::duration<double>(Clock::now() - t1).count());
  if (!placed.startClear) {
    plan.status = PlanStatus::kInvalidStart;
    plan.message = "no double start point near the start is clear (its sub-cell is squeezed to exactly 2r at a centre that is not a double), or the disc cannot move straight from the start to the centre of its sub-cell";
    return;
  }
  plan.paths[0] = std::move(placed.path);
  plan.statistics["moves_repaired"] = static_cast<double>(placed.repairedMoves);
  plan.statistics["moves_unsafe"] = static_cast<double>(placed.unsafeMoves);
  if (timedOut) {
    plan.status = PlanStatus::kTimeout;
    plan.message = "time limit reached during the flow";
  } else if (placed.unsafeMoves > 0) {
    plan.status = PlanStatus::kPartialCoverage;
    plan.message = std::to_string(placed.unsafeMoves) + " moves squeezed to exactly 2r have no exactly safe double coordinates";
  } else {
    plan.status = PlanStatus::kExactSolution;
    plan.message = "entered every free sub-cell 4-connected to the start's; " + std::to_string(unsafe) + " unsafe cells, " +
                   std::to_string(unchecked) + " never sensed (inside obstacles, outside W or enclosed), " + std::to_string(unreachedFree) + " free cells unreached";
  }
}

}  // namespace coverkit::planners
