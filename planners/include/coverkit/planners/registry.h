#pragma once
// The registries: name → factory, for planners and for decompositions. Built-in entries are
// registered by explicit calls in registry.cpp (static self-registration is dropped by linkers
// from static libraries): adding a planner or a decomposition is one file plus one line there.
#include <coverkit/geometry/error.h>
#include <coverkit/planners/decomposition.h>
#include <coverkit/planners/planner.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace coverkit::planners {

/// Name → factory of T. `option` and `kind` name it in errors ("--planner", "planner").
template <class T>
class FactoryRegistry {
public:
  using Factory = std::function<std::unique_ptr<T>()>;
  FactoryRegistry(std::string option, std::string kind) : option_(std::move(option)), kind_(std::move(kind)) {}
  void add(const std::string& name, Factory factory) {
    if (contains(name)) throw std::logic_error(kind_ + " registered twice: " + name);
    entries_.emplace_back(name, std::move(factory));
  }
  bool contains(const std::string& name) const {
    return std::any_of(entries_.begin(), entries_.end(), [&](const auto& e) { return e.first == name; });
  }
  /// Throws InputError(option, name, ...) listing the known names when `name` is unknown.
  std::unique_ptr<T> create(const std::string& name) const {
    for (const auto& e : entries_)
      if (e.first == name) return e.second();
    std::string known;
    for (const auto& n : names()) known += (known.empty() ? "" : ", ") + n;
    throw InputError(option_, name, "unknown " + kind_ + " (known: " + known + ")");
  }
  std::vector<std::string> names() const {   ///< sorted
    std::vector<std::string> n;
    for (const auto& e : entries_) n.push_back(e.first);
    std::sort(n.begin(), n.end());
    return n;
  }

private:
  std::string option_, kind_;
  std::vector<std::pair<std::string, Factory>> entries_;
};

using PlannerFactory = FactoryRegistry<Planner>::Factory;

class Registry : public FactoryRegistry<Planner> {
public:
  /// The registry with every built-in planner.
  static Registry& instance();
  Registry() : FactoryRegistry("--planner", "planner") {}
};

class DecompositionRegistry : public FactoryRegistry<Decomposition> {
public:
  /// The registry with every built-in decomposition.
  static DecompositionRegistry& instance();
  DecompositionRegistry() : FactoryRegistry("--method", "decomposition") {}
};

/// Resolves parameters, runs the planner and adds the cell phase to the plan's timings.
Plan runPlanner(const std::string& name, const PlanningContext& context, const std::map<std::string, std::string>& params,
                double timeLimitSeconds = 0);

/// The path processors that follow planner `name` by default with these parameters
/// (Planner::postProcessing); InputError on an unknown planner or bad parameters.
std::vector<std::string> defaultPostProcessing(const std::string& name, const std::map<std::string, std::string>& params);

/// Resolves parameters and runs the decomposition `name` on the problem's first robot.
Decomposed runDecomposition(const std::string& name, const Problem& problem, const std::map<std::string, std::string>& params);

}  // namespace coverkit::planners
