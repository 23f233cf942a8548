// The coverkit command line: plan, evaluate, render, list, demo. Bad input: a message naming the
// file, the place and the problem on stderr, exit code 2, no output file.
#include "render.h"
#include "cmd_experiment.h"
#include "engine.h"
#include "runner.h"

#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/decomposition.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/registry.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <unistd.h>

#ifndef COVERKIT_GIT_REVISION
#define COVERKIT_GIT_REVISION "unknown"
#endif
#ifndef COVERKIT_VERSION
#define COVERKIT_VERSION "0.0.0"
#endif

namespace fs = std::filesystem;
using namespace coverkit;

namespace {

/// A progress bar on stderr, shown only on a terminal and only once a run has taken a second.
class Progress {
public:
  explicit Progress(std::size_t total) : total_(total), t0_(std::chrono::steady_clock::now()), tty_(isatty(2) != 0) {}
  void step(const std::string& what) {
    ++done_;
    if (!tty_ || std::chrono::steady_clock::now() - t0_ < std::chrono::seconds(1)) return;
    const int width = 30, filled = static_cast<int>(width * std::min(done_, total_) / std::max<std::size_t>(total_, 1));
    std::cerr << "\r[" << std::string(static_cast<std::size_t>(filled), '#') << std::string(static_cast<std::size_t>(width - filled), ' ') << "] "
              << done_ << "/" << total_ << " " << what.substr(0, 40) << "\033[K" << std::flush;
    shown_ = true;
  }
  ~Progress() {
    if (shown_) std::cerr << "\n";
  }

private:
  std::size_t total_, done_ = 0;
  std::chrono::steady_clock::time_point t0_;
  bool tty_, shown_ = false;
};

std::map<std::string, std::string> parseParams(const std::vector<std::string>& kv) {
  std::map<std::string, std::string> out;
  for (const std::string& s : kv) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--param", s, "expected KEY=VALUE");
    out[s.substr(0, eq)] = s.substr(eq + 1);
  }
  return out;
}

/// --time-limit: a finite number of seconds ≥ 0 (0: none), at most 10^9 (a deadline must stay a
/// steady_clock time point).
double parseTimeLimit(const std::string& text) {
  if (text.empty()) return 0;
  char* end = nullptr;
  errno = 0;
  const double t = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') throw InputError("--time-limit", text, "not a number of seconds");
  if (!std::isfinite(t) || t < 0 || t > 1e9) throw InputError("--time-limit", text, "must be a finite number of seconds in [0, 10^9] (0: no limit)");
  return t;
}

Problem makeProblem(const std::string& map, const std::string& radius, const std::string& start, bool unknownFree,
                    const std::string& cellSize) {
  Problem p;
  const Rational r = parseRational(radius, "--radius", radius);
  if (r <= 0) throw InputError("--radius", radius, "robot radius must be > 0");
  Robot robot{r, std::nullopt};
  if (!start.empty()) robot.start = experiments::parsePoint(start, "--start");
  if (!cellSize.empty()) p.cellSize = parseRational(cellSize, "--cell-size", cellSize);
  datasets::MapOptions mo;
  mo.unknownIsFree = unknownFree;
  p.workspace = datasets::loadMap(map, mo);
  p.robots.push_back(robot);
  return p;
}


nlohmann::json evaluationJson(const ValidationReport& v, const Metrics& m) {
  nlohmann::json j;
  j["valid"] = v.valid;
  j["violations"] = nlohmann::json::array();
  for (const auto& x : v.violations)
    j["violations"].push_back({{"kind", x.kind}, {"robot", x.robot}, {"segment", x.segment}, {"detail", x.detail}});
  for (auto& [k, val] : datasets::metricFields(m)) j[k] = val;
  j["area_method"] = m.areaMethod;
  return j;
}

void printEvaluation(const ValidationReport& v, const Metrics& m) {
  std::cout << "valid: " << (v.valid ? "yes" : "no") << "\n";
  for (const auto& x : v.violations)
    std::cout << "  violation [" << x.kind << "] robot " << x.robot << " segment " << x.segment << ": " << x.detail << "\n";
  for (auto& [k, val] : datasets::metricFields(m)) std::cout << "  " << std::left << std::setw(22) << k << formatDouble(val) << "\n";
  std::cout << "  area_method           " << m.areaMethod << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"coverkit: coverage path planning for disc robots on exact geometry"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(COVERKIT_VERSION) + " (" + COVERKIT_GIT_REVISION + ")" +
                                        (experiments::mpiBuiltIn() ? ", experiments with MPI" : ""));

  std::string map, radius, start, out, picture, planner = "stc", pathFile, cellSize;
  std::vector<std::string> params;
  bool unknownFree = false, json = false, showCells = false, showTree = false, showCspace = false, quiet = false;
  std::string timeLimitText;
  bool timings = false;
  unsigned threadCount = 0;
  auto addSpeedOptions = [&](CLI::App* c) {
    c->add_flag("--timings", timings, "print wall and CPU time per phase and the peak memory on stderr");
    c->add_option("--threads", threadCount, "threads for the phases that split (metrics' rasters); 0, the default: every core. "
                                            "The results do not depend on it")
        ->check(CLI::Range(0u, 1024u));
  };

  auto addMapOptions = [&](CLI::App* c, bool needRadius) {
    c->add_option("--map", map, "map file (.yaml ROS map, .map Moving AI, .wkt, .geojson, .grid)")->required();
    auto* r = c->add_option("--radius", radius, "robot disc radius r (map units); sub-cells are 2r unless --cell-size");
    if (needRadius) r->required();
    c->add_option("--cell-size", cellSize, "sub-cell size D (default 2r)");
    c->add_flag("--unknown-free", unknownFree, "ROS maps: treat unknown pixels as free (default: obstacle)");
  };
  auto* plan = app.add_subcommand("plan", "plan a coverage path");
  addMapOptions(plan, true);
  plan->add_option("--planner", planner, "planner name (see 'coverkit list')")->required();
  plan->add_option("--start", start, "start X,Y (default: centre of the first free sub-cell of the largest free component)");
  plan->add_option("--param", params, "planner parameter KEY=VALUE (repeatable)");
  plan->add_option("--time-limit", timeLimitText, "seconds, finite and >= 0 (0: none)");
  plan->add_option("--out", out, "output path file (.json, .csv, .geojson)")->required();
  plan->add_option("--picture", picture, "picture (.png, .svg)");
  addSpeedOptions(plan);

  auto* eval = app.add_subcommand("evaluate", "validate a path file and compute its metrics");
  addMapOptions(eval, false);
  eval->add_option("--path", pathFile, "path file (.json or .csv)")->required();
  eval->add_option("--start", start, "the robot's start X,Y: the path must begin there (default: wherever it begins)");
  eval->add_flag("--json", json, "print one JSON object");
  bool evalCspace = false;
  eval->add_flag("--cspace", evalCspace, "also check every piece against the (conservative) C-obstacles: violations of kind \"cspace\"");
  addSpeedOptions(eval);

  auto* render = app.add_subcommand("render", "draw a map with its cells, a planner's tree and a path");
  addMapOptions(render, true);
  render->add_option("--path", pathFile, "path file to draw");
  render->add_option("--planner", planner, "plan with this planner and draw its tree and path");
  render->add_option("--param", params, "planner parameter KEY=VALUE");
  render->add_option("--start", start, "start X,Y");
  render->add_flag("--cells", showCells, "draw the cell classification");
  render->add_flag("--tree", showTree, "draw the planner's spanning tree");
  render->add_option("--out", out, "picture (.png, .svg)")->required();

  auto* cspace = app.add_subcommand("cspace", "compute the C-space of the disc robot: C-obstacles, C-free components, areas");
  double relEps = 1e-6;
  addMapOptions(cspace, true);
  cspace->add_option("--start", start, "a start X,Y: its C-free component is reported");
  cspace->add_option("--epsilon", relEps, "approximation bound relative to the workspace extent (default 1e-6); C-obstacles err outward only")
      ->check(CLI::Range(1e-15, 1e-2));
  cspace->add_option("--out", out, "C-space file (.json with segments and arcs, or .geojson with arcs sampled)")->required();
  cspace->add_option("--picture", picture, "picture (.png, .svg)");
  render->add_flag("--cspace", showCspace, "overlay the C-space (C-obstacles and C-free components)");

  auto* decompose = app.add_subcommand("decompose", "decompose the robot's exact C-free into cells (docs/decompositions.md)");
  std::string method;
  addMapOptions(decompose, true);
  decompose->add_option("--method", method, "decomposition (see 'coverkit list'): boustrophedon, trapezoidal, grid")->required();
  decompose->add_option("--param", params, "decomposition parameter KEY=VALUE (repeatable), e.g. direction=30");
  decompose->add_option("--out", out, "cells file (.json with segments and arcs, or .geojson with one Polygon per cell)")->required();
  decompose->add_option("--picture", picture, "picture (.png, .svg)");

  auto* list = app.add_subcommand("list", "list planners and decompositions, and their parameters");
  std::string demoOut = "coverkit-demo";
  auto* demo = app.add_subcommand("demo", "plan every built-in scenario with every planner, validate, write a report");
  demo->add_option("--out", demoOut, "output folder (default: coverkit-demo)");
  unsigned demoJobs = 0;
  demo->add_option("--jobs", demoJobs, "plans run at once; 0, the default: every core")->check(CLI::Range(0u, 1024u));
  demo->add_flag("--quiet", quiet, "no summary line");

  CLI::App* experiment = experiments::addExperimentCommand(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  try {
    if (*list) {
      for (const std::string& n : planners::Registry::instance().names()) {
        auto p = planners::Registry::instance().create(n);
        const auto caps = p->capabilities();
        std::cout << n << ": " << p->description() << "\n  capabilities: " << (caps.online ? "online" : "offline")
                  << (caps.multiRobot ? ", multi-robot" : ", single robot") << ", output " << caps.output << ", covers " << caps.coverage << "\n";
        for (const auto& s : p->params())
          std::cout << "  --param " << s.name << "=<" << planners::toString(s.type) << "> default " << s.defaultValue << ", range " << s.range
                    << "\n      " << s.help << "\n";
      }
      for (const std::string& n : planners::DecompositionRegistry::instance().names()) {
        auto d = planners::DecompositionRegistry::instance().create(n);
        const auto caps = d->capabilities();
        std::cout << "decomposition " << n << ": " << d->description() << "\n  capabilities: " << (caps.monotone ? "monotone cells" : "cells not monotone")
                  << (caps.rotatable ? ", any sweep direction" : "") << "\n";
        for (const auto& s : d->params())
          std::cout << "  --param " << s.name << "=<" << planners::toString(s.type) << "> default " << s.defaultValue << ", range " << s.range
                    << "\n      " << s.help << "\n";
      }
      return 0;
    }
    if (*demo) {
      std::string commandLine;
      for (int i = 0; i < argc; ++i) commandLine += (i ? " " : "") + std::string(argv[i]);
      return experiments::runDemo(demoOut, demoJobs, quiet, commandLine);
    }
    if (*decompose) {
      const auto kv = parseParams(params);
      datasets::checkOutputFile(out, "--out", {".json", ".geojson"});
      if (!picture.empty()) experiments::checkPictureOutput(picture);
      {  // unknown method or bad parameters: before any work
        auto d = planners::DecompositionRegistry::instance().create(method);
        planners::ParamSet(d->params(), kv, method, "decomposition");
      }
      Progress progress(3);
      progress.step("reading the map");
      const Problem problem = makeProblem(map, radius, start, unknownFree, cellSize);
      planners::checkProblem(problem);
      progress.step("C-space and cells");
      const planners::Decomposed dec = planners::runDecomposition(method, problem, kv);
      if (dec.cells.cells.empty())
        throw InputError("--radius", radius, "C-free is empty: a disc of this radius fits nowhere in " + map + " (no cells)");
      const datasets::CellsDocument doc = experiments::cellsDocument(map, method, kv, problem, dec, datasets::extensionOf(out) == ".geojson");
      std::vector<CurveRegion> regions;
      for (const auto& c : doc.cells) regions.push_back(c.region);
      progress.step("writing");
      datasets::OutputBatch outputs;
      outputs.add(out, datasets::cellsFileContent(out, doc));
      if (!picture.empty()) {
        experiments::PictureContent pc;
        pc.workspace = &problem.workspace;
        pc.cfree = &regions;
        pc.title = method + " cells of " + fs::path(map).filename().string() + ", r = " + radius;
        outputs.add(picture, experiments::pictureBytes(picture, pc));
      }
      outputs.commit();
      std::cout << method << ": " << doc.cells.size() << " cell(s), " << doc.walls.size() << " wall(s), C-free area " << formatDouble(doc.cfreeArea);
      if (dec.cells.rotation.c != 1) std::cout << ", direction " << formatDouble(doc.directionDegrees) << " deg";
      std::cout << "; C-space " << formatDouble(std::round(dec.cspaceSeconds * 1000) / 1000) << " s, cells "
                << formatDouble(std::round(dec.decomposeSeconds * 1000) / 1000) << " s; wrote " << out << "\n";
      return 0;
    }
    if (*cspace) {
      datasets::checkOutputFile(out, "--out", {".json", ".geojson"});
      if (!picture.empty()) experiments::checkPictureOutput(picture);
      Progress progress(3);
      progress.step("reading the map");
      const Problem problem = makeProblem(map, radius, start, unknownFree, cellSize);
      planners::checkProblem(problem);
      progress.step("C-space");
      const CSpace cs(problem.workspace, problem.robots[0].radius, relEps);
      const datasets::CSpaceDocument doc = experiments::cspaceDocument(map, problem, cs);
      progress.step("writing");
      datasets::OutputBatch outputs;
      outputs.add(out, datasets::cspaceFileContent(out, doc));
      if (!picture.empty()) {
        experiments::PictureContent pc;
        pc.workspace = &problem.workspace;
        pc.cfree = &doc.components;
        pc.cobstacles = &doc.obstacles;
        pc.title = "C-space of " + fs::path(map).filename().string() + ", r = " + radius;
        outputs.add(picture, experiments::pictureBytes(picture, pc));
      }
      outputs.commit();
      std::cout << "C-free: " << doc.components.size() << " component(s), area " << formatDouble(doc.cfreeArea) << " of free area "
                << formatDouble(doc.freeArea) << " (epsilon " << formatDouble(doc.epsilon) << ")";
      if (doc.start) std::cout << "; start in component " << doc.startComponent;
      std::cout << "; wrote " << out << "\n";
      return 0;
    }
    if (*plan) {
      const auto kv = parseParams(params);
      const double timeLimit = parseTimeLimit(timeLimitText);
      if (!picture.empty()) experiments::checkPictureName(picture);
      datasets::checkOutputFile(out, "--out", {".json", ".csv", ".geojson"});
      if (!picture.empty()) experiments::checkPictureOutput(picture);
      planners::Registry::instance().create(planner);  // unknown planner: before any work
      experiments::setThreads(threadCount);
      Progress progress(6);
      experiments::PhaseTimer timer;
      progress.step("reading the map");
      timer.begin("read");
      Problem problem = makeProblem(map, radius, start, unknownFree, cellSize);
      progress.step("classifying cells");
      timer.begin("cells");
      const planners::PlanningContext ctx = planners::makeContext(std::move(problem));
      const std::map<std::string, std::string> phaseName{{"planning", "plan"}, {"validating", "validate"}, {"metrics", "metrics"}};
      const experiments::RunResult r = experiments::runOnce(ctx, planner, kv, timeLimit, [&](const std::string& what) {
        progress.step(what);
        timer.begin(phaseName.at(what));
      });
      progress.step("writing");
      timer.begin("write");
      datasets::OutputBatch outputs;  // everything made in memory first, then written all or nothing
      outputs.add(out, datasets::pathFileContent(out, experiments::pathDocument(ctx, r)));
      if (!picture.empty()) {
        experiments::PictureContent pc{&ctx.problem.workspace, &ctx.cells, &r.plan.treeEdges, &r.plan.paths, ctx.problem.robots[0].radius.get_d(),
                                       planner + " on " + fs::path(map).filename().string()};
        outputs.add(picture, experiments::pictureBytes(picture, pc));
      }
      outputs.commit();
      timer.end();
      for (const auto& [k, v] : r.plan.timings)
        if (k != "cells") timer.part("plan", k, v);
      for (const auto& [k, v] : r.metrics.seconds) timer.part("metrics", k, v);
      if (timings) std::cerr << timer.report();
      std::cout << planner << ": " << toString(r.plan.status) << (r.plan.message.empty() ? "" : " (" + r.plan.message + ")") << "; valid "
                << (r.validation.valid ? "yes" : "no") << "; sub-cell coverage " << formatDouble(r.metrics.subcellCoverage) << "; length "
                << formatDouble(r.metrics.length) << "; wrote " << out << "\n";
      if (!r.metrics.coverableSkipped.empty()) std::cerr << "coverkit: note: coverable coverage not computed: " << r.metrics.coverableSkipped << "\n";
      return succeeded(r.plan.status) && r.validation.valid ? 0 : 1;
    }
    if (*eval) {
      experiments::setThreads(threadCount);
      experiments::PhaseTimer timer;
      timer.begin("read");
      const datasets::PathDocument doc = datasets::readPathFile(pathFile);
      std::string rad = radius;
      if (rad.empty()) {
        if (doc.robotRadius <= 0) throw InputError(pathFile, "robot_radius", "missing: give --radius");
        rad = doc.robotRadius.get_str();
      }
      std::string cs = cellSize;
      if (cs.empty() && doc.cellSize > 0) cs = doc.cellSize.get_str();
      Problem problem = makeProblem(map, rad, "", unknownFree, cs);
      problem.robots.assign(std::max<std::size_t>(doc.paths.size(), 1), problem.robots[0]);
      for (std::size_t i = 0; i < doc.paths.size(); ++i)
        problem.robots[i].start = start.empty() ? Point{exactFromDouble(doc.paths[i].start.x), exactFromDouble(doc.paths[i].start.y)}
                                                : experiments::parsePoint(start, "--start");
      timer.begin("cells");
      const planners::PlanningContext ctx = planners::makeContext(problem);
      ValidationOptions vo;
      std::optional<CSpace> evalSpace;
      if (evalCspace) {
        timer.begin("C-space");
        evalSpace.emplace(ctx.problem.workspace, ctx.problem.robots[0].radius);
        vo.cspace = &*evalSpace;
      }
      timer.begin("validate");
      const ValidationReport v = validatePaths(ctx.problem, doc.paths, vo);
      timer.begin("metrics");
      MetricOptions mo = experiments::defaultMetricOptions();
      mo.cspace = evalSpace ? &*evalSpace : nullptr;
      mo.pathsKnownClear = v.valid;
      const Metrics m = computeMetrics(ctx.problem, ctx.cells, doc.paths, mo);
      timer.end();
      for (const auto& [k, sec] : m.seconds) timer.part("metrics", k, sec);
      if (timings) std::cerr << timer.report();
      if (!m.coverableSkipped.empty()) std::cerr << "coverkit: note: coverable coverage not computed: " << m.coverableSkipped << "\n";
      if (json) std::cout << evaluationJson(v, m).dump(1) << "\n";
      else printEvaluation(v, m);
      return v.valid ? 0 : 1;
    }
    if (*experiment) {
      std::string commandLine;
      for (int i = 0; i < argc; ++i) commandLine += (i ? " " : "") + std::string(argv[i]);
      return experiments::runExperimentCommand(commandLine);
    }
    if (*render) {
      experiments::checkPictureOutput(out, "--out");
      const auto kv = parseParams(params);
      const planners::PlanningContext ctx = planners::makeContext(makeProblem(map, radius, start, unknownFree, cellSize));
      std::vector<Path> paths;
      std::vector<std::pair<PointD, PointD>> tree;
      if (!pathFile.empty()) paths = datasets::readPathFile(pathFile).paths;
      else if (render->count("--planner")) {
        experiments::RunResult r = experiments::runOnce(ctx, planner, kv);
        paths = r.plan.paths;
        tree = r.plan.treeEdges;
      }
      experiments::PictureContent pc{&ctx.problem.workspace, showCells ? &ctx.cells : nullptr, showTree ? &tree : nullptr, &paths,
                                     ctx.problem.robots[0].radius.get_d(), fs::path(map).filename().string()};
      std::optional<CSpace> cs;
      std::vector<CurveRegion> cfree, cobs;
      if (showCspace) {
        cs.emplace(ctx.problem.workspace, ctx.problem.robots[0].radius);
        cfree = cs->components();
        cobs = cs->obstacles();
        pc.cfree = &cfree;
        pc.cobstacles = &cobs;
      }
      const std::string bytes = experiments::pictureBytes(out, pc);
      datasets::writeFileAtomically(out, bytes);
      return 0;
    }
  } catch (const InputError& e) {
    std::cerr << "coverkit: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "coverkit: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
