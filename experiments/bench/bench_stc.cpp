// STC end to end (cells excluded: the context is built once) from 10^4 to 10^7 sub-cells.
#include <benchmark/benchmark.h>

#include <coverkit/datasets/generators.h>
#include <coverkit/planners/registry.h>

#include <cmath>

using namespace coverkit;

namespace {
/// A seeded clustered grid map of about `cells` pixels (5 % blocked), classified with D = 1.
planners::PlanningContext gridContext(long cells, int& side) {
  side = static_cast<int>(std::sqrt(static_cast<double>(cells)));
  datasets::GridMapSpec spec;
  spec.width = spec.height = side;
  spec.density = 0.05;
  spec.clustered = true;
  spec.seed = 5;
  Problem p;
  p.workspace = datasets::gridToWorkspace(datasets::generateGridMap(spec), "bench");
  p.robots.push_back({Rational(1, 2), std::nullopt});  // D = 1: one pixel per sub-cell
  return planners::makeContext(p);
}
}  // namespace

static void BM_Stc(benchmark::State& state) {
  int side = 0;
  const planners::PlanningContext ctx = gridContext(state.range(0), side);
  for (auto _ : state) {
    Plan plan = planners::runPlanner("stc", ctx, {{"tree", state.range(1) == 0 ? "dfs_ccw" : "kruskal_straight"}});
    benchmark::DoNotOptimize(plan);
  }
  state.counters["subcells"] = static_cast<double>(side) * side;
  state.SetComplexityN(static_cast<long>(side) * side);
}
BENCHMARK(BM_Stc)->ArgsProduct({{10'000, 100'000, 1'000'000, 10'000'000}, {0, 1}})->Unit(benchmark::kMillisecond);

static void BM_SpiralStc(benchmark::State& state) {
  int side = 0;
  const planners::PlanningContext ctx = gridContext(state.range(0), side);
  for (auto _ : state) benchmark::DoNotOptimize(planners::runPlanner("spiral_stc", ctx, {}));
  state.counters["subcells"] = static_cast<double>(side) * side;
}
BENCHMARK(BM_SpiralStc)->RangeMultiplier(10)->Range(10'000, 10'000'000)->Unit(benchmark::kMillisecond);
