// The `decompositions` kind of the engine (docs/decompositions.md): boustrophedon (BCD) against
// trapezoidal (TCD) cells of the exact C-free on seeded 20×20 polygon worlds, and boustrophedon
// coverage (on either decomposition) against Full-STC and Smooth-STC on the same worlds. A case is
// one world (hole count, seed); its rows are the four planner runs, each carrying the world's
// decomposition figures. See paper_experiments.h.
#include "charts.h"
#include "experiment_config.h"
#include "paper_experiments.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/planners/registry.h>

#include <sstream>

namespace coverkit::experiments {

namespace {

const std::vector<datasets::ObstacleShape> kShapes{datasets::ObstacleShape::kRotatedRectangle, datasets::ObstacleShape::kConvex,
                                                   datasets::ObstacleShape::kStar, datasets::ObstacleShape::kDisc};
const std::vector<std::string> kShapeNames{"rotated", "convex", "stars", "discs"};
const std::vector<std::pair<std::string, std::map<std::string, std::string>>> kPlannerRuns{
    {"boustrophedon", {{"decomposition", "boustrophedon"}}},
    {"boustrophedon(trapezoidal)", {{"decomposition", "trapezoidal"}}},
    {"full_stc", {}},
    {"smooth_stc", {}}};

class DecompositionExperiment : public Experiment {
public:
  DecompositionExperiment(const std::string& configFile, const ConfigOverrides& overrides) {
    const YAML::Node root = loadConfigRoot(configFile, {"kind", "seeds", "holes"});
    seeds_ = settingValue<int>(root, configFile, overrides, "seeds", 25);
    if (seeds_ < 1 || seeds_ > kDecompositionMaxSeeds)
      throw settingError(configFile, overrides, "seeds", std::to_string(seeds_), "must be 1 to " + std::to_string(kDecompositionMaxSeeds));
    for (const std::string& h : configValue<std::vector<std::string>>(root, configFile, "holes", {"0", "1", "2", "5", "10", "15", "20", "30"})) {
      char* end = nullptr;
      const long c = std::strtol(h.c_str(), &end, 10);
      if (h.empty() || *end != '\0' || c < 0 || c > 1000) throw InputError(configFile, "holes", h + ": not a hole count (0..1000)");
      holeCounts_.push_back(static_cast<int>(c));
    }
    if (holeCounts_.empty()) throw InputError(configFile, "holes", "the list is empty: give at least one hole count");
    settings_ = "kind: decompositions\nseeds: " + std::to_string(seeds_) + "\nholes: [";
    for (std::size_t k = 0; k < holeCounts_.size(); ++k) settings_ += (k ? ", " : "") + std::to_string(holeCounts_[k]);
    settings_ += "]\n";
  }

  std::string kind() const override { return "decompositions"; }
  std::string identity() const override { return settings_; }
  std::vector<Column> columns() const override {
    using T = ColumnType;
    std::vector<Column> c{{"world", T::kInteger},      {"holes", T::kInteger},       {"shape", T::kText},          {"holes_placed", T::kInteger},
                          {"bcd_cells", T::kInteger},  {"tcd_cells", T::kInteger},   {"cspace_seconds", T::kReal}, {"bcd_seconds", T::kReal},
                          {"tcd_seconds", T::kReal},   {"planner", T::kText}};
    for (const Column& k : runColumns()) c.push_back(k);
    return c;
  }
  std::size_t cases() const override { return holeCounts_.size() * static_cast<std::size_t>(seeds_); }
  std::string caseKey(std::size_t i) const override {
    return "holes=" + std::to_string(holeCounts_[i / static_cast<std::size_t>(seeds_)]) + " world=" + std::to_string(i % static_cast<std::size_t>(seeds_) + 1);
  }
  Output run(std::size_t i) const override {
    const int holes = holeCounts_[i / static_cast<std::size_t>(seeds_)], seed = static_cast<int>(i % static_cast<std::size_t>(seeds_)) + 1;
    datasets::PolygonWorldSpec spec;
    spec.width = 20;
    spec.height = 20;
    spec.count = holes;
    spec.minSize = 1;
    spec.maxSize = 3;
    const std::size_t si = static_cast<std::size_t>(seed) % kShapes.size();
    spec.shape = kShapes[si];
    spec.seed = static_cast<std::uint64_t>(seed);
    Problem problem;
    problem.workspace = datasets::generatePolygonWorld(spec);
    problem.robots.push_back({kRadius, std::nullopt});
    std::size_t placed = 0;
    for (const Region& reg : problem.workspace.regions) placed += reg.holes.size();
    const planners::Decomposed bcd = planners::runDecomposition("boustrophedon", problem, {});
    const planners::Decomposed tcd = planners::runDecomposition("trapezoidal", problem, {});
    const Row world{static_cast<std::int64_t>(seed),
                    static_cast<std::int64_t>(holes),
                    kShapeNames[si],
                    static_cast<std::int64_t>(placed),
                    static_cast<std::int64_t>(bcd.cells.cells.size()),
                    static_cast<std::int64_t>(tcd.cells.cells.size()),
                    bcd.cspaceSeconds,
                    bcd.decomposeSeconds,
                    tcd.decomposeSeconds};
    Output out;
    planners::PlanningContext ctx;
    try {
      ctx = planners::makeContext(problem);
    } catch (const InputError& e) {
      // no start for the robot: the world's decomposition figures count, with no plan (planner "")
      Row row = world;
      row.emplace_back(std::string());
      appendRun(row, notStarted(e.what()));
      out.rows.push_back(std::move(row));
      return out;
    }
    const CSpace cspace(problem.workspace, kRadius);
    MetricOptions mo = defaultMetricOptions();
    mo.cspace = &cspace;
    for (const auto& [label, params] : kPlannerRuns) {
      Row row = world;
      row.emplace_back(label);
      appendRun(row, runOnce(ctx, label.substr(0, label.find('(')), params, 0, {}, mo));
      out.rows.push_back(std::move(row));
    }
    return out;
  }
  std::vector<std::pair<std::string, std::string>> inputs() const override { return {{"config.yaml", settings_}}; }

  std::vector<std::pair<std::string, std::string>> summarise(const Table& t) const override {
    struct Acc {
      std::vector<double> coverage, length, turns, seconds;
      std::size_t invalid = 0, failed = 0;
    };
    struct PerCount {
      std::vector<double> bcd, tcd, bcdSeconds, tcdSeconds, cspaceSeconds, placed;
      std::map<std::string, Acc> planners;
    };
    std::vector<PerCount> perCount(holeCounts_.size());
    std::int64_t lastCase = -1;
    for (const Row& row : t.rows) {
      const auto c = static_cast<std::int64_t>(t.real(row, "case"));
      PerCount& pc = perCount[static_cast<std::size_t>(c) / static_cast<std::size_t>(seeds_)];
      if (c != lastCase) {   // the world's figures, once per case
        lastCase = c;
        pc.bcd.push_back(t.real(row, "bcd_cells"));
        pc.tcd.push_back(t.real(row, "tcd_cells"));
        pc.bcdSeconds.push_back(t.real(row, "bcd_seconds"));
        pc.tcdSeconds.push_back(t.real(row, "tcd_seconds"));
        pc.cspaceSeconds.push_back(t.real(row, "cspace_seconds"));
        pc.placed.push_back(t.real(row, "holes_placed"));
      }
      const std::string label = t.text(row, "planner");
      if (label.empty()) continue;
      Acc& a = pc.planners[label];
      const std::string status = t.text(row, "status");
      if (status != toString(PlanStatus::kExactSolution) && status != toString(PlanStatus::kPartialCoverage)) {
        ++a.failed;
        a.coverage.push_back(0);
        continue;
      }
      if (t.real(row, "valid") == 0) {
        ++a.invalid;
        continue;
      }
      a.coverage.push_back(t.real(row, "coverable_coverage"));
      a.length.push_back(t.real(row, "length"));
      a.turns.push_back(t.real(row, "turns"));
      a.seconds.push_back(t.real(row, "plan_seconds"));
    }
    std::ostringstream md;
    md << "# Decompositions: boustrophedon against trapezoidal, and boustrophedon coverage against the STC family\n\n"
       << seeds_ << " seeded 20×20 polygon worlds per hole count (shapes in turn: rotated rectangles, convex polygons, stars, discs; 1-3 m; "
       << "the generator places what fits, `holes placed`), r = 0.25, sweep direction 0°. Cells of the exact C-free; times in seconds on this "
       << "machine (C-space, then the decomposition alone). Coverage: of the coverable region (the start's C-free component ⊕ disc); plans that "
       << "did not succeed count 0, invalid plans are counted and left out. Plan time includes each planner's own C-space or cells.\n\n"
       << "| holes asked | holes placed | BCD cells | TCD cells | C-space s | BCD s | TCD s |\n|---|---|---|---|---|---|---|\n";
    std::map<std::string, std::vector<std::pair<double, double>>> cellSeries, timeSeries, coverageSeries, turnSeries;
    for (std::size_t hi = 0; hi < holeCounts_.size(); ++hi) {
      const PerCount& pc = perCount[hi];
      const double x = stats(pc.placed).mean;
      md << "| " << holeCounts_[hi] << " | " << fmt(x, 1) << " | " << fmt(stats(pc.bcd).mean, 1) << " | " << fmt(stats(pc.tcd).mean, 1) << " | "
         << fmt(stats(pc.cspaceSeconds).mean, 3) << " | " << fmt(stats(pc.bcdSeconds).mean, 3) << " | " << fmt(stats(pc.tcdSeconds).mean, 3) << " |\n";
      cellSeries["boustrophedon"].emplace_back(x, stats(pc.bcd).mean);
      cellSeries["trapezoidal"].emplace_back(x, stats(pc.tcd).mean);
      timeSeries["C-space"].emplace_back(x, stats(pc.cspaceSeconds).mean);
      timeSeries["boustrophedon"].emplace_back(x, stats(pc.bcdSeconds).mean);
      timeSeries["trapezoidal"].emplace_back(x, stats(pc.tcdSeconds).mean);
    }
    md << "\n| holes asked | planner | plans | mean coverage | min coverage | mean length | mean turns | mean plan s | not planned | invalid |\n"
       << "|---|---|---|---|---|---|---|---|---|---|\n";
    std::map<std::string, Acc> all;
    for (std::size_t hi = 0; hi < holeCounts_.size(); ++hi)
      for (const auto& [label, params] : kPlannerRuns) {
        const auto it = perCount[hi].planners.find(label);
        if (it == perCount[hi].planners.end()) continue;
        const Acc& a = it->second;
        const Stats c = stats(a.coverage);
        md << "| " << holeCounts_[hi] << " | " << label << " | " << a.coverage.size() << " | " << fmt(c.mean, 4) << " | " << fmt(c.min, 4) << " | "
           << fmt(stats(a.length).mean, 1) << " | " << fmt(stats(a.turns).mean, 1) << " | " << fmt(stats(a.seconds).mean, 3) << " | " << a.failed
           << " | " << a.invalid << " |\n";
        coverageSeries[label].emplace_back(stats(perCount[hi].placed).mean, c.mean);
        turnSeries[label].emplace_back(stats(perCount[hi].placed).mean, stats(a.turns).mean);
        Acc& sum = all[label];
        sum.coverage.insert(sum.coverage.end(), a.coverage.begin(), a.coverage.end());
        sum.length.insert(sum.length.end(), a.length.begin(), a.length.end());
        sum.turns.insert(sum.turns.end(), a.turns.begin(), a.turns.end());
        sum.seconds.insert(sum.seconds.end(), a.seconds.begin(), a.seconds.end());
        sum.failed += a.failed;
        sum.invalid += a.invalid;
      }
    md << "\nAll worlds:\n\n| planner | plans | mean coverage | min coverage | mean length | mean turns | mean plan s | not planned | invalid |\n"
       << "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& [label, params] : kPlannerRuns) {
      const Acc& a = all[label];
      const Stats c = stats(a.coverage);
      md << "| " << label << " | " << a.coverage.size() << " | " << fmt(c.mean, 4) << " | " << fmt(c.min, 4) << " | " << fmt(stats(a.length).mean, 1)
         << " | " << fmt(stats(a.turns).mean, 1) << " | " << fmt(stats(a.seconds).mean, 3) << " | " << a.failed << " | " << a.invalid << " |\n";
    }
    const std::string svg = lineChartSvg({"cells", "seconds", "mean coverage of the coverable region", "mean turns"}, "holes placed",
                                         {cellSeries, timeSeries, coverageSeries, turnSeries});
    return {{"summary.md", md.str()}, {"chart.svg", svg}};
  }

private:
  const Rational kRadius{1, 4};
  int seeds_ = 25;
  std::vector<int> holeCounts_;
  std::string settings_;
};

}  // namespace

std::unique_ptr<Experiment> decompositionExperiment(const std::string& configFile, const ConfigOverrides& overrides) {
  return withConfigErrors(configFile, [&]() -> std::unique_ptr<Experiment> { return std::make_unique<DecompositionExperiment>(configFile, overrides); });
}

}  // namespace coverkit::experiments
