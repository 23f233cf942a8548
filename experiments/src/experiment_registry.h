#pragma once
// The experiments the engine runs (docs/experiments.md): kinds, made from a YAML config, and the
// named experiments (`coverkit experiment NAME`), each a kind with a shipped config in
// experiments/configs/. A new kind is a class deriving from Experiment (engine.h) and one line in
// experiment_registry.cpp.
#include "engine.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace coverkit::experiments {

using ExperimentFactory = std::function<std::unique_ptr<Experiment>(const std::string& configFile)>;

struct ExperimentKind {
  std::string kind, description;
  ExperimentFactory make;
};
/// A name of `coverkit experiment NAME`: a kind and its shipped config.
struct NamedExperiment {
  std::string name, kind, config, description;
};

const std::vector<ExperimentKind>& experimentKinds();
const std::vector<NamedExperiment>& namedExperiments();

/// The experiment of a config file: its `kind:` (default: sweep) made from it. Bad config:
/// InputError naming the file and the key, before anything runs.
std::unique_ptr<Experiment> experimentFromConfig(const std::string& configFile);

/// The named experiment, or nullptr when `name` is not one.
const NamedExperiment* findNamedExperiment(const std::string& name);

}  // namespace coverkit::experiments
