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
  /// Hook 2: the tree (default: the `tree` parameter's strategy). `rootFirst` is the arm the walk
  /// meets first from the start sub-cell: dfs_ccw scans from there, as the online robot does.
  virtual graph::SpanningTree growTree(const graph::GridGraph& g, int root, const ParamSet& params, int rootFirst) const;
  /// Hook 3: the walk around the tree from the start sub-cell, as sub-cell indices, closed (ends
  /// where it began). Default: counter-clockwise circumnavigation through sub-cell centres. An
  /// online variant grows `tree` during the walk, asking only a sensor about `world`.
  virtual std::vector<CellIndex> circumnavigate(const PlanningContext& context, const graph::GridGraph& world,
                                                graph::SpanningTree& tree, CellIndex start, Plan& plan) const;
};

/// Spiral-STC (Gabriely & Rimon), online: the robot knows nothing beforehand; in each mega-cell it
/// asks its sensor about the neighbours, counter-clockwise from the parent, takes the first new
/// free one as a tree child, moves along the right side of the new edge, and returns to the parent
/// when none is left. Same path as offline STC with tree=dfs_ccw from the same start (tested).
/// Deviation: none in the path; the tree strategy is fixed (BFS or Kruskal need the whole map).
class SpiralStcPlanner : public StcSkeleton {
public:
  std::string name() const override { return "spiral_stc"; }
  std::string description() const override;
  std::vector<ParamSpec> params() const override { return {}; }
  Capabilities capabilities() const override;

protected:
  graph::SpanningTree growTree(const graph::GridGraph& g, int root, const ParamSet& params, int rootFirst) const override;
  std::vector<CellIndex> circumnavigate(const PlanningContext& context, const graph::GridGraph& world, graph::SpanningTree& tree,
                                        CellIndex start, Plan& plan) const override;
};

/// Offline STC: free mega-cells only, tree by `tree`, counter-clockwise circumnavigation.
class StcPlanner : public StcSkeleton {
public:
  std::string name() const override { return "stc"; }
  std::string description() const override;
};

}  // namespace coverkit::planners
