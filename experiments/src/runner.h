#pragma once
// One experiment run: context → plan → validate → metrics. Used by the CLI, the demo and benches.
#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/validate.h>
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
  double totalSeconds = 0;
};

/// The metric options of the command line: everything, including the coverable region.
MetricOptions defaultMetricOptions();

/// `onPhase`, when set, is called as each phase starts ("planning", "validating", "metrics").
RunResult runOnce(const planners::PlanningContext& context, const std::string& planner,
                  const std::map<std::string, std::string>& params, double timeLimit = 0,
                  const std::function<void(const std::string&)>& onPhase = {}, const MetricOptions& metricOptions = defaultMetricOptions());

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
