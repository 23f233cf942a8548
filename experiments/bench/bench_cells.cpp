// Cell classification from 10^4 to 10^7 sub-cells on a seeded clustered grid map (resolution 1,
// D = 1: one pixel per sub-cell) and on a seeded polygon world.
#include <benchmark/benchmark.h>

#include <coverkit/datasets/generators.h>
#include <coverkit/geometry/cell_grid.h>

#include <cmath>

using namespace coverkit;

static void BM_ClassifyGridMap(benchmark::State& state) {
  const int side = static_cast<int>(std::sqrt(static_cast<double>(state.range(0))));
  datasets::GridMapSpec spec;
  spec.width = spec.height = side;
  spec.density = 0.15;
  spec.clustered = true;
  spec.seed = 7;
  const Workspace w = datasets::gridToWorkspace(datasets::generateGridMap(spec), "bench");
  for (auto _ : state) benchmark::DoNotOptimize(classifyCells(w, Rational(1)));
  state.counters["subcells"] = static_cast<double>(side) * side;
  state.counters["vertices"] = static_cast<double>(w.vertexCount());
  state.SetComplexityN(static_cast<long>(side) * side);
}
BENCHMARK(BM_ClassifyGridMap)->RangeMultiplier(10)->Range(10'000, 10'000'000)->Unit(benchmark::kMillisecond)->Complexity();

static void BM_ClassifyPolygonWorld(benchmark::State& state) {
  datasets::PolygonWorldSpec spec;
  spec.width = spec.height = 100;
  spec.count = 60;
  spec.minSize = 2;
  spec.maxSize = 9;
  spec.shape = datasets::ObstacleShape::kStar;
  spec.seed = 3;
  const Workspace w = datasets::generatePolygonWorld(spec);
  const double D = 100.0 / std::sqrt(static_cast<double>(state.range(0)));
  const Rational d = decimalFromDouble(D);
  for (auto _ : state) benchmark::DoNotOptimize(classifyCells(w, d));
  state.counters["subcells"] = static_cast<double>(state.range(0));
  state.counters["vertices"] = static_cast<double>(w.vertexCount());
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_ClassifyPolygonWorld)->RangeMultiplier(10)->Range(10'000, 10'000'000)->Unit(benchmark::kMillisecond)->Complexity();
