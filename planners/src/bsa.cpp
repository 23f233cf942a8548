// BSA with A* backtracking. See bsa.h for the reference and the decisions.
#include <coverkit/graph/grid_graph.h>
#include <coverkit/graph/grid_search.h>
#include <coverkit/planners/bsa.h>

#include "walk_path.h"

#include <algorithm>
#include <chrono>
#include <limits>

namespace coverkit::planners {

namespace {

using Clock = std::chrono::steady_clock;

int directionIndex(const std::string& name) {
  const char* names[4] = {"east", "north", "west", "south"};
  for (int d = 0; d < 4; ++d)
    if (name == names[d]) return d;
  return 1;
}

/// Backtracking points in buckets of B×B cells; the nearest valid one by octile distance is found
/// by searching rings of buckets outwards from the robot's bucket, dropping stale points on the way.
class PointIndex {
public:
  static constexpr int kB = 16;
  PointIndex(int cols, int rows) : cols_(cols), bc_((cols + kB - 1) / kB), br_((rows + kB - 1) / kB), buckets_(static_cast<std::size_t>(bc_) * br_) {}

  void add(int cell) {
    buckets_[static_cast<std::size_t>(bucketOf(cell))].push_back(cell);
    ++size_;
  }
  std::size_t size() const { return size_; }

  /// The nearest point for which `valid` holds (others are dropped), or −1.
  template <class Valid>
  int nearest(int from, Valid valid) {
    const int fc = from % cols_, fr = from / cols_, bx = fc / kB, by = fr / kB;
    double best = std::numeric_limits<double>::infinity();
    int bestCell = -1;
    for (int ring = 0; ring <= std::max(bc_, br_); ++ring) {
      if (size_ == 0) break;
      // every cell in ring k is at least (k − 1)·B + 1 cells away in x or y
      if (bestCell >= 0 && static_cast<double>((ring - 1) * kB) > best) break;
      for (int y = by - ring; y <= by + ring; ++y)
        for (int x = bx - ring; x <= bx + ring; ++x) {
          if (x < 0 || y < 0 || x >= bc_ || y >= br_ || (std::abs(x - bx) != ring && std::abs(y - by) != ring)) continue;
          auto& b = buckets_[static_cast<std::size_t>(y * bc_ + x)];
          for (std::size_t i = 0; i < b.size();) {
            const int c = b[i];
            if (!valid(c)) {  // stale: drop it for good
              b[i] = b.back();
              b.pop_back();
              --size_;
              continue;
            }
            const double dx = std::abs(c % cols_ - fc), dy = std::abs(c / cols_ - fr);
            const double d = dx + dy + (std::sqrt(2.0) - 2.0) * std::min(dx, dy);
            if (d < best || (d == best && c < bestCell)) {
              best = d;
              bestCell = c;
            }
            ++i;
          }
        }
    }
    return bestCell;
  }

private:
  int bucketOf(int cell) const { return (cell / cols_) / kB * bc_ + (cell % cols_) / kB; }
  int cols_, bc_, br_;
  std::vector<std::vector<int>> buckets_;
  std::size_t size_ = 0;
};

}  // namespace

std::string BsaPlanner::description() const {
  return std::string("BSA with A* backtracking (MM Science Journal 2024), offline: ") +
         (filling_ == Filling::kSpiral ? "spiral filling by the reference-lateral-side rules" : "zigzag filling, first free cell counter-clockwise") +
         ", backtracking points, A* on the 8-connected grid (octile heuristic) to the nearest one";
}

std::vector<ParamSpec> BsaPlanner::params() const {
  if (filling_ == Filling::kSpiral)
    return {{"side", ParamType::kChoice, "left", "left|right", "the reference lateral side the spiral keeps turning to (RLS)"}};
  return {{"first", ParamType::kChoice, "north", "north|west|south|east",
           "the direction the counter-clockwise order starts from (north: lanes along columns)"}};
}

Capabilities BsaPlanner::capabilities() const {
  Capabilities c;
  c.coverage = "free_sub_cells";
  return c;
}

Plan BsaPlanner::plan(const PlanningContext& context, const ParamSet& params, const TerminationCondition& stop) {
  Plan plan;
  plan.planner = name();
  Point startPoint;
  CellIndex s;
  if (!beginOnCells(context, name(), true, plan, startPoint, s)) return plan;
  const int side = params.all().count("side") && params.text("side") == "right" ? -1 : 1;
  const int first = params.all().count("first") ? directionIndex(params.text("first")) : 1;

  // As for the STC family: sub-cells no double path can cross are left out and the plan made again.
  bool timedOut = false;
  std::size_t pointsRecorded = 0;
  const bool unsafe = withoutUnplaceableCells(context, s, plan, [&](const PlanningContext& ctx) -> std::vector<CellIndex> {
    const CellGrid& cells = ctx.cells;
    const auto t0 = Clock::now();
    const int cols = cells.subCols(), rows = cells.subRows();
    const std::size_t n = static_cast<std::size_t>(cols) * rows;
    auto usable = [&](int c, int r) { return c >= 0 && r >= 0 && c < cols && r < rows && cells.sub(c, r) == CellState::kFree; };
    std::vector<std::uint8_t> visited(n, 0), recorded(n, 0);
    std::vector<CellIndex> walk;
    PointIndex points(cols, rows);
    std::size_t backtracks = 0, travelMoves = 0, fillMoves = 0;
    pointsRecorded = 0;
    auto idx = [&](int c, int r) { return static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c); };
    auto freeNew = [&](CellIndex c, int d) {
      const int nc = c.col + graph::kDx[d], nr = c.row + graph::kDy[d];
      return usable(nc, nr) && !visited[idx(nc, nr)];
    };
    auto hasFreeNew = [&](CellIndex c) { return freeNew(c, 0) || freeNew(c, 1) || freeNew(c, 2) || freeNew(c, 3); };
    auto enter = [&](CellIndex c) {
      walk.push_back(c);
      visited[idx(c.col, c.row)] = 1;
    };
    // leaving c: a free unvisited neighbour left behind makes c a backtracking point
    auto leave = [&](CellIndex c) {
      if (!recorded[idx(c.col, c.row)] && hasFreeNew(c)) {
        recorded[idx(c.col, c.row)] = 1;
        points.add(static_cast<int>(idx(c.col, c.row)));
        ++pointsRecorded;
      }
    };
    CellIndex cur = s;
    enter(cur);
    int heading = filling_ == Filling::kSpiral ? 0 : first;
    graph::GridAStar astar(cols, rows, true);
    std::vector<int> explored;
    while (!timedOut) {
      // filling
      while (hasFreeNew(cur)) {  // rule 1 ends it
        int d = -1;
        if (filling_ == Filling::kSpiral) {
          for (int turns = 0; turns < 4 && d < 0; ++turns) {
            const int lateral = (heading + side + 4) & 3;
            if (freeNew(cur, lateral)) d = heading = lateral;   // rule 2
            else if (!freeNew(cur, heading)) heading = (heading - side + 4) & 3;  // rule 3
            else d = heading;                                   // rule 4
          }
        } else {
          for (int k = 0; k < 4 && d < 0; ++k)
            if (freeNew(cur, (first + k) & 3)) d = (first + k) & 3;  // rule 2
          heading = d;
        }
        if (d < 0) break;
        const CellIndex next{cur.col + graph::kDx[d], cur.row + graph::kDy[d]};
        visited[idx(next.col, next.row)] = 1;  // so that `leave` does not count the cell moved to
        leave(cur);
        cur = next;
        enter(cur);
        ++fillMoves;
      }
      // backtracking
      timedOut = stop.expired();
      const int target = points.nearest(static_cast<int>(idx(cur.col, cur.row)), [&](int c) { return hasFreeNew(CellIndex{c % cols, c / cols}); });
      if (target < 0) break;
      ++backtracks;
      const std::vector<int> path =
          astar.search(static_cast<int>(idx(cur.col, cur.row)), target, [&](int v) { return cells.sub(v % cols, v / cols) == CellState::kFree; }, explored);
      if (path.empty()) throw std::logic_error("bsa: a backtracking point is not reachable");  // cannot happen: 4-connected to a visited cell
      for (std::size_t i = 1; i < path.size(); ++i) {
        const CellIndex next{path[i] % cols, path[i] / cols};
        visited[idx(next.col, next.row)] = 1;  // cells crossed on the way are swept too
        leave(cur);
        cur = next;
        enter(cur);
        ++travelMoves;
      }
      if (filling_ == Filling::kSpiral)
        for (int k = 0; k < 4; ++k)
          if (freeNew(cur, (heading + k) & 3)) {
            heading = (heading + k) & 3;
            break;
          }
    }
    plan.timings.clear();
    plan.timings.emplace_back("walk", std::chrono::duration<double>(Clock::now() - t0).count());

    std::size_t covered = 0;
    for (std::size_t v = 0; v < n; ++v) covered += visited[v];
    plan.statistics["backtracking_points"] = static_cast<double>(pointsRecorded);
    plan.statistics["backtracks"] = static_cast<double>(backtracks);
    plan.statistics["filling_moves"] = static_cast<double>(fillMoves);
    plan.statistics["travel_moves"] = static_cast<double>(travelMoves);
    plan.statistics["covered_cells"] = static_cast<double>(covered);
    plan.statistics["astar_expansions"] = static_cast<double>(astar.expansions);
    plan.statistics["start_col"] = s.col;
    plan.statistics["start_row"] = s.row;
    plan.statistics["end_col"] = cur.col;
    plan.statistics["end_row"] = cur.row;

    const auto t1 = Clock::now();
    PlacedWalk placed = placeWalk(ctx, walk, startPoint, false);
    plan.timings.emplace_back("path", std::chrono::duration<double>(Clock::now() - t1).count());
    plan.statistics["moves_repaired"] = static_cast<double>(placed.repairedMoves);
    plan.statistics["moves_unsafe"] = static_cast<double>(placed.unsafeMoves);
    if (!placed.startClear) {
      plan.status = PlanStatus::kInvalidStart;
      plan.message = "no double start point near the start is clear (its sub-cell is squeezed to exactly 2r at a centre that is not a double), or the disc cannot move straight from the start to the centre of its sub-cell";
      return {};
    }
    plan.paths[0] = std::move(placed.path);
    plan.status = PlanStatus::kExactSolution;
    return timedOut ? std::vector<CellIndex>{} : placed.unsafeCells;
  });
  if (plan.status == PlanStatus::kInvalidStart) return plan;
  if (timedOut) {
    plan.status = PlanStatus::kTimeout;
    plan.message = "time limit reached";
  } else if (unsafe) {
    plan.status = PlanStatus::kPartialCoverage;
    plan.message = formatDouble(plan.statistics["moves_unsafe"]) + " moves have no exactly safe double coordinates";
  } else {
    plan.message = "visited every free sub-cell 4-connected to the start's; " + std::to_string(pointsRecorded) + " backtracking points";
  }
  return plan;
}

}  // namespace coverkit::planners
