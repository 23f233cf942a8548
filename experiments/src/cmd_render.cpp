// `coverkit render`. See cmd_render.h.
#include "cmd_render.h"

#include "cmd_common.h"
#include "render.h"
#include "runner.h"

#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/cspace.h>

#include <filesystem>
#include <optional>
#include <utility>

namespace fs = std::filesystem;

namespace coverkit::experiments {

namespace {

struct Options {
  CLI::App* command = nullptr;
  MapArgs map;
  std::string path, planner = "stc", start, out;
  std::vector<std::string> params;
  bool cells = false, tree = false, cspace = false;
};
Options& options() {
  static Options o;
  return o;
}

}  // namespace

CLI::App* addRenderCommand(CLI::App& app) {
  Options& o = options();
  auto* render = o.command = app.add_subcommand("render", "draw a map with its cells, a planner's tree and a path");
  addMapOptions(render, o.map, true);
  render->add_option("--path", o.path, "path file to draw");
  render->add_option("--planner", o.planner, "plan with this planner and draw its tree and path");
  render->add_option("--param", o.params, "planner parameter KEY=VALUE");
  render->add_option("--start", o.start, "start X,Y");
  render->add_flag("--cells", o.cells, "draw the cell classification");
  render->add_flag("--tree", o.tree, "draw the planner's spanning tree");
  render->add_option("--out", o.out, "picture (.png, .svg)")->required();
  render->add_flag("--cspace", o.cspace, "overlay the C-space (C-obstacles and C-free components)");
  return render;
}

int runRenderCommand() {
  const Options& o = options();
  checkPictureOutput(o.out, "--out");
  const auto kv = parseParams(o.params);
  const planners::PlanningContext ctx = planners::makeContext(makeProblem(o.map.map, o.map.radius, o.start, o.map.unknownFree, o.map.cellSize));
  std::vector<Path> paths;
  std::vector<std::pair<PointD, PointD>> tree;
  if (!o.path.empty()) paths = datasets::readPathFile(o.path).paths;
  else if (o.command->count("--planner")) {
    RunResult r = runOnce(ctx, o.planner, kv);
    paths = r.plan.paths;
    tree = r.plan.treeEdges;
  }
  PictureContent pc{&ctx.problem.workspace, o.cells ? &ctx.cells : nullptr, o.tree ? &tree : nullptr, &paths,
                    ctx.problem.robots[0].radius.get_d(), fs::path(o.map.map).filename().string()};
  std::optional<CSpace> cs;
  std::vector<CurveRegion> cfree, cobs;
  if (o.cspace) {
    cs.emplace(ctx.problem.workspace, ctx.problem.robots[0].radius);
    cfree = cs->components();
    cobs = cs->obstacles();
    pc.cfree = &cfree;
    pc.cobstacles = &cobs;
  }
  const std::string bytes = pictureBytes(o.out, pc);
  datasets::writeFileAtomically(o.out, bytes);
  return 0;
}

}  // namespace coverkit::experiments
