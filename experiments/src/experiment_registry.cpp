// The engine's experiment kinds and named experiments. See experiment_registry.h.
#include "experiment_registry.h"

#include "paper_experiments.h"

#include <coverkit/geometry/error.h>

#include <yaml-cpp/yaml.h>

namespace coverkit::experiments {

namespace {
/// A kind whose config is all there is (no command-line settings).
template <std::unique_ptr<Experiment> (*Make)(const std::string&)>
std::unique_ptr<Experiment> fromFileOnly(const std::string& configFile, const ConfigOverrides&) {
  return Make(configFile);
}
}  // namespace

const std::vector<ExperimentKind>& experimentKinds() {
  static const std::vector<ExperimentKind> kinds{
      {"sweep", "every planner of the config on seeded polygon worlds or map files, against the radius, the obstacle count or their shape",
       fromFileOnly<sweepExperiment>},
      {"scenarios", "named maps with their own radius (a NAME FILE RADIUS list), every planner on each, a picture per run",
       fromFileOnly<scenarioExperiment>},
      {"coverage-vs-time", "coverage of the coverable region against time at constant speed, every planner of the config on seeded worlds",
       timeExperiment},
      {"bsa-backtracking", "BSA's spiral against zigzag filling on seeded grid maps: backtracks, length, turns", bsaExperiment,
       {"seeds", "size", "density", "obstacles"}},
      {"tracc-scenarios", "TRACC on the paper's 11×11 scenarios", traccExperiment},
      {"decompositions", "boustrophedon against trapezoidal cells, and boustrophedon coverage against the STC family", decompositionExperiment,
       {"seeds"}},
      {"multi-st", "the Multi-ST paper's Tables 5-8 and Figs 15-17: multi_st and multi_stc_balanced on its grids", multiStExperiment},
      {"team-check", "multi_st on seeded team scenarios: validity, completeness, determinism", teamCheckExperiment, {"seeds"}},
  };
  return kinds;
}

const std::vector<NamedExperiment>& namedExperiments() {
  static const std::vector<NamedExperiment> named{
      {"demo", "scenarios", "demo.yaml", "every built-in scenario (datasets/data) with every planner, validated and measured, a picture each"},
      {"coverage-vs-size", "sweep", "coverage_vs_size.yaml", "Smooth-STC paper, Fig 14-15: coverage and overlap against the robot's radius"},
      {"coverage-vs-complexity", "sweep", "coverage_vs_complexity.yaml", "Smooth-STC paper, Fig 16: coverage against the number of obstacles"},
      {"coverage-vs-shape", "sweep", "coverage_vs_shape.yaml", "coverage against the obstacles' shape"},
      {"coverage-vs-time", "coverage-vs-time", "coverage_vs_time.yaml", "Smooth-STC paper, Fig 13: coverage against time"},
      {"bsa-backtracking", "bsa-backtracking", "bsa_backtracking.yaml", "BSA paper, section 3: spiral against zigzag filling"},
      {"tracc-scenarios", "tracc-scenarios", "tracc_scenarios.yaml", "TRACC paper, section 3: its 11×11 scenarios"},
      {"decompositions", "decompositions", "decompositions.yaml", "boustrophedon against trapezoidal cells (docs/decompositions.md)"},
      {"multi-st", "multi-st", "multi_st.yaml", "Multi-ST paper, Tables 5-8 and Figs 15-17, beside multi_stc_balanced (docs/multi-robot.md)"},
      {"team-check", "team-check", "team_check.yaml", "multi_st on 500 seeded team scenarios: valid, complete, deterministic (docs/multi-robot.md)"},
  };
  return named;
}

const NamedExperiment* findNamedExperiment(const std::string& name) {
  for (const NamedExperiment& n : namedExperiments())
    if (n.name == name) return &n;
  return nullptr;
}

const ExperimentKind* findExperimentKind(const std::string& kind) {
  for (const ExperimentKind& k : experimentKinds())
    if (k.kind == kind) return &k;
  return nullptr;
}

std::unique_ptr<Experiment> experimentFromConfig(const std::string& configFile, const ConfigOverrides& overrides, const std::string& requiredKind) {
  std::string kind = requiredKind.empty() ? "sweep" : requiredKind;
  try {
    const YAML::Node root = YAML::LoadFile(configFile);
    if (root.IsMap() && root["kind"].IsDefined()) {
      if (!root["kind"].IsScalar()) throw InputError(configFile, "kind", "expected a name");
      kind = root["kind"].as<std::string>();
    }
  } catch (const YAML::Exception&) {
    // the kind's own reader reports the file's problem with its line
  }
  if (!requiredKind.empty() && kind != requiredKind)
    throw InputError(configFile, "kind", kind + ": this config is of another kind than " + requiredKind + " (run it with: coverkit experiment run " +
                                             configFile + ")");
  const ExperimentKind* k = findExperimentKind(kind);
  if (!k) {
    std::string known;
    for (const ExperimentKind& each : experimentKinds()) known += (known.empty() ? "" : ", ") + each.kind;
    throw InputError(configFile, "kind", "unknown experiment kind '" + kind + "' (known: " + known + ")");
  }
  for (const auto& [key, value] : overrides)
    if (std::find(k->options.begin(), k->options.end(), key) == k->options.end())
      throw InputError("--" + key, value, "not a setting of the " + kind + " experiment");
  return k->make(configFile, overrides);
}

}  // namespace coverkit::experiments
