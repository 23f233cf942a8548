#pragma once
// Fillets: the circular arc tangent to two consecutive pieces of a path, in doubles. Whether a
// fillet is clear is for the caller to decide, exactly (CSpace::arcClear, ClearanceChecker).
#include <coverkit/geometry/path.h>

namespace coverkit {

/// The heading (radians) of a piece at its start or at its end.
double headingOf(const PathSegment& s, bool atEnd);

/// The heading change (radians, in (−π, π], positive to the left) where a ends and b begins.
double turnAt(const PathSegment& a, const PathSegment& b);

/// A piece travelled backwards.
PathSegment reversedPiece(const PathSegment& s);

/// The arc of radius rho tangent to a (which ends at the joint) and to b (which begins there), on
/// the inner side of the turn: a line and a line, a line and an arc, or an arc and a line. a2 is a
/// up to the first tangent point, f the arc, b2 b from the second. False when no such circle
/// touches both pieces inside them (or both are arcs): then nothing is set.
bool filletCorner(const PathSegment& a, const PathSegment& b, double rho, PathSegment& a2, PathSegment& f, PathSegment& b2);

}  // namespace coverkit
