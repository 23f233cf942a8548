#pragma once
// The experiments the engine runs (docs/experiments.md): kinds, made from a YAML config, and the
// named experiments (`coverkit experiment NAME`), each a kind with a shipped config in
// experiments/configs/. A new kind is a class deriving from Experiment (engine.h) and one line in
// experiment_registry.cpp.
#include "engine.h"
#include "experiment_config.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace coverkit::experiments {

/// Makes an experiment of a kind from its config file and the settings given on the command line
/// instead (see ConfigOverrides; only the kind's `options` can be).
using ExperimentFactory = std::function<std::unique_ptr<Experiment>(const std::string& configFile, const ConfigOverrides& overrides)>;

struct ExperimentKind {
  std::string kind, description;
  ExperimentFactory make;
  std::vector<std::string> options = {};   ///< config keys the command line may set (`--KEY VALUE`)
};
/// A name of `coverkit experiment NAME`: a kind and its shipped config.
struct NamedExperiment {
  std::string name, kind, config, description;
};

const std::vector<ExperimentKind>& experimentKinds();
const std::vector<NamedExperiment>& namedExperiments();

/// The experiment of a config file: its `kind:` made from it, with `overrides` (InputError naming
/// --KEY when the kind has no such option). `kind` empty: any kind, `sweep` when the file names
/// none; else the config must be of that kind (or name none). Bad config: InputError naming the
/// file and the key, before anything runs.
std::unique_ptr<Experiment> experimentFromConfig(const std::string& configFile, const ConfigOverrides& overrides = {}, const std::string& kind = "");

/// The kind named `kind`, or nullptr.
const ExperimentKind* findExperimentKind(const std::string& kind);

/// The named experiment, or nullptr when `name` is not one.
const NamedExperiment* findNamedExperiment(const std::string& name);

}  // namespace coverkit::experiments
