#pragma once
// Core value types of coverkit. CGAL-free: geometry/src converts at the edge, once.
#include <coverkit/geometry/rational.h>

#include <string>
#include <vector>

namespace coverkit {

struct Point {
  Rational x, y;
};
inline bool operator==(const Point& a, const Point& b) { return a.x == b.x && a.y == b.y; }

struct PointD {
  double x = 0, y = 0;
};

/// An axis-parallel box in doubles (for sampling and pictures, never for decisions).
struct BoxD {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
};

/// A closed ring of vertices (the last vertex is not repeated). Outer rings are counter-clockwise,
/// holes clockwise, once a Workspace is normalised.
using Ring = std::vector<Point>;

/// One connected free region: its outer boundary and the obstacles inside it (holes).
struct Region {
  Ring outer;
  std::vector<Ring> holes;
};

struct Box {
  Rational xmin, ymin, xmax, ymax;
};

/// The workspace W: a set of interior-disjoint free regions. Everything outside them is obstacle.
/// Grid maps become regions whose holes are merged occupied (and unknown) pixels.
struct Workspace {
  std::vector<Region> regions;
  std::string name;    ///< where it came from (file name or generator spec)
  std::string units = "m";

  Box bbox() const;
  /// Every ring (outer rings and holes) in a stable order.
  std::vector<const Ring*> rings() const;
  std::size_t vertexCount() const;
};

/// Exact parity test: p strictly inside the ring. p must not lie on the ring (callers pick points
/// that cannot, such as an edge midpoint of a ring that only touches others at vertices).
bool insideRing(const Ring& ring, const Point& p);
/// The same parity over the listed edges only (edge i joins vertex i and i + 1): callers that index
/// a large ring's edges pass those an index lists on the ray to p's right (every edge that crosses
/// p's horizontal to its right must be listed).
bool insideRing(const Ring& ring, const Point& p, const std::vector<std::size_t>& edges);
/// Exact twice-signed area of a ring (counter-clockwise positive).
Rational signedArea2(const Ring& ring);
/// Exact area of the free space of a workspace.
Rational freeArea(const Workspace& w);
/// Rejects (InputError) rings that are degenerate, self-intersecting or have repeated vertices,
/// holes not strictly inside their outer ring or inside each other, and overlapping polygons.
/// Rings may touch at vertices. Exact; O(n log n) plus the pairs of edges that overlap in x.
void checkWorkspace(const Workspace& w);
/// Orients outer rings counter-clockwise and holes clockwise.
void normalise(Workspace& w);

}  // namespace coverkit
