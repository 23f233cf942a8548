#pragma once
// The experiment kinds of the engine, one file each (sweep_experiment.cpp, scenario_experiment.cpp,
// bsa_experiment.cpp, tracc_experiment.cpp, time_experiment.cpp, decomposition_experiment.cpp), made
// from a config file (and, for some, settings given on the command line). Registered in
// experiment_registry.cpp.
#include "engine.h"
#include "experiment_config.h"

#include <cstdint>
#include <memory>
#include <string>

namespace coverkit::experiments {

/// BSA paper, section 3 (kind `bsa-backtracking`, experiments/configs/bsa_backtracking.yaml; keys
/// seeds, size, density, obstacles: clustered or scattered; `coverkit experiment bsa-backtracking
/// --seeds N --size N --density D --obstacles K` overrides them): seeded grid maps with random
/// obstacles, start S(0, 0), spiral against zigzag filling. One case per usable seed (the first
/// `seeds` whose start region holds at least half the free cells), one row per filling; summary.md
/// and backtracking.svg (the distributions) from the rows.
constexpr int kBsaMaxSeeds = 100'000;
constexpr int kBsaMaxSize = 1'000;
std::unique_ptr<Experiment> bsaExperiment(const std::string& configFile, const ConfigOverrides& overrides);

/// TRACC paper, section 3 (kind `tracc-scenarios`, experiments/configs/tracc_scenarios.yaml: nothing
/// to set): its 11×11 grid (C1 … C121 row by row from S = C1) without obstacles and in the two
/// scenarios the text describes (scenario 2's obstacles are our assumption: the text names only
/// C60, C62 and C121). One case and row per scenario, with its files scenario-K.grid, .json (the
/// path) and .svg; summary.md.
std::unique_ptr<Experiment> traccExperiment(const std::string& configFile, const ConfigOverrides& overrides);

/// Smooth-STC paper, Fig 14-17 (kind `sweep` of the engine): coverage of the coverable region,
/// overlap and turns of every planner of a YAML config on the same seeded polygon worlds (or on map
/// files, key `maps`), against the robot radius, the number of obstacles or their shape (`vary`).
/// Shipped configs: experiments/configs/coverage_vs_size.yaml, coverage_vs_complexity.yaml,
/// coverage_vs_shape.yaml. One case per world and setting, one row per planner; summary.md and
/// chart.svg from the rows. Bad config: InputError naming the file, the key and the problem.
std::unique_ptr<Experiment> sweepExperiment(const std::string& configFile);

/// The `scenarios` kind: a list of NAME FILE RADIUS lines (datasets/data/scenarios.txt), every
/// planner of the config (default all) on each, one picture per run (pictures/NAME_PLANNER.svg).
/// The demo is this kind with experiments/configs/demo.yaml.
std::unique_ptr<Experiment> scenarioExperiment(const std::string& configFile);

/// Smooth-STC paper, Fig 13 (kind `coverage-vs-time`, experiments/configs/coverage_vs_time.yaml):
/// coverage of the coverable region against time at constant speed, for every planner of the config
/// on seeded polygon worlds: the covered area of each path's prefix at common times (rasterised
/// with its bound; the full path exact). One case per world, one row per planner; summary.md and
/// chart.svg.
std::unique_ptr<Experiment> timeExperiment(const std::string& configFile, const ConfigOverrides& overrides);

/// Read and check a config exactly as sweepExperiment / timeExperiment do (the same InputErrors), then
/// stop: nothing is run or written. For fuzzing the config reader and for tests.
void checkSweepConfig(const std::string& configFile);
void checkCoverageVsTimeConfig(const std::string& configFile);

/// Boustrophedon (BCD) against trapezoidal (TCD) cells of the exact C-free (kind `decompositions`,
/// experiments/configs/decompositions.yaml; keys seeds: worlds per hole count, holes: the hole
/// counts) on seeded 20×20 polygon worlds (rotated rectangles, convex polygons, stars, discs), their
/// times, and boustrophedon coverage (on either decomposition) against Full-STC and Smooth-STC on
/// the same worlds. One case per world, one row per planner; summary.md and chart.svg.
constexpr int kDecompositionMaxSeeds = 10'000;
std::unique_ptr<Experiment> decompositionExperiment(const std::string& configFile, const ConfigOverrides& overrides);

/// The Multi-ST paper's Tables 5-8 and Figs 15-17 (kind `multi-st`, experiments/configs/multi_st.yaml:
/// nothing to set): multi_st and multi_stc_balanced on the paper's grids (sub-cells of 1 m, seeded
/// obstacles; see multi_st_experiment.cpp for the readings of the paper). One case per table row,
/// one row per planner; summary.md and figs15-17.svg.
std::unique_ptr<Experiment> multiStExperiment(const std::string& configFile, const ConfigOverrides& overrides);
/// Seeded team scenarios (kind `team-check`, experiments/configs/team_check.yaml; key seeds, default
/// 500): multi_st planned twice on each, validated, completeness and determinism counted,
/// multi_stc_balanced's makespan beside it on the static ones. summary.md.
std::unique_ptr<Experiment> teamCheckExperiment(const std::string& configFile, const ConfigOverrides& overrides);

/// The path of a config shipped in experiments/configs/.
std::string defaultConfig(const std::string& name);

}  // namespace coverkit::experiments
