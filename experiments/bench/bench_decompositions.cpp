// Decompositions (docs/decompositions.md, "Speed"): boustrophedon and trapezoidal cells of the exact
// C-free against the number of holes (1 … 1000: seeded polygon worlds whose side grows with the
// holes, so their density stays that of 15 holes in 20 m × 20 m), the C-space built outside the
// timed loop; and the whole boustrophedon plan (C-space, cells, sweep) of a 15-hole 20 m × 20 m world.
#include <benchmark/benchmark.h>

#include <coverkit/datasets/generators.h>
#include <coverkit/geometry/decomposition.h>
#include <coverkit/planners/registry.h>

#include <cmath>

using namespace coverkit;

namespace {

Workspace holesWorld(int holes) {
  datasets::PolygonWorldSpec spec;
  const int side = static_cast<int>(std::lround(20 * std::sqrt(std::max(1.0, holes / 15.0))));
  spec.width = side;
  spec.height = side;
  spec.count = holes;
  spec.minSize = 1;
  spec.maxSize = 3;
  spec.shape = datasets::ObstacleShape::kMixed;
  spec.seed = 1;
  return datasets::generatePolygonWorld(spec);
}

void decomposeBench(benchmark::State& state, DecompositionRule rule) {
  const Workspace w = holesWorld(static_cast<int>(state.range(0)));
  const CSpace space(w, Rational(1, 4));
  std::size_t cells = 0;
  for (auto _ : state) {
    const CellDecomposition d = decomposeCSpace(space, rule, "bench");
    cells = d.cells.size();
    benchmark::DoNotOptimize(cells);
  }
  std::size_t placed = 0;
  for (const Region& r : w.regions) placed += r.holes.size();
  state.counters["holes"] = static_cast<double>(placed);
  state.counters["cells"] = static_cast<double>(cells);
}

void BM_DecomposeBoustrophedon(benchmark::State& state) { decomposeBench(state, DecompositionRule::kBoustrophedon); }
void BM_DecomposeTrapezoidal(benchmark::State& state) { decomposeBench(state, DecompositionRule::kTrapezoidal); }
BENCHMARK(BM_DecomposeBoustrophedon)->Arg(1)->Arg(3)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecomposeTrapezoidal)->Arg(1)->Arg(3)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);

/// The C-space alone, for the same worlds (what a decomposition starts from).
void BM_CSpaceOfHoles(benchmark::State& state) {
  const Workspace w = holesWorld(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const CSpace space(w, Rational(1, 4));
    benchmark::DoNotOptimize(space.area());
  }
  std::size_t placed = 0;
  for (const Region& r : w.regions) placed += r.holes.size();
  state.counters["holes"] = static_cast<double>(placed);
}
BENCHMARK(BM_CSpaceOfHoles)->Arg(1)->Arg(3)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);

/// Decomposition + plan of a 15-hole world, end to end (planner phases as counters).
void BM_PlanBoustrophedon15Holes(benchmark::State& state) {
  const Workspace w = holesWorld(15);
  Problem problem;
  problem.workspace = w;
  problem.robots.push_back({Rational(1, 4), std::nullopt});
  const planners::PlanningContext ctx = planners::makeContext(problem);
  Plan plan;
  for (auto _ : state) {
    plan = planners::runPlanner("boustrophedon", ctx, {});
    benchmark::DoNotOptimize(plan.paths.size());
  }
  for (const auto& [phase, s] : plan.timings) state.counters[phase + "_s"] = s;
  state.counters["cells"] = plan.statistics["cells"];
}
BENCHMARK(BM_PlanBoustrophedon15Holes)->Unit(benchmark::kMillisecond);

}  // namespace
