#pragma once
// BSA with A* backtracking: spiral or zigzag filling on the sub-cell grid, backtracking points, and
// A* on the 8-connected grid back to the nearest one.
//
// Reference: "Coverage path planning for service robots based on a backtracking procedure", MM
// Science Journal, October 2024 (../shared/papers/bsa-astar_backtracking.txt), extending BSA of
// E. González et al., "BSA: a complete coverage algorithm", ICRA 2005.
//
// Filling moves in four directions between free sub-cells (D ≥ 2r: the disc fits a cell); a cell
// once visited counts as an obstacle for filling (the paper's Fig. 2).
//  - Spiral (`bsa_spiral`), the paper's four rules with a reference lateral side (RLS, parameter
//    `side`): 1 all around blocked → the spiral ends; 2 RLS free → turn to it and move; 3 front
//    blocked → turn to the opposite side; 4 otherwise move forward.
//  - Zigzag (`bsa_zigzag`), its two rules: 1 all around blocked → the zigzag ends; 2 move to the
//    first free cell in the map's counter-clockwise order (from the direction `first`; north gives
//    lanes along columns, as the paper's Fig. 4).
//  - Backtracking points: a cell is recorded when the robot leaves it with a free unvisited
//    neighbour behind; a point is dropped once it has none left (checked when it is looked at).
//  - When a filling ends, the robot goes to the nearest backtracking point that still has an
//    unvisited neighbour (octile distance; found through a bucket grid, never by scanning every
//    cell) by A* on the 8-connected grid with the paper's octile heuristic, a diagonal step only
//    where both side cells are free, and fills again from there. Cells crossed on the way count as
//    visited. It stops when no point is left: every free cell 4-connected to the start is visited.
// Decisions where the paper is silent: the initial heading is `first`'s direction (zigzag) or east
// (spiral); after a backtrack the spiral's heading is the first free direction counter-clockwise
// from the last one; ties between equally near points go to the lower row, then column.
#include <coverkit/planners/planner.h>

namespace coverkit::planners {

class BsaPlanner : public Planner {
public:
  enum class Filling { kSpiral, kZigzag };
  explicit BsaPlanner(Filling f) : filling_(f) {}
  std::string name() const override { return filling_ == Filling::kSpiral ? "bsa_spiral" : "bsa_zigzag"; }
  std::string description() const override;
  std::vector<ParamSpec> params() const override;
  Capabilities capabilities() const override;
  Plan plan(const PlanningContext& context, const ParamSet& params, const TerminationCondition& stop) override;

private:
  Filling filling_;
};

}  // namespace coverkit::planners
