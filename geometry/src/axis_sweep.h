// Sweeps (CSpace::Sweep) among axis-parallel obstacle edges without Boolean operations: the
// contour of U ∩ C-free is traced on the offsets of the edges near U (segments at distance r from
// the edges, quarter circles about the obstacles' convex corners) in doubles. Private to geometry.
//
// Why and how (docs/smooth-stc.md, "How a sweep is made"): Smooth-STC makes one sweep per opening,
// 174,000 of them on a 10^6 mega-cell map, and CGAL's Boolean operations on circle-segment polygons
// cost about 0.1 ms each whatever their size. Where every edge within reach of U is axis-parallel
// (every grid map), C-free's boundary near U consists of the edges' offset segments and the arcs
// about convex corners only, which a direct trace finds in microseconds. Every decision is taken
// with a margin `tol` (1e-9 of the map's extent) far above the doubles' rounding and far below the
// sweep's slack (ε ≥ 1e-6 of the extent, CSpace): a point closer than `tol` to a tie (a piece along
// another offset, a touch, an ambiguous link) makes the trace give up, and the caller falls back to
// the exact Boolean operations. The pieces it returns are checked exactly by the planner like any
// other, so a wrong trace could cost coverage, never safety; the tests compare the two ways.
#pragma once

#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/types.h>

#include <cstdint>
#include <vector>

namespace coverkit::detail {

/// The edges of a workspace's rings (all, or those added so far), in doubles, each with the
/// obstacle on its right, indexed by a grid of buckets.
class AxisEdges {
public:
  /// `cell`: the buckets' side (about a request's size); at most about 4 million buckets.
  AxisEdges(const Workspace& w, double cell);
  /// Ring 0 of a region is its outer ring, ring k >= 1 hole k - 1; each is added once.
  void addRing(std::size_t region, std::size_t ring);
  void addAll();

  struct Edge {
    double ax, ay, bx, by;   ///< a → b, the obstacle on the right
    bool axis;               ///< axis-parallel (exactly, on the rationals)
    bool convexAtB;          ///< the obstacle's corner at b is convex (the ring turns right or back there)
    bool convexAtA;          ///< the same at a
    std::uint32_t id, next;  ///< this edge and the one that starts at b
  };
  /// The edges whose boxes meet b, each once, in id order.
  void query(const BoxD& b, std::vector<const Edge*>& out) const;
  /// Whether p lies in the obstacles (outside every region, or in a hole), from the edge nearest to
  /// p found in growing squares of buckets: its side at its nearest point, or the convexity of the
  /// corner where that point is a vertex. 0 free, 1 obstacle, -1 undecided (a tie within `tol`, or
  /// no edge at all).
  int inObstacle(double px, double py, double tol) const;
  double extent() const { return extent_; }
  double scale() const { return scale_; }

private:
  const Workspace& w_;
  std::vector<std::vector<std::uint8_t>> added_;
  std::vector<Edge> edges_;
  std::vector<std::vector<std::uint32_t>> buckets_;
  double x0_ = 0, y0_ = 0, cell_ = 1, extent_ = 1, scale_ = 1;
  long nx_ = 1, ny_ = 1;
};

/// The sweep of `q` (as CSpace::sweeps defines it) for C-obstacles of radius `radius` about the
/// edges near U. Returns false, leaving `out` alone, when an edge within reach is not axis-parallel
/// or the trace meets a tie it cannot decide with the margin; the caller then uses the exact way.
bool axisSweep(const AxisEdges& edges, double radius, const CSpace::SweepRequest& q, CSpace::Sweep& out);

}  // namespace coverkit::detail
