// The `coverage-vs-time` kind of the engine: Smooth-STC paper, Fig 13, coverage of the coverable
// region against time: the differential-drive robot's time (robot_time_s, docs/metrics.md: a corner
// costs a stop and a turn on the spot) by default, or constant speed as the paper's figure (`time:
// constant`). A case is one seeded world, a row one planner on it with
// its coverage at each step of the world's time axis (columns coverage_step_K and
// coverage_error_step_K). See paper_experiments.h.
#include "charts.h"
#include "experiment_config.h"
#include "paper_experiments.h"

#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/planners/registry.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace coverkit::experiments {

namespace {

/// The first `length` of a path made of lines (arcs through their polyline), as a path.
Path prefix(const Path& path, double length) {
  Path out;
  out.start = path.start;
  const std::vector<PointD> pts = path.polyline(1e-3);
  double done = 0;
  for (std::size_t i = 0; i + 1 < pts.size() && done < length; ++i) {
    const double d = std::hypot(pts[i + 1].x - pts[i].x, pts[i + 1].y - pts[i].y);
    if (d == 0) continue;
    const double t = std::min(1.0, (length - done) / d);
    out.segments.push_back(PathSegment::line(pts[i], {pts[i].x + t * (pts[i + 1].x - pts[i].x), pts[i].y + t * (pts[i + 1].y - pts[i].y)}));
    done += d;
  }
  return out;
}

class TimeExperiment : public Experiment {
public:
  explicit TimeExperiment(const std::string& configFile) : file_(configFile) {
    ec_ = loadExperimentConfig(configFile, 5, {"kind", "planners", "radius", "time", "speed", "v_max", "a_max", "omega_max", "steps", "worlds"});
    const YAML::Node& cfg = ec_.root;
    rText_ = configValue<std::string>(cfg, configFile, "radius", "0.25");
    r_ = parseRational(rText_, configFile + ": radius", rText_);
    if (r_ <= 0) throw InputError(configFile, "radius", rText_ + ": must be > 0");
    checkRadiusOnWorlds(r_, ec_, configFile, "radius", rText_);
    time_ = configValue<std::string>(cfg, configFile, "time", "robot");
    if (time_ != "robot" && time_ != "constant") throw InputError(configFile, "time", time_ + ": must be robot or constant");
    speed_ = configValue<double>(cfg, configFile, "speed", 0.2);
    if (!(speed_ > 0)) throw InputError(configFile, "speed", "must be > 0");
    for (auto [key, value] : {std::pair<const char*, double*>{"v_max", &drive_.vMax}, {"a_max", &drive_.aMax}, {"omega_max", &drive_.omegaMax}}) {
      *value = configValue<double>(cfg, configFile, key, *value);
      if (!(*value > 0) || !std::isfinite(*value)) throw InputError(configFile, key, "must be a finite number > 0");
    }
    steps_ = configValue<int>(cfg, configFile, "steps", 12);
    if (steps_ < 1 || steps_ > 1000) throw InputError(configFile, "steps", std::to_string(steps_) + ": must be in 1..1000");
    identity_ = "coverage-vs-time\n" + datasets::readTextFile(configFile);
  }

  std::string kind() const override { return "coverage-vs-time"; }
  std::string identity() const override { return identity_; }
  std::vector<Column> columns() const override {
    std::vector<Column> c{{"world", ColumnType::kInteger}, {"planner", ColumnType::kText}, {"finish_time_s", ColumnType::kReal},
                          {"horizon_time_s", ColumnType::kReal}};
    for (int k = 0; k <= steps_; ++k) c.push_back({"coverage_step_" + std::to_string(k), ColumnType::kReal});
    for (int k = 0; k <= steps_; ++k) c.push_back({"coverage_error_step_" + std::to_string(k), ColumnType::kReal});
    for (const Column& k : runColumns()) c.push_back(k);
    return c;
  }
  std::size_t cases() const override { return static_cast<std::size_t>(ec_.count); }
  std::string caseKey(std::size_t i) const override { return "world=" + std::to_string(ec_.seeds[i]); }
  /// The world's planners, then each one's covered area at the common times: the time axis is the
  /// slowest planner's finish split in `steps` (a planner that has finished keeps its final
  /// coverage; prefixes are rasterised with their bound, the full path exact).
  Output run(std::size_t i) const override {
    datasets::PolygonWorldSpec spec = ec_.worlds;
    spec.seed = ec_.seeds[i];
    Problem problem;
    problem.workspace = datasets::generatePolygonWorld(spec);
    problem.robots.push_back({r_, std::nullopt});
    const planners::PlanningContext ctx = planners::makeContext(problem);
    const CSpace cspace(problem.workspace, r_);
    MetricOptions mo = defaultMetricOptions();
    mo.cspace = &cspace;
    mo.speed = speed_;
    mo.vMax = drive_.vMax;
    mo.aMax = drive_.aMax;
    mo.omegaMax = drive_.omegaMax;
    std::vector<RunResult> runs;
    double horizon = 0;
    auto finish = [&](const RunResult& r) { return time_ == "robot" ? r.metrics.robotTime : r.metrics.length / speed_; };
    for (const std::string& p : ec_.planners) {
      runs.push_back(runSpec(ctx, p, file_, mo));
      horizon = std::max(horizon, finish(runs.back()));
    }
    MetricOptions raster = mo;   // prefixes: covered area only, rasterised with its bound
    raster.coverable = false;
    raster.exactAreaMaxSegments = raster.exactAreaMaxSegmentsClear = 0;
    raster.rasterMaxPixels = 250'000;
    Output out;
    for (std::size_t p = 0; p < runs.size(); ++p) {
      const RunResult& res = runs[p];
      std::vector<double> coverage(static_cast<std::size_t>(steps_) + 1, 0.0), error(coverage.size(), 0.0);
      for (int k = 0; k <= steps_; ++k) {
        const double t = horizon * k / steps_;
        if (!res.validation.valid || res.metrics.coverableArea <= 0) continue;
        if (t >= finish(res)) {
          coverage[static_cast<std::size_t>(k)] = res.metrics.coverableCoverage;
        } else if (k > 0) {
          const double along = time_ == "robot" ? robotDistanceAt(res.plan.paths[0], t, mo) : t * speed_;
          const Metrics m = computeMetrics(ctx.problem, ctx.cells, {prefix(res.plan.paths[0], along)}, raster);
          coverage[static_cast<std::size_t>(k)] = m.coveredArea / res.metrics.coverableArea;
          error[static_cast<std::size_t>(k)] = m.areaCoverageError * m.freeArea / res.metrics.coverableArea;
        }
      }
      Row row{static_cast<std::int64_t>(ec_.seeds[i]), ec_.planners[p], finish(res), horizon};
      for (double c : coverage) row.emplace_back(c);
      for (double e : error) row.emplace_back(e);
      appendRun(row, res);
      out.rows.push_back(std::move(row));
    }
    return out;
  }
  std::vector<std::pair<std::string, std::string>> inputs() const override { return {{"config.yaml", datasets::readTextFile(file_)}}; }

  std::vector<std::pair<std::string, std::string>> summarise(const Table& t) const override {
    const double count = ec_.count;
    std::map<std::string, std::vector<double>> meanByStep;
    std::map<std::string, double> meanTotalTime;
    std::size_t invalid = 0;
    for (const Row& row : t.rows) {
      const std::string p = t.text(row, "planner");
      invalid += t.real(row, "valid") == 0;
      meanTotalTime[p] += t.real(row, "finish_time_s") / count;
      auto& series = meanByStep[p];
      series.resize(static_cast<std::size_t>(steps_) + 1, 0.0);
      for (int k = 0; k <= steps_; ++k) series[static_cast<std::size_t>(k)] += t.real(row, "coverage_step_" + std::to_string(k)) / count;
    }
    const datasets::PolygonWorldSpec& spec = ec_.worlds;
    std::ostringstream md;
    md << "# Coverage against time\n\n" << ec_.count << " seeded " << spec.width << "×" << spec.height << " polygon worlds, " << spec.count << " " << ec_.shape
       << " obstacles, r = " << rText_ << ", "
       << (time_ == "robot" ? "a differential-drive robot (v_max " + fmt(drive_.vMax, 2) + " m/s, a_max " + fmt(drive_.aMax, 2) + " m/s², ω_max " +
                                  fmt(drive_.omegaMax, 2) + " rad/s; a corner costs a stop and a turn on the spot)"
                            : "constant speed " + fmt(speed_, 2) + " m/s")
       << ", default start. Each world's time axis is split in " << steps_
       << " steps up to the slowest planner's finish; coverage of the coverable region, averaged over the worlds (a planner that has "
       << "finished keeps its final coverage). Invalid plans: " << invalid << ".\n\n| planner | mean time to finish (s) |";
    for (int k = 1; k <= steps_; ++k) md << " " << fmt(100.0 * k / steps_, 0) << " % |";
    md << "\n|---|---|";
    for (int k = 1; k <= steps_; ++k) md << "---|";
    md << "\n";
    std::map<std::string, std::vector<std::pair<double, double>>> chart;
    for (const std::string& p : ec_.planners) {
      std::vector<double>& series = meanByStep[p];
      series.resize(static_cast<std::size_t>(steps_) + 1, 0.0);
      md << "| " << p << " | " << fmt(meanTotalTime[p], 0) << " |";
      for (int k = 1; k <= steps_; ++k) md << " " << fmt(series[static_cast<std::size_t>(k)], 3) << " |";
      md << "\n";
      for (int k = 0; k <= steps_; ++k) chart[p].emplace_back(100.0 * k / steps_, series[static_cast<std::size_t>(k)]);
    }
    return {{"summary.md", md.str()},
            {"chart.svg", lineChartSvg({"mean coverage of the coverable region"}, "time, % of the slowest planner's", {chart})}};
  }

private:
  std::string file_, identity_, rText_;
  ExperimentConfig ec_;
  Rational r_;
  double speed_ = 0.2;
  std::string time_ = "robot";
  MetricOptions drive_;   ///< v_max, a_max, omega_max
  int steps_ = 12;
};

}  // namespace

std::unique_ptr<Experiment> timeExperiment(const std::string& configFile, const ConfigOverrides&) {
  return withConfigErrors(configFile, [&]() -> std::unique_ptr<Experiment> { return std::make_unique<TimeExperiment>(configFile); });
}
void checkCoverageVsTimeConfig(const std::string& configFile) { timeExperiment(configFile, {}); }

}  // namespace coverkit::experiments
