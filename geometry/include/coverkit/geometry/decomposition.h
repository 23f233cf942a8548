#pragma once
// Exact cell decompositions of a disc robot's C-free (issue 13): the geometry behind the
// `Decomposition` models of planners/decomposition.h. CGAL-free: the exact regions are held behind
// an opaque handle (built and read in geometry/src/decompose.cpp).
//
// One engine serves every built-in model. C-free (CSpace, circle-segment curves, rational centres
// and squared radii) is cut by axis-parallel lines at rational coordinates, recursively (the cost
// follows the curves near each line, not lines × all curves); the connected pieces of C-free in each
// slab (or grid box) are then joined across the lines by a rule:
//  - trapezoidal (TCD): a wall up and down from every vertex of C-free's boundary (arcs are split at
//    their x-extreme points, which are vertices): two pieces on either side of a line are one cell
//    when they meet along one interval of the line whose ends are no vertex;
//  - boustrophedon (BCD, Choset & Pignon): walls only where the connectivity of the sweep line
//    changes: two pieces are one cell when each is the other's only neighbour across the line;
//  - grid: the pieces of C-free in each mega-cell box are the cells (nothing joined).
// So every cell is an exact region, cells are interior-disjoint, their union is C-free, and two
// cells are adjacent exactly when they share a piece of a line of positive length.
//
// Decision (exact walls). A wall is a piece of a vertical line x = q with q rational: a
// circle-segment curve, so cells stay in the same exact traits as C-free (no second kernel). The
// lines are at the x of the vertices whose x is rational: every vertex of an offset piece (tangent
// points and the approximation's vertices are rational), every x-extreme of an arc (centre ± r, with
// r the rational robot radius) and every workspace vertex. A vertex where two C-obstacle boundaries
// cross has an irrational x (a one-root number a0 + a1·√c); an exact wall through it would need
// nested square roots where it meets an arc (CORE algebraic numbers), in every later operation. Such
// a crossing is never a split or merge point of the sweep (C-free's angle there is below 180°, so it
// cannot hold both the up and the down direction), so the boustrophedon decomposition is exact and
// complete without it. The trapezoidal one gives such a vertex no wall: the trapezoid's top or
// bottom bends there. Their number is reported (`unwalledVertices`).
//
// Direction: the decomposition sweeps along +x of a frame rotated by a rational rotation (cos, sin
// from the Pythagorean triple nearest the requested angle: exact, and the angle used is reported).
#include <coverkit/geometry/cspace.h>

#include <memory>
#include <string>
#include <vector>

namespace coverkit {

/// An exact rotation by a rational point of the unit circle: (x, y) ↦ (c·x − s·y, s·x + c·y).
struct Rotation {
  Rational c = 1, s = 0;
  double degrees() const;   ///< the angle it rotates by, in (−180, 180]
  Point apply(const Point& p) const;
  Point inverse(const Point& p) const;
  PointD apply(const PointD& p) const;
  PointD inverse(const PointD& p) const;
  /// The rotation by a rational angle nearest `degrees`: cos = (1 − t²)/(1 + t²), sin = 2t/(1 + t²)
  /// with t ≈ tan(θ/2) the best rational of denominator ≤ `maxDenominator` (exact at multiples of 90°).
  static Rotation nearest(double degrees, long maxDenominator = 1000);
};
Workspace rotate(const Workspace& w, const Rotation& r);
/// A region of the rotated frame back in the workspace's frame (doubles: for output).
CurveRegion unrotate(const CurveRegion& region, const Rotation& r);

enum class DecompositionRule { kTrapezoidal, kBoustrophedon, kGrid };

/// A shared piece of boundary between two adjacent cells: a piece of the line x = `at` (vertical
/// walls, sweep models) or y = `at` (grid's horizontal lines), from `lo` to `hi` along it, doubles.
struct CellWall {
  int a = -1, b = -1;          ///< the two cells, a < b
  bool vertical = true;
  double at = 0, lo = 0, hi = 0;
  double length() const { return hi - lo; }
};

struct DecomposedCell {
  CurveRegion region;          ///< the cell's boundary in doubles (frame of the decomposition)
  double area = 0;
  double xmin = 0, xmax = 0;   ///< extent along the sweep direction (x of the frame)
  double ymin = 0, ymax = 0;
  int component = -1;          ///< index in CSpace::components() of the component holding it
  std::vector<int> neighbours; ///< adjacent cells, sorted
};

namespace detail {
struct ExactCells;   // geometry/src/decompose.cpp
}

/// A piece of a sweep cell's top or bottom boundary, in doubles (for planners that follow it): a
/// segment of the line a·x + b·y + c = 0 or an arc of the circle about `center` of radius `rho`
/// (its upper or lower half), over [x0, x1]. `clockwise`: the boundary (C-free on its left) runs
/// clockwise about the centre, so C-free lies outside the circle there (every arc of a disc
/// robot's C-free does: its centre is an obstacle's vertex).
struct SidePiece {
  double x0 = 0, x1 = 0;
  bool arc = false;
  double a = 0, b = 0, c = 0;      ///< line
  PointD center;                   ///< arc
  double rho = 0;
  bool upperHalf = false, clockwise = true;
  double yAt(double x) const;
};

/// Cells of C-free and their adjacency, in the decomposition's frame (rotated by `rotation`
/// from the workspace's frame: a point p of the workspace is rotation.apply(p) here).
struct CellDecomposition {
  std::string method;
  Rotation rotation;
  std::vector<DecomposedCell> cells;   ///< sorted by (xmin, ymin): deterministic
  std::vector<CellWall> walls;         ///< sorted by (a, b, at, lo)
  std::size_t unwalledVertices = 0;    ///< trapezoidal: crossings of irrational x (see the decision)
  std::size_t lines = 0;               ///< cutting lines used
  std::shared_ptr<const detail::ExactCells> exact;

  /// The interval [lo, hi] of the closed cell on the vertical line x (doubles, frame coordinates),
  /// false when the line misses it. Sweep cells meet every vertical line in one interval; for a grid
  /// cell this is the hull of what it meets.
  bool interval(int cell, double x, double& lo, double& hi) const;
  /// The cell whose closure holds p (frame coordinates, exact), or −1.
  int locate(const Point& p) const;
  /// Whether the closure of `cell` holds p (exact).
  bool contains(int cell, const Point& p) const;
  /// The top (or bottom) boundary of a sweep cell over [x0, x1], sorted by x; vertical pieces left out.
  std::vector<SidePiece> side(int cell, bool top, double x0, double x1) const;
};

/// Builds a decomposition of the C-free of `space` (its workspace is already in the frame).
/// `gridSize`: the mega-cell size for kGrid (boxes from `gridOrigin`), ignored otherwise.
CellDecomposition decomposeCSpace(const CSpace& space, DecompositionRule rule, const std::string& method,
                                  const Rational& gridSize = 0, const Point& gridOrigin = {});

/// The cells as polygons of line segments in the workspace's frame, for line-only files (GeoJSON):
/// arcs replaced by lines within `tolerance` on the cell's inside (geometry/sampling.h), then every
/// vertex checked exactly to lie in its cell (turned into the decomposition's frame exactly) and
/// moved inward (along its corner's bisector, or toward its neighbours at a cusp), a few ulps at a
/// time doubling, until it does. One ring set per cell, in order. `unplaced`, when given, gets per
/// cell the vertices no such move brought into the cell (a sliver thinner than the doubles near it,
/// seen on rotated trapezoidal cells): those are left where rounding put them.
std::vector<SampledRegion> sampledCells(const CellDecomposition& d, double tolerance, std::vector<std::size_t>* unplaced = nullptr);

/// C-free cut by the vertical lines x = xs[i] and the horizontal lines y = ys[j] (rational, any
/// order; lines outside a component are ignored): each connected piece of C-free between them is a
/// cell. The building block for models of one's own (docs/adding-a-decomposition.md).
CellDecomposition decomposeAlongLines(const CSpace& space, const std::vector<Rational>& xs, const std::vector<Rational>& ys,
                                      const std::string& method);

/// What the contract test checks, exactly (CGAL Boolean operations on the cells' exact regions).
struct DecompositionCheck {
  bool disjoint = true;        ///< no two cells share an interior point
  bool unionIsCFree = true;    ///< the union of the cells is C-free (symmetric difference empty)
  bool adjacencyComplete = true;  ///< every pair sharing boundary of positive length is listed, and only those
  bool adjacencySymmetric = true;
  bool monotone = true;        ///< every vertical line meets every cell in at most one interval
  std::string detail;          ///< what failed first
  bool ok(bool wantMonotone) const {
    return disjoint && unionIsCFree && adjacencyComplete && adjacencySymmetric && (!wantMonotone || monotone);
  }
};
/// Independent of the construction: unites the cells with CGAL, intersects them pairwise (boxes
/// first), and finds shared boundary by overlaying the cells' boundaries.
DecompositionCheck checkDecomposition(const CellDecomposition& d, const CSpace& space);

}  // namespace coverkit
