#pragma once
// One experiment run: context → plan → validate → metrics. Used by the CLI, the demo and benches.
#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/validate.h>
#include <coverkit/optimise/processor.h>
#include <coverkit/planners/decomposition.h>
#include <coverkit/planners/planner.h>

#include <functional>
#include <map>
#include <string>

namespace coverkit::experiments {

struct RunResult {
  Plan plan;
  ValidationReport validation;
  Metrics metrics;
  double totalSeconds = 0;    ///< the cells' classification and the planner
  double planSeconds = 0, postSeconds = 0, validateSeconds = 0, metricsSeconds = 0;   ///< wall seconds of each phase
};

/// The metric options of the command line: everything, including the coverable region, on
/// `threads()` threads.
MetricOptions defaultMetricOptions();

/// `--metrics LEVEL`: `basic` (sub-cells, length, turns, time: linear in the path and the grid),
/// `area` (and the covered area, exact or rasterised with a bound), `full` (and the coverable
/// region, two more C-spaces: defaultMetricOptions()). std::invalid_argument for another name.
MetricOptions metricOptionsForLevel(const std::string& level);

/// Threads for the heavy phases that split (the metrics' rasters): `--threads`, 0 = every core.
/// Results are the same for any number.
void setThreads(unsigned n);
unsigned threads();

/// `--timings`: wall and CPU time per phase of a command, and the process's peak memory, printed on
/// stderr (nothing variable goes into an output file). CPU time is the process's, all threads.
class PhaseTimer {
public:
  /// Ends the running phase (if any) and starts `phase`.
  void begin(const std::string& phase);
  void end();
  /// A part of `phase` measured inside it (wall time only), shown indented below it.
  void part(const std::string& phase, const std::string& name, double wallSeconds);
  /// The table: phase, wall s, CPU s; then the total and the peak resident memory.
  std::string report() const;

private:
  struct Row {
    std::string phase;
    double wall = 0, cpu = -1;   ///< cpu < 0: a part (wall only)
  };
  std::vector<Row> rows_;
  bool running_ = false;
  double wall0_ = 0, cpu0_ = 0;
};

/// `onPhase`, when set, is called as each phase starts ("planning", "post-processing", "validating",
/// "metrics"). `post`: path processors run on the plan before it is validated (optimise::postProcess),
/// after those the planner names itself (planners::defaultPostProcessing: smooth_stc's fillet).
RunResult runOnce(const planners::PlanningContext& context, const std::string& planner,
                  const std::map<std::string, std::string>& params, double timeLimit = 0,
                  const std::function<void(const std::string&)>& onPhase = {}, const MetricOptions& metricOptions = defaultMetricOptions(),
                  const std::vector<optimise::PostStep>& post = {});

/// A run that could not start: the problem was refused (`why`, e.g. a start in an obstacle) before
/// any planner ran. Status invalid_start, no path, not valid (one violation of kind "start").
RunResult notStarted(const std::string& why);

/// The path file's content of a run (what `coverkit plan --out` writes; the Python module's
/// Plan.to_json).
datasets::PathDocument pathDocument(const planners::PlanningContext& context, const RunResult& result);

/// The cells file's content of a decomposition (what `coverkit decompose --out` writes), in the
/// workspace's frame; `sampled`: with the checked line polygons that GeoJSON needs.
datasets::CellsDocument cellsDocument(const std::string& map, const std::string& method, const std::map<std::string, std::string>& params,
                                      const Problem& problem, const planners::Decomposed& dec, bool sampled);

/// The C-space file's content (what `coverkit cspace --out` writes); refers to `cs`.
datasets::CSpaceDocument cspaceDocument(const std::string& map, const Problem& problem, const CSpace& cs);

/// Parses "X,Y" exactly.
Point parsePoint(const std::string& text, const std::string& option);

}  // namespace coverkit::experiments
