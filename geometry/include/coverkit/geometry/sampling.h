#pragma once
// Arcs as line segments, for the line-only outputs (CSV and GeoJSON paths, GeoJSON C-space), on the
// safe side (docs/formats.md, "Arcs in line-only formats").
//
// A chord of an arc lies closer to the arc's centre, a tangent polygon farther: an arc that turns
// about an obstacle corner at distance r (Smooth-STC's contour arcs, every C-obstacle arc of the
// C-space) keeps its clearance only when it is replaced by lines *outside* its circle, an arc with an
// obstacle beyond its outer side only with chords. So:
//  - paths: with the workspace, each arc is sampled on the side, and as finely, as the exact
//    clearance test (ClearanceChecker: the validator's own test of line pieces) accepts for every
//    line that replaces it: outside first, then inside, then both again at a quarter of the
//    tolerance, ... A path the validator accepts therefore gives a polyline it accepts too. Without
//    the workspace, arcs are replaced outside their circle.
//  - C-free: every arc of a C-free boundary has the C-obstacle inside its circle (offsets of
//    obstacle corners), so C-free lies outside and its sampled boundary runs outside the circle;
//    each line of the result is checked exactly (ClearanceChecker, radius r: the exact closed
//    C-free), vertices rounded to doubles the wrong way are moved into C-free, sharp spikes and
//    cusps are cut, arcs whose lines still fail are sampled more finely. A component that cannot be
//    made safe is left out: the polygons written lie in the exact C-free, they never claim more.
//    CSpace::sampledComponents feeds it the C-space of radius r + 4·eps, where nothing is pinched.
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/path.h>

#include <vector>

namespace coverkit {

enum class ArcSide {
  kInside,   ///< chords: every point within `tolerance` inside the circle
  kOutside,  ///< a polygon circumscribed to the circle: every point within `tolerance` outside it
};

/// The points that replace the arc `s` after s.from, up to and including s.to. Every point of the
/// polyline s.from → points lies on the given side of the arc's circle (strictly: by a margin of
/// a few ulps of the coordinates, so that rounding to doubles cannot cross it), within `tolerance`
/// of it. An arc with from == to is the full circle (as the validator reads it).
void sampleArc(const PathSegment& s, double tolerance, ArcSide side, std::vector<PointD>& out);

/// The path as points (start, then each piece; a gap before a piece keeps its `from`), arcs replaced
/// outside their circle (`sampleArc`, kOutside).
std::vector<PointD> outerPolyline(const Path& path, double tolerance);

struct SafePolyline {
  std::vector<PointD> points;
  /// The first arc that the validator accepts but for which no sampling was found whose lines it
  /// accepts too (−1: none; never seen). That arc was written outside its circle.
  int unsafeSegment = -1;
};
/// The path as points whose line segments the exact validator accepts wherever it accepts the
/// path: each arc is sampled on the side, and as finely, as ClearanceChecker(w, r) accepts.
SafePolyline safePolyline(const Path& path, const Workspace& w, const Rational& r, double tolerance);

/// C-free components as polygons inside the exact (closed) C-free of radius r: every edge of every
/// ring passes ClearanceChecker(w, r). One result per component, in order; a component that could
/// not be made safe has an empty `outer` (left out by the writers).
std::vector<SampledRegion> sampleFreeRegions(const std::vector<CurveRegion>& components, const Workspace& w,
                                             const Rational& r, double tolerance);
/// Regions with their arcs replaced towards the regions' inside (`inside`) or outside, not checked:
/// C-obstacles (outside: they cover their arcs; the same lines as C-free's before its checks), and
/// C-free when no workspace is at hand.
std::vector<SampledRegion> sampleRegions(const std::vector<CurveRegion>& regions, double tolerance, bool inside);

}  // namespace coverkit
