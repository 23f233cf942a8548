// The papers' experiments. See paper_experiments.h.
#include "paper_experiments.h"

#include "render.h"
#include "runner.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/error.h>
#include <coverkit/graph/grid_search.h>
#include <coverkit/planners/registry.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <numeric>
#include <sstream>
#include <vector>

namespace coverkit::experiments {

namespace fs = std::filesystem;

namespace {

struct Stats {
  double mean = 0, median = 0, min = 0, max = 0;
};
Stats stats(std::vector<double> v) {
  Stats s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  s.median = v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
  s.min = v.front();
  s.max = v.back();
  return s;
}

std::string fmt(double x, int digits = 2) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(digits) << x;
  return os.str();
}

/// Grouped histogram panels (one per measure), one colour per series; plain SVG.
std::string histogramSvg(const std::vector<std::string>& titles, const std::vector<std::map<std::string, std::vector<double>>>& panels) {
  const int pw = 420, ph = 300, ml = 50, mb = 45, mt = 30;
  std::ostringstream svg;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << pw * panels.size() << "' height='" << ph
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n";
  const char* colours[2] = {"#d95f02", "#1b9e77"};
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const int x0 = static_cast<int>(p) * pw + ml, y0 = ph - mb, w = pw - ml - 15, h = ph - mb - mt;
    int maxValue = 0;
    std::size_t maxCount = 1;
    std::vector<std::map<int, std::size_t>> counts;
    for (const auto& [name, values] : panels[p]) {
      std::map<int, std::size_t> c;
      for (double v : values) maxValue = std::max(maxValue, static_cast<int>(v)), ++c[static_cast<int>(v)];
      for (const auto& [k, n] : c) maxCount = std::max(maxCount, n);
      counts.push_back(c);
    }
    const double bw = static_cast<double>(w) / (maxValue + 1);
    svg << "<text x='" << x0 + w / 2 << "' y='18' text-anchor='middle'>" << titles[p] << "</text>\n";
    svg << "<line x1='" << x0 << "' y1='" << y0 << "' x2='" << x0 + w << "' y2='" << y0 << "' stroke='black'/>\n";
    svg << "<line x1='" << x0 << "' y1='" << y0 << "' x2='" << x0 << "' y2='" << y0 - h << "' stroke='black'/>\n";
    for (int k = 0; k <= maxValue; k += std::max(1, (maxValue + 1) / 10))
      svg << "<text x='" << x0 + (k + 0.5) * bw << "' y='" << y0 + 15 << "' text-anchor='middle'>" << k << "</text>\n";
    for (std::size_t k = 0; k <= maxCount; k += std::max<std::size_t>(1, maxCount / 5))
      svg << "<text x='" << x0 - 5 << "' y='" << y0 - static_cast<double>(k) / maxCount * h + 4 << "' text-anchor='end'>" << k << "</text>\n";
    svg << "<text x='" << x0 + w / 2 << "' y='" << ph - 8 << "' text-anchor='middle'>value per map</text>\n";
    svg << "<text x='14' y='" << y0 - h / 2 << "' transform='rotate(-90 14 " << y0 - h / 2 << ")' text-anchor='middle'>maps</text>\n";
    std::size_t series = 0;
    for (const auto& [name, values] : panels[p]) {
      for (const auto& [k, n] : counts[series]) {
        const double bh = static_cast<double>(n) / maxCount * h;
        svg << "<rect x='" << x0 + k * bw + series * bw / 2 << "' y='" << y0 - bh << "' width='" << bw / 2 - 1 << "' height='" << bh
            << "' fill='" << colours[series % 2] << "'/>\n";
      }
      svg << "<rect x='" << x0 + w - 110 << "' y='" << mt + 16 * series << "' width='10' height='10' fill='" << colours[series % 2] << "'/>";
      svg << "<text x='" << x0 + w - 95 << "' y='" << mt + 9 + 16 * series << "'>" << name << "</text>\n";
      ++series;
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace

std::string runBsaExperiment(const BsaExperimentOptions& o, const std::string& outDir) {
  if (o.seeds < 1 || o.seeds > kBsaMaxSeeds)
    throw InputError("--seeds", std::to_string(o.seeds), "must be in 1.." + std::to_string(kBsaMaxSeeds));
  if (o.size < 2 || o.size > kBsaMaxSize)
    throw InputError("--size", std::to_string(o.size), "must be in 2.." + std::to_string(kBsaMaxSize) + " (a map of size² cells, planned, validated and measured per seed)");
  if (!(o.density >= 0 && o.density < 1)) throw InputError("--density", formatDouble(o.density), "must be in [0, 1)");
  const std::vector<std::string> outputs{"results.csv", "summary.md", "backtracking.svg"};
  datasets::checkOutputFolder(outDir, "--out", outputs);
  std::ostringstream csv;
  csv << "seed,planner,valid,covered_cells,free_cells,backtracks,backtracking_points,length,turns,travel_moves\n";
  std::map<std::string, std::vector<double>> backtracks, points, lengths, turns;
  std::size_t invalid = 0, incomplete = 0, zigzagFewer = 0, equal = 0, skipped = 0;
  for (int seed = 1, used = 0; used < o.seeds; ++seed) {
    datasets::GridMapSpec spec;
    spec.width = spec.height = o.size;
    spec.density = o.density;
    spec.clustered = o.clustered;
    spec.seed = static_cast<std::uint64_t>(seed);
    datasets::OccupancyGrid grid = datasets::generateGridMap(spec);
    // S(0, 0): the bottom-left cell and its two neighbours are kept free (a start walled in would
    // count as a map with nothing to do)
    grid.blocked[0] = grid.blocked[1] = grid.blocked[static_cast<std::size_t>(o.size)] = 0;
    Problem problem;
    problem.workspace = datasets::gridToWorkspace(grid, "bsa30");
    problem.robots.push_back({Rational(1, 2), Point{Rational(1, 2), Rational(1, 2)}});
    const planners::PlanningContext ctx = planners::makeContext(problem);
    // a map whose start region holds under half of the free cells (S walled in by obstacles) is
    // not a coverage test: it is counted and replaced by the next seed
    {
      const std::vector<int> comp = graph::gridComponents(o.size, o.size, [&](int v) { return !grid.blocked[static_cast<std::size_t>(v)]; });
      std::size_t reach = 0, free = 0;
      for (auto b : grid.blocked) free += !b;
      for (int k : comp) reach += k == comp[0];  // cell 0 is S, kept free above
      if (2 * reach < free) {
        ++skipped;
        // a density at which S is walled in on nearly every map would never end
        if (skipped > 100 + 10 * static_cast<std::size_t>(o.seeds))
          throw InputError("--density", formatDouble(o.density),
                           "the start S(0, 0) is walled in (its region under half the free cells) on " + std::to_string(skipped) + " of the first " +
                               std::to_string(seed) + " seeded maps: use a lower density");
        continue;
      }
    }
    ++used;
    std::map<std::string, double> bt;
    for (const char* planner : {"bsa_spiral", "bsa_zigzag"}) {
      MetricOptions mo = defaultMetricOptions();  // length and turns are what is compared: no area
      mo.coverable = false;
      mo.exactAreaMaxSegments = mo.exactAreaMaxSegmentsClear = 0;
      mo.rasterMaxPixels = 10'000;
      const RunResult r = runOnce(ctx, planner, {}, 0, {}, mo);
      const auto& st = r.plan.statistics;
      invalid += !r.validation.valid;
      incomplete += r.plan.status != PlanStatus::kExactSolution;
      csv << seed << ',' << planner << ',' << (r.validation.valid ? 1 : 0) << ',' << st.at("covered_cells") << ',' << r.metrics.freeSubcells << ','
          << st.at("backtracks") << ',' << st.at("backtracking_points") << ',' << fmt(r.metrics.length, 4) << ',' << r.metrics.turns << ','
          << st.at("travel_moves") << '\n';
      const std::string name = planner;
      backtracks[name].push_back(st.at("backtracks"));
      points[name].push_back(st.at("backtracking_points"));
      lengths[name].push_back(r.metrics.length);
      turns[name].push_back(static_cast<double>(r.metrics.turns));
      bt[name] = st.at("backtracks");
    }
    zigzagFewer += bt["bsa_zigzag"] < bt["bsa_spiral"];
    equal += bt["bsa_zigzag"] == bt["bsa_spiral"];
  }
  std::ostringstream md;
  md << "# BSA: spiral against zigzag filling\n\n" << o.seeds << " seeded " << o.size << "×" << o.size << " grid maps, " << fmt(100 * o.density, 0)
     << " % " << (o.clustered ? "clustered" : "scattered") << " obstacles, start S(0, 0), one cell per robot. Plans invalid: " << invalid
     << "; plans that did not visit every reachable cell: " << incomplete << "; seeds skipped because S was walled in (its region under half the free cells): "
     << skipped << ".\n\n"
     << "| measure | filling | mean | median | min | max |\n|---|---|---|---|---|---|\n";
  auto row = [&](const std::string& measure, std::map<std::string, std::vector<double>>& m, int digits) {
    for (const char* p : {"bsa_spiral", "bsa_zigzag"}) {
      const Stats s = stats(m[p]);
      md << "| " << measure << " | " << p << " | " << fmt(s.mean, digits) << " | " << fmt(s.median, digits) << " | " << fmt(s.min, digits) << " | "
         << fmt(s.max, digits) << " |\n";
    }
  };
  row("backtracks (points returned to)", backtracks, 2);
  row("backtracking points recorded", points, 1);
  row("length (cells)", lengths, 1);
  row("turns", turns, 1);
  md << "\nZigzag needed fewer backtracks than spiral on " << zigzagFewer << " of " << o.seeds << " maps, as many on " << equal << ".\n";
  const std::string svg = histogramSvg({"backtracks per map", "backtracking points recorded per map"}, {backtracks, points});
  datasets::OutputBatch out(outDir);
  out.addInFolder(outputs[0], csv.str());
  out.addInFolder(outputs[1], md.str());
  out.addInFolder(outputs[2], svg);
  out.commit();
  return md.str();
}

std::string runTraccScenarios(const std::string& outDir) {
  struct Scenario {
    std::string name, blocked, paper;
    std::vector<int> cells;
  };
  const std::vector<Scenario> scenarios{
      {"0", "none", "71 cells visited (six rows), redundancy 45.45 % (cells sensed twice)", {}},
      {"1", "C5; C30, C40, C42, C52 around C41", "detour C4-C15-C16-C17-C6; C41 blocked in", {5, 30, 40, 42, 52}},
      {"2", "ring C49-C51, C59, C61, C71-C73 around C60; C110, C120 beside C121 (assumed)",
       "C60, C62, C121 unchecked after the flow; C121 discarded", {49, 50, 51, 59, 61, 71, 72, 73, 110, 120}}};
  std::ostringstream csv, md;
  csv << "scenario,valid,cells_entered,length,turns,detours,redundancy_rate,unsafe_cells,unchecked_cells,unreached_free_cells,end_cell\n";
  md << "# TRACC: the paper's 11×11 scenarios\n\nStart S = C1 (bottom-left), one cell per robot, flow along rows.\n\n"
     << "| scenario | blocked cells | valid | cells entered | length | turns | detours | redundancy | unsafe | never sensed | end | paper |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::vector<std::pair<std::string, std::string>> files;
  {
    std::vector<std::string> names{"results.csv", "summary.md"};
    for (const Scenario& sc : scenarios)
      for (const char* e : {".grid", ".json", ".svg"}) names.push_back("scenario-" + sc.name + e);
    datasets::checkOutputFolder(outDir, "--out", names);
  }
  for (const Scenario& sc : scenarios) {
    std::string text;
    for (int row = 10; row >= 0; --row) {
      for (int col = 0; col < 11; ++col)
        text += std::find(sc.cells.begin(), sc.cells.end(), row * 11 + col + 1) != sc.cells.end() ? '#' : '.';
      text += '\n';
    }
    Problem problem;
    problem.workspace = datasets::parseTextGrid(text, "scenario-" + sc.name + ".grid");
    problem.robots.push_back({Rational(1, 2), Point{Rational(1, 2), Rational(1, 2)}});
    const planners::PlanningContext ctx = planners::makeContext(problem);
    MetricOptions mo = defaultMetricOptions();
    mo.coverable = false;
    const RunResult r = runOnce(ctx, "tracc", {}, 0, {}, mo);
    const auto& st = r.plan.statistics;
    const int endCell = static_cast<int>(st.at("end_row")) * 11 + static_cast<int>(st.at("end_col")) + 1;
    csv << sc.name << ',' << (r.validation.valid ? 1 : 0) << ',' << st.at("covered_cells") << ',' << fmt(r.metrics.length, 1) << ','
        << r.metrics.turns << ',' << st.at("detours") << ',' << fmt(st.at("redundancy_rate"), 2) << ',' << st.at("unsafe_cells") << ','
        << st.at("unchecked_cells") << ',' << st.at("unreached_free_cells") << ",C" << endCell << '\n';
    md << "| " << sc.name << " | " << sc.blocked << " | " << (r.validation.valid ? "yes" : "no") << " | " << st.at("covered_cells") << " | "
       << fmt(r.metrics.length, 0) << " | " << r.metrics.turns << " | " << st.at("detours") << " | " << fmt(st.at("redundancy_rate"), 1) << " % | "
       << st.at("unsafe_cells") << " | " << st.at("unchecked_cells") << " | C" << endCell << " | " << sc.paper << " |\n";
    datasets::PathDocument doc;
    doc.paths = r.plan.paths;
    doc.planner = "tracc";
    files.emplace_back("scenario-" + sc.name + ".grid", text);
    files.emplace_back("scenario-" + sc.name + ".json", datasets::pathJson(doc));
    PictureContent pc{&ctx.problem.workspace, &ctx.cells, nullptr, &r.plan.paths, 0.5, "TRACC scenario " + sc.name};
    const std::string svgName = "scenario-" + sc.name + ".svg";
    files.emplace_back(svgName, pictureBytes(svgName, pc));
  }
  md << "\nOur agent sweeps every free cell (a disc robot must), where the paper's flow visits every other row and senses the rows "
        "between; its redundancy counts cells sensed twice, ours cells entered twice (docs/grid-rails.md).\n";
  datasets::OutputBatch out(outDir);
  for (const auto& [name, content] : files) out.addInFolder(name, content);
  out.addInFolder("results.csv", csv.str());
  out.addInFolder("summary.md", md.str());
  out.commit();
  return md.str();
}

namespace {

/// Line chart panels (x against y per series), plain SVG.
std::string lineChartSvg(const std::vector<std::string>& titles, const std::string& xLabel,
                         const std::vector<std::map<std::string, std::vector<std::pair<double, double>>>>& panels) {
  const int pw = 440, ph = 320, ml = 55, mb = 45, mt = 30;
  const char* colours[6] = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#e6ab02"};
  std::ostringstream svg;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << pw * panels.size() << "' height='" << ph
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n";
  for (std::size_t p = 0; p < panels.size(); ++p) {
    double x0v = 1e300, x1v = -1e300, y0v = 1e300, y1v = -1e300;
    for (const auto& [name, pts] : panels[p])
      for (auto [x, y] : pts) x0v = std::min(x0v, x), x1v = std::max(x1v, x), y0v = std::min(y0v, y), y1v = std::max(y1v, y);
    if (x1v <= x0v) x1v = x0v + 1;
    if (y1v <= y0v) y1v = y0v + 1e-3;
    const double pad = 0.05 * (y1v - y0v);
    y0v -= pad;
    y1v += pad;
    const int X = static_cast<int>(p) * pw + ml, Y = ph - mb, W = pw - ml - 20, H = ph - mb - mt;
    auto sx = [&](double x) { return X + (x - x0v) / (x1v - x0v) * W; };
    auto sy = [&](double y) { return Y - (y - y0v) / (y1v - y0v) * H; };
    svg << "<text x='" << X + W / 2 << "' y='18' text-anchor='middle'>" << titles[p] << "</text>\n";
    svg << "<rect x='" << X << "' y='" << Y - H << "' width='" << W << "' height='" << H << "' fill='none' stroke='black'/>\n";
    for (int k = 0; k <= 4; ++k) {
      const double yv = y0v + (y1v - y0v) * k / 4, xv = x0v + (x1v - x0v) * k / 4;
      svg << "<text x='" << X - 5 << "' y='" << sy(yv) + 4 << "' text-anchor='end'>" << fmt(yv, 3) << "</text>\n";
      svg << "<text x='" << sx(xv) << "' y='" << Y + 15 << "' text-anchor='middle'>" << fmt(xv, 2) << "</text>\n";
    }
    svg << "<text x='" << X + W / 2 << "' y='" << ph - 8 << "' text-anchor='middle'>" << xLabel << "</text>\n";
    std::size_t series = 0;
    for (const auto& [name, pts] : panels[p]) {
      const char* colour = colours[series % 6];
      svg << "<polyline fill='none' stroke='" << colour << "' stroke-width='2' points='";
      for (auto [x, y] : pts) svg << sx(x) << ',' << sy(y) << ' ';
      svg << "'/>\n";
      for (auto [x, y] : pts) svg << "<circle cx='" << sx(x) << "' cy='" << sy(y) << "' r='3' fill='" << colour << "'/>\n";
      svg << "<text x='" << X + 8 << "' y='" << Y - H + 16 + 15 * series << "' fill='" << colour << "'>" << name << "</text>\n";
      ++series;
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

/// results.csv, summary.md and chart.svg, written together into `outDir`; returns the summary.
std::string writeResults(const std::string& outDir, const std::string& csv, const std::string& md, const std::string& svg) {
  datasets::OutputBatch out(outDir);
  out.addInFolder("results.csv", csv);
  out.addInFolder("summary.md", md);
  out.addInFolder("chart.svg", svg);
  out.commit();
  return md;
}

/// "line N: " for a node read from a file, "" otherwise.
std::string lineOf(const YAML::Node& n) {
  const YAML::Mark m = n.Mark();
  return m.is_null() ? std::string() : "line " + std::to_string(m.line + 1) + ": ";
}

/// What a YAML node is, for messages.
std::string kindOf(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Null: return "nothing";
    case YAML::NodeType::Scalar: return "'" + n.Scalar().substr(0, 40) + "'";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Map: return "a mapping";
    default: return "nothing";
  }
}

template <class T>
const char* expectedKind() {
  if constexpr (std::is_same_v<T, int>) return "an integer";
  else if constexpr (std::is_same_v<T, double>) return "a number";
  else if constexpr (std::is_same_v<T, std::string>) return "a text";
  else return "a list of texts, e.g. [a, b]";
}

/// The value at `key` of the mapping `node` (`place` is the key as written in messages, e.g.
/// "worlds.count"), or `fallback` when the key is absent. A wrong type is an InputError naming the
/// file, the key, the line and what was expected; numbers must be finite.
template <class T>
T configValue(const YAML::Node& node, const std::string& file, const std::string& key, T fallback, const std::string& place = "") {
  const std::string where = place.empty() ? key : place;
  const YAML::Node& map = node;
  const YAML::Node v = map[key];  // const access: never adds the key
  if (!v.IsDefined()) return fallback;
  const std::string got = kindOf(v);
  bool ok = false;
  T out{};
  if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    ok = v.IsSequence();
    for (std::size_t i = 0; ok && i < v.size(); ++i) {
      if (!v[i].IsScalar()) {
        throw InputError(file, where + "[" + std::to_string(i) + "]", lineOf(v[i]) + "expected a text, got " + kindOf(v[i]));
      }
      out.push_back(v[i].Scalar());
    }
  } else {
    if (v.IsScalar()) {
      try {
        out = v.as<T>();
        ok = true;
      } catch (const YAML::Exception&) {
        ok = false;
      }
    }
    if constexpr (std::is_same_v<T, double>)
      if (ok && !std::isfinite(out)) throw InputError(file, where, lineOf(v) + "must be a finite number, got " + got);
  }
  if (!ok) throw InputError(file, where, lineOf(v) + "expected " + expectedKind<T>() + ", got " + got);
  return out;
}

/// InputError unless every key of the mapping `node` is one of `known`.
void checkKeys(const YAML::Node& node, const std::string& file, const std::string& prefix, const std::vector<std::string>& known) {
  for (const auto& kv : node) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string();
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    if (!kv.first.IsScalar())
      throw InputError(file, prefix.empty() ? "keys" : prefix.substr(0, prefix.size() - 1),
                       lineOf(kv.first) + "a key is " + kindOf(kv.first) + ": keys are names (known: " + list + ")");
    throw InputError(file, prefix + key, lineOf(kv.first) + "unknown key (known: " + list + ")");
  }
}

/// An integer value in [lo, hi].
int configInt(const YAML::Node& node, const std::string& file, const std::string& key, int fallback, int lo, int hi, const std::string& place = "") {
  const int v = configValue<int>(node, file, key, fallback, place);
  if (v < lo || v > hi)
    throw InputError(file, place.empty() ? key : place, lineOf(node[key]) + std::to_string(v) + ": must be in " + std::to_string(lo) + ".." + std::to_string(hi));
  return v;
}

/// A planner as a config names it: `name` or `name:key=value;key=value` (parameters), e.g.
/// `smooth_stc:corners=keep`. The whole text is its label in the CSV and the chart.
struct PlannerSpec {
  std::string name;
  std::map<std::string, std::string> params;
};

PlannerSpec parsePlannerSpec(const std::string& text, const std::string& configFile) {
  PlannerSpec p;
  const auto colon = text.find(':');
  p.name = text.substr(0, colon);
  if (!planners::Registry::instance().contains(p.name)) throw InputError(configFile, "planners", "unknown planner '" + p.name + "'");
  if (colon == std::string::npos) return p;
  std::stringstream rest(text.substr(colon + 1));
  std::string kv;
  while (std::getline(rest, kv, ';')) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError(configFile, "planners", "'" + text + "': parameters are key=value, separated by ';'");
    p.params[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
  return p;
}

RunResult runSpec(const planners::PlanningContext& ctx, const std::string& label, const std::string& configFile, const MetricOptions& mo) {
  const PlannerSpec spec = parsePlannerSpec(label, configFile);
  return runOnce(ctx, spec.name, spec.params, 0, {}, mo);
}

/// What every experiment config shares: the planners and the seeded polygon worlds.
struct ExperimentConfig {
  YAML::Node root;
  std::vector<std::string> planners;
  datasets::PolygonWorldSpec worlds;
  std::string shape;  ///< as written
  int count = 0;      ///< worlds: seeds 1 … count
};

ExperimentConfig loadExperimentConfig(const std::string& configFile, int defaultCount, const std::vector<std::string>& keys) {
  ExperimentConfig c;
  try {
    c.root = YAML::LoadFile(configFile);
  } catch (const YAML::BadFile&) {
    throw InputError(configFile, "file", "cannot be read");
  } catch (const YAML::Exception& e) {
    throw InputError(configFile, "line " + std::to_string(e.mark.line + 1), "YAML does not parse: " + e.msg);
  }
  std::string keyList;
  for (const std::string& k : keys) keyList += (keyList.empty() ? "" : ", ") + k;
  // an empty file or a list is not a config (yaml-cpp would turn a list into a mapping at the first
  // lookup, and every setting would silently take its default: the whole default experiment)
  if (c.root.IsNull()) throw InputError(configFile, "", "the config is empty: expected a YAML mapping with the keys " + keyList);
  if (!c.root.IsMap()) throw InputError(configFile, lineOf(c.root).empty() ? "" : lineOf(c.root).substr(0, lineOf(c.root).size() - 2),
                                        "expected a YAML mapping with the keys " + keyList + ", got " + kindOf(c.root));
  checkKeys(c.root, configFile, "", keys);
  const YAML::Node& root = c.root;
  c.planners = configValue<std::vector<std::string>>(root, configFile, "planners", {"stc", "full_stc"});
  if (c.planners.empty()) throw InputError(configFile, "planners", lineOf(root["planners"]) + "the list is empty: name at least one planner");
  for (std::size_t i = 0; i < c.planners.size(); ++i) {
    const std::string& p = c.planners[i];
    const PlannerSpec spec = parsePlannerSpec(p, configFile);
    if (p.find(',') != std::string::npos) throw InputError(configFile, "planners", "'" + p + "': no commas in a planner's label");
    if (std::find(c.planners.begin(), c.planners.begin() + static_cast<long>(i), p) != c.planners.begin() + static_cast<long>(i))
      throw InputError(configFile, "planners", "'" + p + "' is listed twice");
    try {  // the parameters are checked before anything runs
      planners::ParamSet(planners::Registry::instance().create(spec.name)->params(), spec.params, spec.name);
    } catch (const InputError& e) {
      throw InputError(configFile, "planners", "'" + p + "': " + e.what());
    }
  }
  const YAML::Node wn = root["worlds"];
  if (wn.IsDefined()) {
    if (!wn.IsMap())
      throw InputError(configFile, "worlds", lineOf(wn) + "expected a mapping (count, width, height, obstacles, shape, min_size, max_size), got " + kindOf(wn));
    checkKeys(wn, configFile, "worlds.", {"count", "width", "height", "obstacles", "shape", "min_size", "max_size"});
  }
  const YAML::Node worlds = wn.IsDefined() ? wn : YAML::Node(YAML::NodeType::Map);  // absent: every default
  c.count = configInt(worlds, configFile, "count", defaultCount, 1, 10'000, "worlds.count");
  c.worlds.width = configInt(worlds, configFile, "width", 20, 1, 10'000, "worlds.width");
  c.worlds.height = configInt(worlds, configFile, "height", 20, 1, 10'000, "worlds.height");
  c.worlds.count = configInt(worlds, configFile, "obstacles", 10, 0, 10'000, "worlds.obstacles");
  c.worlds.minSize = configValue<double>(worlds, configFile, "min_size", 1, "worlds.min_size");
  c.worlds.maxSize = configValue<double>(worlds, configFile, "max_size", 3, "worlds.max_size");
  if (!(c.worlds.minSize > 0)) throw InputError(configFile, "worlds.min_size", formatDouble(c.worlds.minSize) + ": must be > 0");
  if (c.worlds.maxSize < c.worlds.minSize)
    throw InputError(configFile, "worlds.max_size", formatDouble(c.worlds.maxSize) + ": must be at least min_size (" + formatDouble(c.worlds.minSize) + ")");
  if (c.worlds.maxSize > std::min(c.worlds.width, c.worlds.height))
    throw InputError(configFile, "worlds.max_size", formatDouble(c.worlds.maxSize) + ": an obstacle must fit the " + std::to_string(c.worlds.width) + "×" +
                                                        std::to_string(c.worlds.height) + " world");
  c.shape = configValue<std::string>(worlds, configFile, "shape", "mixed", "worlds.shape");
  if (!datasets::parseObstacleShape(c.shape, c.worlds.shape)) throw InputError(configFile, "worlds.shape", "unknown shape '" + c.shape + "'");
  return c;
}

/// The robot of radius `r` must fit the worlds and its sub-cell grid the cell limit: checked on the
/// worlds' box before anything runs (the generated worlds all have that box).
void checkRadiusOnWorlds(const Rational& r, const ExperimentConfig& c, const std::string& file, const std::string& key, const std::string& text) {
  Problem probe;
  probe.workspace.name = "the " + std::to_string(c.worlds.width) + "×" + std::to_string(c.worlds.height) + " worlds";
  probe.workspace.regions.push_back({{{0, 0}, {c.worlds.width, 0}, {c.worlds.width, c.worlds.height}, {0, c.worlds.height}}, {}});
  probe.robots.push_back({r, std::nullopt});
  try {
    planners::checkProblem(probe);
    planners::checkCellGridSize(probe);
  } catch (const InputError& e) {
    throw InputError(file, key, text + ": " + e.problem());
  }
}

/// Every YAML exception not turned into a precise message above still names the file.
template <class F>
auto withConfigErrors(const std::string& file, F&& f) {
  try {
    return f();
  } catch (const YAML::Exception& e) {
    throw InputError(file, e.mark.is_null() ? "" : "line " + std::to_string(e.mark.line + 1), "bad value: " + e.msg);
  }
}

// checkOnly: read and check the config, then return "" (nothing run, nothing written)
std::string runCoverageVsTimeConfig(const std::string& configFile, const std::string& outDir, bool checkOnly);

}  // namespace

std::string defaultConfig(const std::string& name) { return (std::filesystem::path(COVERKIT_CONFIG_DIR) / name).string(); }

namespace {

/// The map files of a config's `maps` entry: a file, or every map file of a folder (sorted).
std::vector<std::string> mapFilesOf(const std::string& entry, const std::string& configFile) {
  const fs::path base = fs::path(configFile).parent_path();
  const fs::path p = fs::path(entry).is_absolute() ? fs::path(entry) : base / entry;
  std::error_code ec;
  if (fs::is_directory(p, ec)) {
    std::vector<std::string> files;
    for (const auto& f : fs::directory_iterator(p, ec)) {
      const std::string ext = datasets::extensionOf(f.path().string());
      if (f.is_regular_file() && (ext == ".yaml" || ext == ".map" || ext == ".wkt" || ext == ".geojson" || ext == ".grid"))
        files.push_back(f.path().string());
    }
    std::sort(files.begin(), files.end());
    if (files.empty()) throw InputError(configFile, "maps", "'" + entry + "': the folder holds no map file (.yaml, .map, .wkt, .geojson, .grid)");
    return files;
  }
  if (!fs::is_regular_file(p, ec)) throw InputError(configFile, "maps", "'" + entry + "': no such map file or folder (" + p.string() + ")");
  return {p.string()};
}

/// The coverage sweeps (coverage-vs-size, -complexity, -shape, and any `sweep` config): every planner
/// of the config on seeded polygon worlds or on map files, one case per world (or map) and setting,
/// one row per planner (and repetition).
class SweepExperiment : public Experiment {
public:
  explicit SweepExperiment(const std::string& configFile) : file_(configFile) {
    ec_ = loadExperimentConfig(configFile, 10, {"title", "planners", "vary", "radii", "values", "radius", "worlds", "maps", "repetitions", "kind"});
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
                          {"planner", T::kText}, {"repetition", T::kInteger}, {"radius", T::kReal}};
    for (const Column& k : runColumns()) c.push_back(k);
    return c;
  }
  std::size_t cases() const override { return places() * settings_.size(); }
  std::string caseKey(std::size_t i) const override {
    const std::size_t place = i / settings_.size(), si = i % settings_.size();
    return (maps_.empty() ? "world=" + std::to_string(place + 1) : "map=" + fs::path(maps_[place].file).filename().string()) + " " + vary_ + "=" + values_[si];
  }
  Output run(std::size_t i) const override {
    const std::size_t place = i / settings_.size(), si = i % settings_.size();
    Problem problem;
    std::string mapName = "worlds";
    std::int64_t world = 0;
    if (maps_.empty()) {
      datasets::PolygonWorldSpec spec = settings_[si].spec;
      spec.seed = static_cast<std::uint64_t>(place + 1);
      world = static_cast<std::int64_t>(place + 1);
      problem.workspace = datasets::generatePolygonWorld(spec);
    } else {
      problem.workspace = maps_[place].workspace;
      mapName = maps_[place].file;
    }
    const Rational& r = settings_[si].radius;
    problem.robots.push_back({r, std::nullopt});
    planners::PlanningContext ctx;
    try {
      ctx = planners::makeContext(problem);
    } catch (const InputError&) {
      return {};   // the robot does not fit this world: no run
    }
    const CSpace cspace(problem.workspace, r);
    MetricOptions mo = defaultMetricOptions();
    mo.cspace = &cspace;
    std::vector<Row> rows;
    for (const std::string& p : ec_.planners)
      for (int rep = 0; rep < repetitions_; ++rep) {
        const RunResult res = runSpec(ctx, p, file_, mo);
        Row row{mapName, world, vary_, values_[si], p, static_cast<std::int64_t>(rep), r.get_d()};
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
      double coverage = 0, overlap = 0, turns = 0, angle = 0, minCoverage = 1;
      std::size_t n = 0, invalid = 0, failed = 0;
    };
    std::map<std::string, std::vector<Acc>> acc;   // planner → setting
    for (const std::string& p : ec_.planners) acc[p].resize(settings_.size());
    for (const Row& row : t.rows) {
      const std::size_t si = static_cast<std::size_t>(t.real(row, "case")) % settings_.size();
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
    md << (vary_ == "radius" ? std::string("robot radius varied") : "r = " + fixedRadius_) << "; sub-cells 2r; default start. Coverage: covered area / "
       << "coverable area (the start's C-free component ⊕ disc). Overlap: swept area counted with multiplicity / covered area − 1. "
       << "Plans that did not succeed count as coverage 0; invalid plans are counted and left out.\n\n"
       << "| planner | " << vary_ << " | plans | mean coverage | min coverage | mean overlap | mean turns | mean turning angle (°) | not planned | invalid |\n"
       << "|---|---|---|---|---|---|---|---|---|---|\n";
    std::map<std::string, std::vector<std::pair<double, double>>> coverageSeries, overlapSeries, turnSeries, angleSeries;
    for (const std::string& p : ec_.planners)
      for (std::size_t si = 0; si < settings_.size(); ++si) {
        const Acc& a = acc[p][si];
        const std::size_t valid = a.n - a.failed;
        const double mean = a.n ? a.coverage / static_cast<double>(a.n) : 0, overlap = valid ? a.overlap / static_cast<double>(valid) : 0;
        const double turns = valid ? a.turns / static_cast<double>(valid) : 0, angle = valid ? a.angle / static_cast<double>(valid) : 0;
        md << "| " << p << " | " << values_[si] << " | " << a.n << " | " << fmt(mean, 4) << " | " << fmt(a.n ? a.minCoverage : 0, 4) << " | "
           << fmt(overlap, 3) << " | " << fmt(turns, 1) << " | " << fmt(angle, 0) << " | " << a.failed << " | " << a.invalid << " |\n";
        const double x = vary_ == "radius" ? settings_[si].radius.get_d() : vary_ == "obstacles" ? static_cast<double>(settings_[si].spec.count)
                                                                                                   : static_cast<double>(si);
        coverageSeries[p].emplace_back(x, mean);
        overlapSeries[p].emplace_back(x, overlap);
        turnSeries[p].emplace_back(x, turns);
        angleSeries[p].emplace_back(x, angle);
      }
    if (vary_ == "shape") {
      md << "\nx positions in the chart: ";
      for (std::size_t si = 0; si < values_.size(); ++si) md << (si ? ", " : "") << si << " = " << values_[si];
      md << ".\n";
    }
    const std::string xLabel = vary_ == "radius" ? "robot radius r" : vary_ == "obstacles" ? "obstacles per world" : "obstacle shape (see summary)";
    const std::string svg = lineChartSvg({"mean coverage of the coverable region", "mean overlap", "mean turns", "mean total turning angle (°)"},
                                         xLabel, {coverageSeries, overlapSeries, turnSeries, angleSeries});
    return {{"summary.md", md.str()}, {"chart.svg", svg}};
  }

private:
  std::size_t places() const { return maps_.empty() ? static_cast<std::size_t>(ec_.count) : maps_.size(); }
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

std::string runCoverageVsTimeConfig(const std::string& configFile, const std::string& outDir, bool checkOnly) {
  const ExperimentConfig ec = loadExperimentConfig(configFile, 5, {"planners", "radius", "speed", "steps", "worlds"});
  const YAML::Node& cfg = ec.root;
  const std::vector<std::string>& plannerNames = ec.planners;
  const std::string rText = configValue<std::string>(cfg, configFile, "radius", "0.25");
  const Rational r = parseRational(rText, configFile + ": radius", rText);
  if (r <= 0) throw InputError(configFile, "radius", rText + ": must be > 0");
  checkRadiusOnWorlds(r, ec, configFile, "radius", rText);
  const double speed = configValue<double>(cfg, configFile, "speed", 0.2);
  if (!(speed > 0)) throw InputError(configFile, "speed", "must be > 0");
  const int steps = configValue<int>(cfg, configFile, "steps", 12);
  if (steps < 1 || steps > 1000) throw InputError(configFile, "steps", std::to_string(steps) + ": must be in 1..1000");
  if (checkOnly) return "";
  datasets::checkOutputFolder(outDir, "--out", {"results.csv", "summary.md", "chart.svg"});
  datasets::PolygonWorldSpec spec = ec.worlds;
  const std::string& shape = ec.shape;
  const int count = ec.count;

  std::ostringstream csv;
  csv << "world,planner,valid,time_s,coverage,coverage_error\n";
  // coverage at step k of each world, per planner; the common time grid is per world (the slowest
  // planner's time split in `steps`), reported as a fraction of it and in seconds
  std::map<std::string, std::vector<double>> meanByStep;
  std::map<std::string, double> meanTotalTime;
  std::size_t invalid = 0;
  for (int seed = 1; seed <= count; ++seed) {
    spec.seed = static_cast<std::uint64_t>(seed);
    const Workspace world = datasets::generatePolygonWorld(spec);
    Problem problem;
    problem.workspace = world;
    problem.robots.push_back({r, std::nullopt});
    const planners::PlanningContext ctx = planners::makeContext(problem);
    const CSpace cspace(world, r);
    MetricOptions mo = defaultMetricOptions();
    mo.cspace = &cspace;
    mo.speed = speed;
    std::map<std::string, RunResult> runs;
    double horizon = 0;
    for (const std::string& p : plannerNames) {
      runs[p] = runSpec(ctx, p, configFile, mo);
      invalid += !runs[p].validation.valid;
      horizon = std::max(horizon, runs[p].metrics.length / speed);
      meanTotalTime[p] += runs[p].metrics.length / speed / count;
    }
    MetricOptions raster = mo;  // prefixes: covered area only, rasterised with its bound
    raster.coverable = false;
    raster.exactAreaMaxSegments = raster.exactAreaMaxSegmentsClear = 0;
    raster.rasterMaxPixels = 250'000;
    for (const std::string& p : plannerNames) {
      const RunResult& res = runs[p];
      auto& series = meanByStep[p];
      series.resize(static_cast<std::size_t>(steps) + 1, 0.0);
      for (int k = 0; k <= steps; ++k) {
        const double t = horizon * k / steps;
        double coverage = 0, error = 0;
        if (res.validation.valid && res.metrics.coverableArea > 0) {
          if (t >= res.metrics.length / speed) {
            coverage = res.metrics.coverableCoverage;
          } else if (k > 0) {
            const Metrics m = computeMetrics(ctx.problem, ctx.cells, {prefix(res.plan.paths[0], t * speed)}, raster);
            coverage = m.coveredArea / res.metrics.coverableArea;
            error = m.areaCoverageError * m.freeArea / res.metrics.coverableArea;
          }
        }
        series[static_cast<std::size_t>(k)] += coverage / count;
        csv << seed << ',' << p << ',' << (res.validation.valid ? 1 : 0) << ',' << fmt(t, 1) << ',' << fmt(coverage, 5) << ',' << fmt(error, 5) << '\n';
      }
    }
  }
  std::ostringstream md;
  md << "# Coverage against time\n\n" << count << " seeded " << spec.width << "×" << spec.height << " polygon worlds, " << spec.count << " " << shape
     << " obstacles, r = " << rText << ", speed " << speed << " m/s, default start. Each world's time axis is split in " << steps
     << " steps up to the slowest planner's finish; coverage of the coverable region, averaged over the worlds (a planner that has "
     << "finished keeps its final coverage). Invalid plans: " << invalid << ".\n\n| planner | mean time to finish (s) |";
  for (int k = 1; k <= steps; ++k) md << " " << fmt(100.0 * k / steps, 0) << " % |";
  md << "\n|---|---|";
  for (int k = 1; k <= steps; ++k) md << "---|";
  md << "\n";
  std::map<std::string, std::vector<std::pair<double, double>>> chart;
  for (const std::string& p : plannerNames) {
    md << "| " << p << " | " << fmt(meanTotalTime[p], 0) << " |";
    for (int k = 1; k <= steps; ++k) md << " " << fmt(meanByStep[p][static_cast<std::size_t>(k)], 3) << " |";
    md << "\n";
    for (int k = 0; k <= steps; ++k) chart[p].emplace_back(100.0 * k / steps, meanByStep[p][static_cast<std::size_t>(k)]);
  }
  const std::string svg = lineChartSvg({"mean coverage of the coverable region"}, "time, % of the slowest planner's", {chart});
  return writeResults(outDir, csv.str(), md.str(), svg);
}
}  // namespace

std::string runCoverageVsTime(const std::string& configFile, const std::string& outDir) {
  return withConfigErrors(configFile, [&] { return runCoverageVsTimeConfig(configFile, outDir, false); });
}
void checkCoverageVsTimeConfig(const std::string& configFile) {
  withConfigErrors(configFile, [&] { return runCoverageVsTimeConfig(configFile, "", true); });
}

std::string runDecompositionExperiment(const DecompositionExperimentOptions& o, const std::string& outDir) {
  if (o.seeds < 1 || o.seeds > kDecompositionMaxSeeds)
    throw InputError("--seeds", std::to_string(o.seeds), "must be 1 to " + std::to_string(kDecompositionMaxSeeds));
  datasets::checkOutputFolder(outDir, "--out", {"results.csv", "summary.md", "chart.svg"});
  const std::vector<int> holeCounts{0, 1, 2, 5, 10, 15, 20, 30};
  const std::vector<datasets::ObstacleShape> shapes{datasets::ObstacleShape::kRotatedRectangle, datasets::ObstacleShape::kConvex,
                                                    datasets::ObstacleShape::kStar, datasets::ObstacleShape::kDisc};
  const std::vector<std::string> shapeNames{"rotated", "convex", "stars", "discs"};
  const std::vector<std::pair<std::string, std::map<std::string, std::string>>> plannerRuns{
      {"boustrophedon", {{"decomposition", "boustrophedon"}}},
      {"boustrophedon(trapezoidal)", {{"decomposition", "trapezoidal"}}},
      {"full_stc", {}},
      {"smooth_stc", {}}};
  const Rational r(1, 4);
  std::ostringstream csv;
  csv << "world,holes,shape,holes_placed,bcd_cells,tcd_cells,cspace_s,bcd_s,tcd_s,planner,status,valid,plan_s,coverable_coverage,length,turns,"
         "turning_angle_deg\n";
  struct Acc {
    std::vector<double> coverage, length, turns, seconds;
    std::size_t invalid = 0, failed = 0;
  };
  struct Row {
    std::vector<double> bcd, tcd, bcdSeconds, tcdSeconds, cspaceSeconds, placed;
    std::map<std::string, Acc> planners;
  };
  std::vector<Row> rows(holeCounts.size());
  for (std::size_t hi = 0; hi < holeCounts.size(); ++hi)
    for (int seed = 1; seed <= o.seeds; ++seed) {
      datasets::PolygonWorldSpec spec;
      spec.width = 20;
      spec.height = 20;
      spec.count = holeCounts[hi];
      spec.minSize = 1;
      spec.maxSize = 3;
      const std::size_t si = static_cast<std::size_t>(seed) % shapes.size();
      spec.shape = shapes[si];
      spec.seed = static_cast<std::uint64_t>(seed);
      const Workspace world = datasets::generatePolygonWorld(spec);
      std::size_t placed = 0;
      for (const Region& reg : world.regions) placed += reg.holes.size();
      Problem problem;
      problem.workspace = world;
      problem.robots.push_back({r, std::nullopt});
      const planners::Decomposed bcd = planners::runDecomposition("boustrophedon", problem, {});
      const planners::Decomposed tcd = planners::runDecomposition("trapezoidal", problem, {});
      Row& row = rows[hi];
      row.bcd.push_back(static_cast<double>(bcd.cells.cells.size()));
      row.tcd.push_back(static_cast<double>(tcd.cells.cells.size()));
      row.bcdSeconds.push_back(bcd.decomposeSeconds);
      row.tcdSeconds.push_back(tcd.decomposeSeconds);
      row.cspaceSeconds.push_back(bcd.cspaceSeconds);
      row.placed.push_back(static_cast<double>(placed));
      planners::PlanningContext ctx;
      try {
        ctx = planners::makeContext(problem);
      } catch (const InputError&) {
        continue;
      }
      const CSpace cspace(world, r);
      MetricOptions mo = defaultMetricOptions();
      mo.cspace = &cspace;
      for (const auto& [label, params] : plannerRuns) {
        const std::string name = label.substr(0, label.find('('));
        const RunResult res = runOnce(ctx, name, params, 0, {}, mo);
        double planSeconds = 0;
        for (const auto& [phase, sec] : res.plan.timings) planSeconds += sec;
        const Metrics& m = res.metrics;
        csv << seed << ',' << holeCounts[hi] << ',' << shapeNames[si] << ',' << placed << ',' << bcd.cells.cells.size() << ','
            << tcd.cells.cells.size() << ',' << fmt(bcd.cspaceSeconds, 4) << ',' << fmt(bcd.decomposeSeconds, 4) << ',' << fmt(tcd.decomposeSeconds, 4)
            << ',' << label << ',' << toString(res.plan.status) << ',' << (res.validation.valid ? 1 : 0) << ',' << fmt(planSeconds, 4) << ','
            << fmt(m.coverableCoverage, 5) << ',' << fmt(m.length, 3) << ',' << m.turns << ',' << fmt(m.turningAngleDeg, 1) << '\n';
        Acc& a = row.planners[label];
        if (!succeeded(res.plan.status)) {
          ++a.failed;
          a.coverage.push_back(0);
          continue;
        }
        if (!res.validation.valid) {
          ++a.invalid;
          continue;
        }
        a.coverage.push_back(m.coverableCoverage);
        a.length.push_back(m.length);
        a.turns.push_back(static_cast<double>(m.turns));
        a.seconds.push_back(planSeconds);
      }
    }
  std::ostringstream md;
  md << "# Decompositions: boustrophedon against trapezoidal, and boustrophedon coverage against the STC family\n\n"
     << o.seeds << " seeded 20×20 polygon worlds per hole count (shapes in turn: rotated rectangles, convex polygons, stars, discs; 1-3 m; "
     << "the generator places what fits, `holes placed`), r = 0.25, sweep direction 0°. Cells of the exact C-free; times in seconds on this "
     << "machine (C-space, then the decomposition alone). Coverage: of the coverable region (the start's C-free component ⊕ disc); plans that "
     << "did not succeed count 0, invalid plans are counted and left out. Plan time includes each planner's own C-space or cells.\n\n"
     << "| holes asked | holes placed | BCD cells | TCD cells | C-space s | BCD s | TCD s |\n|---|---|---|---|---|---|---|\n";
  std::map<std::string, std::vector<std::pair<double, double>>> cellSeries, timeSeries, coverageSeries, turnSeries;
  for (std::size_t hi = 0; hi < holeCounts.size(); ++hi) {
    const Row& row = rows[hi];
    const double x = stats(row.placed).mean;
    md << "| " << holeCounts[hi] << " | " << fmt(x, 1) << " | " << fmt(stats(row.bcd).mean, 1) << " | " << fmt(stats(row.tcd).mean, 1) << " | "
       << fmt(stats(row.cspaceSeconds).mean, 3) << " | " << fmt(stats(row.bcdSeconds).mean, 3) << " | " << fmt(stats(row.tcdSeconds).mean, 3) << " |\n";
    cellSeries["boustrophedon"].emplace_back(x, stats(row.bcd).mean);
    cellSeries["trapezoidal"].emplace_back(x, stats(row.tcd).mean);
    timeSeries["C-space"].emplace_back(x, stats(row.cspaceSeconds).mean);
    timeSeries["boustrophedon"].emplace_back(x, stats(row.bcdSeconds).mean);
    timeSeries["trapezoidal"].emplace_back(x, stats(row.tcdSeconds).mean);
  }
  md << "\n| holes asked | planner | plans | mean coverage | min coverage | mean length | mean turns | mean plan s | not planned | invalid |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n";
  std::map<std::string, Acc> all;
  for (std::size_t hi = 0; hi < holeCounts.size(); ++hi)
    for (const auto& [label, params] : plannerRuns) {
      const auto it = rows[hi].planners.find(label);
      if (it == rows[hi].planners.end()) continue;
      const Acc& a = it->second;
      const Stats c = stats(a.coverage);
      md << "| " << holeCounts[hi] << " | " << label << " | " << a.coverage.size() << " | " << fmt(c.mean, 4) << " | " << fmt(c.min, 4) << " | "
         << fmt(stats(a.length).mean, 1) << " | " << fmt(stats(a.turns).mean, 1) << " | " << fmt(stats(a.seconds).mean, 3) << " | " << a.failed
         << " | " << a.invalid << " |\n";
      coverageSeries[label].emplace_back(stats(rows[hi].placed).mean, c.mean);
      turnSeries[label].emplace_back(stats(rows[hi].placed).mean, stats(a.turns).mean);
      Acc& t = all[label];
      t.coverage.insert(t.coverage.end(), a.coverage.begin(), a.coverage.end());
      t.length.insert(t.length.end(), a.length.begin(), a.length.end());
      t.turns.insert(t.turns.end(), a.turns.begin(), a.turns.end());
      t.seconds.insert(t.seconds.end(), a.seconds.begin(), a.seconds.end());
      t.failed += a.failed;
      t.invalid += a.invalid;
    }
  md << "\nAll worlds:\n\n| planner | plans | mean coverage | min coverage | mean length | mean turns | mean plan s | not planned | invalid |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& [label, params] : plannerRuns) {
    const Acc& a = all[label];
    const Stats c = stats(a.coverage);
    md << "| " << label << " | " << a.coverage.size() << " | " << fmt(c.mean, 4) << " | " << fmt(c.min, 4) << " | " << fmt(stats(a.length).mean, 1)
       << " | " << fmt(stats(a.turns).mean, 1) << " | " << fmt(stats(a.seconds).mean, 3) << " | " << a.failed << " | " << a.invalid << " |\n";
  }
  const std::string svg = lineChartSvg({"cells", "seconds", "mean coverage of the coverable region", "mean turns"}, "holes placed",
                                       {cellSeries, timeSeries, coverageSeries, turnSeries});
  return writeResults(outDir, csv.str(), md.str(), svg);
}

}  // namespace coverkit::experiments
