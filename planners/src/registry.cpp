#include <coverkit/geometry/error.h>
#include <coverkit/planners/registry.h>
#include <coverkit/planners/stc_skeleton.h>
#include <coverkit/planners/bsa.h>
#include <coverkit/planners/smooth_stc.h>
#include <coverkit/planners/tracc.h>
#include <coverkit/planners/decompositions.h>
#include <coverkit/planners/boustrophedon.h>
#include <coverkit/planners/multi_stc.h>

#include <algorithm>

namespace coverkit::planners {

Registry& Registry::instance() {
  static Registry registry = [] {
    Registry r;
    // One line per built-in planner.
    r.add("stc", [] { return std::make_unique<StcPlanner>(); });
    r.add("spiral_stc", [] { return std::make_unique<SpiralStcPlanner>(); });
    r.add("full_stc", [] { return std::make_unique<FullStcPlanner>(); });
    r.add("smooth_stc", [] { return std::make_unique<SmoothStcPlanner>(); });
    r.add("smooth_stc_online", [] { return std::make_unique<SmoothStcOnlinePlanner>(); });
    r.add("tracc", [] { return std::make_unique<TraccPlanner>(); });
    r.add("bsa_spiral", [] { return std::make_unique<BsaPlanner>(BsaPlanner::Filling::kSpiral); });
    r.add("bsa_zigzag", [] { return std::make_unique<BsaPlanner>(BsaPlanner::Filling::kZigzag); });
    r.add("boustrophedon", [] { return std::make_unique<BoustrophedonPlanner>(); });
    r.add("multi_stc_balanced", [] { return std::make_unique<MultiStcBalancedPlanner>(); });
    r.add("multi_st", [] { return std::make_unique<MultiStPlanner>(); });
    return r;
  }();
  return registry;
}

DecompositionRegistry& DecompositionRegistry::instance() {
  static DecompositionRegistry registry = [] {
    DecompositionRegistry r;
    // One line per built-in decomposition.
    r.add("trapezoidal", [] { return std::make_unique<SweepDecomposition>(DecompositionRule::kTrapezoidal); });
    r.add("boustrophedon", [] { return std::make_unique<SweepDecomposition>(DecompositionRule::kBoustrophedon); });
    r.add("grid", [] { return std::make_unique<GridDecomposition>(); });
    return r;
  }();
  return registry;
}

Plan runPlanner(const std::string& name, const PlanningContext& context, const std::map<std::string, std::string>& params,
                double timeLimitSeconds) {
  auto planner = Registry::instance().create(name);
  const ParamSet set(planner->params(), params, name);
  if (context.problem.robots.size() > 1 && !planner->capabilities().multiRobot)
    throw InputError("--planner", name, "plans for one robot, and the problem has " + std::to_string(context.problem.robots.size()) +
                                            " (team planners: multi_st, multi_stc_balanced)");
  // a planner for one robot in a static world would drive through the moving obstacles
  if (!context.problem.movingObstacles.empty() && !planner->capabilities().multiRobot)
    throw InputError("--planner", name, "plans in static worlds, and the scenario has " + std::to_string(context.problem.movingObstacles.size()) +
                                            " moving obstacle(s) (planners that keep clear of them: multi_st, multi_stc_balanced)");
  Plan plan = planner->plan(context, set, TerminationCondition(timeLimitSeconds));
  plan.planner = name;
  plan.timings.insert(plan.timings.begin(), {"cells", context.cellSeconds});
  return plan;
}

std::vector<std::string> defaultPostProcessing(const std::string& name, const std::map<std::string, std::string>& params) {
  auto planner = Registry::instance().create(name);
  return planner->postProcessing(ParamSet(planner->params(), params, name));
}

}  // namespace coverkit::planners

namespace coverkit::planners {

Decomposed runDecomposition(const std::string& name, const Problem& problem, const std::map<std::string, std::string>& params) {
  auto d = DecompositionRegistry::instance().create(name);
  const ParamSet set(d->params(), params, name, "decomposition");
  return d->decompose(problem.workspace, problem.robots.at(0).radius, set);
}

}  // namespace coverkit::planners
