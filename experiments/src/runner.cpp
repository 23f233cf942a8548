#include "runner.h"

#include <coverkit/geometry/decomposition.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/registry.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <iomanip>
#include <sstream>

#include <sys/resource.h>

namespace coverkit::experiments {

RunResult runOnce(const planners::PlanningContext& ctx, const std::string& planner, const std::map<std::string, std::string>& params,
                  double timeLimit, const std::function<void(const std::string&)>& onPhase, const MetricOptions& metricOptions,
                  const std::vector<optimise::PostStep>& post) {
  auto phase = [&](const char* name) {
    if (onPhase) onPhase(name);
  };
  RunResult r;
  // the planner's own processors first (Planner::postProcessing: smooth_stc's fillet), then the user's
  std::vector<optimise::PostStep> steps;
  for (const std::string& text : planners::defaultPostProcessing(planner, params)) steps.push_back(optimise::parsePostStep(text));
  steps.insert(steps.end(), post.begin(), post.end());
  phase("planning");
  const auto t0 = std::chrono::steady_clock::now();
  r.plan = planners::runPlanner(planner, ctx, params, timeLimit);
  auto since = [](std::chrono::steady_clock::time_point t) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count(); };
  r.planSeconds = since(t0);
  r.totalSeconds = r.planSeconds + ctx.cellSeconds;
  if (succeeded(r.plan.status) && !steps.empty()) {
    phase("post-processing");
    const auto tp = std::chrono::steady_clock::now();
    r.plan = optimise::postProcess(ctx.problem, std::move(r.plan), steps);
    r.postSeconds = since(tp);
  }
  if (succeeded(r.plan.status)) {
    phase("validating");
    const auto t1 = std::chrono::steady_clock::now();
    ValidationOptions vo;
    vo.threads = metricOptions.threads;   // the same share of the cores as the metrics
    r.validation = validatePaths(ctx.problem, r.plan.paths, vo);
    r.validateSeconds = since(t1);
    phase("metrics");
    const auto t2 = std::chrono::steady_clock::now();
    MetricOptions mo = metricOptions;
    mo.pathsKnownClear = r.validation.valid;  // valid implies continuous and clear
    r.metrics = computeMetrics(ctx.problem, ctx.cells, r.plan.paths, mo);
    r.metricsSeconds = since(t2);
  } else {
    r.validation.valid = false;
    r.validation.violations.push_back({"status", 0, -1, std::string(toString(r.plan.status)) + ": " + r.plan.message});
  }
  return r;
}

datasets::PathDocument pathDocument(const planners::PlanningContext& ctx, const RunResult& r) {
  datasets::PathDocument d;
  d.planner = r.plan.planner;
  d.status = toString(r.plan.status);
  d.robotRadius = ctx.problem.robots.at(0).radius;
  d.cellSize = ctx.cells.subSize();
  d.paths = r.plan.paths;
  d.workspace = &ctx.problem.workspace;  // CSV/GeoJSON: arcs sampled on their exactly checked safe side
  if (succeeded(r.plan.status)) d.metrics = datasets::metricFields(r.metrics);
  for (auto& [k, v] : r.plan.statistics) d.statistics.emplace_back(k, v);
  return d;
}

datasets::CellsDocument cellsDocument(const std::string& map, const std::string& method, const std::map<std::string, std::string>& params,
                                      const Problem& problem, const planners::Decomposed& dec, bool sampled) {
  datasets::CellsDocument doc;
  doc.map = map;
  doc.method = method;
  doc.robotRadius = problem.robots.at(0).radius;
  doc.params = params;
  doc.directionDegrees = -dec.cells.rotation.degrees();
  doc.rotationCos = dec.cells.rotation.c.get_str();
  doc.rotationSin = dec.cells.rotation.s.get_str();
  doc.cfreeArea = dec.space->area();
  doc.unwalledVertices = dec.cells.unwalledVertices;
  for (const DecomposedCell& c : dec.cells.cells) {
    doc.cells.push_back({unrotate(c.region, dec.cells.rotation), c.neighbours});
    doc.cells.back().region.area = c.area;
  }
  for (const CellWall& w : dec.cells.walls) {
    const PointD a = w.vertical ? PointD{w.at, w.lo} : PointD{w.lo, w.at}, b = w.vertical ? PointD{w.at, w.hi} : PointD{w.hi, w.at};
    doc.walls.push_back({w.a, w.b, dec.cells.rotation.inverse(a), dec.cells.rotation.inverse(b)});
  }
  if (sampled) doc.sampled = sampledCells(dec.cells, datasets::kArcSampleTolerance, &doc.unplaced);
  return doc;
}

datasets::CSpaceDocument cspaceDocument(const std::string& map, const Problem& problem, const CSpace& cs) {
  datasets::CSpaceDocument doc;
  doc.map = map;
  doc.robotRadius = problem.robots.at(0).radius;
  doc.epsilon = cs.epsilon();
  doc.freeArea = freeArea(problem.workspace).get_d();
  doc.cfreeArea = cs.area();
  doc.components = cs.components();
  doc.obstacles = cs.obstacles();
  doc.cspace = &cs;  // GeoJSON: C-free polygons checked to lie in the exact C-free
  if (problem.robots[0].start) {
    doc.start = PointD{problem.robots[0].start->x.get_d(), problem.robots[0].start->y.get_d()};
    doc.startComponent = cs.componentOf(*problem.robots[0].start);
  }
  return doc;
}

namespace {
unsigned gThreads = 0;
double wallNow() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
double cpuNow() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}
}  // namespace

void setThreads(unsigned n) { gThreads = n; }
unsigned threads() { return gThreads; }

RunResult notStarted(const std::string& why) {
  RunResult r;
  r.plan.status = PlanStatus::kInvalidStart;
  r.plan.message = why;
  r.validation.valid = false;
  r.validation.violations.push_back({"start", 0, -1, why});
  return r;
}

MetricOptions defaultMetricOptions() {
  MetricOptions o;
  o.coverable = true;
  o.threads = gThreads;
  return o;
}

MetricOptions metricOptionsForLevel(const std::string& level) {
  MetricOptions o = defaultMetricOptions();
  if (level == "basic") o.area = o.coverable = false;
  else if (level == "area") o.coverable = false;
  else if (level != "full") throw std::invalid_argument("metric level " + level + " not in {basic,area,full}");
  return o;
}

void PhaseTimer::begin(const std::string& phase) {
  end();
  rows_.push_back({phase, 0, 0});
  wall0_ = wallNow();
  cpu0_ = cpuNow();
  running_ = true;
}

void PhaseTimer::end() {
  if (!running_) return;
  for (auto it = rows_.rbegin(); it != rows_.rend(); ++it)
    if (it->cpu >= 0) {
      it->wall = wallNow() - wall0_;
      it->cpu = cpuNow() - cpu0_;
      break;
    }
  running_ = false;
}

void PhaseTimer::part(const std::string& phase, const std::string& name, double wallSeconds) {
  auto at = std::find_if(rows_.begin(), rows_.end(), [&](const Row& r) { return r.cpu >= 0 && r.phase == phase; });
  if (at == rows_.end()) return;
  ++at;
  while (at != rows_.end() && at->cpu < 0) ++at;   // after the parts it has
  rows_.insert(at, {name, wallSeconds, -1});
}

std::string PhaseTimer::report() const {
  std::ostringstream os;
  os << std::fixed << std::setprecision(4);
  os << "coverkit: timings (s)        wall        cpu\n";
  double wall = 0, cpu = 0;
  for (const Row& r : rows_) {
    const std::string name = r.cpu >= 0 ? r.phase : "  " + r.phase;
    os << "  " << std::left << std::setw(26) << name.substr(0, 26) << std::right << std::setw(10) << r.wall;
    if (r.cpu >= 0) os << std::setw(11) << r.cpu;
    os << "\n";
    if (r.cpu >= 0) {
      wall += r.wall;
      cpu += r.cpu;
    }
  }
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  os << "  " << std::left << std::setw(26) << "total" << std::right << std::setw(10) << wall << std::setw(11) << cpu << "\n";
  os << "  peak memory " << std::setprecision(1) << static_cast<double>(u.ru_maxrss) / 1024.0 << " MiB\n";
  return os.str();
}

Point parsePoint(const std::string& text, const std::string& option) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) throw InputError(option, text, "expected X,Y");
  return {parseRational(text.substr(0, comma), option, text), parseRational(text.substr(comma + 1), option, text)};
}

}  // namespace coverkit::experiments
