#pragma once
// Reading the experiments' YAML configs (experiments/configs/): typed values with messages that
// name the file, the key and the line; the planners and seeded worlds most configs share. Internal
// to the experiments; every kind reads its config with these, so a bad config fails the same way
// whatever the kind (InputError, exit 2, before anything runs).
#include "runner.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/types.h>

#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace coverkit::experiments {

/// "line N: " for a node read from a file, "" otherwise.
std::string lineOf(const YAML::Node& n);

/// What a YAML node is, for messages.
std::string kindOf(const YAML::Node& n);

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
void checkKeys(const YAML::Node& node, const std::string& file, const std::string& prefix, const std::vector<std::string>& known);

/// An integer value in [lo, hi].
int configInt(const YAML::Node& node, const std::string& file, const std::string& key, int fallback, int lo, int hi, const std::string& place = "");

/// A planner as a config names it: `name` or `name:key=value;key=value` (parameters), e.g.
/// `smooth_stc:corners=keep`, then any path processors after '+', each `name` or
/// `name:key=value;...`, e.g. `stc+fillet:max_radius=0.25` (values with a '+' cannot be written
/// here). The whole text is its label in the CSV and the chart.
struct PlannerSpec {
  std::string name;
  std::map<std::string, std::string> params;
  std::vector<optimise::PostStep> post;
};
PlannerSpec parsePlannerSpec(const std::string& text, const std::string& configFile);

/// Runs the planner a config names (`label`, see PlannerSpec) once on `ctx`.
RunResult runSpec(const planners::PlanningContext& ctx, const std::string& label, const std::string& configFile, const MetricOptions& mo);

/// The config file's root: a YAML mapping whose keys are all in `keys` (else InputError).
YAML::Node loadConfigRoot(const std::string& configFile, const std::vector<std::string>& keys);

/// What every experiment config shares: the planners and the seeded polygon worlds.
struct ExperimentConfig {
  YAML::Node root;
  std::vector<std::string> planners;
  datasets::PolygonWorldSpec worlds;
  std::string shape;  ///< as written
  int count = 0;      ///< the number of worlds
  std::vector<std::uint64_t> seeds;   ///< the worlds' seeds: `worlds.seeds`, or 1 … count
};

/// The config's root (loadConfigRoot), its planners (default stc, full_stc; each checked with its
/// parameters) and its `worlds` (default count `defaultCount`).
ExperimentConfig loadExperimentConfig(const std::string& configFile, int defaultCount, const std::vector<std::string>& keys);

/// The robot of radius `r` must fit the worlds and its sub-cell grid the cell limit: checked on the
/// worlds' box before anything runs (the generated worlds all have that box).
void checkRadiusOnWorlds(const Rational& r, const ExperimentConfig& c, const std::string& file, const std::string& key, const std::string& text);

/// Every YAML exception not turned into a precise message above still names the file.
template <class F>
auto withConfigErrors(const std::string& file, F&& f) {
  try {
    return f();
  } catch (const YAML::Exception& e) {
    throw InputError(file, e.mark.is_null() ? "" : "line " + std::to_string(e.mark.line + 1), "bad value: " + e.msg);
  }
}

/// Settings given on the command line instead of in the config (`--seeds 50` for the key `seeds`):
/// key → value as typed.
using ConfigOverrides = std::map<std::string, std::string>;

/// The error about a setting: "--KEY: TEXT: WHY" when the command line gave it, "FILE: KEY: TEXT:
/// WHY" when the config did.
InputError settingError(const std::string& file, const ConfigOverrides& overrides, const std::string& key, const std::string& text, const std::string& why);

/// The value of `key`: its override if given (InputError naming --KEY when it is not a T), else
/// configValue.
template <class T>
T settingValue(const YAML::Node& root, const std::string& file, const ConfigOverrides& overrides, const std::string& key, T fallback) {
  const auto it = overrides.find(key);
  if (it == overrides.end()) return configValue<T>(root, file, key, fallback);
  const std::string& text = it->second;
  if constexpr (std::is_same_v<T, std::string>) {
    return text;
  } else {
    char* end = nullptr;
    errno = 0;
    T v{};
    if constexpr (std::is_same_v<T, int>) {
      const long l = std::strtol(text.c_str(), &end, 10);
      v = static_cast<int>(l);
      if (l != v) errno = ERANGE;
    } else {
      v = std::strtod(text.c_str(), &end);   // nan and inf are read: the kind's range check names them
    }
    if (text.empty() || *end != '\0' || errno == ERANGE) throw InputError("--" + key, text, std::string("expected ") + expectedKind<T>());
    return v;
  }
}

/// The map files of a config's `maps` entry: a file, or every map file of a folder (sorted).
std::vector<std::string> mapFilesOf(const std::string& entry, const std::string& configFile);

}  // namespace coverkit::experiments
