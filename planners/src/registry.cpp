#include <coverkit/geometry/error.h>
#include <coverkit/planners/registry.h>
#include <coverkit/planners/stc_skeleton.h>
#include <coverkit/planners/bsa.h>
#include <coverkit/planners/smooth_stc.h>
#include <coverkit/planners/tracc.h>

#include <algorithm>

namespace coverkit::planners {

Registry& Registry::instance() {
  static Registry registry = [] {
    Registry r;
    // One line per built-in planner.
    r.add("stc", [] { return std::make_unique<StcPlanner>(); });
    r.add("spiral_stc", [] { return std::make_unique<SpiralStcPlanner>(); });
    r.add("full_stc", [] { return std::make_unique<FullStcPlanner>(); });
    r.add("smooth_stc", [] { return std::make_unique<SmoothStcPlanner>(); });
    r.add("smooth_stc_online", [] { return std::make_unique<SmoothStcOnlinePlanner>(); });
    r.add("tracc", [] { return std::make_unique<TraccPlanner>(); });
    r.add("bsa_spiral", [] { return std::make_unique<BsaPlanner>(BsaPlanner::Filling::kSpiral); });
    r.add("bsa_zigzag", [] { return std::make_unique<BsaPlanner>(BsaPlanner::Filling::kZigzag); });
    return r;
  }();
  return registry;
}

void Registry::add(const std::string& name, PlannerFactory factory) {
  if (contains(name)) throw std::logic_error("planner registered twice: " + name);
  entries_.emplace_back(name, std::move(factory));
}

bool Registry::contains(const std::string& name) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const auto& e) { return e.first == name; });
}

std::unique_ptr<Planner> Registry::create(const std::string& name) const {
  for (const auto& e : entries_)
    if (e.first == name) return e.second();
  std::string known;
  for (const auto& n : names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("--planner", name, "unknown planner (known: " + known + ")");
}

std::vector<std::string> Registry::names() const {
  std::vector<std::string> n;
  for (const auto& e : entries_) n.push_back(e.first);
  std::sort(n.begin(), n.end());
  return n;
}

Plan runPlanner(const std::string& name, const PlanningContext& context, const std::map<std::string, std::string>& params,
                double timeLimitSeconds) {
  auto planner = Registry::instance().create(name);
  const ParamSet set(planner->params(), params, name);
  Plan plan = planner->plan(context, set, TerminationCondition(timeLimitSeconds));
  plan.planner = name;
  plan.timings.insert(plan.timings.begin(), {"cells", context.cellSeconds});
  return plan;
}

}  // namespace coverkit::planners
