#pragma once
// One experiment run: context → plan → validate → metrics. Used by the CLI, the demo and benches.
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/validate.h>
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

/// Parses "X,Y" exactly.
Point parsePoint(const std::string& text, const std::string& option);

}  // namespace coverkit::experiments
