// Problem checks before any allocation: cell-grid size, coordinate range.
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/planner.h>

#include "helpers/checkers.h"

#include <gtest/gtest.h>

using namespace coverkit;

namespace {
Problem room(const std::string& radius, std::optional<std::string> cellSize = std::nullopt, const std::string& side = "10") {
  Problem p;
  const Rational s = parseRational(side);
  p.workspace.name = "room";
  p.workspace.regions.push_back({{{0, 0}, {s, 0}, {s, s}, {0, s}}, {}});
  p.robots.push_back({parseRational(radius), std::nullopt});
  if (cellSize) p.cellSize = parseRational(*cellSize);
  return p;
}
std::string messageOf(const std::function<void()>& f) { return testing_helpers::inputErrorMessage(f); }
}  // namespace

TEST(ProblemChecks, ACellGridBeyondTheLimitIsRefusedWithItsNumbers) {
  const std::string m = messageOf([] { planners::makeContext(room("1e-300")); });
  EXPECT_NE(m.find("--radius: 1e-300: the sub-cell grid would have 5e+300 × 5e+300 sub-cells"), std::string::npos) << m;
  EXPECT_NE(m.find("limit of 2e+08"), std::string::npos) << m;
  const std::string c = messageOf([] { planners::makeContext(room("1e-7", "1e-6")); });
  EXPECT_NE(c.find("--cell-size: 1e-06:"), std::string::npos) << c;
  const std::string tiny = messageOf([] { planners::makeContext(room("1e-7", "1e-400")); });
  EXPECT_NE(tiny.find("--cell-size: about 10^-400: the sub-cell grid would have 10^401 × 10^401"), std::string::npos) << tiny;
  // the limit itself: 14142² sub-cells pass the check, the next even count does not
  EXPECT_NO_THROW(planners::checkCellGridSize(room("1/2", std::nullopt, "14142")));
  EXPECT_THROW(planners::checkCellGridSize(room("1/2", std::nullopt, "14144")), InputError);
  // cspace needs no grid: checkProblem alone accepts a tiny radius
  EXPECT_NO_THROW(planners::checkProblem(room("1e-300")));
}

TEST(ProblemChecks, ClassifyCellsCountsExactlyBeforeConverting) {
  Problem p = room("1");
  EXPECT_THROW(classifyCells(p.workspace, parseRational("1e-300")), InputError);  // no overflow into a small grid
}

TEST(ProblemChecks, CoordinatesBeyondTheDoubleRangeAreRefused) {
  Problem p = room("1", std::nullopt, "1e400");
  const std::string m = messageOf([&] { planners::checkProblem(p); });
  EXPECT_NE(m.find("room: coordinates: a coordinate of magnitude about 10^400 is beyond the limit of 10^15"), std::string::npos) << m;
  Problem q = room("1", std::nullopt, "2e15");
  EXPECT_NE(messageOf([&] { planners::checkProblem(q); }).find("is beyond the limit of 10^15"), std::string::npos);
  EXPECT_NO_THROW(planners::checkProblem(room("1", std::nullopt, "1e15")));
}
