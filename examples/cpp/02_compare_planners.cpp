// Example 02: compare planners on one map. Every registered planner plans the same problem; each
// plan is validated exactly; a table of coverage, length and turns, and a picture per planner.
//
//   02_compare_planners DATA_DIR OUT_DIR
#include "render.h"
#include "runner.h"

#include <coverkit/datasets/readers.h>
#include <coverkit/planners/registry.h>

#include <cstdio>
#include <iostream>

using namespace coverkit;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: 02_compare_planners DATA_DIR OUT_DIR\n";
    return 2;
  }
  const std::string data = argv[1], out = argv[2];
  try {
    Problem problem;
    problem.workspace = datasets::loadMap(data + "/pillars.wkt");   // a polygon map: arcs in C-space
    problem.robots.push_back({parseRational("0.25"), std::nullopt});
    const planners::PlanningContext context = planners::makeContext(problem);

    int invalid = 0;
    std::printf("%-20s %-22s %6s %9s %6s %9s\n", "planner", "status", "valid", "coverage", "turns", "length");
    for (const std::string& name : planners::Registry::instance().names()) {   // every registered planner
      const experiments::RunResult run = experiments::runOnce(context, name, {});
      std::printf("%-20s %-22s %6s %9.4f %6zu %9.1f\n", name.c_str(), toString(run.plan.status), run.validation.valid ? "yes" : "no",
                  run.metrics.coverableCoverage, run.metrics.turns, run.metrics.length);
      invalid += succeeded(run.plan.status) && !run.validation.valid;
      experiments::PictureContent picture{&context.problem.workspace, &context.cells, &run.plan.treeEdges, &run.plan.paths, 0.25,
                                          name + " on pillars.wkt"};
      experiments::renderPicture(out + "/02_" + name + ".svg", picture);
    }
    return invalid == 0 ? 0 : 1;
  } catch (const InputError& e) {
    std::cerr << "02_compare_planners: " << e.what() << "\n";
    return 2;
  }
}
