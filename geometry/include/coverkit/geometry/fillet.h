#pragma once
// Fillets: the circular arc tangent to two consecutive pieces of a path, in doubles. Whether a
// fillet is clear is for the caller to decide, exactly (CSpace::arcClear, ClearanceChecker).
#include <coverkit/geometry/path.h>

#include <functional>
#include <vector>

namespace coverkit {

/// The heading (radians) of a piece at its start or at its end.
double headingOf(const PathSegment& s, bool atEnd);

/// The heading change (radians, in (−π, π], positive to the left) where a ends and b begins.
double turnAt(const PathSegment& a, const PathSegment& b);

/// A piece travelled backwards.
PathSegment reversedPiece(const PathSegment& s);

/// Where the line p + s·d (d a unit vector) meets the circle about c of radius R: false when it
/// misses it, else its two parameters, s0 ≤ s1.
bool lineCircleCrossings(PointD p, PointD d, PointD c, double R, double& s0, double& s1);

/// Where the circles about c1 (radius r1) and c2 (radius r2) cross: false when they do not (or
/// share their centre), else the two points (equal where they touch), the first on the left of
/// the way from c1 to c2.
bool circleCrossings(PointD c1, double r1, PointD c2, double r2, PointD& left, PointD& right);

/// The arc of radius rho tangent to a (which ends at the joint) and to b (which begins there), on
/// the inner side of the turn: a line and a line, a line and an arc, an arc and a line, or two
/// arcs. a2 is a up to the first tangent point, f the arc, b2 b from the second. False when no
/// such circle touches both pieces inside them: then nothing is set.
bool filletCorner(const PathSegment& a, const PathSegment& b, double rho, PathSegment& a2, PathSegment& f, PathSegment& b2);

/// How roundCorners looks for a corner's radius: halving from maxRadius while it is at least
/// minRadius until one is accepted, then `bisections` steps between it and the radius above.
struct FilletSearch {
  double maxRadius = 0, minRadius = 0;
  int bisections = 0;
  double minTurnDeg = 1, maxTurnDeg = 179;   ///< corners turning more than min and less than max
  bool arcPairs = false;                      ///< also corners between two arcs
};

struct FilletCount {
  std::size_t corners = 0;   ///< joints of the range turning by more than minTurnDeg
  std::size_t rounded = 0;
};

/// Rounds the corners of segs[from, end), in path order: at a joint turning by more than
/// minTurnDeg and less than maxTurnDeg where at least one piece is a line (or any, with
/// search.arcPairs), the fillet (filletCorner)
/// of the largest radius the search finds such that piece i gives at most room(i, current i,
/// i + 1, true) of its end, piece i + 1 at most room(i + 1, i + 1, current i, false) of its start
/// (the pieces as they are then: i may have lost its start to the fillet before), and
/// accept(i, current i, i + 1, a2, f, b2)
/// holds (the caller's exact clearance and any other test); `rounded(i, a2, f, b2, radius)` hears
/// of each one made. segs itself is unchanged until the end, so the callbacks may read the
/// original pieces there.
FilletCount roundCorners(std::vector<PathSegment>& segs, std::size_t from, const FilletSearch& search,
                         const std::function<double(std::size_t, const PathSegment&, const PathSegment&, bool)>& room,
                         const std::function<bool(std::size_t, const PathSegment&, const PathSegment&, const PathSegment&, const PathSegment&,
                                                  const PathSegment&)>& accept,
                         const std::function<void(std::size_t, const PathSegment&, const PathSegment&, const PathSegment&, double)>& rounded = {});

}  // namespace coverkit
