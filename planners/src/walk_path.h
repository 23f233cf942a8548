#pragma once
// From a walk over sub-cells to a path of doubles that is safe exactly as written (private to
// planners/).
//
// A sub-cell centre is often not a double (D = 0.3, say). Rounding it towards the centre of its
// mega-cell is always safe inside a free mega-cell (STC), but next to a blocked sub-cell with an
// obstacle on the shared border, one unit in the last place the wrong way puts the disc into the
// obstacle: when the sub-cell is exactly 2r wide there is no slack at all.
//
// So each straight run of the walk gets its own fixed coordinate (y of a horizontal run, x of a
// vertical one), a turn's corner takes the fixed coordinates of its two runs, and a reversal takes
// a coordinate of its own. Each of these variables has one candidate when the centre is a double,
// else two: the double on the mega-cell centre's side (preferred) and the other one. Every move
// whose cells, widened by one cell, are not all free is checked exactly (ClearanceChecker); a
// failing move tries the other candidates of its variables, and a combination is kept only when
// every checked move that shares a variable stays clear. Moves among free cells need no check: the
// disc moves ≤ one ulp out of its sub-cell, into free ones. Only a run squeezed on both sides by
// obstacles exactly 2r apart, at a coordinate that is not a double, stays unsafe: no double path
// exists there: the moves are reported with the sub-cells to blame, and the planner leaves those
// sub-cells out (StcSkeleton::plan).
//
// A walk that stays in free mega-cells (STC's, Spiral-STC's) needs none of this: every preferred
// double leans into its own free mega-cell. Its path, the same as the construction above gives, is
// written directly from the cells (placeInFreeMegaCells in walk_path.cpp).
#include <coverkit/planners/planner.h>

#include <functional>
#include <string>
#include <vector>

namespace coverkit::planners {

struct PlacedWalk {
  Path path;                   ///< from the start point along the walk (and back to the start point)
  bool startClear = true;      ///< the straight move from the start point to its sub-cell is clear
  std::size_t checkedMoves = 0, repairedMoves = 0, unsafeMoves = 0;
  /// The sub-cells to blame for the unsafe moves: those on the move squeezed between cells that are
  /// not free on both sides of an axis (within their 3×3 block), at a centre coordinate that is not
  /// a double (else the move's own end cells).
  std::vector<CellIndex> unsafeCells;
};

/// `walk`: sub-cells, each 4-adjacent to the next or diagonal to it with both side cells free
/// (repeats allowed), beginning at the start's sub-cell (and, with `backToStart`, ending there: the
/// path then returns to the start point). A diagonal move stays in its 2×2 block of free cells.
/// Throws std::logic_error when two consecutive sub-cells are not adjacent.
/// `direct = false` always takes the general construction (the tests compare the two).
PlacedWalk placeWalk(const PlanningContext& context, const std::vector<CellIndex>& walk, const Point& start, bool backToStart = true,
                     bool direct = true);

/// The common start of a planner on the sub-cell grid: throws InputError when a sub-cell cannot hold
/// the disc (D < 2r). Adds the plan's path and returns true with the start point and its sub-cell;
/// or sets the status (no free space; invalid start when `needFreeCell` and the start's sub-cell is
/// not free) and returns false.
bool beginOnCells(const PlanningContext& context, const std::string& planner, bool needFreeCell, Plan& plan, Point& start,
                  CellIndex& startCell);

/// Runs `attempt` and, while it returns sub-cells that no double path can cross (PlacedWalk::
/// unsafeCells), runs it again on a copy of the context with those blocked (never `keep`), at most
/// nine times. Sets the statistics "subcells_left_out" and "attempts"; returns true when the last
/// attempt still had such sub-cells.
bool withoutUnplaceableCells(const PlanningContext& context, CellIndex keep, Plan& plan,
                             const std::function<std::vector<CellIndex>(const PlanningContext&)>& attempt);

}  // namespace coverkit::planners
