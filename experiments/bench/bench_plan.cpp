// `coverkit plan` end to end, as the command runs it with its defaults (`--metrics basic`): read
// the map file, classify the cells, plan, validate exactly, measure, and make the path file's
// content (kept in memory: the disk's speed is not ours to measure). Every grid planner on every
// map of datasets/data (the demo's scenarios, at their radii) and on seeded grid maps of 10^4 to
// 10^6 cells written as ROS maps (PGM + YAML) once, outside the loop. The CPU time is the process's
// (every thread), as `--timings` reports it. COVERKIT_BENCH_MAPS adds maps of the user's (below).
// docs/performance.md has the table.
#include <benchmark/benchmark.h>

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/planners/registry.h>

#include "runner.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace coverkit;
namespace fs = std::filesystem;

namespace {

/// The planners that work on the sub-cell grid (boustrophedon works on exact cells instead).
const std::vector<std::string>& gridPlanners() {
  static const std::vector<std::string> p{"stc", "spiral_stc", "full_stc", "smooth_stc", "smooth_stc_online", "bsa_spiral", "bsa_zigzag", "tracc"};
  return p;
}

struct MapCase {
  std::string name, file, radius;
  long cells = 0;   ///< a generated map of about this many cells (file made on first use), else 0
};

/// datasets/data/scenarios.txt: NAME FILE RADIUS [START].
std::vector<MapCase> datasetMaps() {
  std::vector<MapCase> out;
  std::ifstream in(std::string(COVERKIT_DATA_DIR) + "/scenarios.txt");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    MapCase c;
    if (ls >> c.name >> c.file >> c.radius) {
      c.file = std::string(COVERKIT_DATA_DIR) + "/" + c.file;
      out.push_back(c);
    }
  }
  if (out.empty()) throw std::runtime_error("no scenarios in " + std::string(COVERKIT_DATA_DIR) + "/scenarios.txt");
  return out;
}

/// A seeded clustered grid map of about `cells` pixels (5 % blocked, pixels of 1 m), written once
/// as a ROS map in the temporary folder; r = 1/2 makes one pixel a sub-cell.
std::string generatedMapFile(long cells) {
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(cells))));
  const fs::path dir = fs::temp_directory_path() / "coverkit_bench_plan";
  fs::create_directories(dir);
  const std::string stem = "clustered_" + std::to_string(side);
  const fs::path yaml = dir / (stem + ".yaml");
  if (!fs::exists(yaml)) {
    datasets::GridMapSpec spec;
    spec.width = spec.height = side;
    spec.density = 0.05;
    spec.clustered = true;
    spec.seed = 5;
    const datasets::OccupancyGrid g = datasets::generateGridMap(spec);
    std::ofstream pgm(dir / (stem + ".pgm"), std::ios::binary);
    pgm << "P5\n" << g.width << " " << g.height << "\n255\n";
    for (int row = g.height - 1; row >= 0; --row)   // the image's first row is the top
      for (int col = 0; col < g.width; ++col) pgm.put(static_cast<char>(g.at(col, row) ? 0 : 254));
    std::ofstream(yaml) << "image: " << stem << ".pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 0\n"
                        << "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
  }
  return yaml.string();
}

/// One `plan` run: what the command does between its arguments and its output file.
std::string planEndToEnd(const MapCase& m, const std::string& planner, const MetricOptions& metrics, experiments::RunResult& result) {
  Problem p;
  p.workspace = datasets::loadMap(m.file);
  p.robots.push_back({parseRational(m.radius), std::nullopt});
  const planners::PlanningContext ctx = planners::makeContext(std::move(p));
  result = experiments::runOnce(ctx, planner, {}, 0, {}, metrics);
  return datasets::pathFileContent("plan.json", experiments::pathDocument(ctx, result));
}

void runCase(benchmark::State& state, MapCase m, const std::string& planner) {
  if (m.cells > 0) m.file = generatedMapFile(m.cells);
  experiments::setThreads(1);   // one core, as the table's CPU column reads
  const MetricOptions metrics = experiments::metricOptionsForLevel("basic");
  experiments::RunResult r;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string out = planEndToEnd(m, planner, metrics, r);
    bytes = out.size();
    benchmark::DoNotOptimize(out.data());
  }
  if (!r.validation.valid) state.SkipWithError("the plan is not valid");
  state.counters["valid"] = r.validation.valid ? 1 : 0;
  state.counters["subcells"] = static_cast<double>(r.metrics.freeSubcells);
  state.counters["pieces"] = static_cast<double>(r.metrics.segments);
  state.counters["bytes"] = static_cast<double>(bytes);
  // the phases of the last run (wall seconds)
  state.counters["t_plan"] = r.planSeconds;
  state.counters["t_validate"] = r.validateSeconds;
  state.counters["t_metrics"] = r.metricsSeconds;
}

/// COVERKIT_BENCH_MAPS="FILE@RADIUS;FILE@RADIUS...": the user's own maps besides (e.g. the Moving AI
/// and ROS maps of a benchmark suite).
std::vector<MapCase> userMaps() {
  std::vector<MapCase> out;
  const char* env = std::getenv("COVERKIT_BENCH_MAPS");
  std::istringstream in(env ? env : "");
  std::string item;
  while (std::getline(in, item, ';')) {
    const auto at = item.rfind('@');
    if (item.empty()) continue;
    if (at == std::string::npos) throw std::runtime_error("COVERKIT_BENCH_MAPS: " + item + ": expected FILE@RADIUS");
    out.push_back({fs::path(item.substr(0, at)).filename().string(), item.substr(0, at), item.substr(at + 1)});
  }
  return out;
}

/// Registered at start-up: one benchmark per (map, planner), named BM_PlanEndToEnd/MAP/PLANNER.
const bool registered = [] {
  std::vector<MapCase> maps = datasetMaps();
  for (MapCase& m : userMaps()) maps.push_back(m);
  for (long cells : {10'000L, 100'000L, 1'000'000L}) maps.push_back({"clustered_" + std::to_string(cells), "", "1/2", cells});
  for (const MapCase& m : maps)
    for (const std::string& planner : gridPlanners())
      benchmark::RegisterBenchmark(("BM_PlanEndToEnd/" + m.name + "/" + planner).c_str(),
                                   [m, planner](benchmark::State& s) { runCase(s, m, planner); })
          ->MeasureProcessCPUTime()
          ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace
