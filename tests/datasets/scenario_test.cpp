// Scenario files (coverkit.scenario/1): moving obstacles read exactly as written; everything
// malformed is an InputError naming the file, the place and the problem.
#include <coverkit/datasets/scenario.h>
#include <coverkit/geometry/error.h>

#include <gtest/gtest.h>

using namespace coverkit;

namespace {
std::string errorOf(const std::string& text) {
  try {
    datasets::parseScenario(text, "s.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST(Scenario, ReadsMovingObstacles) {
  const auto obs = datasets::parseScenario(R"(format: coverkit.scenario/1
dynamic_obstacles:
  - radius: 0.3
    waypoints: [[0.0, 1.0, 1.0], [5.0, 4.0, 1.0], [9.0, 4.0, 6.0]]   # [t, x, y]
  - radius: 1/4
    waypoints: [[2, 0.5, 0.5]]
)",
                                           "s.yaml");
  ASSERT_EQ(obs.size(), 2u);
  EXPECT_EQ(obs[0].radius, Rational(3, 10));
  ASSERT_EQ(obs[0].waypoints.size(), 3u);
  EXPECT_EQ(obs[0].waypoints[2].t, 9.0);
  EXPECT_EQ(obs[0].waypoints[2].p.y, 6.0);
  EXPECT_EQ(obs[1].radius, Rational(1, 4));
  // linear between waypoints, held before the first and after the last
  EXPECT_EQ(obs[0].at(2.5).x, 2.5);
  EXPECT_EQ(obs[0].at(100).y, 6.0);
  EXPECT_EQ(obs[1].at(0).x, 0.5);
  EXPECT_TRUE(datasets::parseScenario("format: coverkit.scenario/1\n", "s.yaml").empty());
}

TEST(Scenario, BadFilesNameThePlace) {
  const std::string head = "format: coverkit.scenario/1\ndynamic_obstacles:\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"[1, 2]", "s.yaml: not a coverkit.scenario/1 file"},
      {"dynamic_obstacles: []\n", "s.yaml: format: missing"},
      {"format: coverkit.path/1\n", "s.yaml: format: expected \"coverkit.scenario/1\""},
      {"format: coverkit.scenario/1\ndynamic_obstacle: []\n", "s.yaml: dynamic_obstacle: unknown key"},
      {"format: coverkit.scenario/1\ndynamic_obstacles: 3\n", "s.yaml: dynamic_obstacles: expected a list"},
      {head + "  - 3\n", "s.yaml: dynamic_obstacles[0]: expected an obstacle"},
      {head + "  - {waypoints: [[0, 1, 1]]}\n", "s.yaml: dynamic_obstacles[0].radius: missing"},
      {head + "  - {radius: 0, waypoints: [[0, 1, 1]]}\n", "s.yaml: dynamic_obstacles[0].radius: must be > 0"},
      {head + "  - {radius: -1, waypoints: [[0, 1, 1]]}\n", "s.yaml: dynamic_obstacles[0].radius: must be > 0"},
      {head + "  - {radius: abc, waypoints: [[0, 1, 1]]}\n", "s.yaml: dynamic_obstacles[0].radius:"},
      {head + "  - {radius: 1, speed: 2, waypoints: [[0, 1, 1]]}\n", "s.yaml: dynamic_obstacles[0].speed: unknown key"},
      {head + "  - {radius: 1}\n", "s.yaml: dynamic_obstacles[0].waypoints: missing"},
      {head + "  - {radius: 1, waypoints: []}\n", "s.yaml: dynamic_obstacles[0].waypoints: expected a non-empty list"},
      {head + "  - {radius: 1, waypoints: [[0, 1]]}\n", "s.yaml: dynamic_obstacles[0].waypoints[0]: expected [t, x, y]"},
      {head + "  - {radius: 1, waypoints: [[0, 1, x]]}\n", "s.yaml: dynamic_obstacles[0].waypoints[0][2]:"},
      {head + "  - {radius: 1, waypoints: [[0, 1, [2]]]}\n", "s.yaml: dynamic_obstacles[0].waypoints[0][2]: expected a number"},
      {head + "  - {radius: 1, waypoints: [[-1, 1, 1]]}\n", "s.yaml: dynamic_obstacles[0].waypoints[0][0]: time must be >= 0"},
      {head + "  - {radius: 1, waypoints: [[1, 1, 1], [1, 2, 2]]}\n", "s.yaml: dynamic_obstacles[0].waypoints[1][0]: times must increase strictly"},
      {head + "  - {radius: 1, waypoints: [[0, 1e999, 1]]}\n", "s.yaml: dynamic_obstacles[0].waypoints[0][1]"},
      {"format: [unclosed\n", "s.yaml: line "},
  };
  for (const auto& [text, want] : cases) EXPECT_NE(errorOf(text).find(want), std::string::npos) << text << " gave " << errorOf(text);
}
