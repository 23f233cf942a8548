#pragma once
// Scenario files (coverkit.scenario/1, YAML): what moves in a world besides the robots. Spec:
// docs/formats.md, "Scenario files".
#include <coverkit/geometry/path.h>

#include <string>
#include <vector>

namespace coverkit::datasets {

/// The moving obstacles of a scenario file; InputError naming the file, the place
/// ("dynamic_obstacles[1].waypoints[2][0]") and the problem for anything malformed.
std::vector<MovingObstacle> readScenario(const std::string& file);
/// The same from YAML text (`name` stands for the file in errors).
std::vector<MovingObstacle> parseScenario(const std::string& text, const std::string& name);

}  // namespace coverkit::datasets
