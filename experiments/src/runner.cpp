#include "runner.h"

#include <coverkit/geometry/error.h>
#include <coverkit/planners/registry.h>

#include <chrono>

namespace coverkit::experiments {

RunResult runOnce(const planners::PlanningContext& ctx, const std::string& planner, const std::map<std::string, std::string>& params,
                  double timeLimit, const std::function<void(const std::string&)>& onPhase, const MetricOptions& metricOptions) {
  auto phase = [&](const char* name) {
    if (onPhase) onPhase(name);
  };
  RunResult r;
  phase("planning");
  const auto t0 = std::chrono::steady_clock::now();
  r.plan = planners::runPlanner(planner, ctx, params, timeLimit);
  r.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() + ctx.cellSeconds;
  if (succeeded(r.plan.status)) {
    phase("validating");
    r.validation = validatePaths(ctx.problem, r.plan.paths);
    phase("metrics");
    MetricOptions mo = metricOptions;
    mo.pathsKnownClear = r.validation.valid;  // valid implies continuous and clear
    r.metrics = computeMetrics(ctx.problem, ctx.cells, r.plan.paths, mo);
  } else {
    r.validation.valid = false;
    r.validation.violations.push_back({"status", 0, -1, std::string(toString(r.plan.status)) + ": " + r.plan.message});
  }
  return r;
}

MetricOptions defaultMetricOptions() {
  MetricOptions o;
  o.coverable = true;
  return o;
}

Point parsePoint(const std::string& text, const std::string& option) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) throw InputError(option, text, "expected X,Y");
  return {parseRational(text.substr(0, comma), option, text), parseRational(text.substr(comma + 1), option, text)};
}

}  // namespace coverkit::experiments
