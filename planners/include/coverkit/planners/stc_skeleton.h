#pragma once
// The STC family's skeleton (template method): which mega-cells count, how the tree grows, and how
// the robot goes around it are hooks; the loop that times the phases and assembles the Plan is not.
//
// Spanning Tree Coverage: Y. Gabriely and E. Rimon, "Spanning-tree based coverage of continuous
// areas by a mobile robot", Annals of Mathematics and Artificial Intelligence 31, 2001,
// doi:10.1023/A:1016610507833; summarised in Pham, Moore, Truong, Robotics 8(2), 2019, sections 2-3.
#include <coverkit/graph/spanning_tree.h>
#include <coverkit/planners/planner.h>

namespace coverkit::planners {

class StcSkeleton : public Planner {
public:
  std::vector<ParamSpec> params() const override;
  Capabilities capabilities() const override;
  Plan plan(const PlanningContext& context, const ParamSet& params, const TerminationCondition& stop) final;

protected:
  /// Hook 1: the mega-cell graph (default: free mega-cells, 4-neighbours).
  virtual graph::GridGraph buildGraph(const PlanningContext& context) const;
  /// Hook 2: the tree (default: the `tree` parameter's strategy).
  virtual graph::SpanningTree growTree(const graph::GridGraph& g, int root, const ParamSet& params) const;
  /// Hook 3: the walk around the tree from the start sub-cell, as sub-cell indices, closed (ends
  /// where it began). Default: counter-clockwise circumnavigation through sub-cell centres.
  virtual std::vector<CellIndex> circumnavigate(const PlanningContext& context, const graph::SpanningTree& tree,
                                                CellIndex start) const;
};

/// Offline STC: free mega-cells only, tree by `tree`, counter-clockwise circumnavigation.
class StcPlanner : public StcSkeleton {
public:
  std::string name() const override { return "stc"; }
  std::string description() const override;
};

}  // namespace coverkit::planners
