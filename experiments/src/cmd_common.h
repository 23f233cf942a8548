#pragma once
// What several `coverkit` subcommands share: the map and speed options, KEY=VALUE parameters, the
// problem read from the map options, and the progress bar.
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/path.h>
#include <coverkit/planners/planner.h>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace coverkit::experiments {

/// --map, --radius, --cell-size, --unknown-free (plan, evaluate, render, cspace, decompose).
struct MapArgs {
  std::string map, radius, cellSize;
  bool unknownFree = false;
};
void addMapOptions(CLI::App* c, MapArgs& m, bool needRadius);

/// --timings, --threads, --metrics (plan, evaluate).
struct SpeedArgs {
  bool timings = false;
  unsigned threads = 0;
  std::string metrics;   ///< basic or full
  double vMax = 0.5, aMax = 0.5, omegaMax = 1.5;   ///< the robot of robot_time_s (MetricOptions)
};
/// `defaultMetrics`: what --metrics is when not given (plan: basic, evaluate: full).
void addSpeedOptions(CLI::App* c, SpeedArgs& s, const std::string& defaultMetrics);

/// The metric options of --metrics: `full`, every metric of docs/metrics.md; `basic`, all but the
/// coverable region (two C-spaces, nearly all of the time on real maps). The exact validator runs
/// either way.
MetricOptions metricOptionsFor(const SpeedArgs& s);

/// --param KEY=VALUE... as a map; InputError for an entry without a key or '='.
std::map<std::string, std::string> parseParams(const std::vector<std::string>& kv);

/// The problem of one robot of radius `radius` (and `start`, unless empty) on the map `map`.
Problem makeProblem(const std::string& map, const std::string& radius, const std::string& start, bool unknownFree,
                    const std::string& cellSize);
/// A team from the command line: one robot per --start (in order), `robots` in all when larger (0:
/// as many as starts, at least one), all of the first robot's radius; robots without a start are
/// placed by makeContext (planners::spreadStarts). The scenario's moving obstacles, when given.
void addTeam(Problem& problem, const std::vector<std::string>& starts, int robots, const std::string& scenario);
/// planners::makeContext, its problem checks' errors about the scenario ("--scenario") naming the
/// scenario file instead (when there is one).
/// `teamStarts = false` (evaluate): starts too near each other or to an obstacle are the validator's
/// to report (robot_robot, robot_obstacle), not bad input.
planners::PlanningContext makeContext(Problem problem, const std::string& scenario, bool teamStarts = true);

/// A progress bar on stderr, shown only on a terminal and only once a run has taken a second.
class Progress {
public:
  explicit Progress(std::size_t total);
  void step(const std::string& what);
  ~Progress();

private:
  std::size_t total_, done_ = 0;
  std::chrono::steady_clock::time_point t0_;
  bool tty_, shown_ = false;
};

}  // namespace coverkit::experiments
