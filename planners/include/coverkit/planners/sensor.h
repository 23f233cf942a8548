#pragma once
// What an online planner may know of the world: a sensor that answers, for the robot's current
// mega-cell only, whether the neighbour in a direction is free. Any other question is refused with
// an exception (never a silent answer), and every question is logged, so tests can prove that an
// online planner is online.
#include <coverkit/graph/grid_graph.h>

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

}  // namespace coverkit::planners
