// Example 01: a first plan. Read a map, plan a coverage path for a disc robot, check it exactly,
// measure it, write the path file and a picture. (docs/python.md has the same steps in Python.)
//
//   01_first_plan DATA_DIR OUT_DIR      (DATA_DIR: datasets/data of the source tree)
#include "render.h"   // experiments/src: pictures
#include "runner.h"   // experiments/src: plan → validate → metrics, as `coverkit plan` does

#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/planners/registry.h>

#include <iostream>

using namespace coverkit;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: 01_first_plan DATA_DIR OUT_DIR\n";
    return 2;
  }
  const std::string data = argv[1], out = argv[2];
  try {
    // 1. The problem: a workspace (polygons with holes; a grid map becomes one) and a robot, a disc
    //    of radius r. Numbers that decide geometry are exact rationals: "1/8" or 0.125 as text.
    Problem problem;
    problem.workspace = datasets::loadMap(data + "/rooms.grid");
    problem.robots.push_back({parseRational("0.125"), std::nullopt});   // no start: the default one

    // 2. The context: the sub-cell grid (side 2r) classified exactly, shared by every planner.
    const planners::PlanningContext context = planners::makeContext(problem);

    // 3. Plan, validate exactly, measure: what `coverkit plan` does.
    const experiments::RunResult run = experiments::runOnce(context, "spiral_stc", {});
    std::cout << "status " << toString(run.plan.status) << ", valid " << (run.validation.valid ? "yes" : "no") << ", length "
              << run.metrics.length << ", turns " << run.metrics.turns << ", coverage of the coverable region "
              << run.metrics.coverableCoverage << "\n";

    // 4. The path file (coverkit.path/1 JSON, docs/formats.md) and a picture.
    datasets::writePathFile(out + "/01_first_plan.json", experiments::pathDocument(context, run));
    experiments::PictureContent picture{&context.problem.workspace, &context.cells, &run.plan.treeEdges, &run.plan.paths, 0.125,
                                        "spiral_stc on rooms.grid"};
    experiments::renderPicture(out + "/01_first_plan.png", picture);
    return run.validation.valid ? 0 : 1;
  } catch (const InputError& e) {   // bad input: a message naming the file, the place and the problem
    std::cerr << "01_first_plan: " << e.what() << "\n";
    return 2;
  }
}
