#pragma once
// Coverage metrics, independent of any planner. Formulas in docs/metrics.md.
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/path.h>

#include <string>
#include <utility>
#include <vector>

namespace coverkit {

class CSpace;

struct MetricOptions {
  double speed = 0.2;                  ///< m/s, for time_s
  double turnToleranceDeg = 1.0;       ///< heading changes above this count as turns
  double reversalDeg = 150;            ///< heading changes above this count as reversals
  /// The differential-drive robot of robot_time_s (docs/metrics.md): top speed (m/s), acceleration
  /// and deceleration (m/s²), top turning rate (rad/s).
  double vMax = 0.5, aMax = 0.5, omegaMax = 1.5;
  std::size_t exactAreaMaxSegments = 3000;        ///< above this, area coverage is rasterised...
  std::size_t exactAreaMaxSegmentsClear = 20000;  ///< ...unless the path is clear (no clip to F needed)
  std::size_t rasterMaxPixels = 4'000'000;
  /// Measure the covered area (F ∩ swept: exact, or rasterised with a bound) and what derives from
  /// it. Off for `--metrics basic`: on large maps it is most of `plan`'s time (docs/performance.md).
  /// The coverable region needs it: `coverable` without `area` measures neither.
  bool area = true;
  /// Also measure against the coverable region (the starts' closed components of C-free ⊕ disc(r),
  /// docs/metrics.md); builds two C-spaces (radius r − δ and 2r − 2δ), so it is off unless asked for.
  bool coverable = false;
  /// ...but only for workspaces of at most this many vertices when no C-space is given: the
  /// C-space of a large polygon costs minutes (13 s at 10^4 vertices, docs/performance.md), far
  /// more than planning. Above it the coverable metrics are left out (Metrics::coverableSkipped).
  std::size_t coverableMaxVertices = 20000;
  /// A C-space of this workspace and radius whose cached helper C-spaces may be used (else they are
  /// built for this call).
  const CSpace* cspace = nullptr;
  /// The caller's validator already accepted the paths' continuity and clearance: skip that check.
  bool pathsKnownClear = false;
  /// Threads for the rasterised areas (0: every core); the values do not depend on it.
  unsigned threads = 0;
};

struct Metrics {
  std::size_t freeSubcells = 0;        ///< sub-cells classified free
  std::size_t coveredSubcells = 0;     ///< free sub-cells the robot centre entered
  double subcellCoverage = 0;          ///< covered / free
  std::size_t enteredSubcells = 0;     ///< distinct sub-cells entered (any state)
  std::size_t revisitedSubcells = 0;   ///< sub-cells entered more than once
  double overlapRatio = 0;             ///< revisited / entered
  bool hasArea = false;                ///< the covered area and the five below it were computed
  double freeArea = 0;                 ///< area(F)
  double coveredArea = 0;              ///< area(F ∩ swept)
  double areaCoverage = 0;             ///< coveredArea / freeArea
  double areaCoverageError = 0;        ///< bound on |areaCoverage − true value| (0 when exact)
  std::string areaMethod;              ///< "exact" or "raster"
  double sweptAreaOverlap = 0;         ///< (Σ 2r·len + πr²) / coveredArea − 1
  bool hasCoverable = false;           ///< the three below were computed
  std::string coverableSkipped;        ///< why they were not, although asked for (else empty)
  double coverableArea = 0;            ///< area of F ∩ (the starts' closed components of C-free) ⊕ disc(r)
  double coverableAreaError = 0;       ///< bound on |coverableArea − true value|
  double coverableCoverage = 0;        ///< coveredArea / coverableArea
  double length = 0;
  std::size_t turns = 0;
  double turningAngleDeg = 0;
  double time = 0;                     ///< length / speed (s)
  std::size_t reversals = 0;           ///< heading changes above reversalDeg at joints
  double maxCurvature = 0;             ///< largest 1/ρ over the arcs (1/m); corners are turns, not curvature
  double robotTime = 0;                ///< the slowest robot's traversal time, differential drive (s)
  std::size_t segments = 0;
  /// A timed plan's figures (docs/multi-robot.md), from the timelines' entries and the sub-cells
  /// their places lie in; only when some path has a timeline.
  bool hasTeam = false;
  std::size_t robots = 0;
  double makespan = 0;                 ///< the latest last entry's time (s)
  double sumOfTimes = 0;               ///< Σ of each robot's last entry's time (s)
  std::size_t steps = 0;               ///< moves between entries at different places, all robots (A1)
  std::size_t repeatedSteps = 0;       ///< of those, moves into a sub-cell some robot had entered before (A2)
  double coverageRate = 0;             ///< (A1 − A2) / free sub-cells: the Multi-ST paper's Equation (3)
  double iterationRate = 0;            ///< A2 / A1: the paper's iteration rate
  std::size_t mostCells = 0, leastCells = 0;   ///< distinct sub-cells entered by the busiest and the idlest robot
  double balance = 0;                  ///< most / mean distinct sub-cells entered per robot (1: even)
  /// Wall seconds per part ("sub-cells, length, turns", "covered area", "coverable region"): for
  /// `--timings`, never written to a file.
  std::vector<std::pair<std::string, double>> seconds;
};

Metrics computeMetrics(const Problem& problem, const CellGrid& cells, const std::vector<Path>& paths,
                       const MetricOptions& options = {});

/// The time a differential-drive robot takes to drive `path` (docs/metrics.md): it starts and ends
/// at rest; at a joint where the heading changes by more than turnToleranceDeg it stops and turns
/// on the spot at omegaMax; between such corners it drives the pieces without stopping, at most
/// vMax on a line and min(vMax, omegaMax·ρ) on an arc of radius ρ, accelerating and braking at aMax
/// (the time-optimal speed profile under these limits).
double robotTraversalTime(const Path& path, const MetricOptions& options = {});
/// How far along `path` (arc length) that robot is after `seconds` (the whole length once it has
/// finished): the prefix a coverage-against-time curve sweeps.
double robotDistanceAt(const Path& path, double seconds, const MetricOptions& options = {});

/// Area of F ∩ (path ⊕ disc(r)). Exact construction with CGAL (circle-segment traits) when every
/// line segment is axis-parallel or has a rational unit direction and there are no arcs; returns
/// false otherwise (the caller rasterises). With `pathIsClear` (the validator has shown the disc
/// never meets an obstacle interior) the swept set lies in the closure of F, so the intersection
/// with F is skipped: same value, far less work on maps with many vertices.
bool exactCoveredArea(const Workspace& w, const Rational& r, const std::vector<Path>& paths, double& area,
                      bool pathIsClear = false);
/// Rasterised area of F ∩ swept with a rigorous error bound (pixels whose status is uncertain), on
/// `threads` threads (0: every core); the result is the same, to the bit, for any number.
double rasterCoveredArea(const Workspace& w, const Rational& r, const std::vector<Path>& paths,
                         std::size_t maxPixels, double& errorBound, unsigned threads = 0);

}  // namespace coverkit
