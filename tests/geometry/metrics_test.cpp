#include <coverkit/geometry/metrics.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

// The sub-cells a path enters are defined by sampling every D/32 (docs/metrics.md); axis-parallel
// pieces step through their row or column instead. The counts must be those of the sampling, also
// where pieces start, end or run on cell boundaries, leave the grid, or have decimal coordinates.
TEST(Metrics, SubcellsOfAxisParallelPiecesAreThoseOfTheSampling) {
  const Problem p = room(12, 9, Rational(3, 10));   // D = 0.6: boundaries that are not doubles
  const CellGrid cells = classifyCells(p.workspace, Rational(3, 5));
  auto reference = [&](const Path& path) {   // the sampling of the definition
    std::vector<std::uint32_t> visits(cells.subCount(), 0);
    long last = -1;
    auto enter = [&](PointD q) {
      CellIndex c;
      if (!cells.locateSubD(q, c)) { last = -1; return; }
      const long k = static_cast<long>(c.row) * cells.subCols() + c.col;
      if (k != last) ++visits[static_cast<std::size_t>(k)];
      last = k;
    };
    const double D = cells.subSizeD();
    for (const std::vector<PointD>& pts : path.polylineWithin(D / 1000, BoxD{-D, -D, 12 + D, 9 + D})) {
      last = -1;
      enter(pts.front());
      for (std::size_t i = 1; i < pts.size(); ++i) {
        const double len = std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
        const long n = std::max(1L, static_cast<long>(std::ceil(len / (D / 32))));
        for (long k = 1; k <= n; ++k) {
          const double t = static_cast<double>(k) / static_cast<double>(n);
          enter({pts[i - 1].x + t * (pts[i].x - pts[i - 1].x), pts[i - 1].y + t * (pts[i].y - pts[i - 1].y)});
        }
      }
    }
    std::size_t entered = 0, revisited = 0;
    for (std::uint32_t v : visits) {
      entered += v > 0;
      revisited += v > 1;
    }
    return std::make_pair(entered, revisited);
  };
  std::mt19937 rng(5);
  const double coords[] = {0.6, 1.2, 0.3, 0.9, 1.8, 0.1, 0.7, 3.0000000000000004, 6, 0, 12, 2.9999999999999996};
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<PointD> pts{{0.3 + 0.6 * (rng() % 19), 0.3 + 0.6 * (rng() % 14)}};
    for (int k = 0; k < 12; ++k) {
      PointD q = pts.back();
      const double c = coords[rng() % 12] + (rng() % 10);
      (rng() % 2 ? q.x : q.y) = std::min(c, (rng() % 7 == 0) ? 13.0 : 11.9);   // now and then beyond the grid
      pts.push_back(q);
    }
    if (trial % 5 == 0) pts.push_back({pts.back().x + 0.37, pts.back().y + 0.41});   // a slanted piece too
    const Path path = polyline(pts);
    const Metrics m = computeMetrics(p, cells, {path});
    const auto [entered, revisited] = reference(path);
    ASSERT_EQ(m.enteredSubcells, entered) << "trial " << trial;
    ASSERT_EQ(m.revisitedSubcells, revisited) << "trial " << trial;
  }
}
