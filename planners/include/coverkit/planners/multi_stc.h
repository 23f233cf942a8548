#pragma once
// Multi-robot coverage planners (docs/multi-robot.md). See multi_stc.cpp for the construction and
// its decisions.
#include <coverkit/planners/planner.h>

namespace coverkit::planners {

/// The balanced baseline: one STC tour shared by the team, cut into a stretch around each robot's
/// start so that the makespan is least; timed in steps, collision-free by construction (offline,
/// static worlds).
class MultiStcBalancedPlanner : public Planner {
public:
  std::string name() const override { return "multi_stc_balanced"; }
  std::string description() const override;
  std::vector<ParamSpec> params() const override;
  Capabilities capabilities() const override;
  Plan plan(const PlanningContext& context, const ParamSet& params, const TerminationCondition& stop) override;
};

class TeamSensor;

/// What a team's timed paths left: free sub-cells that no robot entered, reachable (4-connected)
/// from the robots' starts, and from where they are when the last moving obstacle stops. Sub-cells
/// whose centre is within r + ρ of an obstacle's last place, and moves between centres passing that
/// near one, are neither counted nor crossed (blocked for good). Doubles; docs/multi-robot.md ("500
/// seeded scenarios") says why the second count is the one a team without the obstacles' future can
/// be held to. Reported by `coverkit evaluate` and the team-check experiment.
struct MissedSubcells {
  std::size_t fromStarts = 0, fromTeam = 0;
};
MissedSubcells missedSubcells(const PlanningContext& context, const std::vector<Path>& paths);

/// Multi-ST (Pham et al.): online and step-synchronous; the robots grow disjoint spanning trees on
/// the shared mega-cell grid, sense only their neighbourhood (TeamSensor) and consult a rule
/// knowledge base when a robot or a moving obstacle is in the way.
class MultiStPlanner : public Planner {
public:
  std::string name() const override { return "multi_st"; }
  std::string description() const override;
  std::vector<ParamSpec> params() const override;
  Capabilities capabilities() const override;
  Plan plan(const PlanningContext& context, const ParamSet& params, const TerminationCondition& stop) override;
  /// The same with the caller's sensor (tests: a sensor that throws on any question outside the
  /// robots' neighbourhood, started at the robots' start sub-cells); null: the planner's own.
  Plan planWith(const PlanningContext& context, const ParamSet& params, const TerminationCondition& stop, TeamSensor* sensor);
};

}  // namespace coverkit::planners
