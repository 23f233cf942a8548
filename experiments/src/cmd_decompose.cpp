// `coverkit decompose`. See cmd_decompose.h.
#include "cmd_decompose.h"

#include "cmd_common.h"
#include "render.h"
#include "runner.h"

#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/registry.h>

#include <cmath>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;

namespace coverkit::experiments {

namespace {

struct Options {
  MapArgs map;
  std::string method, out, picture;
  std::vector<std::string> params;
};
Options& options() {
  static Options o;
  return o;
}

}  // namespace

CLI::App* addDecomposeCommand(CLI::App& app) {
  Options& o = options();
  auto* decompose = app.add_subcommand("decompose", "decompose the robot's exact C-free into cells (docs/decompositions.md)");
  addMapOptions(decompose, o.map, true);
  decompose->add_option("--method", o.method, "decomposition (see 'coverkit list'): boustrophedon, trapezoidal, grid")->required();
  decompose->add_option("--param", o.params, "decomposition parameter KEY=VALUE (repeatable), e.g. direction=30");
  decompose->add_option("--out", o.out, "cells file (.json with segments and arcs, or .geojson with one Polygon per cell)")->required();
  decompose->add_option("--picture", o.picture, "picture (.png, .svg)");
  return decompose;
}

int runDecomposeCommand() {
  const Options& o = options();
  const auto kv = parseParams(o.params);
  datasets::checkOutputFile(o.out, "--out", {".json", ".geojson"});
  if (!o.picture.empty()) checkPictureOutput(o.picture);
  {  // unknown method or bad parameters: before any work
    auto d = planners::DecompositionRegistry::instance().create(o.method);
    planners::ParamSet(d->params(), kv, o.method, "decomposition");
  }
  Progress progress(3);
  progress.step("reading the map");
  const Problem problem = makeProblem(o.map.map, o.map.radius, "", o.map.unknownFree, o.map.cellSize);
  planners::checkProblem(problem);
  progress.step("C-space and cells");
  const planners::Decomposed dec = planners::runDecomposition(o.method, problem, kv);
  if (dec.cells.cells.empty())
    throw InputError("--radius", o.map.radius, "C-free is empty: a disc of this radius fits nowhere in " + o.map.map + " (no cells)");
  const datasets::CellsDocument doc = cellsDocument(o.map.map, o.method, kv, problem, dec, datasets::extensionOf(o.out) == ".geojson");
  std::vector<CurveRegion> regions;
  for (const auto& c : doc.cells) regions.push_back(c.region);
  progress.step("writing");
  datasets::OutputBatch outputs;
  outputs.add(o.out, datasets::cellsFileContent(o.out, doc));
  if (!o.picture.empty()) {
    PictureContent pc;
    pc.workspace = &problem.workspace;
    pc.cfree = &regions;
    pc.title = o.method + " cells of " + fs::path(o.map.map).filename().string() + ", r = " + o.map.radius;
    outputs.add(o.picture, pictureBytes(o.picture, pc));
  }
  outputs.commit();
  std::cout << o.method << ": " << doc.cells.size() << " cell(s), " << doc.walls.size() << " wall(s), C-free area " << formatDouble(doc.cfreeArea);
  if (dec.cells.rotation.c != 1) std::cout << ", direction " << formatDouble(doc.directionDegrees) << " deg";
  std::cout << "; C-space " << formatDouble(std::round(dec.cspaceSeconds * 1000) / 1000) << " s, cells "
            << formatDouble(std::round(dec.decomposeSeconds * 1000) / 1000) << " s; wrote " << o.out << "\n";
  return 0;
}

}  // namespace coverkit::experiments
