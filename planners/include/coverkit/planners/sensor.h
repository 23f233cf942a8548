#pragma once
// What an online planner may know of the world: a sensor that answers, for the robot's current
// mega-cell only, whether the neighbour in a direction is free. Any other question is refused with
// an exception (never a silent answer), and every question is logged, so tests can prove that an
// online planner is online.
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/types.h>
#include <coverkit/graph/grid_graph.h>

#include <array>
#include <cstdlib>
#include <functional>
#include <stdexcept>
#include <vector>

namespace coverkit::planners {

class MegaCellSensor {
public:
  struct Query {
    int from, direction;
    bool answer;
  };

  MegaCellSensor(const graph::GridGraph& world, int start) : world_(world), here_(start) {}

  /// Is the mega-cell next to `cell` in `direction` free (and its shared border open)?
  /// Throws std::logic_error unless `cell` is where the robot is.
  bool neighbourFree(int cell, int direction) {
    if (cell != here_) throw std::logic_error("sensor: asked about a cell the robot is not in");
    const bool answer = world_.neighbour(cell, direction) >= 0;
    log_.push_back({cell, direction, answer});
    return answer;
  }
  /// The robot moves to an adjacent mega-cell (or stays); anything else is refused.
  void moveTo(int cell) {
    if (cell != here_) {
      bool adjacent = false;
      for (int d = 0; d < 4; ++d) adjacent = adjacent || world_.neighbour(here_, d) == cell;
      if (!adjacent) throw std::logic_error("sensor: the robot cannot jump to a cell that is not a free neighbour");
    }
    here_ = cell;
  }
  int here() const { return here_; }
  const std::vector<Query>& log() const { return log_; }

private:
  const graph::GridGraph& world_;
  int here_;
  std::vector<Query> log_;
};

/// The same contract on the sub-cell grid (TRACC, BSA): the robot senses the four cells next to its
/// own; a sub-cell is free when CellGrid says so. Questions about any other cell, and moves to a
/// cell that is not a free 4-neighbour, throw std::logic_error; every question is logged.
class CellSensor {
public:
  struct Query {
    CellIndex from;
    int direction;
    bool answer;
  };

  CellSensor(const CellGrid& cells, CellIndex start) : cells_(cells), here_(start) {}

  bool neighbourFree(CellIndex cell, int direction) {
    if (!(cell == here_)) throw std::logic_error("sensor: asked about a cell the robot is not in");
    const int c = cell.col + graph::kDx[direction], r = cell.row + graph::kDy[direction];
    const bool answer = cells_.insideSub(c, r) && cells_.sub(c, r) == CellState::kFree;
    log_.push_back({cell, direction, answer});
    return answer;
  }
  void moveTo(CellIndex cell) {
    const int d = std::abs(cell.col - here_.col) + std::abs(cell.row - here_.row);
    if (d > 1 || !cells_.insideSub(cell.col, cell.row) || cells_.sub(cell.col, cell.row) != CellState::kFree)
      throw std::logic_error("sensor: the robot cannot jump to a cell that is not a free neighbour");
    here_ = cell;
  }
  CellIndex here() const { return here_; }
  const std::vector<Query>& log() const { return log_; }

private:
  const CellGrid& cells_;
  CellIndex here_;
  std::vector<Query> log_;
};

/// What the online Smooth-STC robot senses of the obstacles' geometry: asked about a mega-cell, it
/// reports the rings of the workspace (a region's outer ring, the walls, or a hole) that come into
/// that mega-cell's box grown by one sub-cell (decided by the boxes of the rings' edges, so it may
/// report a ring that only passes near), which is all a sweep inside the mega-cell needs: a sweep
/// depends on what lies within r + ε + δ < D of its rectangle. It answers only for the robot's
/// mega-cell and its four neighbours; any other question throws std::logic_error, and every
/// question is counted. The robot's place is set with moveTo (its walk is the Spiral-STC robot's,
/// itself proven online by MegaCellSensor); a blocked mega-cell or one outside the grid is refused.
class ObstacleSensor {
public:
  struct RingRef {
    std::size_t region, ring;   ///< ring 0: the region's outer ring; k >= 1: hole k - 1
  };
  ObstacleSensor(const Workspace& w, const CellGrid& cells);
  void moveTo(int col, int row);
  const std::vector<RingRef>& sense(int col, int row);
  std::size_t queries() const { return queries_; }

private:
  const CellGrid& cells_;
  int col_ = -1, row_ = -1;
  std::size_t queries_ = 0;
  std::vector<std::vector<RingRef>> near_;   ///< per mega-cell (row-major)
};

/// What a Multi-ST robot senses (multi_st): the four sub-cells of its own mega-cell and of the four
/// mega-cells next to it, and whether a move between 4-neighbouring sub-cells (or a wait) near it
/// is clear of the moving obstacles over a step of the next few (a proximity sensor that tracks
/// what moves near it and predicts it over `horizon` steps; the answer is the validator's exact test
/// on the obstacles' motion over that step). Questions about any other mega-cell, moves that start
/// more than `horizon` sub-cells from the robot, and jumps throw std::logic_error; every question is
/// counted. Robots share what they sensed and where they are (the paper's server and shared visited
/// array); nothing else of the world reaches the planner.
class TeamSensor {
public:
  using MoveCheck = std::function<bool(std::size_t robot, CellIndex from, CellIndex to, long step)>;
  TeamSensor(const CellGrid& cells, std::vector<CellIndex> at, MoveCheck moveClear, int horizon = 20)
      : cells_(cells), at_(std::move(at)), moveClear_(std::move(moveClear)), horizon_(horizon) {}
  /// The states of mega-cell (mc, mr)'s sub-cells (quadrants 0 bottom-left, 1 bottom-right, 2 top-
  /// right, 3 top-left); outside the grid: all blocked.
  std::array<CellState, 4> megaCell(std::size_t robot, int mc, int mr) {
    const CellIndex h = at_.at(robot);
    if (std::abs(h.col / 2 - mc) + std::abs(h.row / 2 - mr) > 1)
      throw std::logic_error("sensor: asked about a mega-cell that is neither the robot's nor next to it");
    ++queries_;
    std::array<CellState, 4> out{};
    for (int q = 0; q < 4; ++q) {
      const int c = 2 * mc + (q == 1 || q == 2 ? 1 : 0), r = 2 * mr + (q >= 2 ? 1 : 0);
      out[static_cast<std::size_t>(q)] = cells_.insideSub(c, r) ? cells_.sub(c, r) : CellState::kBlocked;
    }
    return out;
  }
  /// Is a move from `from` to `to` (equal: a wait) over step `step` clear of the moving obstacles?
  bool moveClear(std::size_t robot, CellIndex from, CellIndex to, long step) {
    const CellIndex h = at_.at(robot);
    if (std::abs(h.col - from.col) + std::abs(h.row - from.row) > horizon_ || std::abs(from.col - to.col) + std::abs(from.row - to.row) > 1)
      throw std::logic_error("sensor: asked about a move beyond the robot's neighbourhood");
    ++queries_;
    return moveClear_(robot, from, to, step);
  }
  void moveTo(std::size_t robot, CellIndex to) {
    const CellIndex h = at_.at(robot);
    if (std::abs(h.col - to.col) + std::abs(h.row - to.row) > 1 || !cells_.insideSub(to.col, to.row) || cells_.sub(to.col, to.row) != CellState::kFree)
      throw std::logic_error("sensor: the robot cannot jump to a cell that is not a free neighbour");
    at_[robot] = to;
  }
  CellIndex here(std::size_t robot) const { return at_.at(robot); }
  int horizon() const { return horizon_; }
  std::size_t queries() const { return queries_; }

private:
  const CellGrid& cells_;
  std::vector<CellIndex> at_;
  MoveCheck moveClear_;
  int horizon_;
  std::size_t queries_ = 0;
};

}  // namespace coverkit::planners
