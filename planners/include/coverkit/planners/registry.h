#pragma once
// The planner registry: name → factory. Built-in planners are registered by explicit calls in
// registry.cpp (static self-registration is dropped by linkers from static libraries): adding a
// planner is one file plus one line there.
#include <coverkit/planners/planner.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace coverkit::planners {

using PlannerFactory = std::function<std::unique_ptr<Planner>()>;

class Registry {
public:
  /// The registry with every built-in planner.
  static Registry& instance();
  void add(const std::string& name, PlannerFactory factory);
  bool contains(const std::string& name) const;
  /// Throws InputError("--planner", ...) listing the known names when `name` is unknown.
  std::unique_ptr<Planner> create(const std::string& name) const;
  std::vector<std::string> names() const;   ///< sorted

private:
  std::vector<std::pair<std::string, PlannerFactory>> entries_;
};

/// Resolves parameters, runs the planner and adds the cell phase to the plan's timings.
Plan runPlanner(const std::string& name, const PlanningContext& context, const std::map<std::string, std::string>& params,
                double timeLimitSeconds = 0);

}  // namespace coverkit::planners
