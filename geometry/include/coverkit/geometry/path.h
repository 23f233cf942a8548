#pragma once
// Paths, plans and problems: what planners produce and what the validator and metrics read.
#include <coverkit/geometry/types.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace coverkit {

/// A straight segment or a circular arc of the robot centre. Coordinates are doubles (output);
/// the validator reads them as the exact rationals they hold.
struct PathSegment {
  enum class Kind { kLine, kArc };
  Kind kind = Kind::kLine;
  PointD from, to;
  PointD center;      ///< arcs only
  bool ccw = true;    ///< arcs only: counter-clockwise from `from` to `to`

  static PathSegment line(PointD a, PointD b) { return {Kind::kLine, a, b, {}, true}; }
  static PathSegment arc(PointD a, PointD b, PointD c, bool ccw) { return {Kind::kArc, a, b, c, ccw}; }
  double length() const;
};

/// A place at a time: the robot centre (or a moving obstacle's) is at `p` at `t` seconds.
struct TimedPoint {
  double t = 0;
  PointD p;
};

struct Path {
  PointD start;
  std::vector<PathSegment> segments;
  /// A timed plan's motion (empty: untimed): from t = 0 at `start`, times strictly increasing, the
  /// robot moving linearly between consecutive entries (an equal place is a wait) along `segments`,
  /// and staying at the last entry's place afterwards. Needed for every robot of a team and with
  /// moving obstacles (docs/multi-robot.md).
  std::vector<TimedPoint> timeline;
  /// A polyline through the points (line segments), starting at the first.
  static Path fromPoints(const std::vector<PointD>& points);
  double length() const;
  /// Points along the path, arcs sampled so the chord error is at most `tolerance`.
  std::vector<PointD> polyline(double tolerance) const;
  /// The parts of the path inside `box`, as runs of points (pieces clipped to the box, arcs sampled
  /// with chord error ≤ `tolerance`); a run ends where the path leaves the box. The number of points
  /// is bounded by what lies inside the box, whatever the path does outside it (an arc of radius
  /// 1e12 costs what its part in the box costs): metrics and pictures sample with this.
  std::vector<std::vector<PointD>> polylineWithin(double tolerance, const BoxD& box) const;
};

struct Robot {
  Rational radius;                 ///< disc radius r > 0
  std::optional<Point> start;      ///< none: the documented default start is used
};

/// A disc of radius `radius` moving linearly between its waypoints (times strictly increasing), at its
/// first waypoint before that one's time and at its last one after (coverkit.scenario/1).
struct MovingObstacle {
  Rational radius;
  std::vector<TimedPoint> waypoints;
  /// Where it is at time t (doubles; the validator interpolates exactly).
  PointD at(double t) const;
};

/// One planning problem. D (sub-cell size) is 2r unless set.
struct Problem {
  Workspace workspace;
  std::vector<Robot> robots;
  std::optional<Rational> cellSize;
  std::vector<MovingObstacle> movingObstacles;   ///< none: a static world
  Rational subCellSize() const { return cellSize ? *cellSize : Rational(2 * robots.at(0).radius); }
};

enum class PlanStatus {
  kExactSolution,     ///< the planner's coverage goal was met
  kPartialCoverage,   ///< planned, but some reachable cells were left (e.g. time-out)
  kInvalidStart,      ///< the start is not usable for this planner (e.g. not in a free mega-cell)
  kNoFreeSpace,       ///< nothing to cover
  kTimeout,
};
const char* toString(PlanStatus s);
inline bool succeeded(PlanStatus s) { return s == PlanStatus::kExactSolution || s == PlanStatus::kPartialCoverage; }

struct Plan {
  std::string planner;
  PlanStatus status = PlanStatus::kExactSolution;
  std::string message;                        ///< human-readable detail for the status
  std::vector<Path> paths;                    ///< one per robot
  std::vector<std::pair<std::string, double>> timings;   ///< phase → seconds, in order
  std::map<std::string, double> statistics;   ///< planner-specific numbers
  std::vector<std::pair<PointD, PointD>> treeEdges;   ///< spanning-tree edges (for pictures), if any
};

}  // namespace coverkit
