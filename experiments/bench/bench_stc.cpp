// The STC family end to end (cells excluded: the context is built once) from 10^4 to 10^7 sub-cells.
#include <benchmark/benchmark.h>

#include <coverkit/datasets/generators.h>
#include <coverkit/planners/registry.h>

#include <chrono>
#include <cmath>
#include <map>

using namespace coverkit;

namespace {
/// A seeded clustered grid map of about `cells` pixels (5 % blocked), one pixel per sub-cell:
/// pixels of 1 and r = 1/2 (centres are doubles), or pixels of 1/10 and r = 1/20 (they are not).
planners::PlanningContext gridContext(long cells, int& side, bool decimal = false) {
  side = static_cast<int>(std::sqrt(static_cast<double>(cells)));
  datasets::GridMapSpec spec;
  spec.width = spec.height = side;
  spec.density = 0.05;
  spec.clustered = true;
  spec.seed = 5;
  spec.resolution = decimal ? Rational(1, 10) : Rational(1);
  Problem p;
  p.workspace = datasets::gridToWorkspace(datasets::generateGridMap(spec), "bench");
  p.robots.push_back({decimal ? Rational(1, 20) : Rational(1, 2), std::nullopt});
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

// Full-STC: arg 1 = 0 pixels of 1 (no rounding), 1 pixels of 1/10 (waypoints checked and repaired
// next to obstacles).
static void BM_FullStc(benchmark::State& state) {
  int side = 0;
  const planners::PlanningContext ctx = gridContext(state.range(0), side, state.range(1) == 1);
  double repaired = 0, checked = 0;
  for (auto _ : state) {
    Plan plan = planners::runPlanner("full_stc", ctx, {});
    repaired = plan.statistics["moves_repaired"];
    checked = plan.statistics["moves_checked_exactly"];
    state.counters["attempts"] = plan.statistics["attempts"];
    state.counters["left_out"] = plan.statistics["subcells_left_out"];
    for (const auto& [phase, seconds] : plan.timings) state.counters["t_" + phase] = seconds;
    benchmark::DoNotOptimize(plan);
  }
  state.counters["subcells"] = static_cast<double>(side) * side;
  state.counters["repaired"] = repaired;
  state.counters["checked"] = checked;
}
BENCHMARK(BM_FullStc)->ArgsProduct({{10'000, 100'000, 1'000'000, 10'000'000}, {0, 1}})->Unit(benchmark::kMillisecond);

// Smooth-STC against STC on the same maps, 10^3 … 10^6 mega-cells (4·10^3 … 4·10^6 sub-cells):
// time of each and their ratio per map (counters), with Smooth-STC's phases. Smooth-STC plans with
// the paper's tree and every detour, rooms left (the online planner's plan, and the configuration
// docs/performance.md's history was measured in); with the last argument 1 it plans with its
// defaults (straight tree, needed detours, rooms and gaps; the rounding is the pipeline's, not timed).
static void BM_SmoothStcVsStc(benchmark::State& state) {
  int side = 0;
  planners::PlanningContext ctx = gridContext(4 * state.range(0), side);
  ctx.threads = static_cast<unsigned>(state.range(1));  // Smooth-STC's sweeps; STC has no parallel phase
  double smoothSeconds = 0, stcSeconds = 0;
  const std::map<std::string, std::string> params =
      state.range(2) ? std::map<std::string, std::string>{} : std::map<std::string, std::string>{{"tree", "dfs_ccw"}, {"detours", "every"}, {"rooms", "leave"}, {"contours", "none"}, {"taut", "0"}};
  for (auto _ : state) {
    auto t0 = std::chrono::steady_clock::now();
    Plan smooth = planners::runPlanner("smooth_stc", ctx, params);
    auto t1 = std::chrono::steady_clock::now();
    Plan stc = planners::runPlanner("stc", ctx, {});
    auto t2 = std::chrono::steady_clock::now();
    smoothSeconds = std::chrono::duration<double>(t1 - t0).count();
    stcSeconds = std::chrono::duration<double>(t2 - t1).count();
    for (const auto& [phase, seconds] : smooth.timings) state.counters["t_" + phase] = seconds;
    state.counters["sweeps"] = smooth.statistics["sweeps"];
    state.counters["traced"] = smooth.statistics["sweeps_traced"];
    state.counters["pockets"] = smooth.statistics["pockets_joined"];
    state.counters["travel_passes"] = smooth.statistics["travel_passes"];
    state.counters["rooms"] = smooth.statistics["rooms_joined"];
    state.counters["gaps"] = smooth.statistics["gaps_visited"];
    benchmark::DoNotOptimize(smooth);
    benchmark::DoNotOptimize(stc);
  }
  state.counters["mega_cells"] = static_cast<double>(side) * side / 4;
  state.counters["smooth_s"] = smoothSeconds;
  state.counters["stc_s"] = stcSeconds;
  state.counters["ratio"] = stcSeconds > 0 ? smoothSeconds / stcSeconds : 0;
  state.counters["threads"] = ctx.threads;
  state.counters["defaults"] = static_cast<double>(state.range(2));
}
BENCHMARK(BM_SmoothStcVsStc)
    ->ArgsProduct({{1'000, 10'000, 100'000, 1'000'000}, {1, 2}, {0, 1}})
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
