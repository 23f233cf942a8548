// Large inputs end to end (docs/performance.md, "Large inputs"): a single polygon of 10^3 … 10^6
// vertices read from WKT text, classified, planned (stc), validated and measured; and a path file of
// 10^3 … 10^6 pieces read, validated and measured on a fixed 1000 m × 1000 m room. The coverable
// metric is left out (it needs the C-space, whose cost is measured in bench_cspace.cpp), and the
// covered area is rasterised (the exact area's cost grows with the path, not the input measured).
#include <benchmark/benchmark.h>

#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/validate.h>
#include <coverkit/planners/registry.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

using namespace coverkit;

namespace {

/// A "coastline": n vertices on a wavy circle of radius 5000 m, millimetre coordinates, seeded.
std::string coastWkt(long n) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(3);
  std::string first;
  os << "POLYGON((";
  for (long i = 0; i < n; ++i) {
    const double a = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    const double rad = 5000 * (1 + 0.05 * std::sin(37 * a) + 0.02 * std::sin(301 * a)) + jitter(rng);
    std::ostringstream v;
    v.setf(std::ios::fixed);
    v.precision(3);
    v << rad * std::cos(a) << " " << rad * std::sin(a);
    if (i == 0) first = v.str();
    os << (i ? "," : "") << v.str();
  }
  os << "," << first << "))";
  return os.str();
}

/// A boustrophedon path of n pieces (0.5 m long, r = 0.25) in the lower strip of the room.
std::string zigzagJson(long n) {
  std::ostringstream os;
  os << "{\"format\":\"coverkit.path/1\",\"planner\":\"bench\",\"robot_radius\":0.25,\"robots\":[{\"start\":[1,1],\"segments\":[";
  double x = 1, y = 1;
  int dir = 1;
  for (long i = 0; i < n; ++i) {
    double nx = x + dir * 0.5, ny = y;
    if (nx > 999 || nx < 1) {
      nx = x;
      ny = y + 0.5 > 45 ? y - 0.5 : y + 0.5;
      dir = -dir;
    }
    os << (i ? "," : "") << "{\"type\":\"line\",\"from\":[" << x << "," << y << "],\"to\":[" << nx << "," << ny << "]}";
    x = nx;
    y = ny;
  }
  os << "]}]}";
  return os.str();
}

Workspace room1000() {
  std::ostringstream os;
  os << "POLYGON((0 0,1000 0,1000 1000,0 1000,0 0)";
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      const int x = 50 + 100 * i, y = 50 + 100 * j;
      os << ",(" << x << " " << y << "," << x << " " << y + 10 << "," << x + 10 << " " << y + 10 << "," << x + 10 << " " << y << "," << x << " " << y << ")";
    }
  os << ")";
  return datasets::parseWkt(os.str(), "room1000");
}

}  // namespace

static void BM_LargePolygonPlan(benchmark::State& state) {
  const std::string wkt = coastWkt(state.range(0));
  for (auto _ : state) {
    Problem p;
    p.workspace = datasets::parseWkt(wkt, "coast");
    p.robots.push_back({Rational(10), std::nullopt});
    const planners::PlanningContext ctx = planners::makeContext(p);
    const Plan plan = planners::runPlanner("stc", ctx, {});
    const ValidationReport v = validatePaths(ctx.problem, plan.paths);
    MetricOptions mo;
    mo.pathsKnownClear = v.valid;
    mo.exactAreaMaxSegments = mo.exactAreaMaxSegmentsClear = 0;  // the raster: its cost is not the path's size
    const Metrics m = computeMetrics(ctx.problem, ctx.cells, plan.paths, mo);
    if (!v.valid) state.SkipWithError("invalid plan");
    benchmark::DoNotOptimize(m);
  }
  state.counters["vertices"] = static_cast<double>(state.range(0));
}
BENCHMARK(BM_LargePolygonPlan)->RangeMultiplier(10)->Range(1'000, 1'000'000)->Unit(benchmark::kMillisecond)->Iterations(1);

static void BM_LongPathEvaluate(benchmark::State& state) {
  const std::string file = (std::filesystem::temp_directory_path() / ("coverkit-bench-path-" + std::to_string(state.range(0)) + ".json")).string();
  std::ofstream(file) << zigzagJson(state.range(0));
  Problem p;
  p.workspace = room1000();
  p.robots.push_back({Rational(1, 4), Point{Rational(1), Rational(1)}});
  const planners::PlanningContext ctx = planners::makeContext(p);
  for (auto _ : state) {
    const datasets::PathDocument doc = datasets::readPathFile(file);
    const ValidationReport v = validatePaths(ctx.problem, doc.paths);
    MetricOptions mo;
    mo.pathsKnownClear = v.valid;
    const Metrics m = computeMetrics(ctx.problem, ctx.cells, doc.paths, mo);
    if (!v.valid) state.SkipWithError("invalid path");
    benchmark::DoNotOptimize(m);
  }
  std::filesystem::remove(file);
  state.counters["pieces"] = static_cast<double>(state.range(0));
}
BENCHMARK(BM_LongPathEvaluate)->RangeMultiplier(10)->Range(1'000, 1'000'000)->Unit(benchmark::kMillisecond)->Iterations(1);
