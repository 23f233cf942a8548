#include <coverkit/datasets/generators.h>

#include <gtest/gtest.h>

using namespace coverkit;

TEST(Generators, SameSeedSameWorldDifferentSeedDifferentWorld) {
  for (auto shape : {datasets::ObstacleShape::kRectangle, datasets::ObstacleShape::kConvex, datasets::ObstacleShape::kNonConvex, datasets::ObstacleShape::kStar}) {
    datasets::PolygonWorldSpec s;
    s.shape = shape;
    s.count = 12;
    const Workspace a = datasets::generatePolygonWorld(s), b = datasets::generatePolygonWorld(s);
    s.seed = 2;
    const Workspace c = datasets::generatePolygonWorld(s);
    EXPECT_EQ(freeArea(a), freeArea(b));
    EXPECT_NE(freeArea(a), freeArea(c));
    EXPECT_GE(a.regions[0].holes.size(), 6u);  // most obstacles placed
  }
}

TEST(Generators, GridDensity) {
  for (bool clustered : {false, true}) {
    datasets::GridMapSpec s;
    s.width = s.height = 100;
    s.density = 0.3;
    s.clustered = clustered;
    const auto g = datasets::generateGridMap(s);
    std::size_t blocked = 0;
    for (auto b : g.blocked) blocked += b;
    EXPECT_NEAR(static_cast<double>(blocked) / 10000, 0.3, 0.03) << clustered;
    EXPECT_EQ(g.blocked, datasets::generateGridMap(s).blocked);
  }
}
