// placeWalk writes a walk that stays in free mega-cells (STC's, Spiral-STC's) straight from the
// cells; it must give the path the general construction gives, double for double.
#include "walk_path.h"

#include <coverkit/datasets/generators.h>

#include <gtest/gtest.h>

#include <random>

using namespace coverkit;

namespace {

/// A random walk of 4-adjacent sub-cells in free mega-cells from the start's sub-cell, with repeats
/// and reversals, returning to it when `closed` (back along the way it came).
std::vector<CellIndex> randomWalk(const CellGrid& cells, CellIndex start, std::mt19937& rng, int steps, bool closed) {
  auto freeMega = [&](CellIndex c) {
    return c.col >= 0 && c.row >= 0 && c.col < cells.subCols() && c.row < cells.subRows() &&
           cells.insideMega(c.col / 2, c.row / 2) && cells.mega(c.col / 2, c.row / 2) == CellState::kFree;
  };
  std::vector<CellIndex> walk{start};
  const int dx[] = {1, 0, -1, 0}, dy[] = {0, 1, 0, -1};
  for (int i = 0; i < steps; ++i) {
    const int d = static_cast<int>(rng() % 4);
    const CellIndex n{walk.back().col + dx[d], walk.back().row + dy[d]};
    if (freeMega(n)) walk.push_back(n);
    else if (rng() % 4 == 0) walk.push_back(walk.back());   // a repeat
  }
  if (closed)
    for (std::size_t i = walk.size() - 1; i-- > 0;) walk.push_back(walk[i]);
  return walk;
}

}  // namespace

TEST(WalkPath, WalksInFreeMegaCellsArePlacedAsByTheGeneralConstruction) {
  struct World {
    Rational pixel, radius;
  } worlds[] = {{Rational(1), Rational(1, 2)}, {Rational(1, 10), Rational(1, 20)}, {Rational(3, 10), Rational(3, 20)}};
  std::mt19937 rng(17);
  int compared = 0;   // every walk here is one the direct way takes: all its cells in free mega-cells
  for (const World& w : worlds) {
    datasets::GridMapSpec spec;
    spec.width = spec.height = 40;
    spec.density = 0.1;
    spec.clustered = true;
    spec.resolution = w.pixel;
    spec.seed = 3;
    Problem p;
    p.workspace = datasets::gridToWorkspace(datasets::generateGridMap(spec), "walks");
    p.robots.push_back({w.radius, std::nullopt});
    const planners::PlanningContext ctx = planners::makeContext(p);
    const CellGrid& cells = ctx.cells;
    for (int trial = 0; trial < 60; ++trial) {
      CellIndex s{static_cast<int>(rng() % cells.subCols()), static_cast<int>(rng() % cells.subRows())};
      if (!cells.insideMega(s.col / 2, s.row / 2) || cells.mega(s.col / 2, s.row / 2) != CellState::kFree) continue;
      const std::vector<CellIndex> walk = randomWalk(cells, s, rng, 300, trial % 2 == 0);
      const Point start = cells.subCenter(s.col, s.row);
      const bool back = trial % 3 != 0;
      const planners::PlacedWalk a = planners::placeWalk(ctx, walk, start, back, true);
      const planners::PlacedWalk b = planners::placeWalk(ctx, walk, start, back, false);
      ASSERT_EQ(a.path.segments.size(), b.path.segments.size()) << "trial " << trial;
      EXPECT_EQ(a.path.start.x, b.path.start.x);
      EXPECT_EQ(a.path.start.y, b.path.start.y);
      for (std::size_t i = 0; i < a.path.segments.size(); ++i) {
        ASSERT_EQ(a.path.segments[i].from.x, b.path.segments[i].from.x) << "trial " << trial << " segment " << i;
        ASSERT_EQ(a.path.segments[i].from.y, b.path.segments[i].from.y) << "trial " << trial << " segment " << i;
        ASSERT_EQ(a.path.segments[i].to.x, b.path.segments[i].to.x) << "trial " << trial << " segment " << i;
        ASSERT_EQ(a.path.segments[i].to.y, b.path.segments[i].to.y) << "trial " << trial << " segment " << i;
      }
      EXPECT_EQ(a.startClear, b.startClear);
      EXPECT_EQ(a.unsafeMoves, b.unsafeMoves);
      ++compared;
    }
  }
  EXPECT_GT(compared, 100);
}
