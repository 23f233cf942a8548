#pragma once
// The papers' experiments, one function each (the `coverkit experiment NAME` command).
#include "engine.h"

#include <cstdint>
#include <memory>
#include <string>

namespace coverkit::experiments {

/// BSA paper, section 3: 30×30 grid maps with random obstacles, start S(0, 0), spiral against
/// zigzag filling, over many seeds. Writes OUT/results.csv (one row per seed and filling),
/// OUT/summary.md (the table) and OUT/backtracking.svg (the distributions). Returns the summary.
/// The largest --seeds and --size accepted (a size² map is planned, validated and measured per seed).
constexpr int kBsaMaxSeeds = 100'000;
constexpr int kBsaMaxSize = 1'000;
struct BsaExperimentOptions {
  int seeds = 100;
  int size = 30;
  double density = 0.05;  ///< fraction of blocked cells aimed at
  bool clustered = true;  ///< blobs (as the paper's figures) or scattered single cells
};
std::string runBsaExperiment(const BsaExperimentOptions& options, const std::string& outDir);

/// TRACC paper, section 3: its 11×11 grid (C1 … C121 row by row from S = C1) without obstacles and
/// in the two scenarios the text describes (scenario 2's obstacles are our assumption: the text
/// names only C60, C62 and C121). Writes OUT/scenario-K.grid, OUT/scenario-K.json (the path),
/// OUT/scenario-K.svg, OUT/results.csv and OUT/summary.md. Returns the summary.
std::string runTraccScenarios(const std::string& outDir);

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

/// Smooth-STC paper, Fig 13: coverage of the coverable region against time at constant speed, for
/// every planner of the config (experiments/configs/coverage_vs_time.yaml) on seeded polygon worlds:
/// the covered area of each path's prefix at common times (rasterised with its bound; the full path
/// exact). Writes OUT/results.csv, OUT/summary.md and OUT/chart.svg.
std::string runCoverageVsTime(const std::string& configFile, const std::string& outDir);

/// Read and check a config exactly as sweepExperiment / runCoverageVsTime do (the same InputErrors), then
/// stop: nothing is run or written. For fuzzing the config reader and for tests.
void checkSweepConfig(const std::string& configFile);
void checkCoverageVsTimeConfig(const std::string& configFile);

/// Issue 13: boustrophedon (BCD) against trapezoidal (TCD) cells of the exact C-free on seeded 20×20
/// polygon worlds with 0 … 30 holes (rotated rectangles, convex polygons, stars, discs), their
/// times, and boustrophedon coverage (on either decomposition) against Full-STC and Smooth-STC on
/// the same worlds. Writes OUT/results.csv, OUT/summary.md and OUT/chart.svg; returns the summary.
constexpr int kDecompositionMaxSeeds = 10'000;
struct DecompositionExperimentOptions {
  int seeds = 25;   ///< worlds per hole count
};
std::string runDecompositionExperiment(const DecompositionExperimentOptions& options, const std::string& outDir);

/// The path of a config shipped in experiments/configs/.
std::string defaultConfig(const std::string& name);

}  // namespace coverkit::experiments
