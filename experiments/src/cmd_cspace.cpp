// `coverkit cspace`. See cmd_cspace.h.
#include "cmd_cspace.h"

#include "cmd_common.h"
#include "render.h"
#include "runner.h"

#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/planners/planner.h>

#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;

namespace coverkit::experiments {

namespace {

struct Options {
  MapArgs map;
  std::string start, out, picture;
  double relEps = 1e-6;
  unsigned threads = 0;
};
Options& options() {
  static Options o;
  return o;
}

}  // namespace

CLI::App* addCspaceCommand(CLI::App& app) {
  Options& o = options();
  auto* cspace = app.add_subcommand("cspace", "compute the C-space of the disc robot: C-obstacles, C-free components, areas");
  addMapOptions(cspace, o.map, true);
  cspace->add_option("--start", o.start, "a start X,Y: its C-free component is reported");
  cspace->add_option("--epsilon", o.relEps, "approximation bound relative to the workspace extent (default 1e-6); C-obstacles err outward only")
      ->check(CLI::Range(1e-15, 1e-2));
  cspace->add_option("--out", o.out, "C-space file (.json with segments and arcs, or .geojson with arcs sampled)")->required();
  cspace->add_option("--picture", o.picture, "picture (.png, .svg)");
  cspace->add_option("--threads", o.threads, "threads for the obstacles' offsets; 0, the default: every core. The C-space does not depend on it")
      ->check(CLI::Range(0u, 1024u));
  return cspace;
}

int runCspaceCommand() {
  const Options& o = options();
  datasets::checkOutputFile(o.out, "--out", {".json", ".geojson"});
  if (!o.picture.empty()) checkPictureOutput(o.picture);
  Progress progress(3);
  progress.step("reading the map");
  const Problem problem = makeProblem(o.map.map, o.map.radius, o.start, o.map.unknownFree, o.map.cellSize);
  planners::checkProblem(problem);
  progress.step("C-space");
  const CSpace cs(problem.workspace, problem.robots[0].radius, o.relEps, o.threads);
  const datasets::CSpaceDocument doc = cspaceDocument(o.map.map, problem, cs);
  progress.step("writing");
  datasets::OutputBatch outputs;
  outputs.add(o.out, datasets::cspaceFileContent(o.out, doc));
  if (!o.picture.empty()) {
    PictureContent pc;
    pc.workspace = &problem.workspace;
    pc.cfree = &doc.components;
    pc.cobstacles = &doc.obstacles;
    pc.title = "C-space of " + fs::path(o.map.map).filename().string() + ", r = " + o.map.radius;
    outputs.add(o.picture, pictureBytes(o.picture, pc));
  }
  outputs.commit();
  std::cout << "C-free: " << doc.components.size() << " component(s), area " << formatDouble(doc.cfreeArea) << " of free area "
            << formatDouble(doc.freeArea) << " (epsilon " << formatDouble(doc.epsilon) << ")";
  if (doc.start) std::cout << "; start in component " << doc.startComponent;
  std::cout << "; wrote " << o.out << "\n";
  return 0;
}

}  // namespace coverkit::experiments
