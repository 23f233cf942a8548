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
  enum class Outcome { kDone, kUnsafe };
  /// One attempt: graph, tree, walk, path. kUnsafe when some moves could not be made exactly safe
  /// in doubles; `unsafe` then holds the sub-cells to blame.
  Outcome planOnce(const PlanningContext& context, const ParamSet& params, const Point& start, Plan& plan,
                   std::vector<CellIndex>& unsafe) const;

  /// Hook 1: the mega-cell graph (default: free mega-cells, 4-neighbours).
  virtual graph::GridGraph buildGraph(const PlanningContext& context) const;
  /// Hook 2: the tree (default: the `tree` parameter's strategy). `rootFirst` is the arm the walk
  /// meets first from the start sub-cell: dfs_ccw scans from there, as the online robot does.
  virtual graph::SpanningTree growTree(const graph::GridGraph& g, int root, const ParamSet& params, int rootFirst) const;
  /// Hook 3: the walk around the tree from the start sub-cell, as sub-cell indices, closed (ends
  /// where it began). Default: counter-clockwise circumnavigation through sub-cell centres. An
  /// online variant grows `tree` during the walk, asking only a sensor about `world`.
  virtual std::vector<CellIndex> circumnavigate(const PlanningContext& context, const graph::GridGraph& world,
                                                graph::SpanningTree& tree, CellIndex start, const ParamSet& params,
                                                Plan& plan) const;
  /// Hook 4: once per plan, before any attempt (default: nothing). Smooth-STC builds its C-space.
  virtual void prepare(const PlanningContext& context, const ParamSet& params, Plan& plan) const;
  /// Hook 5: the placed path of the walk may be changed (default: left as it is). Smooth-STC
  /// inserts its sweeps of partially occupied mega-cells. `walk` is the sub-cell walk placed.
  virtual void refinePath(const PlanningContext& context, const std::vector<CellIndex>& walk, const ParamSet& params, Path& path,
                          Plan& plan) const;
  /// The closed walk (hook 3) around the tree (hook 2) grown in `g` from sub-cell s's node; empty
  /// when s has none. Smooth-STC tours the pockets it joins with it.
  std::vector<CellIndex> tourFrom(const PlanningContext& context, const graph::GridGraph& g, CellIndex s, const ParamSet& params) const;
  /// tourFrom in time and memory of s's component rather than of the map: the tree is grown in a
  /// graph of the component's box alone and walked as the skeleton's circumnavigate walks (for a
  /// planner that keeps the skeleton's walk; a graph with layers or links falls back to tourFrom).
  /// The same walk: the box keeps the nodes' row-major order and their neighbours. Smooth-STC tours
  /// its rooms and pockets with it (191 rooms on a map of 10^6 mega-cells: a tree the size of the
  /// map for each was most of the plan's time).
  std::vector<CellIndex> tourOfComponent(const PlanningContext& context, const graph::GridGraph& g, CellIndex s,
                                         const ParamSet& params) const;
  /// Hook 6: the start lies in no node (hook "startNode" gave -1): plan without a tree, or return
  /// false (default), and the plan's status is invalid_start. Smooth-STC passes the contours.
  virtual bool planWithoutTree(const PlanningContext& context, const ParamSet& params, const Point& start, Plan& plan) const;
  /// The graph node the start sub-cell belongs to, or -1 (default: its mega-cell, when active).
  virtual int startNode(const PlanningContext& context, const graph::GridGraph& g, CellIndex start) const;
  /// The cells a start must lie in (for the invalid_start message).
  virtual std::string startCells() const { return "a free mega-cell"; }
  /// What a successful plan covers (the plan's message).
  virtual std::string coverageClaim() const { return "covered every sub-cell of the start's component of free mega-cells"; }
};

/// The walk's quadrant numbering inside a mega-cell, counter-clockwise: 0 bottom-left,
/// 1 bottom-right, 2 top-right, 3 top-left.
inline int quadrantOf(CellIndex c) { return (c.row % 2 == 0) ? (c.col % 2 == 0 ? 0 : 1) : (c.col % 2 == 0 ? 3 : 2); }
inline CellIndex subCellOf(int megaCol, int megaRow, int quadrant) {
  return CellIndex{2 * megaCol + (quadrant == 1 || quadrant == 2), 2 * megaRow + (quadrant >= 2)};
}

/// Spiral-STC (Gabriely & Rimon), online: the robot knows nothing beforehand; in each mega-cell it
/// asks its sensor about the neighbours, counter-clockwise from the parent, takes the first new
/// free one as a tree child, moves along the right side of the new edge, and returns to the parent
/// when none is left. Same path as offline STC with tree=dfs_ccw from the same start (tested).
///
/// Tree strategies online (decision): a breadth-first or minimum spanning tree needs the whole map,
/// which an online robot does not have, so `tree` selects the online rule that follows the same
/// idea with what the robot has sensed so far:
///  - dfs_ccw: the paper's: the first new free neighbour counter-clockwise becomes a child.
///  - bfs: on its first arrival in a mega-cell the robot claims every new free neighbour it senses
///    as a child (breadth-first discovery); a claimed cell is entered only from its claimer.
///  - kruskal_straight: on arrival it claims the neighbour straight ahead first (straight runs,
///    the preference of the offline Kruskal weights); the rest as dfs_ccw.
/// Only dfs_ccw equals its offline counterpart; all three cover the same mega-cells.
class SpiralStcPlanner : public StcSkeleton {
public:
  std::string name() const override { return "spiral_stc"; }
  std::string description() const override;
  std::vector<ParamSpec> params() const override;
  Capabilities capabilities() const override;

protected:
  graph::SpanningTree growTree(const graph::GridGraph& g, int root, const ParamSet& params, int rootFirst) const override;
  std::vector<CellIndex> circumnavigate(const PlanningContext& context, const graph::GridGraph& world, graph::SpanningTree& tree,
                                        CellIndex start, const ParamSet& params, Plan& plan) const override;
};

/// Full-STC (Gabriely & Rimon's full coverage variant): partially occupied mega-cells take part;
/// only blocked sub-cells are skipped. See full_stc.cpp for the construction (node doubling,
/// single-sided edges) and the proof sketch of completeness.
class FullStcPlanner : public StcSkeleton {
public:
  std::string name() const override { return "full_stc"; }
  std::string description() const override;
  Capabilities capabilities() const override;

protected:
  graph::GridGraph buildGraph(const PlanningContext& context) const override;
  std::vector<CellIndex> circumnavigate(const PlanningContext& context, const graph::GridGraph& world, graph::SpanningTree& tree,
                                        CellIndex start, const ParamSet& params, Plan& plan) const override;
  int startNode(const PlanningContext& context, const graph::GridGraph& g, CellIndex start) const override;
  std::string startCells() const override { return "a free sub-cell"; }
  std::string coverageClaim() const override { return "covered every free sub-cell 4-connected to the start's sub-cell"; }
};

/// Offline STC: free mega-cells only, tree by `tree`, counter-clockwise circumnavigation.
class StcPlanner : public StcSkeleton {
public:
  std::string name() const override { return "stc"; }
  std::string description() const override;
};

}  // namespace coverkit::planners
