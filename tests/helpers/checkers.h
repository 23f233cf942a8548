#pragma once
// Reusable checkers returning testing::AssertionResult with specific messages.
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/validate.h>
#include <coverkit/planners/planner.h>

#include <gtest/gtest.h>

namespace coverkit::testing_helpers {

/// The plan succeeded and the independent validator accepts every path.
::testing::AssertionResult planIsValid(const planners::PlanningContext& ctx, const Plan& plan);
/// Every sub-cell of the free mega-cells 4-connected to the start's mega-cell is entered.
::testing::AssertionResult coversStartComponent(const planners::PlanningContext& ctx, const Plan& plan);
/// A context for a workspace with one robot.
planners::PlanningContext contextFor(const Workspace& w, const Rational& radius, std::optional<Point> start = std::nullopt);

}  // namespace coverkit::testing_helpers
