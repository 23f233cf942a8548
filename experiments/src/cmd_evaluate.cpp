// `coverkit evaluate`. See cmd_evaluate.h.
#include "cmd_evaluate.h"

#include "cmd_common.h"
#include "runner.h"

#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/scenario.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/multi_stc.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <optional>

namespace coverkit::experiments {

namespace {

struct Options {
  MapArgs map;
  SpeedArgs speed;
  std::string path, start, scenario;
  bool json = false, cspace = false;
};
Options& options() {
  static Options o;
  return o;
}

/// The metrics, and for timed (team) plans what they left (missed_from_starts, missed_from_team).
std::vector<std::pair<std::string, double>> fields(const Metrics& m, const std::optional<planners::MissedSubcells>& missed) {
  std::vector<std::pair<std::string, double>> out;
  for (auto& [k, val] : datasets::metricFields(m)) out.emplace_back(k, val);
  if (missed) {
    out.emplace_back("missed_from_starts", static_cast<double>(missed->fromStarts));
    out.emplace_back("missed_from_team", static_cast<double>(missed->fromTeam));
  }
  return out;
}

nlohmann::json evaluationJson(const ValidationReport& v, const Metrics& m, const std::optional<planners::MissedSubcells>& missed) {
  nlohmann::json j;
  j["valid"] = v.valid;
  j["violations"] = nlohmann::json::array();
  for (const auto& x : v.violations)
    j["violations"].push_back({{"kind", x.kind}, {"robot", x.robot}, {"segment", x.segment}, {"detail", x.detail}});
  for (auto& [k, val] : fields(m, missed)) j[k] = val;
  if (m.hasArea) j["area_method"] = m.areaMethod;
  return j;
}

void printEvaluation(const ValidationReport& v, const Metrics& m, const std::optional<planners::MissedSubcells>& missed) {
  std::cout << "valid: " << (v.valid ? "yes" : "no") << "\n";
  for (const auto& x : v.violations)
    std::cout << "  violation [" << x.kind << "] robot " << x.robot << " segment " << x.segment << ": " << x.detail << "\n";
  for (auto& [k, val] : fields(m, missed)) std::cout << "  " << std::left << std::setw(22) << k << formatDouble(val) << "\n";
  if (m.hasArea) std::cout << "  area_method           " << m.areaMethod << "\n";
}

}  // namespace

CLI::App* addEvaluateCommand(CLI::App& app) {
  Options& o = options();
  auto* eval = app.add_subcommand("evaluate", "validate a path file and compute its metrics");
  addMapOptions(eval, o.map, false);
  eval->add_option("--path", o.path, "path file (.json or .csv)")->required();
  eval->add_option("--start", o.start, "the robot's start X,Y: the path must begin there (default: wherever it begins)");
  eval->add_option("--scenario", o.scenario, "scenario file (coverkit.scenario/1): the plan must keep clear of its moving obstacles");
  eval->add_flag("--json", o.json, "print one JSON object");
  eval->add_flag("--cspace", o.cspace, "also check every piece against the (conservative) C-obstacles: violations of kind \"cspace\"");
  addSpeedOptions(eval, o.speed, "full");
  return eval;
}

int runEvaluateCommand() {
  const Options& o = options();
  setThreads(o.speed.threads);
  PhaseTimer timer;
  timer.begin("read");
  const datasets::PathDocument doc = datasets::readPathFile(o.path);
  std::string rad = o.map.radius;
  if (rad.empty()) {
    if (doc.robotRadius <= 0) throw InputError(o.path, "robot_radius", "missing: give --radius");
    rad = doc.robotRadius.get_str();
  }
  std::string cs = o.map.cellSize;
  if (cs.empty() && doc.cellSize > 0) cs = doc.cellSize.get_str();
  Problem problem = makeProblem(o.map.map, rad, "", o.map.unknownFree, cs);
  problem.robots.assign(std::max<std::size_t>(doc.paths.size(), 1), problem.robots[0]);
  for (std::size_t i = 0; i < doc.paths.size(); ++i)
    problem.robots[i].start = o.start.empty() ? Point{exactFromDouble(doc.paths[i].start.x), exactFromDouble(doc.paths[i].start.y)}
                                              : parsePoint(o.start, "--start");
  if (!o.scenario.empty()) problem.movingObstacles = datasets::readScenario(o.scenario);
  timer.begin("cells");
  const planners::PlanningContext ctx = makeContext(std::move(problem), o.scenario, false);
  ValidationOptions vo;
  vo.threads = threads();
  std::optional<CSpace> evalSpace;
  if (o.cspace) {
    timer.begin("C-space");
    evalSpace.emplace(ctx.problem.workspace, ctx.problem.robots[0].radius, 1e-6, threads());
    vo.cspace = &*evalSpace;
  }
  timer.begin("validate");
  const ValidationReport v = validatePaths(ctx.problem, doc.paths, vo);
  timer.begin("metrics");
  MetricOptions mo = metricOptionsFor(o.speed);
  mo.cspace = evalSpace ? &*evalSpace : nullptr;
  mo.pathsKnownClear = v.valid;
  const Metrics m = computeMetrics(ctx.problem, ctx.cells, doc.paths, mo);
  timer.end();
  for (const auto& [k, sec] : m.seconds) timer.part("metrics", k, sec);
  if (o.speed.timings) std::cerr << timer.report();
  if (!m.coverableSkipped.empty()) std::cerr << "coverkit: note: coverable coverage not computed: " << m.coverableSkipped << "\n";
  // timed plans (teams, or among moving obstacles): the free sub-cells they left
  std::optional<planners::MissedSubcells> missed;
  if (std::any_of(doc.paths.begin(), doc.paths.end(), [](const Path& p) { return !p.timeline.empty(); }))
    missed = planners::missedSubcells(ctx, doc.paths);
  if (o.json) std::cout << evaluationJson(v, m, missed).dump(1) << "\n";
  else printEvaluation(v, m, missed);
  return v.valid ? 0 : 1;
}

}  // namespace coverkit::experiments
