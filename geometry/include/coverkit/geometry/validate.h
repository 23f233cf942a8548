#pragma once
// The independent validator: continuity, exact clearance, start respected.
// It knows nothing of planners; it reads a path's doubles as the exact rationals they hold.
#include <coverkit/geometry/path.h>

#include <memory>

#include <string>
#include <vector>

namespace coverkit {

class CSpace;

struct Violation {
  std::string kind;      ///< "continuity", "clearance", "start", "arc", "empty"
  int robot = 0;
  int segment = -1;      ///< index in the robot's segments, -1 for the path as a whole
  std::string detail;
};

struct ValidationReport {
  bool valid = true;
  std::vector<Violation> violations;
  std::size_t segmentsChecked = 0;
  std::size_t exactTests = 0;   ///< segment/edge pairs that needed exact arithmetic
};

struct ValidationOptions {
  /// Gap between consecutive pieces accepted as continuous (the gap itself is checked for
  /// clearance as a segment). Default 1e-9 (map units).
  double continuityTolerance = 1e-9;
  /// Distance within which the path must start at the robot's start.
  double startTolerance = 1e-9;
  std::size_t maxViolations = 50;
  /// When set, every piece is also checked against this C-space's (conservative) C-obstacles and
  /// a failure is a violation of kind "cspace". The distance check above is already exact against
  /// the exact C-obstacles; this one is stricter by up to the C-space's eps.
  const CSpace* cspace = nullptr;
  /// Threads (0: every core) over ranges of a long path (from 4,096 pieces a range); the report is
  /// the same for any number.
  unsigned threads = 1;
};

/// Validates one path per robot of `problem` (paths.size() must equal robots.size()).
ValidationReport validatePaths(const Problem& problem, const std::vector<Path>& paths,
                               const ValidationOptions& options = {});

/// Exact: the disc of radius r centred anywhere on the segment [a,b] lies in W and meets no obstacle
/// interior (distance to every boundary edge ≥ r, and a inside W). Exposed for tests and planners.
bool segmentClear(const Workspace& w, const Rational& r, const Point& a, const Point& b);

/// Whether a disc centre moving linearly from a (at time t0) to b (at t1 ≥ t0; a == b: waiting)
/// stays at least minDist from moving obstacle m throughout [t0, t1] (t1 = +inf: held at b from t0
/// on), decided exactly as the team validator decides it. For planners that time their moves.
bool movesClearOf(PointD a, PointD b, double t0, double t1, const MovingObstacle& m, const Rational& minDist);

/// segmentClear for many segments of one workspace and radius: the edge index is built once.
/// `clear` does not test that a lies in W (planners that call it know it does); the rest is exact.
/// Edges near the piece are first bounded with interval arithmetic and only the undecided ones are
/// computed exactly (`filtered`); `filtered = false` decides every nearby edge exactly, which gives
/// the same answers, slower (the tests compare the two).
class ClearanceChecker {
public:
  ClearanceChecker(const Workspace& w, const Rational& r, bool filtered = true);
  ~ClearanceChecker();
  ClearanceChecker(const ClearanceChecker&) = delete;
  ClearanceChecker& operator=(const ClearanceChecker&) = delete;
  bool clear(const Point& a, const Point& b);
  /// The same for a piece whose ends are doubles (a path's), read exactly as they are: no rationals
  /// are made unless an edge needs the exact test.
  bool clear(PointD a, PointD b);
  /// The arc from `from` about `center` (radius |from − center|), ccw or not, to the ray through
  /// `to`, as the validator reads an arc (false as well when `to` is not on the circle).
  bool clearArc(const Point& from, const Point& to, const Point& center, bool ccw);
  /// The same for an arc whose points are doubles, read exactly: decided on intervals where they
  /// suffice, the rationals made only otherwise (the same verdict).
  bool clearArc(PointD from, PointD to, PointD center, bool ccw);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace coverkit
