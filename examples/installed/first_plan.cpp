// Uses an installed coverkit (find_package(coverkit)): reads a map, plans with every registered
// planner, validates each plan exactly and prints one line per planner.
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/validate.h>
#include <coverkit/planners/registry.h>

#include <iostream>

int main(int argc, char** argv) {
  using namespace coverkit;
  if (argc != 2) {
    std::cerr << "usage: first_plan MAP\n";
    return 2;
  }
  try {
    Problem problem;
    problem.workspace = datasets::loadMap(argv[1]);
    problem.robots.push_back({parseRational("0.25"), std::nullopt});
    const planners::PlanningContext context = planners::makeContext(problem);
    int bad = 0;
    for (const std::string& name : planners::Registry::instance().names()) {
      const Plan plan = planners::runPlanner(name, context, {});
      const bool valid = succeeded(plan.status) && validatePaths(context.problem, plan.paths).valid;
      std::cout << name << ": " << toString(plan.status) << ", valid " << (valid ? "yes" : "no") << "\n";
      bad += !valid;
    }
    return bad == 0 ? 0 : 1;
  } catch (const InputError& e) {
    std::cerr << "first_plan: " << e.what() << "\n";
    return 2;
  }
}
