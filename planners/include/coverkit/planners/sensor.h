#pragma once
// What an online planner may know of the world: a sensor that answers, for the robot's current
// mega-cell only, whether the neighbour in a direction is free. Any other question is refused with
// an exception (never a silent answer), and every question is logged, so tests can prove that an
// online planner is online.
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/types.h>
#include <coverkit/graph/grid_graph.h>

#include <cstdlib>
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

}  // namespace coverkit::planners
