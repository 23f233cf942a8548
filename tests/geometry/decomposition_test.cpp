// The decomposition engine's contract (issue 13), checked exactly with CGAL Boolean operations
// (checkDecomposition): cells interior-disjoint, their union C-free, adjacency symmetric and
// complete; boustrophedon cells monotone; never more boustrophedon than trapezoidal cells.
#include <coverkit/datasets/generators.h>
#include <coverkit/geometry/decomposition.h>

#include <gtest/gtest.h>

#include "helpers/worlds.h"

namespace coverkit {
namespace {

using testing_helpers::boxWith;

Ring rect(Rational x0, Rational y0, Rational x1, Rational y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

struct Case {
  std::string name;
  Workspace w;
  Rational r;
};

void expectContract(const Case& c) {
  SCOPED_TRACE(c.name);
  const CSpace space(c.w, c.r);
  const CellDecomposition tcd = decomposeCSpace(space, DecompositionRule::kTrapezoidal, "trapezoidal");
  const CellDecomposition bcd = decomposeCSpace(space, DecompositionRule::kBoustrophedon, "boustrophedon");
  const CellDecomposition grid = decomposeCSpace(space, DecompositionRule::kGrid, "grid", 4 * c.r, Point{0, 0});
  for (const CellDecomposition* d : {&tcd, &bcd, &grid}) {
    SCOPED_TRACE(d->method);
    const DecompositionCheck k = checkDecomposition(*d, space);
    EXPECT_TRUE(k.ok(d != &grid)) << k.detail << " disjoint " << k.disjoint << " union " << k.unionIsCFree << " adjacency "
                                  << k.adjacencyComplete << " symmetric " << k.adjacencySymmetric << " monotone " << k.monotone;
    double area = 0;
    for (const DecomposedCell& cell : d->cells) area += cell.area;
    EXPECT_NEAR(area, space.area(), 1e-9 * (1 + space.area()));
  }
  EXPECT_LE(bcd.cells.size(), tcd.cells.size());
  if (space.componentCount() > 0) {
    EXPECT_GE(bcd.cells.size(), space.componentCount());
  }
}

TEST(Decomposition, ContractOnHandMadeWorlds) {
  std::vector<Case> cases;
  cases.push_back({"empty box", boxWith({}), 1});
  cases.push_back({"one square", boxWith({rect(4, 4, 6, 6)}), ratio(1, 2)});
  cases.push_back({"two squares whose C-obstacles overlap", boxWith({rect(2, 4, 4, 6), rect(5, 4, 7, 6)}), 1});
  cases.push_back({"a wall splitting C-free", boxWith({rect(4, ratio(1, 2), 5, ratio(19, 2))}), 1});
  cases.push_back({"triangle", boxWith({{{3, 3}, {7, 4}, {4, 7}}}), ratio(1, 3)});
  for (const Case& c : cases) expectContract(c);
}

TEST(Decomposition, ContractOnSeededWorlds) {
  int n = 0;
  for (auto shape : {datasets::ObstacleShape::kRectangle, datasets::ObstacleShape::kRotatedRectangle, datasets::ObstacleShape::kConvex,
                     datasets::ObstacleShape::kStar, datasets::ObstacleShape::kDisc, datasets::ObstacleShape::kMixed})
    for (std::uint64_t seed = 1; seed <= 9; ++seed) {
      datasets::PolygonWorldSpec spec;
      spec.width = 16;
      spec.height = 12;
      spec.count = static_cast<int>(2 + seed * 2);
      spec.shape = shape;
      spec.seed = seed;
      const Rational r = seed % 3 == 0 ? Rational(ratio(3, 4)) : Rational(ratio(2, 5));
      expectContract({"seed " + std::to_string(seed) + " shape " + std::to_string(static_cast<int>(shape)), datasets::generatePolygonWorld(spec), r});
      ++n;
    }
  EXPECT_GE(n, 50);
}

}  // namespace
}  // namespace coverkit
