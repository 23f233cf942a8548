// The `bsa-backtracking` kind of the engine: BSA paper, section 3, spiral against zigzag filling on
// seeded grid maps. See paper_experiments.h.
//
// A case is one usable seeded map, its two rows the two fillings. Which seeds are usable (the start's
// region holds at least half of the free cells) is decided when the experiment is made, by a scan
// of the seeds in order: making a map and labelling its components costs microseconds against the
// seconds of planning it, and it keeps the experiment what the paper ran, N maps that are coverage
// tests, with every case known before any runs (so that cases can be resumed, sharded and handed
// out to MPI ranks).
#include "charts.h"
#include "experiment_config.h"
#include "paper_experiments.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/graph/grid_search.h>
#include <coverkit/planners/registry.h>

#include <sstream>

namespace coverkit::experiments {

namespace {

constexpr const char* kFillings[2] = {"bsa_spiral", "bsa_zigzag"};

class BsaExperiment : public Experiment {
public:
  BsaExperiment(const std::string& configFile, const ConfigOverrides& overrides) {
    const YAML::Node root = loadConfigRoot(configFile, {"kind", "seeds", "size", "density", "obstacles"});
    seeds_ = settingValue<int>(root, configFile, overrides, "seeds", 100);
    size_ = settingValue<int>(root, configFile, overrides, "size", 30);
    density_ = settingValue<double>(root, configFile, overrides, "density", 0.05);
    const std::string obstacles = settingValue<std::string>(root, configFile, overrides, "obstacles", "clustered");
    auto fail = [&](const std::string& key, const std::string& text, const std::string& why) {
      return settingError(configFile, overrides, key, text, why);
    };
    if (seeds_ < 1 || seeds_ > kBsaMaxSeeds) throw fail("seeds", std::to_string(seeds_), "must be in 1.." + std::to_string(kBsaMaxSeeds));
    if (size_ < 2 || size_ > kBsaMaxSize)
      throw fail("size", std::to_string(size_),
                 "must be in 2.." + std::to_string(kBsaMaxSize) + " (a map of size² cells, planned, validated and measured per seed)");
    if (!(density_ >= 0 && density_ < 1)) throw fail("density", formatDouble(density_), "must be in [0, 1)");
    if (obstacles != "clustered" && obstacles != "scattered") throw fail("obstacles", obstacles, "must be clustered or scattered");
    clustered_ = obstacles == "clustered";
    settings_ = "kind: bsa-backtracking\nseeds: " + std::to_string(seeds_) + "\nsize: " + std::to_string(size_) + "\ndensity: " +
                formatDouble(density_) + "\nobstacles: " + obstacles + "\n";
    // the first `seeds_` usable seeds
    for (int seed = 1; static_cast<int>(used_.size()) < seeds_; ++seed) {
      const datasets::OccupancyGrid grid = map(seed);
      const std::vector<int> comp = graph::gridComponents(size_, size_, [&](int v) { return !grid.blocked[static_cast<std::size_t>(v)]; });
      std::size_t reach = 0, free = 0;
      for (auto b : grid.blocked) free += !b;
      for (int k : comp) reach += k == comp[0];   // cell 0 is S, kept free
      if (2 * reach >= free) {
        used_.push_back(seed);
        continue;
      }
      ++skipped_;
      // a density at which S is walled in on nearly every map would never end
      if (skipped_ > 100 + 10 * static_cast<std::size_t>(seeds_))
        throw fail("density", formatDouble(density_),
                   "the start S(0, 0) is walled in (its region under half the free cells) on " + std::to_string(skipped_) + " of the first " +
                       std::to_string(seed) + " seeded maps: use a lower density");
    }
  }

  std::string kind() const override { return "bsa-backtracking"; }
  std::string identity() const override { return settings_; }
  std::vector<Column> columns() const override {
    using T = ColumnType;
    std::vector<Column> c{{"seed", T::kInteger},    {"planner", T::kText},          {"covered_cells", T::kInteger},
                          {"backtracks", T::kInteger}, {"backtracking_points", T::kInteger}, {"travel_moves", T::kInteger}};
    for (const Column& k : runColumns()) c.push_back(k);
    return c;
  }
  std::size_t cases() const override { return used_.size(); }
  std::string caseKey(std::size_t i) const override { return "seed=" + std::to_string(used_[i]); }
  Output run(std::size_t i) const override {
    Problem problem;
    problem.workspace = datasets::gridToWorkspace(map(used_[i]), "bsa30");
    problem.robots.push_back({Rational(1, 2), Point{Rational(1, 2), Rational(1, 2)}});
    const planners::PlanningContext ctx = planners::makeContext(problem);
    MetricOptions mo = defaultMetricOptions();   // length and turns are what is compared: no area
    mo.coverable = false;
    mo.exactAreaMaxSegments = mo.exactAreaMaxSegmentsClear = 0;
    mo.rasterMaxPixels = 10'000;
    Output out;
    for (const char* planner : kFillings) {
      const RunResult r = runOnce(ctx, planner, {}, 0, {}, mo);
      const auto& st = r.plan.statistics;
      auto count = [&](const char* k) { return static_cast<std::int64_t>(st.at(k)); };
      Row row{static_cast<std::int64_t>(used_[i]), std::string(planner), count("covered_cells"), count("backtracks"), count("backtracking_points"),
              count("travel_moves")};
      appendRun(row, r);
      out.rows.push_back(std::move(row));
    }
    return out;
  }
  std::vector<std::pair<std::string, std::string>> inputs() const override { return {{"config.yaml", settings_}}; }

  std::vector<std::pair<std::string, std::string>> summarise(const Table& t) const override {
    std::map<std::string, std::vector<double>> backtracks, points, lengths, turns;
    std::size_t invalid = 0, incomplete = 0, zigzagFewer = 0, equal = 0;
    std::map<std::int64_t, std::map<std::string, double>> byCase;   // case → filling → backtracks
    for (const Row& row : t.rows) {
      const std::string p = t.text(row, "planner");
      invalid += t.real(row, "valid") == 0;
      incomplete += t.text(row, "status") != toString(PlanStatus::kExactSolution);
      backtracks[p].push_back(t.real(row, "backtracks"));
      points[p].push_back(t.real(row, "backtracking_points"));
      lengths[p].push_back(t.real(row, "length"));
      turns[p].push_back(t.real(row, "turns"));
      byCase[static_cast<std::int64_t>(t.real(row, "case"))][p] = t.real(row, "backtracks");
    }
    for (auto& [c, bt] : byCase) {
      zigzagFewer += bt["bsa_zigzag"] < bt["bsa_spiral"];
      equal += bt["bsa_zigzag"] == bt["bsa_spiral"];
    }
    std::ostringstream md;
    md << "# BSA: spiral against zigzag filling\n\n" << seeds_ << " seeded " << size_ << "×" << size_ << " grid maps, " << fmt(100 * density_, 0) << " % "
       << (clustered_ ? "clustered" : "scattered") << " obstacles, start S(0, 0), one cell per robot. Plans invalid: " << invalid
       << "; plans that did not visit every reachable cell: " << incomplete
       << "; seeds skipped because S was walled in (its region under half the free cells): " << skipped_ << ".\n\n"
       << "| measure | filling | mean | median | min | max |\n|---|---|---|---|---|---|\n";
    auto line = [&](const std::string& measure, std::map<std::string, std::vector<double>>& m, int digits) {
      for (const char* p : kFillings) {
        const Stats s = stats(m[p]);
        md << "| " << measure << " | " << p << " | " << fmt(s.mean, digits) << " | " << fmt(s.median, digits) << " | " << fmt(s.min, digits) << " | "
           << fmt(s.max, digits) << " |\n";
      }
    };
    line("backtracks (points returned to)", backtracks, 2);
    line("backtracking points recorded", points, 1);
    line("length (cells)", lengths, 1);
    line("turns", turns, 1);
    md << "\nZigzag needed fewer backtracks than spiral on " << zigzagFewer << " of " << seeds_ << " maps, as many on " << equal << ".\n";
    return {{"summary.md", md.str()}, {"backtracking.svg", histogramSvg({"backtracks per map", "backtracking points recorded per map"}, {backtracks, points})}};
  }

private:
  /// The seeded map; S(0, 0), the bottom-left cell, and its two neighbours kept free (a start
  /// walled in would count as a map with nothing to do).
  datasets::OccupancyGrid map(int seed) const {
    datasets::GridMapSpec spec;
    spec.width = spec.height = size_;
    spec.density = density_;
    spec.clustered = clustered_;
    spec.seed = static_cast<std::uint64_t>(seed);
    datasets::OccupancyGrid grid = datasets::generateGridMap(spec);
    grid.blocked[0] = grid.blocked[1] = grid.blocked[static_cast<std::size_t>(size_)] = 0;
    return grid;
  }

  int seeds_ = 100, size_ = 30;
  double density_ = 0.05;
  bool clustered_ = true;
  std::string settings_;
  std::vector<int> used_;
  std::size_t skipped_ = 0;
};

}  // namespace

std::unique_ptr<Experiment> bsaExperiment(const std::string& configFile, const ConfigOverrides& overrides) {
  return withConfigErrors(configFile, [&]() -> std::unique_ptr<Experiment> { return std::make_unique<BsaExperiment>(configFile, overrides); });
}

}  // namespace coverkit::experiments
