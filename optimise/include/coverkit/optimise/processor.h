#pragma once
// Path post-processing (issue 15): a PathProcessor turns a plan into a plan (fillets, smoothing),
// chained after any planner (`coverkit plan --post NAME[:k=v;...]`, experiment configs' `post`).
// Processors declare their parameters as planners do (ParamSpec), and a registry holds them: a
// new processor is one file and one line in processor.cpp. Every processed plan is validated
// exactly again by the chain (postProcess); a step whose result is not valid is reverted.
#include <coverkit/planners/planner.h>
#include <coverkit/planners/registry.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace coverkit::optimise {

class PathProcessor {
public:
  virtual ~PathProcessor() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  virtual std::vector<planners::ParamSpec> params() const = 0;
  /// The processed plan: one path per robot, from the same starts, every piece it adds checked
  /// exactly clear for the problem's robots; its own statistics (without prefix) in
  /// plan.statistics. Input plans come with paths (postProcess passes no others).
  virtual Plan process(const Problem& problem, const Plan& plan, const planners::ParamSet& params) const = 0;
};

class ProcessorRegistry : public planners::FactoryRegistry<PathProcessor> {
public:
  /// The registry with every built-in processor.
  static ProcessorRegistry& instance();
  ProcessorRegistry() : FactoryRegistry("--post", "path processor") {}
};

/// One step of a chain: a processor and its parameters.
struct PostStep {
  std::string name;
  std::map<std::string, std::string> params;
};

/// "NAME" or "NAME:k=v;k=v". InputError (naming --post and the text) for an empty name, an entry
/// without '=' or a key given twice; an unknown name or parameter is refused by postProcess.
PostStep parsePostStep(const std::string& text);

/// Checks every step's name and parameters (InputError as ParamSet does) without running it.
void checkPostSteps(const std::vector<PostStep>& steps);

/// Runs the steps in order on a plan with paths (another plan is returned as it is). Each step's
/// result is validated exactly (validatePaths); an invalid one is replaced by the step's input
/// (statistic post_NAME_reverted = 1). The step's own statistics are added as post_NAME_KEY
/// (post_NAME_2_KEY for the second step of that name, and so on), its wall time as the timing
/// "post NAME".
Plan postProcess(const Problem& problem, Plan plan, const std::vector<PostStep>& steps);

}  // namespace coverkit::optimise
