// The path processor registry and chain (see processor.h).
#include <coverkit/optimise/fillet.h>
#include <coverkit/optimise/smooth.h>
#include <coverkit/optimise/processor.h>

#include <coverkit/geometry/error.h>
#include <coverkit/geometry/validate.h>

#include <chrono>

namespace coverkit::optimise {

ProcessorRegistry& ProcessorRegistry::instance() {
  static ProcessorRegistry r = [] {
    ProcessorRegistry reg;
    reg.add("fillet", [] { return std::make_unique<FilletProcessor>(); });
    reg.add("smooth", [] { return std::make_unique<SmoothProcessor>(); });
    return reg;
  }();
  return r;
}

PostStep parsePostStep(const std::string& text) {
  PostStep step;
  const auto colon = text.find(':');
  step.name = text.substr(0, colon);
  if (step.name.empty()) throw InputError("--post", text, "expected NAME or NAME:KEY=VALUE;...");
  if (colon == std::string::npos) return step;
  const std::string rest = text.substr(colon + 1);
  std::size_t at = 0;
  while (at <= rest.size()) {
    const auto end = std::min(rest.find(';', at), rest.size());
    const std::string kv = rest.substr(at, end - at);
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--post", text, "expected KEY=VALUE, got '" + kv + "'");
    if (!step.params.emplace(kv.substr(0, eq), kv.substr(eq + 1)).second)
      throw InputError("--post", text, "parameter '" + kv.substr(0, eq) + "' given twice");
    at = end + 1;
  }
  return step;
}

void checkPostSteps(const std::vector<PostStep>& steps) {
  for (const PostStep& s : steps) {
    const auto p = ProcessorRegistry::instance().create(s.name);
    try {
      planners::ParamSet(p->params(), s.params, s.name, "path processor");
    } catch (const InputError& e) {   // ParamSet names --param; here the parameter came with --post
      throw InputError("--post", s.name + ":" + e.place(), e.problem());
    }
  }
}

Plan postProcess(const Problem& problem, Plan plan, const std::vector<PostStep>& steps) {
  if (plan.paths.empty() || steps.empty()) return plan;
  // A processor moves the pieces, which a timeline's entries lie on. One robot in a static world
  // needs no timing: its timeline is dropped (the robot-time metric times the processed path). A
  // team, or a robot among moving obstacles, must keep its timing: refused (docs/post-processing.md).
  bool timed = false;
  for (const Path& p : plan.paths) timed = timed || !p.timeline.empty();
  if (timed && (plan.paths.size() > 1 || !problem.movingObstacles.empty()))
    throw InputError("--post", steps.front().name,
                     "a team plan (or one among moving obstacles) is timed, and a path processor would move its pieces off its timeline");
  if (timed) {
    for (Path& p : plan.paths) p.timeline.clear();
    plan.statistics["post_timeline_dropped"] = 1;
  }
  std::map<std::string, int> seen;
  for (const PostStep& s : steps) {
    // the second fillet of a chain reports as post_fillet_2_...
    const int n = ++seen[s.name];
    const std::string prefix = "post_" + s.name + (n > 1 ? "_" + std::to_string(n) : "") + "_";
    const auto processor = ProcessorRegistry::instance().create(s.name);
    const planners::ParamSet params(processor->params(), s.params, s.name, "path processor");
    const auto t0 = std::chrono::steady_clock::now();
    Plan out = processor->process(problem, plan, params);
    bool valid = out.paths.size() == plan.paths.size();
    if (valid) valid = validatePaths(problem, out.paths).valid;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    for (const auto& [k, v] : out.statistics) plan.statistics[prefix + k] = v;
    plan.statistics[prefix + "reverted"] = valid ? 0 : 1;
    plan.timings.emplace_back("post " + s.name, seconds);
    if (valid) plan.paths = std::move(out.paths);
  }
  return plan;
}

}  // namespace coverkit::optimise
