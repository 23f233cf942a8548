#pragma once
// Reusable checkers returning testing::AssertionResult with specific messages.
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/validate.h>
#include <coverkit/planners/planner.h>

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace coverkit::testing_helpers {

/// The contract test's seeded worlds: six grid maps (resolution 1/10, 0-12 % blocked, scattered
/// and clustered) and six polygon worlds (8 obstacles of four shapes), with their labels.
std::vector<std::pair<std::string, Workspace>> contractWorlds();
/// A seeded size × size polygon world of `obstacles` mixed obstacles of 1-2.5 m (the Smooth-STC tests').
Workspace mixedWorld(std::uint64_t seed, int size, int obstacles);
/// The radius the contract test gives a robot on a contract world: 1/10 on grids, 1/4 on polygons.
Rational contractRadius(const std::string& label);

/// The message of the InputError that f throws (empty when it throws none).
std::string inputErrorMessage(const std::function<void()>& f);

/// The plan succeeded and the independent validator accepts every path.
::testing::AssertionResult planIsValid(const planners::PlanningContext& ctx, const Plan& plan);
/// Every sub-cell of the free mega-cells 4-connected to the start's mega-cell is entered.
::testing::AssertionResult coversStartComponent(const planners::PlanningContext& ctx, const Plan& plan);
/// The swept area covers at least `minimum` of the coverable region (the start's closed component
/// of C-free ⊕ disc(r), metrics.h), the metric's error bound in the plan's favour.
::testing::AssertionResult coversCFreeComponent(const planners::PlanningContext& ctx, const Plan& plan, double minimum,
                                                double* coverage = nullptr);
/// What a planner's capabilities promise: coversStartComponent, coversReachableSubcells or
/// coversCFreeComponent (0.95 of the region on every world: the averages are the experiments').
::testing::AssertionResult coversWhatItClaims(const planners::PlanningContext& ctx, const Plan& plan, const std::string& coverage);
/// Every free sub-cell 4-connected to the start's sub-cell through free sub-cells is entered,
/// except those only reachable through sub-cells squeezed to exactly 2r (cells that are not free on
/// both sides of an axis, within the 3×3 block) at a centre that is not a double: no double path
/// may be safe there, and the plan must report sub-cells left out.
::testing::AssertionResult coversReachableSubcells(const planners::PlanningContext& ctx, const Plan& plan);
/// The definition the coverage checker excuses by: squeezed to exactly 2r between cells that are not
/// free (both sides of an axis, within the 3×3 block) at a centre coordinate that is not a double.
bool squeezedSubcell(const planners::PlanningContext& ctx, CellIndex c);
/// Sub-cells the paths' centres pass through (dense sampling, independent of the metrics).
std::vector<char> enteredSubcells(const CellGrid& cells, const Plan& plan);
/// Gabriely & Rimon's bound for Spiral-STC: length ≤ (n + m)·D (+ 2D for the start's connector),
/// n sub-cells entered, m of them next to a cell that is not free or to the grid's edge.
::testing::AssertionResult withinGabrielyRimonBound(const planners::PlanningContext& ctx, const Plan& plan);
/// The paths of a plan as the path file's JSON (byte-for-byte comparisons).
std::string pathJsonOf(const Plan& plan);
/// A context for a workspace with one robot.
planners::PlanningContext contextFor(const Workspace& w, const Rational& radius, std::optional<Point> start = std::nullopt);

}  // namespace coverkit::testing_helpers
