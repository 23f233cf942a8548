// Exact cell classification against a brute-force reference (every cell against every edge).
#include <coverkit/geometry/cell_grid.h>

#include "helpers/worlds.h"

#include <gtest/gtest.h>

#include <array>
#include <random>

using namespace coverkit;

namespace {


/// Does the closed segment meet the open square (x0,x1)×(y0,y1)? Liang–Barsky clipping, exact.
bool meetsOpenSquare(const Point& a, const Point& b, const Rational& x0, const Rational& y0, const Rational& x1, const Rational& y1) {
  Rational t0 = 0, t1 = 1;
  const Rational dx = b.x - a.x, dy = b.y - a.y;
  auto clip = [&](const Rational& p, const Rational& q) {  // need p·t < q strictly (open)
    if (p == 0) return q > 0;
    const Rational t = q / p;
    if (p < 0) { if (t > t0) t0 = t; }
    else { if (t < t1) t1 = t; }
    return true;
  };
  if (!clip(-dx, a.x - x0) || !clip(dx, x1 - a.x) || !clip(-dy, a.y - y0) || !clip(dy, y1 - a.y)) return false;
  return t0 < t1 || (t0 == t1 && dx == 0 && dy == 0);
}

CellState reference(const Workspace& w, const CellGrid& g, int c, int r) {
  const Rational& D = g.subSize();
  const Rational x0 = g.originX() + D * c, y0 = g.originY() + D * r, x1 = x0 + D, y1 = y0 + D;
  for (const Ring* ring : w.rings())
    for (std::size_t i = 0; i < ring->size(); ++i)
      if (meetsOpenSquare((*ring)[i], (*ring)[(i + 1) % ring->size()], x0, y0, x1, y1)) return CellState::kPartial;
  return strictlyInside(w, g.subCenter(c, r)) ? CellState::kFree : CellState::kBlocked;
}

}  // namespace

TEST(Cells, SquareHoleOnTheGrid) {
  const Workspace w = testing_helpers::boxWith({{{2, 2}, {2, 4}, {4, 4}, {4, 2}}});
  const CellGrid g = classifyCells(w, Rational(1));
  EXPECT_EQ(g.subCols(), 10);
  EXPECT_EQ(g.subRows(), 10);
  EXPECT_EQ(g.count(CellState::kBlocked), 4u);
  EXPECT_EQ(g.count(CellState::kPartial), 0u);
  EXPECT_EQ(g.count(CellState::kFree), 96u);
  EXPECT_EQ(g.mega(1, 1), CellState::kBlocked);
  EXPECT_EQ(g.mega(0, 0), CellState::kFree);
}

TEST(Cells, GridIsExtendedToWholeMegaCellsAndOutsideIsBlocked) {
  const Workspace w = testing_helpers::boxWith({}, 5, 3);
  const CellGrid g = classifyCells(w, Rational(1));
  EXPECT_EQ(g.megaCols(), 3);
  EXPECT_EQ(g.megaRows(), 2);
  EXPECT_EQ(g.count(CellState::kFree), 15u);
  EXPECT_EQ(g.count(CellState::kBlocked), 9u);
  EXPECT_EQ(g.mega(2, 0), CellState::kPartial);  // half inside
}

TEST(Cells, MatchesBruteForceOnRandomPolygons) {
  std::mt19937_64 rng(42);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Ring> holes;
    for (int k = 0; k < 4; ++k) {
      const int cx = 2 + k * 2 + static_cast<int>(rng() % 1), cy = 2 + static_cast<int>(rng() % 6);
      const Rational s = ratio(1 + static_cast<long>(rng() % 7), 8);
      holes.push_back({{Rational(cx) - s, Rational(cy)}, {Rational(cx), Rational(cy) - s}, {Rational(cx) + s, Rational(cy) + s / 3}});
    }
    const Workspace w = testing_helpers::boxWith(holes);
    const Rational D = ratio(3 + static_cast<long>(rng() % 5), 7);
    const CellGrid g = classifyCells(w, D);
    for (int r = 0; r < g.subRows(); ++r)
      for (int c = 0; c < g.subCols(); ++c) ASSERT_EQ(g.sub(c, r), reference(w, g, c, r)) << "trial " << trial << " cell " << c << "," << r;
  }
}

TEST(Cells, RejectsNonPositiveSize) { EXPECT_ANY_THROW(classifyCells(testing_helpers::boxWith({}), Rational(0))); }

// Sub-cell centres are made from doubles where doubles give them exactly: the same rational and the
// same double as the rational formula, on dyadic grids, on 0.05 m grids and with huge origins.
TEST(Cells, CentresAreTheRationalFormulasToTheBit) {
  const std::vector<std::array<Rational, 3>> grids = {
      {Rational(0), Rational(0), Rational(1, 2)},        {Rational(-7, 4), Rational(3, 8), Rational(1, 4)},
      {Rational(1, 20), Rational(-3, 10), Rational(1, 40)}, {Rational(1, 3), Rational(0), Rational(1, 2)},
      {Rational(1) << 60, Rational(-5), Rational(1, 8)},  {Rational(123456789, 1024), Rational(1, 1024), Rational(3, 64)}};
  for (const auto& [ox, oy, d] : grids) {
    const CellGrid g(ox, oy, d, 40, 30);
    for (int col = 0; col < g.subCols(); col += 7)
      for (int row = 0; row < g.subRows(); row += 5) {
        const Rational x = ox + d * (2 * col + 1) / 2, y = oy + d * (2 * row + 1) / 2;
        const Point p = g.subCenter(col, row);
        ASSERT_EQ(p.x, x) << ox << " " << d << " col " << col;
        ASSERT_EQ(p.y, y) << oy << " " << d << " row " << row;
        const PointD q = g.subCenterD(col, row);
        ASSERT_EQ(q.x, toDouble(x));
        ASSERT_EQ(q.y, toDouble(y));
      }
  }
}
