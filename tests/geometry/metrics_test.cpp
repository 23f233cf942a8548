#include <coverkit/geometry/metrics.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace coverkit;

namespace {
Problem room(int w, int h, Rational r) {
  Problem p;
  Region reg;
  reg.outer = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  p.workspace.regions.push_back(reg);
  p.robots.push_back({r, std::nullopt});
  return p;
}
Path polyline(const std::vector<PointD>& pts) { return Path::fromPoints(pts); }
}  // namespace

TEST(Metrics, ExactAreaOfADiscAndAStadium) {
  const Problem p = room(10, 10, Rational(1));
  double a = 0;
  Path dot;
  dot.start = {5, 5};
  ASSERT_TRUE(exactCoveredArea(p.workspace, Rational(1), {dot}, a));
  EXPECT_NEAR(a, M_PI, 1e-12);
  ASSERT_TRUE(exactCoveredArea(p.workspace, Rational(1), {polyline({{2, 5}, {8, 5}})}, a));
  EXPECT_NEAR(a, M_PI + 12, 1e-12);
  // a Pythagorean direction (3,4) is exact too
  ASSERT_TRUE(exactCoveredArea(p.workspace, Rational(1), {polyline({{2, 2}, {5, 6}})}, a));
  EXPECT_NEAR(a, M_PI + 10, 1e-12);
  // clipped by the workspace: a disc centred on the corner has a quarter inside
  Path corner;
  corner.start = {0, 0};
  ASSERT_TRUE(exactCoveredArea(p.workspace, Rational(1), {corner}, a));
  EXPECT_NEAR(a, M_PI / 4, 1e-12);
  // a generic direction is left to the raster
  EXPECT_FALSE(exactCoveredArea(p.workspace, Rational(1), {polyline({{2, 2}, {5, 7}})}, a));
}

TEST(Metrics, RasterAgreesWithExactWithinItsBound) {
  const Problem p = room(10, 6, Rational(1, 2));
  const Path path = polyline({{0.5, 0.5}, {9.5, 0.5}, {9.5, 1.5}, {0.5, 1.5}, {0.5, 3.5}, {6, 3.5}, {6, 5.5}});
  double exact = 0, err = 0;
  ASSERT_TRUE(exactCoveredArea(p.workspace, Rational(1, 2), {path}, exact));
  double skipped = 0;  // the path is clear: skipping the clip to F gives the same exact value
  ASSERT_TRUE(exactCoveredArea(p.workspace, Rational(1, 2), {path}, skipped, true));
  EXPECT_NEAR(skipped, exact, 1e-12);
  for (std::size_t pixels : {20'000u, 200'000u, 2'000'000u}) {
    const double raster = rasterCoveredArea(p.workspace, Rational(1, 2), {path}, pixels, err);
    EXPECT_LE(std::abs(raster - exact), err) << pixels;
    EXPECT_GT(err, 0);
  }
}

TEST(Metrics, RasterBoundStaysSmallBetweenTouchingPasses) {
  // passes exactly 2r apart: every point between them is covered, the midlines are where the
  // disc boundaries touch; refinement keeps the uncertain band thin
  const Problem p = room(20, 8, Rational(1, 2));
  std::vector<PointD> pts;
  for (int k = 0; k < 8; ++k) {
    pts.push_back({0.5, 0.5 + k});
    pts.push_back({19.5, 0.5 + k});
    if (k % 2 == 1) std::swap(pts[pts.size() - 1], pts[pts.size() - 2]);
  }
  const Path path = Path::fromPoints(pts);
  double exact = 0, err = 0;
  ASSERT_TRUE(exactCoveredArea(p.workspace, Rational(1, 2), {path}, exact));
  const double raster = rasterCoveredArea(p.workspace, Rational(1, 2), {path}, 200'000, err);
  EXPECT_LE(std::abs(raster - exact), err);
  EXPECT_LT(err / 160, 0.01);
}

TEST(Metrics, RasterIsTheSameToTheBitOnAnyNumberOfThreads) {
  // a generic direction and an arc: the raster decides every square
  const Problem p = room(12, 9, Rational(1, 3));
  Path path = Path::fromPoints({{0.4, 0.4}, {11.1, 2.3}, {1.7, 5.9}, {10.6, 8.5}});
  path.segments.push_back(PathSegment::arc({10.6, 8.5}, {6.6, 4.5}, {6.6, 8.5}, false));
  double err1 = 0;
  const double a1 = rasterCoveredArea(p.workspace, Rational(1, 3), {path}, 1'000'000, err1, 1);
  EXPECT_GT(a1, 0);
  EXPECT_GT(err1, 0);
  for (unsigned threads : {2u, 3u, 7u, 0u}) {
    double err = 0;
    const double a = rasterCoveredArea(p.workspace, Rational(1, 3), {path}, 1'000'000, err, threads);
    EXPECT_EQ(a, a1) << threads;   // bit for bit, not near
    EXPECT_EQ(err, err1) << threads;
  }
}

TEST(Metrics, LengthTurnsAndSubcells) {
  Problem p = room(4, 4, Rational(1, 2));
  const CellGrid cells = classifyCells(p.workspace, Rational(1));
  const Path path = polyline({{0.5, 0.5}, {3.5, 0.5}, {3.5, 1.5}, {0.5, 1.5}, {0.5, 0.5}});
  const Metrics m = computeMetrics(p, cells, {path});
  EXPECT_DOUBLE_EQ(m.length, 3 + 1 + 3 + 1);
  EXPECT_EQ(m.turns, 3u);
  EXPECT_NEAR(m.turningAngleDeg, 270, 1e-9);
  EXPECT_EQ(m.freeSubcells, 16u);
  EXPECT_EQ(m.coveredSubcells, 8u);
  EXPECT_DOUBLE_EQ(m.subcellCoverage, 0.5);
  EXPECT_EQ(m.revisitedSubcells, 1u);  // the start cell, entered again at the end
  EXPECT_EQ(m.areaMethod, "exact");
}
