#include <coverkit/datasets/generators.h>

#include <gtest/gtest.h>

using namespace coverkit;

TEST(Generators, SameSeedSameWorldDifferentSeedDifferentWorld) {
  for (auto shape : {datasets::ObstacleShape::kRectangle, datasets::ObstacleShape::kConvex, datasets::ObstacleShape::kNonConvex, datasets::ObstacleShape::kStar,
                     datasets::ObstacleShape::kRotatedRectangle, datasets::ObstacleShape::kDisc, datasets::ObstacleShape::kMixed}) {
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

TEST(Generators, ShapesNotAlignedWithTheGrid) {
  datasets::PolygonWorldSpec s;
  s.count = 10;
  s.shape = datasets::ObstacleShape::kRotatedRectangle;
  std::size_t slanted = 0;
  const Workspace rotated = datasets::generatePolygonWorld(s);
  for (const Ring& h : rotated.regions[0].holes) {
    ASSERT_EQ(h.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) slanted += h[i].x != h[(i + 1) % 4].x && h[i].y != h[(i + 1) % 4].y;
  }
  EXPECT_GT(slanted, 0u);  // edges neither horizontal nor vertical
  s.shape = datasets::ObstacleShape::kDisc;
  const Workspace discs = datasets::generatePolygonWorld(s);
  EXPECT_GE(discs.regions[0].holes.size(), 5u);
  for (const Ring& h : discs.regions[0].holes) EXPECT_GE(h.size(), 20u);  // 24-gons, after lattice rounding
  datasets::ObstacleShape parsed;
  EXPECT_TRUE(datasets::parseObstacleShape("rotated", parsed));
  EXPECT_EQ(parsed, datasets::ObstacleShape::kRotatedRectangle);
  EXPECT_TRUE(datasets::parseObstacleShape("discs", parsed));
  EXPECT_TRUE(datasets::parseObstacleShape("mixed", parsed));
  EXPECT_FALSE(datasets::parseObstacleShape("blobs", parsed));
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
