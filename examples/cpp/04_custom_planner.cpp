// Example 04: a planner of your own, in one file, registered with one line. It is then a planner
// like every other: `runOnce` plans, validates and measures it, and the registry lists it.
//
// The planner: depth-first coverage of the free sub-cells (side 2r). From the start's sub-cell it
// moves to a free neighbour not yet visited (right, up, left, down first), and back to the cell it
// came from when there is none. A move joins the centres of two free sub-cells that share a side:
// the disc on that segment stays inside the two squares, so every move is clear; the validator
// checks it anyway.
//
//   04_custom_planner DATA_DIR OUT_DIR
#include "render.h"
#include "runner.h"

#include <coverkit/datasets/readers.h>
#include <coverkit/planners/registry.h>

#include <iostream>
#include <vector>

using namespace coverkit;

class DepthFirstPlanner : public planners::Planner {
public:
  std::string name() const override { return "depth_first"; }
  std::string description() const override { return "depth-first walk over the free sub-cells, backtracking to the parent"; }
  std::vector<planners::ParamSpec> params() const override { return {}; }
  planners::Capabilities capabilities() const override {
    planners::Capabilities c;
    c.coverage = "free_sub_cells";   // every free sub-cell 4-connected to the start's
    return c;
  }
  Plan plan(const planners::PlanningContext& ctx, const planners::ParamSet&, const planners::TerminationCondition& stop) override {
    Plan plan;
    plan.planner = name();
    const CellGrid& g = ctx.cells;
    CellIndex at;
    if (!ctx.problem.robots[0].start || !g.locateSub(*ctx.problem.robots[0].start, at) || g.sub(at.col, at.row) != CellState::kFree) {
      plan.status = PlanStatus::kInvalidStart;
      plan.message = "the start is not in a free sub-cell";
      return plan;
    }
    std::vector<char> seen(g.subCount(), 0);
    auto index = [&](int c, int r) { return static_cast<std::size_t>(r) * static_cast<std::size_t>(g.subCols()) + static_cast<std::size_t>(c); };
    std::vector<CellIndex> stack{at};
    seen[index(at.col, at.row)] = 1;
    std::vector<PointD> points{g.subCenterD(at.col, at.row)};
    const int dc[4] = {1, 0, -1, 0}, dr[4] = {0, 1, 0, -1};
    while (!stack.empty()) {
      if (stop.expired()) {
        plan.status = PlanStatus::kTimeout;
        break;
      }
      const CellIndex cur = stack.back();
      bool moved = false;
      for (int k = 0; k < 4 && !moved; ++k) {
        const int c = cur.col + dc[k], r = cur.row + dr[k];
        if (!g.insideSub(c, r) || g.sub(c, r) != CellState::kFree || seen[index(c, r)]) continue;
        seen[index(c, r)] = 1;
        stack.push_back({c, r});
        points.push_back(g.subCenterD(c, r));
        moved = true;
      }
      if (!moved) {   // back to the parent
        stack.pop_back();
        if (!stack.empty()) points.push_back(g.subCenterD(stack.back().col, stack.back().row));
      }
    }
    // the path starts at the robot's start (the centre of its sub-cell, or a point in it)
    points.front() = {ctx.problem.robots[0].start->x.get_d(), ctx.problem.robots[0].start->y.get_d()};
    plan.paths.push_back(Path::fromPoints(points));
    return plan;
  }
};

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: 04_custom_planner DATA_DIR OUT_DIR\n";
    return 2;
  }
  const std::string data = argv[1], out = argv[2];
  // the one registration line (in the library, it goes in planners/src/registry.cpp)
  planners::Registry::instance().add("depth_first", [] { return std::make_unique<DepthFirstPlanner>(); });
  try {
    Problem problem;
    problem.workspace = datasets::loadMap(data + "/rooms.grid");
    problem.robots.push_back({parseRational("0.125"), std::nullopt});
    const planners::PlanningContext context = planners::makeContext(problem);
    for (const std::string name : {"depth_first", "spiral_stc"}) {
      const experiments::RunResult run = experiments::runOnce(context, name, {});
      std::cout << name << ": " << toString(run.plan.status) << ", valid " << (run.validation.valid ? "yes" : "no") << ", sub-cell coverage "
                << run.metrics.subcellCoverage << ", length " << run.metrics.length << ", revisited sub-cells " << run.metrics.revisitedSubcells
                << "\n";
      if (!run.validation.valid) return 1;
      if (name == "depth_first") {
        experiments::PictureContent picture{&context.problem.workspace, &context.cells, nullptr, &run.plan.paths, 0.125,
                                            "depth_first (example 04) on rooms.grid"};
        experiments::renderPicture(out + "/04_custom_planner.png", picture);
      }
    }
    return 0;
  } catch (const InputError& e) {
    std::cerr << "04_custom_planner: " << e.what() << "\n";
    return 2;
  }
}
