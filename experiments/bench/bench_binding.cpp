// The work `coverkit.plan` does in Python, done in C++ (docs/python.md, "Binding overhead"):
// makeContext + runOnce + the path document, on the cases of COVERKIT_BINDING_CASES
// ("MAP|RADIUS|PLANNER;..."); python/bench/bench_binding.py sets it, times the same cases from
// Python and prints both. Without the variable: rooms.grid at r = 0.125 with stc.
#include "runner.h"

#include <benchmark/benchmark.h>

#include <coverkit/datasets/readers.h>
#include <coverkit/planners/registry.h>

#include <cstdlib>
#include <sstream>

using namespace coverkit;

namespace {

struct Case {
  std::string map, radius, planner;
};

std::vector<Case> cases() {
  const char* env = std::getenv("COVERKIT_BINDING_CASES");
  std::string text = env ? env : std::string(COVERKIT_DATA_DIR) + "/rooms.grid|0.125|stc";
  std::vector<Case> out;
  std::stringstream all(text);
  std::string item;
  while (std::getline(all, item, ';')) {
    std::stringstream one(item);
    Case c;
    std::getline(one, c.map, '|');
    std::getline(one, c.radius, '|');
    std::getline(one, c.planner, '|');
    if (!c.map.empty()) out.push_back(c);
  }
  return out;
}

void planInProcess(benchmark::State& state, const Case& c) {
  const Workspace w = datasets::loadMap(c.map);   // Python reads the map once too, outside its timing
  for (auto _ : state) {
    Problem problem;
    problem.workspace = w;
    problem.robots.push_back({parseRational(c.radius), std::nullopt});
    const planners::PlanningContext ctx = planners::makeContext(std::move(problem));
    const experiments::RunResult r = experiments::runOnce(ctx, c.planner, {});
    const std::string json = datasets::pathJson(experiments::pathDocument(ctx, r));
    benchmark::DoNotOptimize(json.size());
  }
}

const bool registered = [] {
  for (const Case& c : cases())
    benchmark::RegisterBenchmark(("BM_PlanInProcess/" + c.map + "|" + c.radius + "|" + c.planner).c_str(),
                                 [c](benchmark::State& s) { planInProcess(s, c); })
        ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace
