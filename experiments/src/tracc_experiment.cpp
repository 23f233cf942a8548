// The `tracc-scenarios` kind of the engine: TRACC paper, section 3, its 11×11 grid (C1 … C121 row by
// row from S = C1) without obstacles and in the two scenarios the text describes. A case is one
// scenario (one row); its grid, path and picture are the case's files. See paper_experiments.h.
#include "charts.h"
#include "experiment_config.h"
#include "paper_experiments.h"
#include "render.h"

#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/planners/registry.h>

#include <algorithm>
#include <sstream>

namespace coverkit::experiments {

namespace {

struct TraccScenario {
  std::string name, blocked, paper;
  std::vector<int> cells;
};

// scenario 2's obstacles are our assumption: the text names only C60, C62 and C121
const std::vector<TraccScenario>& traccScenarios() {
  static const std::vector<TraccScenario> s{
      {"0", "none", "71 cells visited (six rows), redundancy 45.45 % (cells sensed twice)", {}},
      {"1", "C5; C30, C40, C42, C52 around C41", "detour C4-C15-C16-C17-C6; C41 blocked in", {5, 30, 40, 42, 52}},
      {"2", "ring C49-C51, C59, C61, C71-C73 around C60; C110, C120 beside C121 (assumed)",
       "C60, C62, C121 unchecked after the flow; C121 discarded", {49, 50, 51, 59, 61, 71, 72, 73, 110, 120}}};
  return s;
}

class TraccExperiment : public Experiment {
public:
  explicit TraccExperiment(const std::string& configFile) {
    loadConfigRoot(configFile, {"kind"});   // the scenarios are the paper's: nothing to set
  }
  std::string kind() const override { return "tracc-scenarios"; }
  std::string identity() const override { return "kind: tracc-scenarios\n"; }
  std::vector<Column> columns() const override {
    using T = ColumnType;
    std::vector<Column> c{{"scenario", T::kText},       {"blocked", T::kText},           {"cells_entered", T::kInteger},
                          {"detours", T::kInteger},     {"redundancy_rate", T::kReal},   {"unsafe_cells", T::kInteger},
                          {"unchecked_cells", T::kInteger}, {"unreached_free_cells", T::kInteger}, {"end_cell", T::kText}};
    for (const Column& k : runColumns()) c.push_back(k);
    return c;
  }
  std::size_t cases() const override { return traccScenarios().size(); }
  std::string caseKey(std::size_t i) const override { return "scenario=" + traccScenarios()[i].name; }
  Output run(std::size_t i) const override {
    const TraccScenario& sc = traccScenarios()[i];
    std::string text;
    for (int row = 10; row >= 0; --row) {
      for (int col = 0; col < 11; ++col) text += std::find(sc.cells.begin(), sc.cells.end(), row * 11 + col + 1) != sc.cells.end() ? '#' : '.';
      text += '\n';
    }
    const std::string base = "scenario-" + sc.name;
    Problem problem;
    problem.workspace = datasets::parseTextGrid(text, base + ".grid");
    problem.robots.push_back({Rational(1, 2), Point{Rational(1, 2), Rational(1, 2)}});
    const planners::PlanningContext ctx = planners::makeContext(problem);
    MetricOptions mo = defaultMetricOptions();
    mo.coverable = false;
    const RunResult r = runOnce(ctx, "tracc", {}, 0, {}, mo);
    const auto& st = r.plan.statistics;
    auto count = [&](const char* k) { return static_cast<std::int64_t>(st.at(k)); };
    const int endCell = static_cast<int>(st.at("end_row")) * 11 + static_cast<int>(st.at("end_col")) + 1;
    Row row{sc.name,          sc.blocked,           count("covered_cells"),        count("detours"), st.at("redundancy_rate"), count("unsafe_cells"),
            count("unchecked_cells"), count("unreached_free_cells"), "C" + std::to_string(endCell)};
    appendRun(row, r);
    datasets::PathDocument doc;
    doc.paths = r.plan.paths;
    doc.planner = "tracc";
    PictureContent pc{&ctx.problem.workspace, &ctx.cells, nullptr, &r.plan.paths, 0.5, "TRACC scenario " + sc.name};
    return {{std::move(row)}, {{base + ".grid", text}, {base + ".json", datasets::pathJson(doc)}, {base + ".svg", pictureBytes(base + ".svg", pc)}}};
  }
  std::vector<std::pair<std::string, std::string>> summarise(const Table& t) const override {
    std::ostringstream md;
    md << "# TRACC: the paper's 11×11 scenarios\n\nStart S = C1 (bottom-left), one cell per robot, flow along rows.\n\n"
       << "| scenario | blocked cells | valid | cells entered | length | turns | detours | redundancy | unsafe | never sensed | end | paper |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& row : t.rows) {
      const TraccScenario& sc = traccScenarios()[static_cast<std::size_t>(t.real(row, "case"))];
      md << "| " << sc.name << " | " << sc.blocked << " | " << (t.real(row, "valid") != 0 ? "yes" : "no") << " | " << t.text(row, "cells_entered")
         << " | " << fmt(t.real(row, "length"), 0) << " | " << t.text(row, "turns") << " | " << t.text(row, "detours") << " | "
         << fmt(t.real(row, "redundancy_rate"), 1) << " % | " << t.text(row, "unsafe_cells") << " | " << t.text(row, "unchecked_cells") << " | "
         << t.text(row, "end_cell") << " | " << sc.paper << " |\n";
    }
    md << "\nOur agent sweeps every free cell (a disc robot must), where the paper's flow visits every other row and senses the rows "
          "between; its redundancy counts cells sensed twice, ours cells entered twice (docs/grid-rails.md).\n";
    return {{"summary.md", md.str()}};
  }
};

}  // namespace

std::unique_ptr<Experiment> traccExperiment(const std::string& configFile, const ConfigOverrides&) {
  return withConfigErrors(configFile, [&]() -> std::unique_ptr<Experiment> { return std::make_unique<TraccExperiment>(configFile); });
}

}  // namespace coverkit::experiments
