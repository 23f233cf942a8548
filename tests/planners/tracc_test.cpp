// TRACC: the paper's 11×11 scenario, online sensing, complete coverage of reachable cells.
#include "helpers/checkers.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/planners/registry.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace coverkit;

namespace {
/// The paper's numbering: C1 … C121, row by row from S = C1; C1 is our bottom-left cell.
CellIndex paperCell(int k) { return {(k - 1) % 11, (k - 1) / 11}; }

Workspace paperGrid(const std::set<int>& blocked) {
  std::string text;
  for (int row = 10; row >= 0; --row) {
    for (int col = 0; col < 11; ++col) text += blocked.count(row * 11 + col + 1) ? '#' : '.';
    text += '\n';
  }
  return datasets::parseTextGrid(text, "tracc11.grid");
}

std::vector<CellIndex> cellsOf(const planners::PlanningContext& ctx, const Plan& plan) {
  std::vector<CellIndex> out;
  const auto pts = plan.paths[0].polyline(0.01);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i)
    for (int k = 0; k < 100; ++k) {
      CellIndex c;
      const PointD p{pts[i].x + (pts[i + 1].x - pts[i].x) * k / 100, pts[i].y + (pts[i + 1].y - pts[i].y) * k / 100};
      if (ctx.cells.locateSubD(p, c) && (out.empty() || !(out.back() == c))) out.push_back(c);
    }
  return out;
}
}  // namespace

TEST(Tracc, PaperScenarioOne) {
  // C5 blocked, and the cells around C41 (C30, C40, C42, C52): C41 is enclosed. Start S = C1.
  const Workspace w = paperGrid({5, 30, 40, 42, 52});
  const auto ctx = testing_helpers::contextFor(w, Rational(1, 2), Point{Rational(1, 2), Rational(1, 2)});
  const Plan plan = planners::runPlanner("tracc", ctx, {});
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
  EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan));
  EXPECT_EQ(plan.statistics.at("unsafe_cells"), 5.0);
  EXPECT_EQ(plan.statistics.at("unchecked_cells"), 1.0);  // C41, never sensed: enclosed
  EXPECT_EQ(plan.statistics.at("covered_cells"), 115.0);
  EXPECT_EQ(plan.statistics.at("unreached_free_cells"), 1.0);  // C41 is free but walled in
  EXPECT_EQ(plan.statistics.at("end_phase_visits"), 0.0);      // the flow over every row left none
  // the paper's detour around C5: C4 => C15 => C16 => C17 => C6
  const auto cells = cellsOf(ctx, plan);
  std::vector<CellIndex> detour;
  for (int k : {4, 15, 16, 17, 6}) detour.push_back(paperCell(k));
  EXPECT_NE(std::search(cells.begin(), cells.end(), detour.begin(), detour.end()), cells.end());
}

TEST(Tracc, PaperScenarioTwoReportsEnclosedCells) {
  // C121 bounded by unsafe cells (C110, C120); C60 and C62 behind walls but reachable
  const Workspace w = paperGrid({49, 50, 51, 59, 61, 71, 72, 73, 110, 120});
  const auto ctx = testing_helpers::contextFor(w, Rational(1, 2), Point{Rational(1, 2), Rational(1, 2)});
  const Plan plan = planners::runPlanner("tracc", ctx, {});
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
  EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan));
  EXPECT_EQ(plan.statistics.at("unchecked_cells"), 2.0);  // C60 (inside the ring) and C121
  EXPECT_EQ(plan.statistics.at("unsafe_cells"), 10.0);
  EXPECT_EQ(plan.statistics.at("unreached_free_cells"), 2.0);
}

TEST(Tracc, OnlineCompleteAndDeterministicOnSeededMaps) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    datasets::GridMapSpec g;
    g.width = 30 + static_cast<int>(seed) * 4;
    g.height = 25;
    g.density = 0.03 * static_cast<double>(seed % 7);
    g.clustered = seed % 2 == 1;
    g.seed = seed;
    const auto ctx = testing_helpers::contextFor(datasets::gridToWorkspace(datasets::generateGridMap(g), "grid"), Rational(1, 2));
    for (const char* flow : {"rows", "columns"}) {
      const Plan plan = planners::runPlanner("tracc", ctx, {{"flow", flow}});
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan)) << seed;
      EXPECT_TRUE(testing_helpers::coversReachableSubcells(ctx, plan)) << seed;
      // four questions at most per cell entered, each about a neighbour (the sensor throws otherwise)
      EXPECT_LE(plan.statistics.at("sensor_queries"), 4 * plan.statistics.at("covered_cells"));
      EXPECT_GE(plan.statistics.at("redundancy_rate"), 0.0);
      EXPECT_LT(plan.statistics.at("redundancy_rate"), 100.0);
    }
  }
}
