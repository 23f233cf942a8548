// The `scenarios` kind of the engine: named maps, each with its own robot radius, planned with
// every planner of the config (default: every registered one), one picture per run; a case is one
// scenario (its C-space shared by its planners), a row one planner. The demo
// (`coverkit demo`, the README's first command) is this kind on datasets/data/scenarios.txt.
#include "engine.h"
#include "experiment_config.h"
#include "paper_experiments.h"
#include "render.h"
#include "runner.h"

#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/registry.h>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <optional>
#include <sstream>

namespace coverkit::experiments {

namespace fs = std::filesystem;

namespace {

class ScenarioExperiment : public Experiment {
public:
  explicit ScenarioExperiment(const std::string& configFile) : file_(configFile) {
    const YAML::Node root = loadConfigRoot(configFile, {"kind", "title", "scenarios", "planners"});
    title_ = configValue<std::string>(root, configFile, "title", "Scenarios");
    const std::string list = configValue<std::string>(root, configFile, "scenarios", "");
    if (list.empty()) throw InputError(configFile, "scenarios", "expected the path of a scenario list (NAME FILE RADIUS [START] per line)");
    readList((fs::path(configFile).parent_path() / list).string());
    const YAML::Node p = root["planners"];
    if (p.IsDefined() && !(p.IsScalar() && p.Scalar() == "all")) {
      planners_ = configValue<std::vector<std::string>>(root, configFile, "planners", {});
      if (planners_.empty()) throw InputError(configFile, "planners", lineOf(p) + "the list is empty: name planners, or all");
      for (const std::string& name : planners_)
        if (!planners::Registry::instance().contains(name)) throw InputError(configFile, "planners", "unknown planner '" + name + "'");
    } else {
      planners_ = planners::Registry::instance().names();
    }
    identity_ = "scenarios\n" + datasets::readTextFile(configFile) + "\n" + listText_;
  }

  std::string kind() const override { return "scenarios"; }
  std::string identity() const override { return identity_; }
  std::vector<Column> columns() const override {
    std::vector<Column> c{{"map", ColumnType::kText}, {"file", ColumnType::kText}, {"planner", ColumnType::kText}, {"radius", ColumnType::kReal}};
    for (const Column& k : runColumns()) c.push_back(k);
    return c;
  }
  std::size_t cases() const override { return scenarios_.size(); }
  std::string caseKey(std::size_t i) const override { return "scenario=" + scenarios_[i].name; }
  /// One scenario: its C-space built once (the coverable region of every plan, and its picture),
  /// then one row and one picture per planner.
  Output run(std::size_t i) const override {
    const Scenario& s = scenarios_[i];
    Problem problem;
    problem.workspace = s.workspace;
    problem.robots.push_back({s.radius, s.start});
    const planners::PlanningContext ctx = planners::makeContext(problem);
    const CSpace cs(ctx.problem.workspace, s.radius);
    MetricOptions mo = defaultMetricOptions();
    mo.cspace = &cs;
    Output out;
    for (const std::string& planner : planners_) {
      const RunResult r = runOnce(ctx, planner, {}, 0, {}, mo);
      Row row{s.name, fs::path(s.file).filename().string(), planner, s.radius.get_d()};
      appendRun(row, r);
      out.rows.push_back(std::move(row));
      const std::string pic = "pictures/" + s.name + "_" + planner + ".svg";
      PictureContent pc;
      pc.workspace = &ctx.problem.workspace;
      pc.cells = &ctx.cells;
      pc.tree = &r.plan.treeEdges;
      pc.paths = &r.plan.paths;
      pc.radius = s.radius.get_d();
      pc.title = s.name + " / " + planner + " / r=" + s.radiusText + " / " + toString(r.plan.status);
      out.files.emplace_back(pic, pictureBytes(pic, pc));
    }
    const std::vector<CurveRegion> cfree = cs.components(), cobs = cs.obstacles();
    PictureContent cp;
    cp.workspace = &ctx.problem.workspace;
    cp.cfree = &cfree;
    cp.cobstacles = &cobs;
    cp.title = s.name + " / C-space, r=" + s.radiusText + " / " + std::to_string(cfree.size()) + " component(s)";
    const std::string name = "pictures/" + s.name + "_cspace.svg";
    out.files.emplace_back(name, pictureBytes(name, cp));
    return out;
  }
  std::vector<std::pair<std::string, std::string>> inputs() const override {
    return {{"config.yaml", datasets::readTextFile(file_)}, {"scenarios.txt", listText_}};
  }
  std::vector<std::pair<std::string, std::string>> summarise(const Table& t) const override {
    std::ostringstream md;
    std::size_t invalid = 0;
    md << "# " << title_ << "\n\n" << scenarios_.size() << " scenarios × " << planners_.size()
       << " planners; every plan checked by the independent validator (continuity, exact clearance, start). Columns: docs/metrics.md.\n\n"
       << "| map | planner | status | valid | sub-cell coverage | area coverage | coverable coverage | length | turns |\n"
       << "|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& row : t.rows) {
      const bool valid = t.real(row, "valid") != 0;
      if (!valid) ++invalid;
      std::ostringstream cov;
      cov << std::fixed << std::setprecision(4) << t.real(row, "subcell_coverage") << " | " << t.real(row, "area_coverage") << " | "
          << t.real(row, "coverable_coverage");
      md << "| " << t.text(row, "map") << " | " << t.text(row, "planner") << " | " << t.text(row, "status") << " | " << (valid ? "yes" : "**no**")
         << " | " << cov.str() << " | " << formatDouble(std::round(t.real(row, "length") * 1000) / 1000) << " | " << t.text(row, "turns") << " |\n";
    }
    md << "\n" << t.rows.size() << " plans, " << invalid << " invalid.\n";
    return {{"summary.md", md.str()}};
  }

private:
  struct Scenario {
    std::string name, file, radiusText;
    Rational radius;
    std::optional<Point> start;   ///< the list's START, or the planners' default
    Workspace workspace;   ///< read once, when the config is checked
  };
  void readList(const std::string& list) {
    listText_ = datasets::readTextFile(list);
    std::istringstream in(listText_);
    std::string line;
    for (int lineNo = 1; std::getline(in, line); ++lineNo) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream ls(line);
      Scenario s;
      const std::string where = "line " + std::to_string(lineNo);
      if (!(ls >> s.name >> s.file >> s.radiusText)) throw InputError(list, where, "expected NAME FILE RADIUS [START]");
      s.radius = parseRational(s.radiusText, list, where);
      if (s.radius <= 0) throw InputError(list, where, s.radiusText + ": the radius must be > 0");
      std::string startText, extra;
      if (ls >> startText) {
        try {
          s.start = parsePoint(startText, "START");
        } catch (const InputError& e) {
          throw InputError(list, where, "'" + startText + "': the start must be X,Y (" + e.problem() + ")");
        }
      }
      if (ls >> extra) throw InputError(list, where, "'" + extra + "': expected NAME FILE RADIUS [START], and nothing after");
      for (const Scenario& other : scenarios_)
        if (other.name == s.name) throw InputError(list, where, "'" + s.name + "': a scenario of this name is listed before (names name the pictures)");
      s.file = (fs::path(list).parent_path() / s.file).string();
      s.workspace = datasets::loadMap(s.file);   // a bad map stops the run before it starts
      Problem probe;
      probe.workspace = s.workspace;
      probe.robots.push_back({s.radius, s.start});
      try {   // the robot must fit the map and the start lie in it: checked before anything runs
        planners::checkProblem(probe);
      } catch (const InputError& e) {
        throw InputError(list, where, e.what());
      }
      scenarios_.push_back(s);
    }
    if (scenarios_.empty()) throw InputError(list, "", "no scenario (NAME FILE RADIUS per line)");
  }

  std::string file_, identity_, title_, listText_;
  std::vector<Scenario> scenarios_;
  std::vector<std::string> planners_;
};

}  // namespace

std::unique_ptr<Experiment> scenarioExperiment(const std::string& configFile) {
  return withConfigErrors(configFile, [&]() -> std::unique_ptr<Experiment> { return std::make_unique<ScenarioExperiment>(configFile); });
}

}  // namespace coverkit::experiments
