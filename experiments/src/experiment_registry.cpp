// The engine's experiment kinds and named experiments. See experiment_registry.h.
#include "experiment_registry.h"

#include "paper_experiments.h"

#include <coverkit/geometry/error.h>

#include <yaml-cpp/yaml.h>

namespace coverkit::experiments {

const std::vector<ExperimentKind>& experimentKinds() {
  static const std::vector<ExperimentKind> kinds{
      {"sweep", "every planner of the config on seeded polygon worlds or map files, against the radius, the obstacle count or their shape",
       sweepExperiment},
      {"scenarios", "named maps with their own radius (a NAME FILE RADIUS list), every planner on each, a picture per run", scenarioExperiment},
  };
  return kinds;
}

const std::vector<NamedExperiment>& namedExperiments() {
  static const std::vector<NamedExperiment> named{
      {"demo", "scenarios", "demo.yaml", "every built-in scenario (datasets/data) with every planner, validated and measured, a picture each"},
      {"coverage-vs-size", "sweep", "coverage_vs_size.yaml", "Smooth-STC paper, Fig 14-15: coverage and overlap against the robot's radius"},
      {"coverage-vs-complexity", "sweep", "coverage_vs_complexity.yaml", "Smooth-STC paper, Fig 16: coverage against the number of obstacles"},
      {"coverage-vs-shape", "sweep", "coverage_vs_shape.yaml", "coverage against the obstacles' shape"},
  };
  return named;
}

const NamedExperiment* findNamedExperiment(const std::string& name) {
  for (const NamedExperiment& n : namedExperiments())
    if (n.name == name) return &n;
  return nullptr;
}

std::unique_ptr<Experiment> experimentFromConfig(const std::string& configFile) {
  std::string kind = "sweep";
  try {
    const YAML::Node root = YAML::LoadFile(configFile);
    if (root.IsMap() && root["kind"].IsDefined()) {
      if (!root["kind"].IsScalar()) throw InputError(configFile, "kind", "expected a name");
      kind = root["kind"].as<std::string>();
    }
  } catch (const YAML::Exception&) {
    // the kind's own reader reports the file's problem with its line
  }
  std::string known;
  for (const ExperimentKind& k : experimentKinds()) {
    if (k.kind == kind) return k.make(configFile);
    known += (known.empty() ? "" : ", ") + k.kind;
  }
  throw InputError(configFile, "kind", "unknown experiment kind '" + kind + "' (known: " + known + ")");
}

}  // namespace coverkit::experiments
