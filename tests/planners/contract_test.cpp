// The contract every registered planner keeps (after OMPL's PlannerTest): on seeded grid and polygon
// worlds, with every value of every choice parameter, the plan succeeds or says why, the validator
// accepts it, the same input gives the same output, and its coverage claim holds.
#include "helpers/checkers.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/path_io.h>
#include <coverkit/planners/registry.h>

#include <gtest/gtest.h>

#include <sstream>

using namespace coverkit;

namespace {

std::vector<std::map<std::string, std::string>> parameterVariants(const planners::Planner& p) {
  std::vector<std::map<std::string, std::string>> out{{}};
  for (const auto& spec : p.params()) {
    if (spec.type != planners::ParamType::kChoice) continue;
    std::istringstream in(spec.range);
    std::string v;
    while (std::getline(in, v, '|')) out.push_back({{spec.name, v}});
  }
  return out;
}

}  // namespace

class PlannerContract : public ::testing::TestWithParam<std::string> {};

TEST_P(PlannerContract, ValidCompleteDeterministicOnSeededWorlds) {
  const std::string name = GetParam();
  auto planner = planners::Registry::instance().create(name);
  for (const auto& [label, world] : testing_helpers::contractWorlds()) {
    const Rational r = testing_helpers::contractRadius(label);
    const auto ctx = testing_helpers::contextFor(world, r);
    for (const auto& params : parameterVariants(*planner)) {
      SCOPED_TRACE(label + " " + (params.empty() ? "defaults" : params.begin()->second));
      const Plan a = planners::runPlanner(name, ctx, params);
      if (a.status == PlanStatus::kInvalidStart || a.status == PlanStatus::kNoFreeSpace) {
        EXPECT_FALSE(a.message.empty());
        continue;
      }
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, a));
      EXPECT_TRUE(testing_helpers::coversWhatItClaims(ctx, a, planner->capabilities().coverage));
      const Plan b = planners::runPlanner(name, ctx, params);
      datasets::PathDocument da, db;
      da.paths = a.paths;
      db.paths = b.paths;
      EXPECT_EQ(datasets::pathJson(da), datasets::pathJson(db)) << "not deterministic";
    }
  }
}

TEST_P(PlannerContract, DeclaresItself) {
  auto p = planners::Registry::instance().create(GetParam());
  EXPECT_EQ(p->name(), GetParam());
  EXPECT_FALSE(p->description().empty());
  for (const auto& s : p->params()) {
    EXPECT_FALSE(s.help.empty()) << s.name;
    EXPECT_NO_THROW(planners::ParamSet(p->params(), {{s.name, s.defaultValue}}, GetParam())) << s.name;
  }
  EXPECT_ANY_THROW(planners::ParamSet(p->params(), {{"no_such_parameter", "1"}}, GetParam()));
}

INSTANTIATE_TEST_SUITE_P(AllPlanners, PlannerContract, ::testing::ValuesIn(planners::Registry::instance().names()),
                         [](const auto& info) { return info.param; });
