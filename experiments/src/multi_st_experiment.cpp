// The `multi-st` and `team-check` kinds of the engine (docs/multi-robot.md).
//
// multi-st: the Multi-ST paper's Tables 5-8 and Figs 15-17 (../shared/papers/multi-st_pham-et-al.txt,
// section 7) with multi_st and multi_stc_balanced side by side. The paper's grids are read as grids
// of sub-cells (one robot-sized cell each; r = 1/2 on 1 m pixels): its Table 6 counts "cells" of a
// 24 × 24 grid per robot, which only a sub-cell reading makes sum to about 576 (the paper's own
// counts add up to 582). Its obstacles are described, not given: we draw them seeded (rectangles and
// L shapes of 2-7 cells). Time = steps × 100 ms, as the paper's.
//  * t6: 24 × 24, 4 robots at the corners (0,0), (23,23), (23,0), (0,23) or at the adjacent centre
//    cells (11,11), (11,12), (12,11), (12,12); free and with five obstacles.
//  * t5 (Figs 15-17): 1-4 robots spread over 50 × 50 (free), 80 × 80 (8 obstacles) and 100 × 100
//    (20 obstacles): the makespan (the paper's maximum time) and the mean time per robot.
//  * t7: 50 × 50 with 0, 4 and 10 obstacles, 1-4 robots: repeated steps (the paper's iterations)
//    and the iteration rate.
//  * t8: 50 × 50, 4 robots, four moving obstacles crossing the map (5 seeds): steps, iterations and
//    working time with the knowledge base on and off.
//
// team-check: seeded scenarios (1-8 robots, 0-10 moving obstacles, grid and polygon worlds, radii
// 1/4, 1/2 and 1), multi_st on each, planned twice: valid under the team validator (violations by
// kind), every free sub-cell reachable from the starts once the obstacles have passed entered, the
// same bytes twice; multi_stc_balanced's makespan beside multi_st's on the static ones.
#include "charts.h"
#include "experiment_config.h"
#include "paper_experiments.h"
#include "runner.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/multi_stc.h>
#include <coverkit/planners/registry.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <random>
#include <sstream>
#include <variant>

namespace coverkit::experiments {

namespace {

std::uint64_t draw(std::mt19937_64& g, std::uint64_t n) { return n ? g() % n : 0; }

/// A width × height map of 1 m pixels with `count` seeded obstacles (rectangles and L shapes of 2-7
/// pixels a side), none on the pixels in `keep`.
Workspace pixelWorld(int width, int height, int count, std::uint64_t seed, const std::vector<std::pair<int, int>>& keep) {
  datasets::OccupancyGrid g;
  g.width = width;
  g.height = height;
  g.blocked.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
  std::mt19937_64 rng(seed);
  auto fill = [&](int x, int y, int w, int h) {
    for (int r = y; r < std::min(height, y + h); ++r)
      for (int c = x; c < std::min(width, x + w); ++c) g.blocked[static_cast<std::size_t>(r) * static_cast<std::size_t>(width) + static_cast<std::size_t>(c)] = 1;
  };
  for (int i = 0; i < count; ++i) {
    const int w = 2 + static_cast<int>(draw(rng, 6)), h = 2 + static_cast<int>(draw(rng, 6));
    const int x = 1 + static_cast<int>(draw(rng, static_cast<std::uint64_t>(std::max(1, width - w - 2))));
    const int y = 1 + static_cast<int>(draw(rng, static_cast<std::uint64_t>(std::max(1, height - h - 2))));
    fill(x, y, w, h);
    if (draw(rng, 2)) fill(x, y, 2, h + 2 + static_cast<int>(draw(rng, 3)));   // an L
  }
  for (const auto& [c, r] : keep) g.blocked[static_cast<std::size_t>(r) * static_cast<std::size_t>(width) + static_cast<std::size_t>(c)] = 0;
  return datasets::gridToWorkspace(g, "multi-st world");
}

MetricOptions teamMetrics() {
  MetricOptions mo = defaultMetricOptions();
  mo.coverable = false;
  mo.area = false;
  return mo;
}

struct TeamCase {
  std::string table, setting;
  int width = 0, height = 0, obstacles = 0, robots = 0, moving = 0;
  std::uint64_t seed = 0;
  std::vector<std::pair<int, int>> starts;   ///< start cells (col, row from the bottom); empty: spread
  std::vector<std::string> planners;         ///< "multi_st", "multi_st:kb=off", "multi_stc_balanced"
};

std::vector<TeamCase> paperCases() {
  std::vector<TeamCase> out;
  const std::vector<std::pair<int, int>> corners{{0, 0}, {23, 23}, {23, 0}, {0, 23}}, centre{{11, 11}, {11, 12}, {12, 11}, {12, 12}};
  for (int obstacles : {0, 5})
    for (int where = 0; where < 2; ++where)
      out.push_back({"t6", (where ? "centre" : "corners") + std::string(obstacles ? ", obstacles" : ", free"), 24, 24, obstacles, 4, 0, 6,
                     where ? centre : corners, {"multi_st", "multi_stc_balanced"}});
  const int side[3] = {50, 80, 100}, blobs[3] = {0, 8, 20};
  for (int m = 0; m < 3; ++m)
    for (int k = 1; k <= 4; ++k)
      out.push_back({"t5", "fig" + std::to_string(15 + m), side[m], side[m], blobs[m], k, 0, static_cast<std::uint64_t>(15 + m), {},
                     {"multi_st", "multi_stc_balanced"}});
  for (int obstacles : {0, 4, 10})
    for (int k = 1; k <= 4; ++k)
      out.push_back({"t7", std::to_string(obstacles) + " obstacles", 50, 50, obstacles, k, 0, 7, {}, {"multi_st", "multi_stc_balanced"}});
  for (std::uint64_t seed = 1; seed <= 5; ++seed)
    out.push_back({"t8", "seed " + std::to_string(seed), 50, 50, 0, 4, 4, 80 + seed, {}, {"multi_st", "multi_st:kb=off", "multi_stc_balanced"}});
  return out;
}

/// Moving obstacles crossing a width × height map: radius 1/4-1/2, 2-4 waypoints, at most 2 m/s
/// (a robot steps 10 m/s on 1 m cells), starting after 1 s.
std::vector<MovingObstacle> crossingObstacles(int count, double width, double height, std::uint64_t seed) {
  std::mt19937_64 rng(seed * 7919 + 17);
  std::vector<MovingObstacle> out;
  for (int i = 0; i < count; ++i) {
    MovingObstacle m;
    m.radius = Rational(1 + static_cast<long>(draw(rng, 2))) / 4;
    double t = 1 + static_cast<double>(draw(rng, 20)) / 4;
    PointD p{0.5 + static_cast<double>(draw(rng, static_cast<std::uint64_t>(width))), 0.5 + static_cast<double>(draw(rng, static_cast<std::uint64_t>(height)))};
    m.waypoints.push_back({t, p});
    const int legs = 1 + static_cast<int>(draw(rng, 3));
    for (int l = 0; l < legs; ++l) {
      const PointD q{0.5 + static_cast<double>(draw(rng, static_cast<std::uint64_t>(width))), 0.5 + static_cast<double>(draw(rng, static_cast<std::uint64_t>(height)))};
      const double speed = 0.5 + static_cast<double>(draw(rng, 4)) / 2;   // 0.5-2 m/s
      t += std::max(0.5, std::hypot(q.x - p.x, q.y - p.y) / speed);
      m.waypoints.push_back({t, q});
      p = q;
    }
    out.push_back(m);
  }
  return out;
}

std::pair<std::string, std::map<std::string, std::string>> plannerSpec(const std::string& s) {
  const auto colon = s.find(':');
  if (colon == std::string::npos) return {s, {}};
  const auto eq = s.find('=', colon);
  return {s.substr(0, colon), {{s.substr(colon + 1, eq - colon - 1), s.substr(eq + 1)}}};
}

/// Distinct sub-cells each robot's timeline enters ("a/b/c"), as the paper's Table 6 counts cells.
std::string cellsPerRobot(const CellGrid& cells, const Plan& plan) {
  std::string out;
  for (std::size_t i = 0; i < plan.paths.size(); ++i) {
    std::vector<long> seen;
    for (const TimedPoint& e : plan.paths[i].timeline) {
      CellIndex c;
      if (cells.locateSubD(e.p, c)) seen.push_back(static_cast<long>(c.row) * cells.subCols() + c.col);
    }
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    out += (i ? "/" : "") + std::to_string(seen.size());
  }
  return out;
}

class MultiStExperiment : public Experiment {
public:
  explicit MultiStExperiment(const std::string& configFile) : cases_(paperCases()) { loadConfigRoot(configFile, {"kind"}); }
  std::string kind() const override { return "multi-st"; }
  std::string identity() const override { return "kind: multi-st\n"; }
  std::vector<Column> columns() const override {
    using T = ColumnType;
    return {{"table", T::kText},        {"setting", T::kText},          {"robots", T::kInteger},      {"planner", T::kText},
            {"status", T::kText},       {"valid", T::kInteger},         {"makespan_s", T::kReal},     {"mean_time_s", T::kReal},
            {"steps", T::kInteger},     {"repeated_steps", T::kInteger}, {"iteration_rate", T::kReal}, {"coverage_rate", T::kReal},
            {"cells_per_robot", T::kText}, {"balance", T::kReal},       {"missed_subcells", T::kInteger}, {"plan_seconds", T::kReal}};
  }
  std::size_t cases() const override { return cases_.size(); }
  std::string caseKey(std::size_t i) const override { return cases_[i].table + " " + cases_[i].setting + " k=" + std::to_string(cases_[i].robots); }
  Output run(std::size_t i) const override {
    const TeamCase& c = cases_[i];
    Problem p;
    p.workspace = pixelWorld(c.width, c.height, c.obstacles, c.seed, c.starts);
    for (int r = 0; r < c.robots; ++r) {
      Robot robot{Rational(1, 2), std::nullopt};
      if (!c.starts.empty()) robot.start = Point{Rational(2 * c.starts[static_cast<std::size_t>(r)].first + 1, 2), Rational(2 * c.starts[static_cast<std::size_t>(r)].second + 1, 2)};
      p.robots.push_back(robot);
    }
    p.movingObstacles = crossingObstacles(c.moving, c.width, c.height, c.seed);
    const planners::PlanningContext ctx = planners::makeContext(p);
    Output out;
    for (const std::string& spec : c.planners) {
      const auto [name, params] = plannerSpec(spec);
      const RunResult r = runOnce(ctx, name, params, 0, {}, teamMetrics());
      const Metrics& m = r.metrics;
      out.rows.push_back(Row{c.table, c.setting, static_cast<std::int64_t>(c.robots), spec, std::string(toString(r.plan.status)),
                             static_cast<std::int64_t>(r.validation.valid), m.makespan, m.sumOfTimes / c.robots, static_cast<std::int64_t>(m.steps),
                             static_cast<std::int64_t>(m.repeatedSteps), m.iterationRate, m.coverageRate, cellsPerRobot(ctx.cells, r.plan),
                             m.balance, static_cast<std::int64_t>(planners::missedSubcells(ctx, r.plan.paths).fromStarts), r.planSeconds});
    }
    return out;
  }
  std::vector<std::pair<std::string, std::string>> summarise(const Table& t) const override;

private:
  std::vector<TeamCase> cases_;
};

std::vector<std::pair<std::string, std::string>> MultiStExperiment::summarise(const Table& t) const {
  std::ostringstream md;
  auto rowsOf = [&](const std::string& table) {
    std::vector<const Row*> out;
    for (const Row& r : t.rows)
      if (t.text(r, "table") == table) out.push_back(&r);
    return out;
  };
  md << "# Multi-ST: the paper's Tables 5-8 and Figs 15-17 beside multi_stc_balanced\n\n"
     << "Grids of sub-cells (r = 1/2 on 1 m pixels), time = steps × 100 ms. Every plan validated by the team validator; "
     << "`missed` counts free sub-cells reachable from the starts (once the moving obstacles have passed) that no robot entered.\n\n";
  md << "## Table 6: starting places on a 24 × 24 grid, 4 robots\n\nPaper (cells per robot): corners 148/150/150/134 (free), "
     << "145/131/142/161 (obstacles); adjacent centre cells 45/85/211/241 (free), 70/72/199/233 (obstacles).\n\n"
     << "| setting | planner | status | valid | cells per robot | balance | makespan | repeated steps | missed |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const Row* r : rowsOf("t6"))
    md << "| " << t.text(*r, "setting") << " | " << t.text(*r, "planner") << " | " << t.text(*r, "status") << " | " << (t.real(*r, "valid") ? "yes" : "no") << " | "
       << t.text(*r, "cells_per_robot") << " | " << fmt(t.real(*r, "balance"), 2) << " | " << fmt(t.real(*r, "makespan_s"), 1) << " s | "
       << t.text(*r, "repeated_steps") << " | " << t.text(*r, "missed_subcells") << " |\n";
  md << "\n## Table 5, Figs 15-17: time against the number of robots\n\nPaper (units as printed): Fig 15 (50 × 50) 500 / 350 / 275 / 200; "
     << "Fig 16 (80 × 80) 700 / 480 / 350 / 260; Fig 17 (100 × 100) 1000 / 750 / 560 / 400. Ours: the makespan (the paper's maximum "
     << "time) and the mean time per robot, in seconds, and the makespan as a share of one robot's.\n\n"
     << "| figure | robots | planner | valid | makespan | mean time | share of one robot's | paper's share | missed |\n|---|---|---|---|---|---|---|---|---|\n";
  const double paper[3][4] = {{500, 350, 275, 200}, {700, 480, 350, 260}, {1000, 750, 560, 400}};
  std::vector<std::map<std::string, std::vector<std::pair<double, double>>>> panels(3);
  std::map<std::string, double> single;
  for (const Row* r : rowsOf("t5"))
    if (t.real(*r, "robots") == 1) single[t.text(*r, "setting") + t.text(*r, "planner")] = t.real(*r, "makespan_s");
  for (const Row* r : rowsOf("t5")) {
    const int fig = std::stoi(t.text(*r, "setting").substr(3)) - 15, k = static_cast<int>(t.real(*r, "robots"));
    const double one = single[t.text(*r, "setting") + t.text(*r, "planner")];
    const double share = one > 0 ? t.real(*r, "makespan_s") / one : 0;
    md << "| " << 15 + fig << " | " << k << " | " << t.text(*r, "planner") << " | " << (t.real(*r, "valid") ? "yes" : "no") << " | "
       << fmt(t.real(*r, "makespan_s"), 1) << " s | " << fmt(t.real(*r, "mean_time_s"), 1) << " s | " << fmt(share, 2) << " | "
       << fmt(paper[fig][k - 1] / paper[fig][0], 2) << " | " << t.text(*r, "missed_subcells") << " |\n";
    panels[static_cast<std::size_t>(fig)][t.text(*r, "planner") + " (share)"].push_back({k, share});
    if (t.text(*r, "planner") == "multi_st") panels[static_cast<std::size_t>(fig)]["paper (share)"].push_back({k, paper[fig][k - 1] / paper[fig][0]});
  }
  md << "\n![time against robots](figs15-17.svg)\n\n## Table 7: obstacles and repeated steps (50 × 50)\n\nPaper: iterations 1000 (one robot) "
     << "to 1100 (four), iteration rate 0.10 to 0.11 without obstacles; 1500 and 0.15 with 10 obstacles and four robots (elsewhere it "
     << "gives the rate as 0.48-7.42). Our iterations are repeated steps (A2), the rate A2 / A1.\n\n"
     << "| obstacles | robots | planner | steps (A1) | repeated (A2) | iteration rate | coverage rate | missed |\n|---|---|---|---|---|---|---|---|\n";
  for (const Row* r : rowsOf("t7"))
    md << "| " << t.text(*r, "setting") << " | " << t.text(*r, "robots") << " | " << t.text(*r, "planner") << " | " << t.text(*r, "steps") << " | "
       << t.text(*r, "repeated_steps") << " | " << fmt(t.real(*r, "iteration_rate"), 3) << " | " << fmt(t.real(*r, "coverage_rate"), 3) << " | "
       << t.text(*r, "missed_subcells") << " |\n";
  md << "\n## Table 8: the knowledge base among moving obstacles (50 × 50, 4 robots, 4 obstacles)\n\nPaper: with the knowledge base the "
     << "steps and iterations rise slightly and the working time falls markedly (its figures did not survive).\n\n"
     << "| seed | planner | status | valid | steps | repeated steps | working time (makespan) | missed |\n|---|---|---|---|---|---|---|---|\n";
  std::map<std::string, std::vector<double>> work;
  for (const Row* r : rowsOf("t8")) {
    md << "| " << t.text(*r, "setting") << " | " << t.text(*r, "planner") << " | " << t.text(*r, "status") << " | " << (t.real(*r, "valid") ? "yes" : "no")
       << " | " << t.text(*r, "steps") << " | " << t.text(*r, "repeated_steps") << " | " << fmt(t.real(*r, "makespan_s"), 1) << " s | "
       << t.text(*r, "missed_subcells") << " |\n";
    work[t.text(*r, "planner")].push_back(t.real(*r, "makespan_s"));
  }
  md << "\nMean working time:";
  for (const auto& [planner, v] : work) {
    double s = 0;
    for (double x : v) s += x;
    md << " " << planner << " " << fmt(v.empty() ? 0 : s / static_cast<double>(v.size()), 1) << " s;";
  }
  md << "\n";
  return {{"summary.md", md.str()},
          {"figs15-17.svg", lineChartSvg({"Fig 15: 50 × 50", "Fig 16: 80 × 80", "Fig 17: 100 × 100"}, "robots", panels)}};
}

// ---------------------------------------------------------------------------------------------
// team-check

/// The workspace as WKT (MULTIPOLYGON, coordinates as the shortest decimals that read back to the
/// same doubles; the generators' lattices make those the exact values).
std::string workspaceWkt(const Workspace& w) {
  std::ostringstream out;
  out << "MULTIPOLYGON (";
  auto ring = [&](const Ring& r) {
    out << "(";
    for (std::size_t i = 0; i <= r.size(); ++i) {
      const Point& p = r[i % r.size()];
      out << (i ? ", " : "") << formatDouble(toDouble(p.x)) << " " << formatDouble(toDouble(p.y));
    }
    out << ")";
  };
  for (std::size_t g = 0; g < w.regions.size(); ++g) {
    out << (g ? ", " : "") << "(";
    ring(w.regions[g].outer);
    for (const Ring& h : w.regions[g].holes) {
      out << ", ";
      ring(h);
    }
    out << ")";
  }
  out << ")\n";
  return out.str();
}

std::string scenarioYaml(const std::vector<MovingObstacle>& obstacles) {
  std::ostringstream out;
  out << "format: coverkit.scenario/1\ndynamic_obstacles:\n";
  for (const MovingObstacle& m : obstacles) {
    out << "  - radius: " << m.radius.get_str() << "\n    waypoints: [";
    for (std::size_t i = 0; i < m.waypoints.size(); ++i)
      out << (i ? ", " : "") << "[" << formatDouble(m.waypoints[i].t) << ", " << formatDouble(m.waypoints[i].p.x) << ", " << formatDouble(m.waypoints[i].p.y) << "]";
    out << "]\n";
  }
  return out.str();
}

struct CheckCase {
  std::uint64_t seed;
  bool grid;
  Rational radius;
  int robots, moving;
};

class TeamCheckExperiment : public Experiment {
public:
  TeamCheckExperiment(const std::string& configFile, const ConfigOverrides& overrides) {
    const YAML::Node root = loadConfigRoot(configFile, {"kind", "seeds"});
    scenarios_ = settingValue<int>(root, configFile, overrides, "seeds", 500);
    if (scenarios_ < 1 || scenarios_ > 100'000) throw settingError(configFile, overrides, "seeds", std::to_string(scenarios_), "must be in [1, 100000]");
  }
  std::string kind() const override { return "team-check"; }
  std::string identity() const override { return "kind: team-check\nseeds: " + std::to_string(scenarios_) + "\n"; }
  std::vector<Column> columns() const override {
    using T = ColumnType;
    return {{"seed", T::kInteger},        {"world", T::kText},          {"radius", T::kText},          {"robots", T::kInteger},
            {"moving_obstacles", T::kInteger}, {"status", T::kText},     {"valid", T::kInteger},        {"static_violations", T::kInteger},
            {"robot_robot", T::kInteger}, {"robot_obstacle", T::kInteger}, {"timeline", T::kInteger},   {"missed_subcells", T::kInteger},
            {"missed_from_team", T::kInteger},
            {"deterministic", T::kInteger}, {"makespan_s", T::kReal},     {"balanced_makespan_s", T::kReal}, {"balanced_valid", T::kInteger},
            {"plan_seconds", T::kReal}, {"message", T::kText}};
  }
  std::size_t cases() const override { return static_cast<std::size_t>(scenarios_); }
  std::string caseKey(std::size_t i) const override { return "seed=" + std::to_string(i + 1); }
  static CheckCase caseOf(std::size_t i) {
    const std::uint64_t seed = i + 1;
    const Rational radii[3] = {Rational(1, 4), Rational(1, 2), Rational(1)};
    return {seed, seed % 2 == 1, radii[seed % 3], 1 + static_cast<int>(seed % 8), static_cast<int>((seed / 8) % 11)};
  }
  Output run(std::size_t i) const override {
    const CheckCase c = caseOf(i);
    Problem p;
    const int side = 16 + static_cast<int>(c.seed % 5) * 4;
    if (c.grid) {
      datasets::GridMapSpec spec;
      spec.width = spec.height = side;
      spec.density = 0.03 * static_cast<double>(c.seed % 5);
      spec.clustered = c.seed % 4 != 1;
      spec.seed = c.seed;
      p.workspace = datasets::gridToWorkspace(datasets::generateGridMap(spec), "check");
    } else {
      datasets::PolygonWorldSpec spec;
      spec.width = spec.height = side;
      spec.count = static_cast<int>(c.seed % 9);
      spec.shape = datasets::ObstacleShape::kMixed;
      spec.seed = c.seed;
      p.workspace = datasets::generatePolygonWorld(spec);
    }
    p.robots.assign(static_cast<std::size_t>(c.robots), Robot{c.radius, std::nullopt});
    p.movingObstacles = crossingObstacles(c.moving, side, side, c.seed);
    Row row{static_cast<std::int64_t>(c.seed), std::string(c.grid ? "grid" : "polygons"), c.radius.get_str(), static_cast<std::int64_t>(c.robots),
            static_cast<std::int64_t>(c.moving)};
    planners::PlanningContext ctx;
    try {
      ctx = planners::makeContext(p);
    } catch (const InputError& e) {   // e.g. no room for the team's starts: reported, not counted
      for (const Value& v : std::vector<Value>{std::string("refused: ") + e.what(), std::int64_t{1}, std::int64_t{0}, std::int64_t{0}, std::int64_t{0},
                                               std::int64_t{0}, std::int64_t{0}, std::int64_t{0}, std::int64_t{1}, 0.0, 0.0, std::int64_t{1}, 0.0, std::string()})
        row.push_back(v);
      return {{row}, {}};
    }
    const RunResult a = runOnce(ctx, "multi_st", {}, 0, {}, teamMetrics());
    const RunResult b = runOnce(ctx, "multi_st", {}, 0, {}, teamMetrics());
    std::map<std::string, std::int64_t> kinds;
    for (const Violation& v : a.validation.violations) ++kinds[v.kind];
    std::int64_t staticViolations = 0;
    for (const auto& [k, n] : kinds)
      if (k != "robot_robot" && k != "robot_obstacle" && k != "timeline") staticViolations += n;
    datasets::PathDocument da, db;
    da.paths = a.plan.paths;
    db.paths = b.plan.paths;
    double balanced = 0;
    std::int64_t balancedValid = 1;
    if (p.movingObstacles.empty()) {
      const RunResult m = runOnce(ctx, "multi_stc_balanced", {}, 0, {}, teamMetrics());
      balanced = m.metrics.makespan;
      balancedValid = m.validation.valid;
    }
    const planners::MissedSubcells missed = planners::missedSubcells(ctx, a.plan.paths);
    for (const Value& v : std::vector<Value>{std::string(toString(a.plan.status)), static_cast<std::int64_t>(a.validation.valid), staticViolations,
                                             kinds["robot_robot"], kinds["robot_obstacle"], kinds["timeline"],
                                             static_cast<std::int64_t>(missed.fromStarts), static_cast<std::int64_t>(missed.fromTeam),
                                             static_cast<std::int64_t>(datasets::pathJson(da) == datasets::pathJson(db)), a.metrics.makespan, balanced,
                                             balancedValid, a.planSeconds, a.plan.message})
      row.push_back(v);
    Output out{{row}, {}};
    if (!a.validation.valid || missed.fromStarts + missed.fromTeam > 0) {   // the world, its obstacles and the command, to look again
      const std::string base = "failures/seed-" + std::to_string(c.seed);
      std::string starts;
      for (const Robot& robot : ctx.problem.robots) starts += " --start " + formatDouble(toDouble(robot.start->x)) + "," + formatDouble(toDouble(robot.start->y));
      out.files = {{base + ".wkt", workspaceWkt(p.workspace)},
                   {base + ".yaml", scenarioYaml(p.movingObstacles)},
                   {base + ".sh", "coverkit plan --map seed-" + std::to_string(c.seed) + ".wkt --radius " + c.radius.get_str() + starts +
                                      " --scenario seed-" + std::to_string(c.seed) + ".yaml --planner multi_st --out seed-" + std::to_string(c.seed) +
                                      ".json\n"}};
    }
    return out;
  }
  std::vector<std::pair<std::string, std::string>> summarise(const Table& t) const override {
    std::size_t n = 0, refused = 0, valid = 0, complete = 0, completeFromTeam = 0, same = 0, staticV = 0, rr = 0, ro = 0, tl = 0, compared = 0, notAbove = 0, bValid = 0;
    double worstRatio = 0;
    for (const Row& r : t.rows) {
      if (t.text(r, "status").rfind("refused", 0) == 0) {
        ++refused;
        continue;
      }
      ++n;
      valid += t.real(r, "valid") != 0;
      complete += t.real(r, "missed_subcells") == 0;
      completeFromTeam += t.real(r, "missed_from_team") == 0;
      same += t.real(r, "deterministic") != 0;
      staticV += static_cast<std::size_t>(t.real(r, "static_violations"));
      rr += static_cast<std::size_t>(t.real(r, "robot_robot"));
      ro += static_cast<std::size_t>(t.real(r, "robot_obstacle"));
      tl += static_cast<std::size_t>(t.real(r, "timeline"));
      if (t.real(r, "moving_obstacles") == 0 && t.real(r, "balanced_makespan_s") > 0) {
        ++compared;
        bValid += t.real(r, "balanced_valid") != 0;
        notAbove += t.real(r, "balanced_makespan_s") <= t.real(r, "makespan_s");
        worstRatio = std::max(worstRatio, t.real(r, "balanced_makespan_s") / std::max(1e-9, t.real(r, "makespan_s")));
      }
    }
    std::ostringstream md;
    md << "# Team check: multi_st on " << t.rows.size() << " seeded scenarios\n\n"
       << "1-8 robots, 0-10 moving obstacles, grid and polygon worlds, r = 1/4, 1/2, 1; each planned twice.\n\n"
       << "| measure | value |\n|---|---|\n"
       << "| scenarios planned | " << n << " (" << refused << " refused as input: no room for the team) |\n"
       << "| valid under the team validator | " << valid << " |\n"
       << "| static violations | " << staticV << " |\n"
       << "| robot-robot approaches closer than allowed | " << rr << " |\n"
       << "| robot-obstacle approaches closer than allowed | " << ro << " |\n"
       << "| timeline violations | " << tl << " |\n"
       << "| every free sub-cell reachable from the starts entered | " << complete << " |\n"
       << "| every free sub-cell reachable from the team when the last obstacle stops entered | " << completeFromTeam << " |\n"
       << "| the same bytes twice | " << same << " |\n"
       << "| static scenarios with multi_stc_balanced beside | " << compared << " (valid " << bValid << ") |\n"
       << "| multi_stc_balanced's makespan not above multi_st's | " << notAbove << " (" << fmt(compared ? 100.0 * static_cast<double>(notAbove) / static_cast<double>(compared) : 0, 1)
       << " %; worst ratio " << fmt(worstRatio, 2) << ") |\n";
    return {{"summary.md", md.str()}};
  }

private:
  int scenarios_;
};

}  // namespace

std::unique_ptr<Experiment> multiStExperiment(const std::string& configFile, const ConfigOverrides&) {
  return withConfigErrors(configFile, [&]() -> std::unique_ptr<Experiment> { return std::make_unique<MultiStExperiment>(configFile); });
}

std::unique_ptr<Experiment> teamCheckExperiment(const std::string& configFile, const ConfigOverrides& overrides) {
  return withConfigErrors(configFile, [&]() -> std::unique_ptr<Experiment> { return std::make_unique<TeamCheckExperiment>(configFile, overrides); });
}

}  // namespace coverkit::experiments
