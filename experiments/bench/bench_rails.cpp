// TRACC and BSA (the grid-rail planners) end to end, cells classified once, from 10^3 to 10^6 cells.
#include <benchmark/benchmark.h>

#include <coverkit/datasets/generators.h>
#include <coverkit/planners/registry.h>

#include <cmath>

using namespace coverkit;

namespace {
/// A seeded clustered grid map of about `cells` pixels (8 % blocked), one pixel per cell.
planners::PlanningContext railsContext(long cells, int& side) {
  side = static_cast<int>(std::sqrt(static_cast<double>(cells)));
  datasets::GridMapSpec spec;
  spec.width = spec.height = side;
  spec.density = 0.08;
  spec.clustered = true;
  spec.seed = 9;
  Problem p;
  p.workspace = datasets::gridToWorkspace(datasets::generateGridMap(spec), "rails");
  p.robots.push_back({Rational(1, 2), std::nullopt});
  return planners::makeContext(p);
}

void runRails(benchmark::State& state, const char* planner) {
  int side = 0;
  const planners::PlanningContext ctx = railsContext(state.range(0), side);
  Plan plan;
  for (auto _ : state) {
    plan = planners::runPlanner(planner, ctx, {});
    benchmark::DoNotOptimize(plan);
  }
  state.counters["subcells"] = static_cast<double>(side) * side;
  state.counters["astar_expansions"] = plan.statistics["astar_expansions"];
  state.counters["covered"] = plan.statistics["covered_cells"];
  if (plan.statistics.count("backtracks")) state.counters["backtracks"] = plan.statistics["backtracks"];
  if (plan.statistics.count("detours")) state.counters["detours"] = plan.statistics["detours"];
}
}  // namespace

static void BM_Tracc(benchmark::State& state) { runRails(state, "tracc"); }
static void BM_BsaSpiral(benchmark::State& state) { runRails(state, "bsa_spiral"); }
static void BM_BsaZigzag(benchmark::State& state) { runRails(state, "bsa_zigzag"); }
BENCHMARK(BM_Tracc)->RangeMultiplier(10)->Range(1'000, 1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BsaSpiral)->RangeMultiplier(10)->Range(1'000, 1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BsaZigzag)->RangeMultiplier(10)->Range(1'000, 1'000'000)->Unit(benchmark::kMillisecond);
