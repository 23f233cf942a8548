#pragma once
// The validator's team checks (team.cpp): timelines, robot-robot and robot-moving-obstacle
// clearance in time, exact. Internal to coverkit::geometry.
#include <coverkit/geometry/validate.h>

#include <functional>
#include <vector>

namespace coverkit::detail {

/// Whether `paths` are a team plan or a timed one: several robots, moving obstacles, or a timeline.
bool needsTeamChecks(const Problem& problem, const std::vector<Path>& paths);

/// Adds the team violations (kinds "timeline", "robot_robot", "robot_obstacle") in a fixed order:
/// each robot's timeline, then the pairs of robots, then each robot against each obstacle.
void checkTeam(const Problem& problem, const std::vector<Path>& paths, const std::function<void(Violation)>& add);

}  // namespace coverkit::detail
