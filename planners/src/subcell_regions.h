#pragma once
// Regions at sub-cell level for multi_stc_balanced (planners/src/multi_stc.cpp): where a team is so
// crowded that a split into whole mega-cells cannot be balanced (⌈n/k⌉ / (n/k) for n mega-cells and
// k robots), the regions are refined by passing single sub-cells, and each robot covers its region
// by a walk of its own. Internal to planners/.
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/graph/grid_graph.h>
#include <coverkit/planners/planner.h>

#include <vector>

namespace coverkit::planners {

/// Sub-cell regions around the robots' start sub-cells over the sub-cells of the free mega-cells
/// of `g` (the STC mega-cell graph: sub-cells of one mega-cell are neighbours, sub-cells of two
/// mega-cells are when g links the two), one connected region per robot holding its start, each
/// covered by a walk from the start that enters only the region's sub-cells (route[i][m]: robot i's
/// sub-cell at step m + 1, as writeTimedPaths takes it).
///
/// `megaOwner` (the whole-mega-cell regions, or empty) and `megaRoutes` (their tours) are one start;
/// a breadth-first split of the sub-cells from all starts at once is the other. From each, sub-cells
/// are passed along chains of neighbouring regions, from the region whose walk is longest towards
/// one whose walk is at least two steps shorter, while that lowers (longest walk, sum of squared
/// walks). Returns the better result's routes, or empty when `stop` expires first or two robots
/// start in one sub-cell.
std::vector<std::vector<CellIndex>> subcellRegions(const CellGrid& cells, const graph::GridGraph& g, const std::vector<CellIndex>& startCell,
                                                   const std::vector<int>& megaOwner, const std::vector<std::vector<CellIndex>>& megaRoutes,
                                                   const TerminationCondition& stop);

}  // namespace coverkit::planners
