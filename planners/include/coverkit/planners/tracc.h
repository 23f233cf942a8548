#pragma once
// TRACC, the TRaversal Algorithm for Complete Coverage (online).
//
// Reference: K. Thiayarajan and C. G. Balaji, "Traversal Algorithm for Complete Coverage" (2012),
// ../shared/papers/tracc_thiayarajan-balaji.txt (Table 2, Fig. 2-5).
//
// The agent lives on the sub-cell grid (cells of D ≥ 2r, so the disc fits a cell) and knows nothing
// beforehand: before entering a cell it has sensed it from a neighbour (CellSensor answers only for
// the four cells next to the robot). It follows a boustrophedon flow path over the cells (rows in
// alternating direction, Fig. 2) from its start; when the next flow cell is blocked or not next to
// it, it goes there by the shortest path (A*) that avoids every cell it knows to be unsafe.
//
// Decisions where the paper is vague:
//  - Shortest paths may cross cells not sensed yet (the paper's own detour C4 → C15 → C16 → C17 →
//    C6 does: C16 and C17 are unknown at C4). Every cell the robot enters has been sensed safe from
//    the cell before it; a path whose next cell turns out unsafe is planned again.
//  - The paper's flow visits every other row, its sensing covering the rows between. A disc robot
//    must sweep, so the flow visits every row; every flow cell not yet visited is a target.
//    Reachable free cells are therefore all entered, and the end phase of Table 2 (unchecked cells
//    with a safe neighbour) has nothing left to visit (it runs, and counts its visits): the report
//    gives the unsafe cells, the cells never sensed (inside obstacles, outside W or walled in) and,
//    for evaluation, the free cells never reached.
//  - A* searches from the target back to the robot, so a failed search has explored exactly the
//    target's side: those cells are marked unreachable once and never searched again (O(N log N)).
//  - Redundancy rate: the formula says R = U/C with U "uncovered cells", the text "the ratio of the
//    overlapped cell and the covered cell". We follow the text: R = 100 · (cells entered more than
//    once) / (cells entered). The paper's 45.45 % for its 11×11 flow is 55/121, the cells of the
//    five rows it does not visit but senses twice, from both sides.
#include <coverkit/planners/planner.h>

namespace coverkit::planners {

class TraccPlanner : public Planner {
public:
  std::string name() const override { return "tracc"; }
  std::string description() const override;
  std::vector<ParamSpec> params() const override;
  Capabilities capabilities() const override;
  Plan plan(const PlanningContext& context, const ParamSet& params, const TerminationCondition& stop) override;

private:
  /// One online run from start cell `s`; `unsafeCells` gets the sub-cells no double path can cross.
  void runOnce(const PlanningContext& context, CellIndex s, const ParamSet& params, const TerminationCondition& stop, Plan& plan,
               std::vector<CellIndex>& unsafeCells) const;
};

}  // namespace coverkit::planners
