// What several `coverkit` subcommands share. See cmd_common.h.
#include "cmd_common.h"

#include "runner.h"

#include <coverkit/datasets/readers.h>
#include <coverkit/datasets/scenario.h>
#include <coverkit/geometry/error.h>

#include <algorithm>
#include <iostream>
#include <optional>
#include <unistd.h>

namespace coverkit::experiments {

void addMapOptions(CLI::App* c, MapArgs& m, bool needRadius) {
  c->add_option("--map", m.map, "map file (.yaml ROS map, .map Moving AI, .wkt, .geojson, .grid)")->required();
  auto* r = c->add_option("--radius", m.radius, "robot disc radius r (map units); sub-cells are 2r unless --cell-size");
  if (needRadius) r->required();
  c->add_option("--cell-size", m.cellSize, "sub-cell size D (default 2r)");
  c->add_flag("--unknown-free", m.unknownFree, "ROS maps: treat unknown pixels as free (default: obstacle)");
}

void addSpeedOptions(CLI::App* c, SpeedArgs& s, const std::string& defaultMetrics) {
  c->add_flag("--timings", s.timings, "print wall and CPU time per phase and the peak memory on stderr");
  c->add_option("--threads", s.threads, "threads for the phases that split (Smooth-STC's sweeps, validation of long paths, the metrics' rasters, the "
                                        "coverable region's two C-spaces); 0, the default: every core. "
                                        "The results do not depend on it")
      ->check(CLI::Range(0u, 1024u));
  s.metrics = defaultMetrics;
  c->add_option("--metrics", s.metrics, "basic (sub-cells, length, turns, time: milliseconds), area (and the covered area), or full "
                                        "(and the coverable region, which needs two more C-spaces): docs/metrics.md; default " +
                                            defaultMetrics + ". The exact validator runs at every level")
      ->check(CLI::IsMember({"basic", "area", "full"}));
  c->add_option("--v-max", s.vMax, "robot_time_s: the differential-drive robot's top speed (m/s, default 0.5)")->check(CLI::PositiveNumber);
  c->add_option("--a-max", s.aMax, "robot_time_s: its acceleration and braking (m/s^2, default 0.5)")->check(CLI::PositiveNumber);
  c->add_option("--omega-max", s.omegaMax, "robot_time_s: its top turning rate (rad/s, default 1.5)")->check(CLI::PositiveNumber);
}

MetricOptions metricOptionsFor(const SpeedArgs& s) {
  MetricOptions o = metricOptionsForLevel(s.metrics);
  o.vMax = s.vMax;
  o.aMax = s.aMax;
  o.omegaMax = s.omegaMax;
  return o;
}

std::map<std::string, std::string> parseParams(const std::vector<std::string>& kv) {
  std::map<std::string, std::string> out;
  for (const std::string& s : kv) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--param", s, "expected KEY=VALUE");
    out[s.substr(0, eq)] = s.substr(eq + 1);
  }
  return out;
}

Problem makeProblem(const std::string& map, const std::string& radius, const std::string& start, bool unknownFree,
                    const std::string& cellSize) {
  Problem p;
  const Rational r = parseRational(radius, "--radius", radius);
  if (r <= 0) throw InputError("--radius", radius, "robot radius must be > 0");
  Robot robot{r, std::nullopt};
  if (!start.empty()) robot.start = parsePoint(start, "--start");
  if (!cellSize.empty()) p.cellSize = parseRational(cellSize, "--cell-size", cellSize);
  datasets::MapOptions mo;
  mo.unknownIsFree = unknownFree;
  p.workspace = datasets::loadMap(map, mo);
  p.robots.push_back(robot);
  return p;
}

void addTeam(Problem& problem, const std::vector<std::string>& starts, int robots, const std::string& scenario) {
  if (robots < 0) throw InputError("--robots", std::to_string(robots), "must be >= 1");
  if (robots > 1000) throw InputError("--robots", std::to_string(robots), "at most 1000 robots");
  if (robots > 0 && static_cast<std::size_t>(robots) < starts.size())
    throw InputError("--robots", std::to_string(robots), "fewer robots than --start options (" + std::to_string(starts.size()) + ")");
  const std::size_t n = std::max<std::size_t>({1, starts.size(), static_cast<std::size_t>(robots)});
  const Robot first = problem.robots.at(0);
  problem.robots.assign(n, Robot{first.radius, std::nullopt});
  for (std::size_t i = 0; i < starts.size(); ++i) problem.robots[i].start = parsePoint(starts[i], "--start");
  if (!scenario.empty()) problem.movingObstacles = datasets::readScenario(scenario);
}

planners::PlanningContext makeContext(Problem problem, const std::string& scenario, bool teamStarts) {
  try {
    return planners::makeContext(std::move(problem), teamStarts);
  } catch (const InputError& e) {
    if (e.file() == "--scenario" && !scenario.empty()) throw InputError(scenario, e.place(), e.problem());
    throw;
  }
}

Progress::Progress(std::size_t total) : total_(total), t0_(std::chrono::steady_clock::now()), tty_(isatty(2) != 0) {}

void Progress::step(const std::string& what) {
  ++done_;
  if (!tty_ || std::chrono::steady_clock::now() - t0_ < std::chrono::seconds(1)) return;
  const int width = 30, filled = static_cast<int>(width * std::min(done_, total_) / std::max<std::size_t>(total_, 1));
  std::cerr << "\r[" << std::string(static_cast<std::size_t>(filled), '#') << std::string(static_cast<std::size_t>(width - filled), ' ') << "] "
            << done_ << "/" << total_ << " " << what.substr(0, 40) << "\033[K" << std::flush;
  shown_ = true;
}

Progress::~Progress() {
  if (shown_) std::cerr << "\n";
}

}  // namespace coverkit::experiments
