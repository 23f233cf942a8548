// The `smooth` path processor (docs/post-processing.md): its time against the path's length, 10^2 …
// 10^5 line pieces, on a path that zigzags by 0.05 r about the middle line of a long empty room
// (r = 0.5, pieces of 0.2): one stretch, every vertex movable, every new piece checked exactly.
#include <benchmark/benchmark.h>

#include <coverkit/geometry/types.h>
#include <coverkit/optimise/processor.h>

using namespace coverkit;

static void BM_SmoothPieces(benchmark::State& state) {
  const long n = state.range(0);
  Problem problem;
  Region room;
  const Rational length = Rational(n) / 5 + 2;
  room.outer = {{0, 0}, {length, 0}, {length, 4}, {0, 4}};
  problem.workspace.regions = {room};
  problem.robots = {{Rational(1, 2), Point{1, 2}}};
  Plan plan;
  plan.status = PlanStatus::kExactSolution;
  Path path;
  path.start = {1, 2};
  PointD at{1, 2};
  for (long i = 1; i <= n; ++i) {
    const PointD next{1 + 0.2 * static_cast<double>(i), 2 + (i % 2 ? 0.025 : 0)};
    path.segments.push_back(PathSegment::line(at, next));
    at = next;
  }
  plan.paths = {path};
  double iterations = 0;
  for (auto _ : state) {
    const Plan out = optimise::postProcess(problem, plan, {{"smooth", {}}});
    iterations = out.statistics.at("post_smooth_iterations");
    benchmark::DoNotOptimize(out.paths.data());
  }
  state.counters["pieces"] = static_cast<double>(n);
  state.counters["iterations"] = iterations;
  state.SetComplexityN(n);
}
BENCHMARK(BM_SmoothPieces)->RangeMultiplier(10)->Range(100, 100'000)->Unit(benchmark::kMillisecond)->Complexity();
