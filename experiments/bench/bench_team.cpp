// Teams at scale (issue 16): multi_stc_balanced and multi_st for 10 … 100 robots on a 256 × 256 grid map, with
// the team validator (robots against robots, exactly) and the team's metrics (`basic`), one thread. The map
// is a seeded clustered grid map (5 % blocked, pixels of 1 m, r = 1/2: a pixel is a sub-cell) made
// once; COVERKIT_BENCH_TEAM_MAP=FILE@RADIUS takes another (e.g. a Moving AI map of that size).
// Counters: the makespan in steps and the time per step of the plan and of the validation.
// docs/multi-robot.md has the table and the log-log chart.
#include <benchmark/benchmark.h>

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/validate.h>
#include <coverkit/planners/registry.h>

#include <chrono>
#include <cstdlib>
#include <string>

using namespace coverkit;

namespace {

const Workspace& teamMap(Rational& radius) {
  static Rational r(1, 2);
  static const Workspace w = [] {
    const char* env = std::getenv("COVERKIT_BENCH_TEAM_MAP");
    if (env && *env) {
      const std::string spec(env);
      const auto at = spec.rfind('@');
      r = parseRational(spec.substr(at + 1));
      return datasets::loadMap(spec.substr(0, at));
    }
    datasets::GridMapSpec s;
    s.width = s.height = 256;
    s.density = 0.05;
    s.clustered = true;
    s.seed = 16;
    return datasets::gridToWorkspace(datasets::generateGridMap(s), "clustered_256");
  }();
  radius = r;
  return w;
}

void BM_TeamPlan(benchmark::State& state, const std::string& planner) {
  Rational r;
  const Workspace& w = teamMap(r);
  Problem p;
  p.workspace = w;
  p.robots.assign(static_cast<std::size_t>(state.range(0)), Robot{r, std::nullopt});
  const planners::PlanningContext ctx = planners::makeContext(p);   // starts spread once
  Plan plan;
  ValidationReport rep;
  double tPlan = 0, tValidate = 0, tMetrics = 0;
  using Clock = std::chrono::steady_clock;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    plan = planners::runPlanner(planner, ctx, {}, 0);
    const auto t1 = Clock::now();
    rep = validatePaths(ctx.problem, plan.paths);
    const auto t2 = Clock::now();
    MetricOptions basic;   // `plan --metrics basic`: no areas
    basic.area = false;
    const Metrics m = computeMetrics(ctx.problem, ctx.cells, plan.paths, basic);
    benchmark::DoNotOptimize(m.steps);
    tPlan = std::chrono::duration<double>(t1 - t0).count();
    tValidate = std::chrono::duration<double>(t2 - t1).count();
    tMetrics = std::chrono::duration<double>(Clock::now() - t2).count();
  }
  if (!rep.valid) state.SkipWithError(("the team plan is not valid: " + rep.violations.at(0).detail).c_str());
  const double steps = plan.statistics.at("makespan_steps");
  state.counters["robots"] = static_cast<double>(state.range(0));
  state.counters["makespan_steps"] = steps;
  const auto tour = plan.statistics.find("tour_subcells");
  if (tour != plan.statistics.end()) state.counters["tour_subcells"] = tour->second;
  const auto entered = plan.statistics.find("subcells_entered");
  if (entered != plan.statistics.end()) state.counters["subcells_entered"] = entered->second;
  state.counters["t_plan"] = tPlan;
  state.counters["t_validate"] = tValidate;
  state.counters["t_metrics"] = tMetrics;
  state.counters["s_per_step"] = (tPlan + tValidate) / steps;
}
BENCHMARK_CAPTURE(BM_TeamPlan, multi_stc_balanced, std::string("multi_stc_balanced"))->Arg(10)->Arg(14)->Arg(20)->Arg(30)->Arg(50)->Arg(70)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_TeamPlan, multi_st, std::string("multi_st"))->Arg(10)->Arg(14)->Arg(20)->Arg(30)->Arg(50)->Arg(70)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
