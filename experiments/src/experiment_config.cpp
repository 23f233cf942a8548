// Reading the experiments' configs. See experiment_config.h.
#include "experiment_config.h"

#include <coverkit/datasets/readers.h>
#include <coverkit/planners/registry.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace coverkit::experiments {

namespace fs = std::filesystem;

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

int configInt(const YAML::Node& node, const std::string& file, const std::string& key, int fallback, int lo, int hi, const std::string& place) {
  const int v = configValue<int>(node, file, key, fallback, place);
  if (v < lo || v > hi)
    throw InputError(file, place.empty() ? key : place, lineOf(node[key]) + std::to_string(v) + ": must be in " + std::to_string(lo) + ".." + std::to_string(hi));
  return v;
}

PlannerSpec parsePlannerSpec(const std::string& label, const std::string& configFile) {
  PlannerSpec p;
  const auto plus = label.find('+');
  const std::string text = label.substr(0, plus);
  if (plus != std::string::npos) {
    std::stringstream steps(label.substr(plus + 1));
    std::string step;
    while (std::getline(steps, step, '+')) {
      try {
        p.post.push_back(optimise::parsePostStep(step));
        optimise::checkPostSteps({p.post.back()});
      } catch (const InputError& e) {
        throw InputError(configFile, "planners", "'" + label + "': " + e.what());
      }
    }
    if (p.post.empty()) throw InputError(configFile, "planners", "'" + label + "': no path processor after '+'");
  }
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
  return runOnce(ctx, spec.name, spec.params, 0, {}, mo, spec.post);
}

YAML::Node loadConfigRoot(const std::string& configFile, const std::vector<std::string>& keys) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(configFile);
  } catch (const YAML::BadFile&) {
    throw InputError(configFile, "file", "cannot be read");
  } catch (const YAML::Exception& e) {
    throw InputError(configFile, "line " + std::to_string(e.mark.line + 1), "YAML does not parse: " + e.msg);
  }
  std::string keyList;
  for (const std::string& k : keys) keyList += (keyList.empty() ? "" : ", ") + k;
  // an empty file or a list is not a config (yaml-cpp would turn a list into a mapping at the first
  // lookup, and every setting would silently take its default: the whole default experiment)
  if (root.IsNull()) throw InputError(configFile, "", "the config is empty: expected a YAML mapping with the keys " + keyList);
  if (!root.IsMap()) throw InputError(configFile, lineOf(root).empty() ? "" : lineOf(root).substr(0, lineOf(root).size() - 2),
                                        "expected a YAML mapping with the keys " + keyList + ", got " + kindOf(root));
  checkKeys(root, configFile, "", keys);
  return root;
}

ExperimentConfig loadExperimentConfig(const std::string& configFile, int defaultCount, const std::vector<std::string>& keys) {
  ExperimentConfig c;
  c.root = loadConfigRoot(configFile, keys);
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
      throw InputError(configFile, "worlds", lineOf(wn) + "expected a mapping (count or seeds, width, height, obstacles, shape, min_size, max_size), got " + kindOf(wn));
    checkKeys(wn, configFile, "worlds.", {"count", "seeds", "width", "height", "obstacles", "shape", "min_size", "max_size"});
  }
  const YAML::Node worlds = wn.IsDefined() ? wn : YAML::Node(YAML::NodeType::Map);  // absent: every default
  c.count = configInt(worlds, configFile, "count", defaultCount, 1, 10'000, "worlds.count");
  if (worlds["seeds"].IsDefined()) {   // the worlds' seeds listed, instead of 1 … count
    if (worlds["count"].IsDefined()) throw InputError(configFile, "worlds.seeds", lineOf(worlds["seeds"]) + "give count or seeds, not both");
    for (const std::string& text : configValue<std::vector<std::string>>(worlds, configFile, "seeds", {}, "worlds.seeds")) {
      char* end = nullptr;
      errno = 0;
      const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
      if (text.empty() || text[0] == '-' || *end != '\0' || errno == ERANGE || v > 9'223'372'036'854'775'807ULL)
        throw InputError(configFile, "worlds.seeds", lineOf(worlds["seeds"]) + text + ": not a seed (an integer 0 … 2^63 - 1)");
      if (std::find(c.seeds.begin(), c.seeds.end(), v) != c.seeds.end())
        throw InputError(configFile, "worlds.seeds", lineOf(worlds["seeds"]) + text + ": listed twice");
      c.seeds.push_back(static_cast<std::uint64_t>(v));
    }
    if (c.seeds.empty() || c.seeds.size() > 10'000)
      throw InputError(configFile, "worlds.seeds", lineOf(worlds["seeds"]) + "give 1 to 10000 seeds");
    c.count = static_cast<int>(c.seeds.size());
  } else {
    for (int k = 1; k <= c.count; ++k) c.seeds.push_back(static_cast<std::uint64_t>(k));
  }
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

InputError settingError(const std::string& file, const ConfigOverrides& overrides, const std::string& key, const std::string& text, const std::string& why) {
  if (overrides.count(key)) return InputError("--" + key, text, why);
  return InputError(file, key, text + ": " + why);
}

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

}  // namespace coverkit::experiments
