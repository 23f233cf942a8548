#pragma once
// What the team planners (multi_stc_balanced, multi_st) share: robots that step between the
// centres of 4-neighbouring sub-cells, one step of `step` seconds at a time, and the timed paths
// made from their cell routes. Internal to planners/.
#include <coverkit/planners/planner.h>

#include <string>
#include <vector>

namespace coverkit::planners {

/// Where a robot stands in a sub-cell (x of its column, y of its row: stcWaypoint) and how long a
/// step takes; `clear` asks whether a move keeps robot `robot` clear of every moving obstacle (the
/// validator's own exact test).
struct StepTiming {
  const Problem* problem = nullptr;
  std::vector<double> x, y;
  double step = 0.1;
  PointD centre(CellIndex c) const { return {x[static_cast<std::size_t>(c.col)], y[static_cast<std::size_t>(c.row)]}; }
  bool clear(std::size_t robot, PointD a, PointD b, double t0, double t1) const;
  bool clearOf(std::size_t robot, std::size_t obstacle, PointD a, PointD b, double t0, double t1) const;
};
StepTiming makeStepTiming(const PlanningContext& ctx, double step);

/// Every sub-cell centre of the grid is a double (then robots stand exactly at the centres).
bool centresAreDoubles(const CellGrid& cells);

/// InputError unless the team is of equal discs on a grid where two robots side by side can stand
/// at sub-cell centres exactly D apart (centres that are doubles, or D a little larger than 2r).
void checkTeamGrid(const PlanningContext& ctx, const std::string& planner);

/// The plan's paths from cell routes: route[i][m] is robot i's sub-cell at step m + 1 (step 0: its
/// start). Each path's timeline has an entry per step (trailing waits dropped), its segments the
/// same polyline. Fills the statistics robots, makespan_steps, makespan_s, moves_total,
/// moves_most and moves_least.
void writeTimedPaths(const Problem& problem, const StepTiming& timing, const std::vector<std::vector<CellIndex>>& route, Plan& plan);

/// False, with status no_free_space and empty paths, when some robot has no start (makeContext found
/// no free sub-cell for a default one).
bool everyRobotHasAStart(const Problem& problem, Plan& plan);

/// Every robot at its start, timed (a plan whose robots could not move).
void stayAtStarts(const Problem& problem, Plan& plan);

}  // namespace coverkit::planners
