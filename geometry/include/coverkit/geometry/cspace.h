#pragma once
// The configuration space of a disc robot of radius r (issue: exact C-space).
//
// C-obstacle = obstacle ⊕ disc(r); the workspace boundary is eroded by r. C-free is the set of
// centres at which the disc lies in W and meets no obstacle interior. It is built with CGAL's
// `approximated_offset_2` (circle-segment traits, exact kernel): every arc of the result is exact
// (rational centre, rational squared radius); where the exact offset would need an irrational line,
// the construction replaces it by rational pieces that lie *outside* the exact offset, within eps.
// So the C-obstacles used here contain the exact ones (an approximation errs outward, never inward)
// and the C-free used here is contained in the exact C-free: whatever it calls free is free.
// The approximation bound (found in issue 14): CGAL's eps bounds its approximation of each edge's
// length, not the distance of its pieces from the exact offset (up to 93 × eps measured on seeded
// convex polygons, 2.4 at eps = 0.1, r = 10: still outward, never inside). Strictly convex
// obstacles are therefore offset by our own construction (cspace.cpp, convexOffset: exact arcs,
// tangent roofs within eps / 10, checked exactly; CSpace.ConvexOffsetsLieOutsideTheExactOneWithinEps);
// non-convex ones still by approximated_offset_2, whose pieces can lie further than eps outside near
// slanted edges (C-free a little smaller there than eps says; the closed convention's margin δ
// below assumes eps). Edges parallel to an axis (grid maps) are exact either way.
// eps defaults to 1e-6 × the workspace's extent (docs/architecture.md has the measured choice).
//
// Decision (issue 12, "one convention for narrow gaps"): C-free is CLOSED, for the C-space, the
// validator and the metrics alike: a centre is free when its distance to every obstacle (and to W's
// boundary) is >= r, so the disc may touch both sides of a gap exactly 2r wide and pass through it.
// That is what the validator has always accepted (distance >= r is valid), and what the STC family
// does in corridors one 2r sub-cell wide (Moving AI mazes and rooms).
//  - The polygons this class holds are an INNER approximation of that closed set: regularised
//    Boolean operations drop its zero-width parts (the centre line of a corridor exactly 2r wide, the
//    point between two corners exactly 2r apart), and the approximated offsets close gaps up to 2·eps
//    wider. So `componentOf`, `segmentClear`, `arcClear`, `classify` and `sweeps` stay one-sided:
//    what they call free is free exactly (the planners' checks, Smooth-STC's sweeps included, never
//    pass through a gap of exactly 2r; the STC grid does, on exact cells, and the validator accepts it).
//  - Connectivity and the coverable region follow the closed set: `closedComponentOf` and
//    `coverableArea` use the C-space of radius r − δ, δ = 4·eps' (eps' = min(eps, r/64), the
//    approximation bound of those helper C-spaces). Every point of the closed C-free of radius r lies
//    in the interior of that C-space (its points are >= r > r − δ + eps' from the obstacles), so a
//    valid path never leaves one of its components, and (component ⊕ disc(r)) ∩ F contains all it can
//    sweep: coverable coverage <= 1 up to the stated error bounds (docs/metrics.md). The price: gaps
//    narrower than 2r by less than 2δ (about 1e-5 of the map's extent) count as open.
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/path.h>

#include <memory>
#include <vector>

namespace coverkit {

namespace detail {
struct CSpaceAccess;   // geometry/src: the exact C-free for other CGAL files of the library
}

/// The coverable region of `CSpace::coverableArea` without a C-space of radius r at hand (it is not
/// needed: only the helper C-spaces of radius r − δ and 2r − 2δ are built).
/// `threads` (0: every core): the two helper C-spaces are built at once when more than one, and the
/// raster splits over them; the value does not depend on it.
double coverableArea(const Workspace& w, const Rational& radius, const std::vector<Point>& starts, double& errorBound,
                     double relativeEps = 1e-6, unsigned threads = 0);

/// A closed boundary of line segments and circular arcs, in doubles (for output and pictures).
struct CurveLoop {
  std::vector<PathSegment> pieces;
};

/// One connected component of C-free (or one C-obstacle): outer boundary and holes.
struct CurveRegion {
  CurveLoop outer;
  std::vector<CurveLoop> holes;
  double area = 0;
};

/// A region as rings of doubles (line segments only): outer counter-clockwise, holes clockwise, the
/// first point not repeated. geometry/sampling.h makes them.
struct SampledRegion {
  std::vector<PointD> outer;
  std::vector<std::vector<PointD>> holes;
};

/// Cells classified by C-space (the robot's centre), with the C-free contour of every partial
/// mega-cell. Sub-cell states: free = the closed cell lies in C-free (the centre may be anywhere in
/// it); blocked = the cell and C-free share no interior point (touching along an edge or a point
/// counts as blocked); partial = the rest. A mega-cell is free when its four sub-cells are, blocked
/// when they all are, partial otherwise.
struct CSpaceCells {
  int subCols = 0, subRows = 0;
  std::vector<CellState> sub;   ///< row-major, row 0 at the bottom, the CellGrid's indexing
  CellState subState(int col, int row) const { return sub[static_cast<std::size_t>(row) * subCols + col]; }
  CellState mega(int col, int row) const;

  /// A partial mega-cell: C-free ∩ cell, and the boundary of C-free inside the cell as chains in
  /// boundary order (C-free on the left). A chain starts where it enters the cell's border (`entry`)
  /// and ends where it leaves it (`exit`); a closed chain (an obstacle wholly inside) has none.
  struct Chain {
    std::vector<PathSegment> pieces;
    bool closed = false;
    PointD entry, exit;
  };
  struct MegaContour {
    int col = 0, row = 0;
    std::vector<CurveRegion> pieces;
    std::vector<Chain> chains;
  };
  std::vector<MegaContour> contours;   ///< partial mega-cells, in row-major order
  const MegaContour* contour(int col, int row) const;
};

class CSpace {
public:
  /// Throws InputError when r < 0 or the workspace is not valid (checkWorkspace). r = 0 (a point)
  /// gives C-free = W; the command line rejects it, as a robot has a size. `relativeEps` scales with
  /// the workspace's extent.
  /// `threads` (0: every core): the obstacles' offsets are computed on that many threads; C-free is
  /// the same, to the bit, for any number.
  CSpace(const Workspace& w, const Rational& radius, double relativeEps = 1e-6, unsigned threads = 1);
  ~CSpace();
  CSpace(CSpace&&) noexcept;
  CSpace& operator=(CSpace&&) noexcept;

  const Rational& radius() const;
  double epsilon() const;                       ///< the absolute approximation bound used
  std::size_t componentCount() const;
  /// Index of the component whose closure contains p (exact), or -1 when p is not in C-free.
  int componentOf(const Point& p) const;
  bool contains(const Point& p) const { return componentOf(p) >= 0; }
  double area() const;                          ///< area of C-free
  std::vector<CurveRegion> components() const;  ///< the components of C-free, largest first
  /// The C-obstacles within W (W minus C-free: obstacles ⊕ disc and the band along W's boundary),
  /// united, for pictures and files.
  std::vector<CurveRegion> obstacles() const;

  /// Clearance against these C-obstacles, exact (an arrangement zone walk over C-free's boundary):
  /// true when every point of the segment lies in the closed C-free. Touching the boundary, or
  /// running along it, is clear. As the C-obstacles contain the exact ones, clear here implies clear
  /// exactly; the converse may fail within eps of the boundary.
  bool segmentClear(const Point& a, const Point& b) const;
  /// The same for a circular arc about `center` from `from` (radius |from − center|), ccw or not, to
  /// the ray through `to`; `from == to` is the full circle.
  bool arcClear(const Point& from, const Point& to, const Point& center, bool ccw) const;

  /// The closed component holding p: components of the closed C-free (distance >= r), joined where
  /// their closures touch (a gap exactly 2r wide, two corners exactly 2r apart), found as the
  /// components of the C-space of radius r − δ (see the decision above). Returns an index into those
  /// components, not into `components()`, or −1 when p is within r − δ of an obstacle (roughly).
  /// Built on first use.
  int closedComponentOf(const Point& p) const;
  /// δ of the closed convention (above): the helper C-spaces use radius r − δ and 2r − 2δ.
  double closedMargin() const;

  /// The area of the coverable region of the closed components holding `starts`: K ⊕ disc(r) ∩ F,
  /// K those components of the C-space of radius r − δ; it contains everything a valid path (the
  /// exact validator's closed convention) from one of the starts can sweep. Computed as the area of
  /// the components of the C-space of radius 2r − 2δ that lie in K (exact curves) plus the area of
  /// F ∩ (∂K ⊕ disc(r)) (rasterised with a rigorous bound); `errorBound` bounds the raster's error
  /// and the two parts' overlap (a band of width δ + eps' inside the first). Starts in no
  /// component add nothing. Built on first use (the two helpers at once when `threads` allows).
  double coverableArea(const std::vector<Point>& starts, double& errorBound, unsigned threads = 0) const;

  /// C-free as polygons of line segments that lie in the exact closed C-free, for line-only files
  /// (GeoJSON): the components of the C-space of radius r + 4·eps (so the approximation's own error
  /// and the rounding of its points to doubles stay on the safe side, and pinch points where two
  /// C-obstacles touch, gaps exactly 2r wide, open), arcs replaced outside their circles within
  /// `tolerance`, every edge then checked exactly at radius r (sampling.h: sampleFreeRegions).
  /// `component` is the index in components() of the component holding each; a piece that could
  /// not be made safe is left out (never seen).
  struct SampledComponent {
    int component = -1;
    SampledRegion region;
  };
  std::vector<SampledComponent> sampledComponents(double tolerance) const;

  /// Classifies the cells of `grid` by C-space: recursive quadrant clipping, so the cost follows the
  /// cells that C-free's boundary crosses, not all cells × all curves. With `contours`, partial
  /// mega-cells get their C-free pieces and boundary chains.
  CSpaceCells classify(const CellGrid& grid, bool contours = true) const;

  /// A sweep of the rectangle U beside an axis-parallel base segment: U has the base [a, d] as one
  /// side and extends `depth` to the right of the direction a → d. The sweep is the boundary of
  /// U ∩ C-free, counter-clockwise (C-free on the left), from the point `entry` of the base nearest
  /// a that lies in C-free to the point `exit` where that boundary comes back to the base for the
  /// last time (the far end of the base interval that holds `entry`). Smooth-STC's leaf rule
  /// (planners/src/smooth_stc.cpp) is built on it.
  struct SweepRequest {
    Point a, d;
    Rational depth;
  };
  struct Sweep {
    bool reached = false;              ///< some point of the base lies in C-free
    std::vector<PathSegment> pieces;   ///< from entry to exit, in doubles (arcs merged per circle)
    PointD entry, exit;                ///< on the base (doubles of exact points)
    double entryT = 0, exitT = 0;      ///< their places on the base, 0 at a, 1 at d
    bool farSide = false;              ///< the sweep runs along U's side opposite the base
    bool traced = false;               ///< made by the direct trace among axis-parallel edges (localSweeps)
  };
  /// All requests at once: C-free is clipped recursively to boxes around groups of requests, so the
  /// cost follows the requests and the curves near them, not requests × all curves.
  std::vector<Sweep> sweeps(const std::vector<SweepRequest>& requests) const;
  /// The same sweeps as CSpace(w, radius, relativeEps).sweeps(requests), without that C-space:
  /// each request's U ∩ C-free is built from the C-obstacle pieces near U only (the same exact
  /// pieces the constructor joins, large ones cut into tiles about a request in size, found through
  /// a grid of buckets), so the cost grows with the requests and the obstacles near them, never with
  /// the union of all. The requests split into strips along x, one per thread (0: every core), each
  /// with its own pieces; the sweeps do not depend on `threads`.
  ///
  /// With `trace` (the default), a request whose edges within reach are all axis-parallel (every
  /// grid map) is first traced directly on the offsets of those edges, in doubles with a margin of
  /// 1e-9 of the map's extent for every decision (Sweep::traced); the trace gives up on any tie it
  /// cannot decide with that margin, and the request then gets the exact sweep above. A traced
  /// sweep is the exact one up to the doubles' rounding (tested), not to the bit. The workspace is
  /// checked (checkWorkspace, which CGAL's preconditions need) only when some request needs the
  /// exact way; the readers check every polygon file anyway, and grid maps are valid by construction.
  static std::vector<Sweep> localSweeps(const Workspace& w, const Rational& radius, const std::vector<SweepRequest>& requests,
                                        double relativeEps = 1e-6, unsigned threads = 1, bool trace = true);

private:
  friend struct detail::CSpaceAccess;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Sweeps (CSpace::Sweep) for a robot that learns the obstacles as it goes (online Smooth-STC):
/// U ∩ C-free is built from the rings added so far only, with the pieces CSpace::localSweeps
/// uses, so a request whose nearby rings have all been added gets the same sweep as there. A
/// region takes part once it is added (addRegion: the robot's own; addRing adds a ring's region
/// too), with its C-free inside its outer ring's box minus the pieces of its rings added so far:
/// the caller must add every ring within r of a request's rectangle before asking for it (a
/// sensor's report of the mega-cells around it does). eps is the whole map's (its extent is known).
class OnlineSweeper {
public:
  /// `cell`: the side of the buckets that index the pieces (a mega-cell). `w` is read as rings are
  /// added: it must outlive the sweeper (it is not copied). `trace`: as CSpace::localSweeps, from
  /// the edges of the rings added so far, so that the sweeps equal localSweeps' once every ring
  /// near a request is known.
  OnlineSweeper(const Workspace& w, const Rational& radius, double cell, double relativeEps = 1e-6, bool trace = true);
  ~OnlineSweeper();
  OnlineSweeper(const OnlineSweeper&) = delete;
  OnlineSweeper& operator=(const OnlineSweeper&) = delete;
  void addRegion(std::size_t region);
  /// Ring 0 of a region is its outer ring (the walls: the outside's offset), ring k >= 1 hole k - 1.
  void addRing(std::size_t region, std::size_t ring);
  CSpace::Sweep sweep(const CSpace::SweepRequest& q) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace coverkit
