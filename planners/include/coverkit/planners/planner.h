#pragma once
// The planner interface (after OMPL's Planner): one pure virtual does the work and returns a Plan
// whose status carries expected outcomes; only misuse and bad input throw (InputError).
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/path.h>

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace coverkit::planners {

enum class ParamType { kInt, kDouble, kBool, kChoice, kPath };
const char* toString(ParamType t);

/// A declared parameter. `range` is "lo:hi" for numbers (inclusive), "lo:hi|word|..." for a number or
/// one of the words (direction=best), or "a|b|c" for choices. A kPath value is one of its range's
/// words or the path of a file (any other non-empty text; the planner reads it and names it in errors).
struct ParamSpec {
  std::string name;
  ParamType type = ParamType::kDouble;
  std::string defaultValue;
  std::string range;
  std::string help;
};

/// Resolved parameter values (text), validated against the specs.
class ParamSet {
public:
  ParamSet() = default;
  /// Validates `given` (KEY → VALUE) against `specs`, filling defaults. Throws InputError for an
  /// unknown key, a value of the wrong type or out of range.
  /// `planner` and `kind` name the owner in errors ("planner 'stc'", "decomposition 'grid'").
  ParamSet(const std::vector<ParamSpec>& specs, const std::map<std::string, std::string>& given, const std::string& planner,
           const std::string& kind = "planner");
  const std::string& text(const std::string& name) const;
  double number(const std::string& name) const;
  long integer(const std::string& name) const;
  bool flag(const std::string& name) const;
  const std::map<std::string, std::string>& all() const { return values_; }

private:
  std::map<std::string, std::string> values_;
};

struct Capabilities {
  bool online = false;
  bool multiRobot = false;
  bool needsCells = true;
  std::string output = "lines";   ///< "lines" or "lines+arcs"
  /// What a successful plan covers: "free_mega_cells" (every sub-cell of the free mega-cells
  /// 4-connected to the start's), "free_sub_cells" (every free sub-cell 4-connected to the start's)
  /// or "cfree_component" (the start's component of C-free ⊕ disc(r), measured as an area).
  std::string coverage = "free_mega_cells";
};

/// Stops a planner: a deadline (or none).
class TerminationCondition {
public:
  TerminationCondition() = default;
  explicit TerminationCondition(double seconds)
      : deadline_(std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds))),
        bounded_(seconds > 0) {}
  bool expired() const { return bounded_ && std::chrono::steady_clock::now() > deadline_; }

private:
  std::chrono::steady_clock::time_point deadline_{};
  bool bounded_ = false;
};

/// What every planner gets: the problem and the shared, once-computed products.
struct PlanningContext {
  Problem problem;
  CellGrid cells;                      ///< exact classification with D = problem.subCellSize()
  double cellSeconds = 0;              ///< time spent classifying (reported as a phase)
  /// Threads a planner's heavy phases may use (0: every core; Smooth-STC's sweeps). Plans do not
  /// depend on it. 1 by default: the experiment engine runs cases side by side instead.
  unsigned threads = 1;
};

/// Checks robots, radii, starts and cell size against the workspace (InputError on bad input); the
/// workspace's coordinates must stay within ±10^150 (paths are doubles). makeContext adds
/// checkCellGridSize; a command without a cell grid (cspace) needs only this.
/// `teamStarts = false` leaves out the checks between robots' starts and moving obstacles' first
/// places (coverkit evaluate: a plan whose robots start too near is invalid, which the validator says).
void checkProblem(const Problem& problem, bool teamStarts = true);

/// The most sub-cells a problem may have (the cell grid takes about 2 bytes per sub-cell, the
/// planners' arrays more); the same limit as classifyCells.
constexpr long kMaxSubCells = 200'000'000L;
/// InputError naming --radius (or --cell-size when given), the grid's dimensions and the limit
/// when the sub-cell grid over the workspace's bounding box would exceed kMaxSubCells; counted
/// exactly, before anything is allocated.
void checkCellGridSize(const Problem& problem);

/// The sub-cell size a team plans on where D = 2r will not do. Two robots side by side in one
/// mega-cell stand exactly D apart at the sub-cell centres; where a centre is not a double (2r = 4/5
/// on a grid from 0, say) it is written an ulp towards its mega-cell's centre, and the two robots
/// would be an ulp nearer than 2r (and one robot among moving obstacles, whose timed steps go from
/// centre to centre, an ulp into a wall beside it). So for a problem of two robots or more, or
/// with moving obstacles, without a cell size of its own, whose centres at D = 2r are not all
/// doubles, D is 2r rounded up to a multiple of
/// δ = 2^(e − 30), plus δ, where 2^e is the power of two just above the map's largest coordinate
/// (at least 1): on a map of 32 m, δ = 2^-25 m (3·10^-8 m). The centres are then doubles wherever
/// the map's corner is a multiple of δ/2, and otherwise more than 2^20 ulps further apart than 2r.
/// The lanes of neighbouring sub-cells are at most 2δ further apart than the disc is wide, below what
/// any area figure resolves. nullopt: D = 2r (or the given cell size) stands. makeContext applies it.
std::optional<Rational> teamSubCellSize(const Problem& problem);

/// Builds the context: checks the problem and the size of its cell grid (InputError) before allocating
/// anything, classifies cells once, and fills in the default start where none was given (see defaultStart).
PlanningContext makeContext(Problem problem, bool teamStarts = true);

/// The documented default start: the centre of the first free sub-cell, in row order from the
/// bottom-left, that lies in a free mega-cell of the largest 4-connected component of free
/// mega-cells; without free mega-cells, the first free sub-cell of the largest 4-connected component
/// of free sub-cells. Nothing free: nullopt. The point is the double nearest the centre on the side
/// of its mega-cell's centre, read exactly, so a path file can state it exactly.
std::optional<Point> defaultStart(const CellGrid& cells);
/// Where STC puts the robot in sub-cell (col, row) of a free mega-cell: the double next to the
/// sub-cell's centre towards its mega-cell's centre (x depends on the column only, y on the row).
PointD stcWaypoint(const CellGrid& cells, int col, int row);
/// Starts for the robots of a team that have none (deterministic farthest-point placement): the
/// first at the default start unless some robot has a start (or, where a moving obstacle starts
/// within reach of it, at the nearest sub-cell clear of them, the first in row order among equals);
/// each next at the centre (as STC places it) of the sub-cell of a free mega-cell that is farthest, in 4-connected steps over such
/// sub-cells, from the starts placed so far (the first in row order among equals). InputError when
/// the reachable sub-cells run out. Sub-cells within r + ρ of where a moving obstacle goes in the
/// first second are passed over (a robot placed there could not get out of its way in time). makeContext calls it for problems of several robots.
void spreadStarts(const CellGrid& cells, std::vector<Robot>& robots, const std::vector<MovingObstacle>& obstacles = {});

class Planner {
public:
  virtual ~Planner() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  virtual std::vector<ParamSpec> params() const = 0;
  virtual Capabilities capabilities() const = 0;
  /// Plans. Bad parameters were rejected before (ParamSet); planning outcomes are statuses.
  virtual Plan plan(const PlanningContext& context, const ParamSet& params, const TerminationCondition& stop) = 0;
  /// The path processors (optimise/, each "NAME" or "NAME:KEY=VALUE;...") that follow this planner
  /// by default with these parameters. The pipeline (experiments::runOnce: `coverkit plan`, the
  /// experiment engine, Python) runs them, then any the user asks for, and validates the result
  /// exactly again; plan() itself returns the planner's own path. None by default.
  virtual std::vector<std::string> postProcessing(const ParamSet& /*params*/) const { return {}; }
};

}  // namespace coverkit::planners
