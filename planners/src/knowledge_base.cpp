// The knowledge base's reader and rule selection (knowledge_base.h). Decisions:
//  * the format is strict, like every coverkit file: `format: coverkit.kb/1`, `rules` (a list,
//    possibly empty), optional `learning_rate` in [0, 1] and `outcome_steps` ≥ 1; a rule has a
//    `name`, an `event`, an `action` and optional `blocked_at_least` ≥ 0, `blocked_below` >
//    blocked_at_least, `priority` (robot_ahead only), `mode` and `weight` in [0, 1]; any other key
//    is an error, so that a misspelt condition cannot silently widen a rule.
//  * the shipped rules are planners/data/multi_st_kb.yaml, compiled in (CMake reads the file), so
//    the binary needs no data directory and the text a user copies is the text that runs.
#include <coverkit/geometry/error.h>
#include <coverkit/planners/knowledge_base.h>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace coverkit::planners {

extern const char* const kDefaultKnowledgeBaseYaml;   // generated from planners/data/multi_st_kb.yaml

const char* toString(KbEvent e) { return e == KbEvent::kRobotAhead ? "robot_ahead" : "obstacle_ahead"; }
const char* toString(KbAction a) {
  switch (a) {
    case KbAction::kWait: return "wait";
    case KbAction::kDetour: return "detour";
    case KbAction::kGiveWay: return "give_way";
    case KbAction::kSkip: return "skip";
  }
  return "?";
}

const std::string& defaultKnowledgeBaseText() {
  static const std::string text(kDefaultKnowledgeBaseYaml);
  return text;
}

namespace {

class KbReader {
public:
  explicit KbReader(std::string source) : source_(std::move(source)) {}

  KnowledgeBase read(const YAML::Node& y) const {
    if (!y.IsMap()) fail("", "not a coverkit.kb/1 file (expected a mapping)");
    onlyKeys(y, {"format", "learning_rate", "outcome_steps", "rules"}, "");
    if (!y["format"]) fail("format", "missing: not a coverkit.kb/1 file");
    if (!y["format"].IsScalar() || y["format"].Scalar() != "coverkit.kb/1") fail("format", "expected \"coverkit.kb/1\"");
    KnowledgeBase kb;
    if (y["learning_rate"]) kb.learningRate = unit(y["learning_rate"], "learning_rate");
    if (y["outcome_steps"]) kb.outcomeSteps = integer(y["outcome_steps"], "outcome_steps", 1);
    const YAML::Node rules = y["rules"];
    if (!rules) fail("rules", "missing (an empty list [] for no rules)");
    if (!rules.IsSequence()) fail("rules", "expected a list of rules");
    std::set<std::string> names;
    for (std::size_t i = 0; i < rules.size(); ++i) {
      KbRule r = rule(rules[i], "rules[" + std::to_string(i) + "]");
      if (!names.insert(r.name).second) fail("rules[" + std::to_string(i) + "].name", "'" + r.name + "' is the name of an earlier rule");
      kb.rules.push_back(r);
    }
    return kb;
  }

private:
  [[noreturn]] void fail(const std::string& place, const std::string& why) const { throw InputError(source_, place, why); }

  void onlyKeys(const YAML::Node& m, const std::set<std::string>& keys, const std::string& place) const {
    for (const auto& kv : m) {
      const std::string k = kv.first.IsScalar() ? kv.first.Scalar() : "?";
      if (!keys.count(k)) fail(place.empty() ? k : place + "." + k, "unknown key");
    }
  }
  std::string word(const YAML::Node& n, const std::string& place, const std::set<std::string>& allowed) const {
    if (!n.IsScalar()) fail(place, "expected one of the words below");
    const std::string v = n.Scalar();
    if (!allowed.count(v)) {
      std::string list;
      for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
      fail(place, "'" + v + "' is not one of " + list);
    }
    return v;
  }
  double unit(const YAML::Node& n, const std::string& place) const {
    if (!n.IsScalar()) fail(place, "expected a number in [0, 1]");
    double v = 0;
    std::istringstream in(n.Scalar());
    if (!(in >> v) || !(in >> std::ws).eof() || !std::isfinite(v) || v < 0 || v > 1) fail(place, "expected a number in [0, 1], got '" + n.Scalar() + "'");
    return v;
  }
  int integer(const YAML::Node& n, const std::string& place, int least) const {
    if (!n.IsScalar()) fail(place, "expected an integer");
    long v = 0;
    std::istringstream in(n.Scalar());
    if (!(in >> v) || !(in >> std::ws).eof() || v < least || v > 1'000'000)
      fail(place, "expected an integer in [" + std::to_string(least) + ", 1000000], got '" + n.Scalar() + "'");
    return static_cast<int>(v);
  }
  KbRule rule(const YAML::Node& n, const std::string& place) const {
    if (!n.IsMap()) fail(place, "expected a rule (name, event, action, ...)");
    onlyKeys(n, {"name", "event", "blocked_at_least", "blocked_below", "priority", "mode", "action", "weight"}, place);
    KbRule r;
    if (!n["name"] || !n["name"].IsScalar() || n["name"].Scalar().empty()) fail(place + ".name", "missing");
    r.name = n["name"].Scalar();
    if (!n["event"]) fail(place + ".event", "missing");
    r.event = word(n["event"], place + ".event", {"robot_ahead", "obstacle_ahead"}) == "robot_ahead" ? KbEvent::kRobotAhead : KbEvent::kObstacleAhead;
    if (!n["action"]) fail(place + ".action", "missing");
    const std::string a = word(n["action"], place + ".action", {"wait", "detour", "give_way", "skip"});
    r.action = a == "wait" ? KbAction::kWait : a == "detour" ? KbAction::kDetour : a == "give_way" ? KbAction::kGiveWay : KbAction::kSkip;
    if (n["blocked_at_least"]) r.blockedAtLeast = integer(n["blocked_at_least"], place + ".blocked_at_least", 0);
    if (n["blocked_below"]) {
      r.blockedBelow = integer(n["blocked_below"], place + ".blocked_below", 1);
      if (r.blockedBelow <= r.blockedAtLeast) fail(place + ".blocked_below", "must be larger than blocked_at_least: the rule could never fire");
    }
    if (n["priority"]) {
      r.priority = word(n["priority"], place + ".priority", {"lower", "higher", "any"});
      if (r.event != KbEvent::kRobotAhead && r.priority != "any") fail(place + ".priority", "only a robot ahead has a priority");
    }
    if (n["mode"]) r.mode = word(n["mode"], place + ".mode", {"tree", "travel", "any"});
    if (r.action == KbAction::kGiveWay && r.event != KbEvent::kRobotAhead) fail(place + ".action", "give_way answers a robot ahead only");
    if (n["weight"]) r.weight = unit(n["weight"], place + ".weight");
    return r;
  }

  std::string source_;
};

}  // namespace

KnowledgeBase parseKnowledgeBase(const std::string& text, const std::string& source) {
  YAML::Node y;
  try {
    y = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(source, "line " + std::to_string(e.mark.line + 1), "not YAML: " + e.msg);
  }
  return KbReader(source).read(y);
}

KnowledgeBase loadKnowledgeBase(const std::string& spec) {
  if (spec == "on") return parseKnowledgeBase(defaultKnowledgeBaseText(), "the shipped knowledge base");
  std::error_code ec;
  if (std::filesystem::is_directory(spec, ec)) throw InputError(spec, "", "is a directory, not a knowledge base file (--param kb=FILE)");
  std::ifstream in(spec, std::ios::binary);
  if (!in) throw InputError(spec, "", "cannot read the knowledge base file (--param kb=FILE; on or off for the shipped rules or none)");
  std::ostringstream text;
  text << in.rdbuf();
  return parseKnowledgeBase(text.str(), spec);
}

int selectRule(const KnowledgeBase& kb, const std::vector<double>& weights, const KbSituation& s) {
  int best = -1;
  for (std::size_t i = 0; i < kb.rules.size(); ++i) {
    const KbRule& r = kb.rules[i];
    if (r.event != s.event || s.blockedSteps < r.blockedAtLeast || s.blockedSteps >= r.blockedBelow) continue;
    if (r.priority == "lower" && !s.otherHasPriority) continue;
    if (r.priority == "higher" && s.otherHasPriority) continue;
    if ((r.mode == "tree" && s.travelling) || (r.mode == "travel" && !s.travelling)) continue;
    if (best < 0 || weights[i] > weights[static_cast<std::size_t>(best)]) best = static_cast<int>(i);
  }
  return best;
}

}  // namespace coverkit::planners
