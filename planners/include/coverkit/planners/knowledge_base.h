#pragma once
// The Multi-ST robots' knowledge base: event-condition-action rules, read from YAML
// (format coverkit.kb/1, docs/multi-robot.md "The knowledge base"), with weights that each robot
// updates from the outcome of the rules it fires (the paper's steps 6-7).
#include <climits>
#include <string>
#include <vector>

namespace coverkit::planners {

/// What stops a robot's next move.
enum class KbEvent { kRobotAhead, kObstacleAhead };
/// What a rule makes the robot do (docs/multi-robot.md says what each one is).
enum class KbAction { kWait, kDetour, kGiveWay, kSkip };

const char* toString(KbEvent e);
const char* toString(KbAction a);

struct KbRule {
  std::string name;
  KbEvent event = KbEvent::kRobotAhead;
  int blockedAtLeast = 0;        ///< fires when the robot has been blocked for at least this many steps
  int blockedBelow = INT_MAX;    ///< ... and for fewer than this many
  std::string priority = "any";  ///< robot_ahead only: "lower" (the robot ahead has priority), "higher" or "any"
  std::string mode = "any";      ///< "tree" (growing or walking its tree), "travel" or "any"
  KbAction action = KbAction::kWait;
  double weight = 0.5;           ///< in [0, 1]: among the rules that match, the heaviest fires (the first among equals)
};

struct KnowledgeBase {
  std::vector<KbRule> rules;
  double learningRate = 0.2;   ///< an outcome moves a weight this share of the way to 1 (success) or 0 (failure)
  int outcomeSteps = 3;        ///< a fired rule succeeded when the robot moves within this many steps
};

/// The rules shipped with coverkit (planners/data/multi_st_kb.yaml), as text.
const std::string& defaultKnowledgeBaseText();
/// Parses coverkit.kb/1 text; `source` names it in errors. InputError (source, key, problem) for
/// anything that is not a well-formed rule set: unknown keys, events, actions, weights outside [0, 1].
KnowledgeBase parseKnowledgeBase(const std::string& text, const std::string& source);
/// `spec`: "on" (the shipped rules) or the path of a coverkit.kb/1 file (InputError naming it when
/// it cannot be read or parsed). "off" has no rules: the caller's baseline.
KnowledgeBase loadKnowledgeBase(const std::string& spec);

/// The situation a robot is in when its move is refused.
struct KbSituation {
  KbEvent event = KbEvent::kRobotAhead;
  int blockedSteps = 0;       ///< steps in a row it has been blocked (0 the first time)
  bool otherHasPriority = false;
  bool travelling = false;
};

/// The index of the rule that fires (the heaviest matching one; the first among equals), or -1.
/// `weights` are the robot's own (one per rule).
int selectRule(const KnowledgeBase& kb, const std::vector<double>& weights, const KbSituation& s);

}  // namespace coverkit::planners
