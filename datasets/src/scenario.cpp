// Scenario files. See scenario.h; the format is in docs/formats.md. Decisions:
//  * `format` must be "coverkit.scenario/1"; `dynamic_obstacles` (optional: none) a sequence; no
//    other keys, so that a misspelt one is an error rather than a world without obstacles;
//  * an obstacle: `radius` a number > 0 (read exactly from its decimal text), `waypoints` a
//    non-empty sequence of [t, x, y], each a finite number (t and the place read as the nearest
//    doubles), times ≥ 0 and strictly increasing; no other keys.
#include <coverkit/datasets/readers.h>
#include <coverkit/datasets/scenario.h>
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/rational.h>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <set>

namespace coverkit::datasets {

namespace {

class ScenarioReader {
public:
  explicit ScenarioReader(std::string file) : file_(std::move(file)) {}

  std::vector<MovingObstacle> read(const YAML::Node& y) const {
    if (!y.IsMap()) fail("", "not a coverkit.scenario/1 file (expected a mapping)");
    onlyKeys(y, {"format", "dynamic_obstacles"}, "");
    if (!y["format"]) fail("format", "missing: not a coverkit.scenario/1 file");
    if (!y["format"].IsScalar() || y["format"].Scalar() != "coverkit.scenario/1")
      fail("format", "expected \"coverkit.scenario/1\"");
    std::vector<MovingObstacle> out;
    const YAML::Node obs = y["dynamic_obstacles"];
    if (!obs || obs.IsNull()) return out;
    if (!obs.IsSequence()) fail("dynamic_obstacles", "expected a list of obstacles");
    for (std::size_t i = 0; i < obs.size(); ++i) out.push_back(obstacle(obs[i], "dynamic_obstacles[" + std::to_string(i) + "]"));
    return out;
  }

private:
  [[noreturn]] void fail(const std::string& place, const std::string& why) const { throw InputError(file_, place, why); }

  void onlyKeys(const YAML::Node& m, const std::set<std::string>& keys, const std::string& place) const {
    for (const auto& kv : m) {
      const std::string k = kv.first.IsScalar() ? kv.first.Scalar() : "?";
      if (!keys.count(k)) fail(place.empty() ? k : place + "." + k, "unknown key");
    }
  }

  Rational number(const YAML::Node& n, const std::string& place) const {
    if (!n || !n.IsScalar()) fail(place, "expected a number");
    return parseRational(n.Scalar(), file_, place);
  }

  double finite(const YAML::Node& n, const std::string& place) const {
    const double v = toDouble(number(n, place));
    if (!std::isfinite(v)) fail(place, "not a finite number");
    return v;
  }

  MovingObstacle obstacle(const YAML::Node& o, const std::string& place) const {
    if (!o.IsMap()) fail(place, "expected an obstacle (radius, waypoints)");
    onlyKeys(o, {"radius", "waypoints"}, place);
    MovingObstacle m;
    if (!o["radius"]) fail(place + ".radius", "missing");
    m.radius = number(o["radius"], place + ".radius");
    if (m.radius <= 0) fail(place + ".radius", "must be > 0");
    const YAML::Node w = o["waypoints"];
    if (!w) fail(place + ".waypoints", "missing");
    if (!w.IsSequence() || w.size() == 0) fail(place + ".waypoints", "expected a non-empty list of [t, x, y]");
    for (std::size_t k = 0; k < w.size(); ++k) {
      const std::string at = place + ".waypoints[" + std::to_string(k) + "]";
      if (!w[k].IsSequence() || w[k].size() != 3) fail(at, "expected [t, x, y]");
      TimedPoint p{finite(w[k][0], at + "[0]"), {finite(w[k][1], at + "[1]"), finite(w[k][2], at + "[2]")}};
      if (p.t < 0) fail(at + "[0]", "time must be >= 0");
      if (k > 0 && !(p.t > m.waypoints.back().t)) fail(at + "[0]", "times must increase strictly");
      m.waypoints.push_back(p);
    }
    return m;
  }

  std::string file_;
};

}  // namespace

std::vector<MovingObstacle> parseScenario(const std::string& text, const std::string& name) {
  YAML::Node y;
  try {
    y = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(name, "line " + std::to_string(e.mark.line + 1), "YAML does not parse: " + e.msg);
  }
  try {
    return ScenarioReader(name).read(y);
  } catch (const YAML::Exception& e) {  // a node access not checked above: still bad input
    throw InputError(name, "line " + std::to_string(e.mark.line + 1), "unexpected YAML: " + e.msg);
  }
}

std::vector<MovingObstacle> readScenario(const std::string& file) { return parseScenario(readTextFile(file), file); }

}  // namespace coverkit::datasets
