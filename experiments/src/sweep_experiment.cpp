// The `sweep` kind of the engine (coverage-vs-size, -complexity, -shape and any sweep config):
// Smooth-STC paper, Fig 14-17. See paper_experiments.h.
#include "charts.h"
#include "experiment_config.h"
#include "paper_experiments.h"

#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/planners/registry.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <sstream>

namespace coverkit::experiments {

namespace fs = std::filesystem;

namespace {

/// The coverage sweeps (coverage-vs-size, -complexity, -shape, and any `sweep` config): every planner
/// of the config on seeded polygon worlds or on map files, one case per world (or map) and setting,
/// one row per planner (and repetition).
class SweepExperiment : public Experiment {
public:
  explicit SweepExperiment(const std::string& configFile) : file_(configFile) {
    ec_ = loadExperimentConfig(configFile, 10, {"title", "planners", "vary", "radii", "values", "radius", "worlds", "maps", "starts", "repetitions", "kind"});
    const YAML::Node& cfg = ec_.root;
    identity_ = "sweep\n" + datasets::readTextFile(configFile);
    title_ = configValue<std::string>(cfg, configFile, "title", "Coverage and overlap against robot size");
    vary_ = configValue<std::string>(cfg, configFile, "vary", "radius");
    if (vary_ != "radius" && vary_ != "obstacles" && vary_ != "shape") throw InputError(configFile, "vary", vary_ + ": must be radius, obstacles or shape");
    const std::string valuesKey = vary_ == "radius" ? "radii" : "values", otherKey = vary_ == "radius" ? "values" : "radii";
    if (cfg[otherKey].IsDefined())
      throw InputError(configFile, otherKey, lineOf(cfg[otherKey]) + "not used with vary: " + vary_ + " (the values varied are '" + valuesKey + "')");
    if (vary_ == "radius" && cfg["radius"].IsDefined())
      throw InputError(configFile, "radius", lineOf(cfg["radius"]) + "not used with vary: radius (the radii varied are 'radii')");
    const std::vector<std::string> defaults = vary_ == "radius" ? std::vector<std::string>{"0.15", "0.2", "0.25", "0.3", "0.4", "0.5"}
                                              : vary_ == "obstacles" ? std::vector<std::string>{"2", "5", "10", "15", "20", "25"}
                                                                     : std::vector<std::string>{"rectangles", "rotated", "convex", "nonconvex", "stars", "discs"};
    values_ = configValue<std::vector<std::string>>(cfg, configFile, valuesKey, defaults);
    if (values_.empty()) throw InputError(configFile, valuesKey, lineOf(cfg[valuesKey]) + "the list is empty: give at least one value");
    fixedRadius_ = configValue<std::string>(cfg, configFile, "radius", "0.25");
    repetitions_ = configInt(cfg, configFile, "repetitions", 1, 1, 1000);
    // the robot's starts: `default` (the planners' own choice) or X,Y in map coordinates, exact
    for (const std::string& text : configValue<std::vector<std::string>>(cfg, configFile, "starts", {"default"})) {
      if (std::find_if(starts_.begin(), starts_.end(), [&](const Start& s) { return s.text == text; }) != starts_.end())
        throw InputError(configFile, "starts", lineOf(cfg["starts"]) + "'" + text + "' is listed twice");
      Start st{text, std::nullopt};
      if (text != "default") {
        try {
          st.point = parsePoint(text, "starts");
        } catch (const InputError& e) {
          throw InputError(configFile, "starts", lineOf(cfg["starts"]) + "'" + text + "': expected default or X,Y (" + e.problem() + ")");
        }
      }
      starts_.push_back(st);
    }
    if (starts_.empty()) throw InputError(configFile, "starts", lineOf(cfg["starts"]) + "the list is empty: give default or X,Y points");
    if (cfg["maps"].IsDefined()) {
      if (cfg["worlds"].IsDefined()) throw InputError(configFile, "maps", lineOf(cfg["maps"]) + "give maps or worlds, not both");
      if (vary_ != "radius") throw InputError(configFile, "vary", vary_ + ": with maps only the radius can vary");
      for (const std::string& entry : configValue<std::vector<std::string>>(cfg, configFile, "maps", {}))
        for (const std::string& f : mapFilesOf(entry, configFile)) {
          try {
            maps_.push_back({f, datasets::loadMap(f)});
          } catch (const InputError& e) {
            throw InputError(configFile, "maps", "'" + entry + "': " + e.what());
          }
        }
      if (maps_.empty()) throw InputError(configFile, "maps", lineOf(cfg["maps"]) + "the list is empty: name at least one map file or folder");
    }
    for (const std::string& v : values_) {
      const std::string rKey = vary_ == "radius" ? "radii" : "radius", rText = vary_ == "radius" ? v : fixedRadius_;
      Setting st{parseRational(rText, configFile + ": " + rKey, rText), ec_.worlds};
      if (st.radius <= 0) throw InputError(configFile, rKey, rText + ": must be > 0");
      if (maps_.empty()) checkRadiusOnWorlds(st.radius, ec_, configFile, rKey, rText);
      if (vary_ == "obstacles") {
        char* end = nullptr;
        const long c = std::strtol(v.c_str(), &end, 10);
        if (*end != '\0' || c < 0 || c > 10000) throw InputError(configFile, "values", v + ": not an obstacle count");
        st.spec.count = static_cast<int>(c);
      }
      if (vary_ == "shape" && !datasets::parseObstacleShape(v, st.spec.shape)) throw InputError(configFile, "values", "unknown shape '" + v + "'");
      settings_.push_back(st);
    }
  }

  std::string kind() const override { return "sweep"; }
  std::string identity() const override { return identity_; }
  std::vector<Column> columns() const override {
    using T = ColumnType;
    std::vector<Column> c{{"map", T::kText},     {"world", T::kInteger},      {"vary", T::kText}, {"value", T::kText},
                          {"planner", T::kText}, {"repetition", T::kInteger}, {"radius", T::kReal}, {"start", T::kText}};
    for (const Column& k : runColumns()) c.push_back(k);
    return c;
  }
  /// Cases: world (or map), then setting, then start, in that order (with one start, the case
  /// numbers of a config without `starts`).
  std::size_t cases() const override { return places() * settings_.size() * starts_.size(); }
  std::string caseKey(std::size_t i) const override {
    const Index x = index(i);
    return (maps_.empty() ? "world=" + std::to_string(ec_.seeds[x.place]) : "map=" + fs::path(maps_[x.place].file).filename().string()) + " " + vary_ + "=" +
           values_[x.setting] + (starts_.size() > 1 ? " start=" + starts_[x.start].text : "");
  }
  Output run(std::size_t i) const override {
    const Index x = index(i);
    const std::size_t place = x.place, si = x.setting;
    const Start& start = starts_[x.start];
    Problem problem;
    std::string mapName = "worlds";
    std::int64_t world = 0;
    if (maps_.empty()) {
      datasets::PolygonWorldSpec spec = settings_[si].spec;
      spec.seed = ec_.seeds[place];
      world = static_cast<std::int64_t>(ec_.seeds[place]);
      problem.workspace = datasets::generatePolygonWorld(spec);
    } else {
      problem.workspace = maps_[place].workspace;
      mapName = maps_[place].file;
    }
    const Rational& r = settings_[si].radius;
    problem.robots.push_back({r, start.point});
    planners::PlanningContext ctx;
    std::vector<Row> rows;
    try {
      ctx = planners::makeContext(problem);
    } catch (const InputError& e) {
      if (!start.point) return {};   // the robot does not fit this world: no run
      // a start given in the config that lies outside this world or in an obstacle: every planner's
      // row says so (status invalid_start, not valid), counted as not planned
      const RunResult none = notStarted(e.what());
      for (const std::string& p : ec_.planners)
        for (int rep = 0; rep < repetitions_; ++rep) {
          Row row{mapName, world, vary_, values_[si], p, static_cast<std::int64_t>(rep), r.get_d(), start.text};
          appendRun(row, none);
          rows.push_back(std::move(row));
        }
      return {rows, {}};
    }
    const CSpace cspace(problem.workspace, r);
    MetricOptions mo = defaultMetricOptions();
    mo.cspace = &cspace;
    for (const std::string& p : ec_.planners)
      for (int rep = 0; rep < repetitions_; ++rep) {
        const RunResult res = runSpec(ctx, p, file_, mo);
        Row row{mapName, world, vary_, values_[si], p, static_cast<std::int64_t>(rep), r.get_d(), start.text};
        appendRun(row, res);
        rows.push_back(std::move(row));
      }
    return {rows, {}};
  }
  std::vector<std::pair<std::string, std::string>> inputs() const override {
    return {{"config.yaml", datasets::readTextFile(file_)}};
  }

  std::vector<std::pair<std::string, std::string>> summarise(const Table& t) const override {
    struct Acc {
      double coverage = 0, overlap = 0, turns = 0, angle = 0, reversals = 0, robotTime = 0, minCoverage = 1;
      std::size_t n = 0, invalid = 0, failed = 0;
    };
    std::map<std::string, std::vector<Acc>> acc;   // planner → setting
    for (const std::string& p : ec_.planners) acc[p].resize(settings_.size());
    for (const Row& row : t.rows) {
      const std::size_t si = index(static_cast<std::size_t>(t.real(row, "case"))).setting;
      Acc& a = acc[t.text(row, "planner")][si];
      const std::string status = t.text(row, "status");
      if (status != toString(PlanStatus::kExactSolution) && status != toString(PlanStatus::kPartialCoverage)) {   // e.g. STC when the start has no free mega-cell: coverage 0
        ++a.failed;
        ++a.n;
        a.minCoverage = 0;
        continue;
      }
      if (t.real(row, "valid") == 0) {
        ++a.invalid;
        continue;
      }
      ++a.n;
      const double c = t.real(row, "coverable_coverage");
      a.coverage += c;
      a.overlap += t.real(row, "swept_area_overlap");
      a.turns += t.real(row, "turns");
      a.angle += t.real(row, "turning_angle_deg");
      a.reversals += t.real(row, "reversals");
      a.robotTime += t.real(row, "robot_time_s");
      a.minCoverage = std::min(a.minCoverage, c);
    }
    const datasets::PolygonWorldSpec& base = ec_.worlds;
    std::ostringstream md;
    md << "# " << title_ << "\n\n";
    if (maps_.empty())
      md << places() << " seeded " << base.width << "×" << base.height << " polygon worlds per setting ("
         << (vary_ == "obstacles" ? std::string("obstacle count varied") : std::to_string(base.count) + " obstacles") << ", "
         << (vary_ == "shape" ? std::string("shape varied") : ec_.shape) << ", " << base.minSize << "-" << base.maxSize << " m), ";
    else
      md << maps_.size() << " map files per setting, ";
    md << (vary_ == "radius" ? std::string("robot radius varied") : "r = " + fixedRadius_) << "; sub-cells 2r; " << startsText() << ". Coverage: covered area / "
       << "coverable area (the start's C-free component ⊕ disc). Overlap: swept area counted with multiplicity / covered area − 1. "
       << "Plans that did not succeed count as coverage 0; invalid plans are counted and left out. Robot time: a differential-drive "
       << "robot's (docs/metrics.md; a corner costs a stop and a turn on the spot).\n\n"
       << "| planner | " << vary_ << " | plans | mean coverage | min coverage | mean overlap | mean turns | mean turning angle (°) | mean reversals | mean robot time (s) | not planned | invalid |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    std::map<std::string, std::vector<std::pair<double, double>>> coverageSeries, overlapSeries, turnSeries, angleSeries, timeSeries;
    for (const std::string& p : ec_.planners)
      for (std::size_t si = 0; si < settings_.size(); ++si) {
        const Acc& a = acc[p][si];
        const std::size_t valid = a.n - a.failed;
        const double mean = a.n ? a.coverage / static_cast<double>(a.n) : 0, overlap = valid ? a.overlap / static_cast<double>(valid) : 0;
        const double turns = valid ? a.turns / static_cast<double>(valid) : 0, angle = valid ? a.angle / static_cast<double>(valid) : 0;
        const double reversals = valid ? a.reversals / static_cast<double>(valid) : 0, robotTime = valid ? a.robotTime / static_cast<double>(valid) : 0;
        md << "| " << p << " | " << values_[si] << " | " << a.n << " | " << fmt(mean, 4) << " | " << fmt(a.n ? a.minCoverage : 0, 4) << " | "
           << fmt(overlap, 3) << " | " << fmt(turns, 1) << " | " << fmt(angle, 0) << " | " << fmt(reversals, 1) << " | " << fmt(robotTime, 0) << " | "
           << a.failed << " | " << a.invalid << " |\n";
        const double x = vary_ == "radius" ? settings_[si].radius.get_d() : vary_ == "obstacles" ? static_cast<double>(settings_[si].spec.count)
                                                                                                   : static_cast<double>(si);
        coverageSeries[p].emplace_back(x, mean);
        overlapSeries[p].emplace_back(x, overlap);
        turnSeries[p].emplace_back(x, turns);
        angleSeries[p].emplace_back(x, angle);
        timeSeries[p].emplace_back(x, robotTime);
      }
    if (vary_ == "shape") {
      md << "\nx positions in the chart: ";
      for (std::size_t si = 0; si < values_.size(); ++si) md << (si ? ", " : "") << si << " = " << values_[si];
      md << ".\n";
    }
    const std::string xLabel = vary_ == "radius" ? "robot radius r" : vary_ == "obstacles" ? "obstacles per world" : "obstacle shape (see summary)";
    const std::string svg = lineChartSvg({"mean coverage of the coverable region", "mean overlap", "mean turns", "mean total turning angle (°)",
                                          "mean robot time (s)"},
                                         xLabel, {coverageSeries, overlapSeries, turnSeries, angleSeries, timeSeries});
    return {{"summary.md", md.str()}, {"chart.svg", svg}};
  }

private:
  std::size_t places() const { return maps_.empty() ? static_cast<std::size_t>(ec_.count) : maps_.size(); }
  struct Index {
    std::size_t place, setting, start;
  };
  Index index(std::size_t i) const {
    return {i / (settings_.size() * starts_.size()), (i / starts_.size()) % settings_.size(), i % starts_.size()};
  }
  struct Start {
    std::string text;
    std::optional<Point> point;   ///< none: the planners' default start
  };
  std::vector<Start> starts_;
  std::string startsText() const {
    if (starts_.size() == 1 && !starts_[0].point) return "default start";
    std::string t = "starts";
    for (std::size_t k = 0; k < starts_.size(); ++k) t += (k ? ", " : " ") + starts_[k].text;
    return t + " (a start outside a world or in an obstacle: not planned)";
  }
  struct Setting {
    Rational radius;
    datasets::PolygonWorldSpec spec;
  };
  struct MapFile {
    std::string file;
    Workspace workspace;
  };
  std::string file_, identity_, title_, vary_, fixedRadius_;
  ExperimentConfig ec_;
  std::vector<std::string> values_;
  std::vector<Setting> settings_;
  std::vector<MapFile> maps_;
  int repetitions_ = 1;
};

}  // namespace

std::unique_ptr<Experiment> sweepExperiment(const std::string& configFile) {
  return withConfigErrors(configFile, [&]() -> std::unique_ptr<Experiment> { return std::make_unique<SweepExperiment>(configFile); });
}
void checkSweepConfig(const std::string& configFile) { sweepExperiment(configFile); }

std::string defaultConfig(const std::string& name) { return (std::filesystem::path(COVERKIT_CONFIG_DIR) / name).string(); }

}  // namespace coverkit::experiments
