// `coverkit plan`. See cmd_plan.h.
#include "cmd_plan.h"

#include "cmd_common.h"
#include "render.h"
#include "runner.h"

#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/registry.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>

namespace fs = std::filesystem;

namespace coverkit::experiments {

namespace {

struct Options {
  MapArgs map;
  SpeedArgs speed;
  std::string out, picture, planner = "stc", timeLimit, scenario;
  std::vector<std::string> starts, params, post;
  int robots = 0;
};
Options& options() {
  static Options o;
  return o;
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

}  // namespace

CLI::App* addPlanCommand(CLI::App& app) {
  Options& o = options();
  auto* plan = app.add_subcommand("plan", "plan a coverage path");
  addMapOptions(plan, o.map, true);
  plan->add_option("--planner", o.planner, "planner name (see 'coverkit list')")->required();
  plan->add_option("--start", o.starts, "start X,Y (default: centre of the first free sub-cell of the largest free component); "
                                        "repeatable: one robot per start (a team planner, e.g. multi_stc_balanced)");
  plan->add_option("--robots", o.robots, "team size: robots without a --start are placed farthest apart (deterministic)");
  plan->add_option("--scenario", o.scenario, "scenario file (coverkit.scenario/1: moving obstacles, docs/formats.md)");
  plan->add_option("--param", o.params, "planner parameter KEY=VALUE (repeatable)");
  plan->add_option("--post", o.post, "path processor NAME[:KEY=VALUE;...] run on the plan before it is validated (repeatable, in order; "
                                     "see 'coverkit list')");
  plan->add_option("--time-limit", o.timeLimit, "seconds, finite and >= 0 (0: none)");
  plan->add_option("--out", o.out, "output path file (.json, .csv, .geojson)")->required();
  plan->add_option("--picture", o.picture, "picture (.png, .svg)");
  addSpeedOptions(plan, o.speed, "basic");
  return plan;
}

int runPlanCommand() {
  const Options& o = options();
  const auto kv = parseParams(o.params);
  const double timeLimit = parseTimeLimit(o.timeLimit);
  if (!o.picture.empty()) checkPictureName(o.picture);
  datasets::checkOutputFile(o.out, "--out", {".json", ".csv", ".geojson"});
  if (!o.picture.empty()) checkPictureOutput(o.picture);
  planners::Registry::instance().create(o.planner);  // unknown planner: before any work
  std::vector<optimise::PostStep> post;
  for (const std::string& p : o.post) post.push_back(optimise::parsePostStep(p));
  optimise::checkPostSteps(post);
  setThreads(o.speed.threads);
  Progress progress(post.empty() ? 6 : 7);
  PhaseTimer timer;
  progress.step("reading the map");
  timer.begin("read");
  Problem problem = makeProblem(o.map.map, o.map.radius, o.starts.empty() ? "" : o.starts[0], o.map.unknownFree, o.map.cellSize);
  addTeam(problem, o.starts, o.robots, o.scenario);
  progress.step("classifying cells");
  timer.begin("cells");
  planners::PlanningContext ctx = makeContext(std::move(problem), o.scenario);
  ctx.threads = threads();
  const std::map<std::string, std::string> phaseName{
      {"planning", "plan"}, {"post-processing", "post"}, {"validating", "validate"}, {"metrics", "metrics"}};
  const RunResult r = runOnce(ctx, o.planner, kv, timeLimit, [&](const std::string& what) {
    progress.step(what);
    timer.begin(phaseName.at(what));
  }, metricOptionsFor(o.speed), post);
  progress.step("writing");
  timer.begin("write");
  datasets::OutputBatch outputs;  // everything made in memory first, then written all or nothing
  outputs.add(o.out, datasets::pathFileContent(o.out, pathDocument(ctx, r)));
  if (!o.picture.empty()) {
    PictureContent pc{&ctx.problem.workspace, &ctx.cells, &r.plan.treeEdges, &r.plan.paths, ctx.problem.robots[0].radius.get_d(),
                      o.planner + " on " + fs::path(o.map.map).filename().string()};
    outputs.add(o.picture, pictureBytes(o.picture, pc));
  }
  outputs.commit();
  timer.end();
  for (const auto& [k, v] : r.plan.timings) {
    if (k == "cells") continue;
    const bool post = k.rfind("post ", 0) == 0;   // optimise::postProcess's steps
    timer.part(post ? "post" : "plan", post ? k.substr(5) : k, v);
  }
  for (const auto& [k, v] : r.metrics.seconds) timer.part("metrics", k, v);
  if (o.speed.timings) std::cerr << timer.report();
  std::cout << o.planner << ": " << toString(r.plan.status) << (r.plan.message.empty() ? "" : " (" + r.plan.message + ")") << "; valid "
            << (r.validation.valid ? "yes" : "no") << "; sub-cell coverage " << formatDouble(r.metrics.subcellCoverage) << "; length "
            << formatDouble(r.metrics.length) << "; wrote " << o.out << "\n";
  if (!r.metrics.coverableSkipped.empty()) std::cerr << "coverkit: note: coverable coverage not computed: " << r.metrics.coverableSkipped << "\n";
  return succeeded(r.plan.status) && r.validation.valid ? 0 : 1;
}

}  // namespace coverkit::experiments
