#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/validate.h>

#include "helpers/checkers.h"
#include "helpers/worlds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

using namespace coverkit;

using testing_helpers::boxWith;

TEST(CSpace, ConvexObstacleAreaIsAPlusPerimeterRPlusPiR2) {
  // a triangle with irrational edge normals, far from the walls; eps tiny so the bound holds at 1e-12
  const Ring tri = {{3, 3}, {6, 4}, {4, 7}};
  const Rational r(1, 2);
  const CSpace cs(boxWith({tri}), r, 1e-15);
  const double A = 0.5 * std::abs((6 - 3) * (7 - 3) - (4 - 3) * (4 - 3));
  const double P = std::hypot(3, 1) + std::hypot(2, 3) + std::hypot(1, 4);
  const double expected = (10 - 1.0) * (10 - 1.0) - (A + P * 0.5 + M_PI * 0.25);
  EXPECT_NEAR(cs.area(), expected, 1e-12 * expected);
  EXPECT_LE(cs.area(), expected);  // conservative: never more C-free than the exact one
  EXPECT_EQ(cs.componentCount(), 1u);
}

TEST(CSpace, SquareGivesARoundedSquare) {
  const Rational r(1, 4);
  const CSpace cs(boxWith({{{4, 4}, {6, 4}, {6, 6}, {4, 6}}}), r, 1e-15);
  const double expected = 9.5 * 9.5 - (4 + 8 * 0.25 + M_PI / 16);
  EXPECT_NEAR(cs.area(), expected, 1e-12 * expected);
  // the C-obstacle of the square: straight sides and four quarter circles about the corners
  std::size_t arcs = 0, lines = 0, found = 0;
  for (const CurveRegion& o : cs.obstacles())
    if (std::abs(o.area - (4 + 2 + M_PI / 16)) < 1e-9) {
      ++found;
      for (const PathSegment& s : o.outer.pieces) (s.kind == PathSegment::Kind::kArc ? arcs : lines) += 1;
    }
  EXPECT_EQ(found, 1u);
  EXPECT_EQ(lines, 4u);
  EXPECT_GE(arcs, 4u);  // each quarter circle may be split at its x-extreme points
}

TEST(CSpace, GapsNarrowerThanTheDiscCloseAndTwoRExactlyIsClosed) {
  // two 4×4 rooms joined by a neck of width g
  auto rooms = [](const Rational& g) {
    Workspace w;
    Region reg;
    const Rational lo = 2 - g / 2, hi = 2 + g / 2;
    reg.outer = {{0, 0}, {4, 0}, {4, lo}, {6, lo}, {6, 0}, {10, 0}, {10, 4}, {6, 4}, {6, hi}, {4, hi}, {4, 4}, {0, 4}};
    w.regions.push_back(reg);
    normalise(w);
    return w;
  };
  const Rational r(1, 2);
  EXPECT_EQ(CSpace(rooms(Rational(101, 100)), r).componentCount(), 1u);
  EXPECT_EQ(CSpace(rooms(Rational(99, 100)), r).componentCount(), 2u);
  // g = 2r: the polygons (an inner approximation) drop the zero-width passage, but the closed C-free
  // (the validator's convention) passes it: one closed component
  const CSpace exactGap(rooms(Rational(1)), r);
  EXPECT_EQ(exactGap.componentCount(), 2u);
  const Point left{Rational(1), Rational(2)}, right{Rational(9), Rational(2)};
  EXPECT_GE(exactGap.closedComponentOf(left), 0);
  EXPECT_EQ(exactGap.closedComponentOf(left), exactGap.closedComponentOf(right));
  EXPECT_GE(exactGap.closedComponentOf({Rational(5), Rational(2)}), 0);  // the neck's centre line is free
  const CSpace narrower(rooms(Rational(99, 100)), r);
  EXPECT_NE(narrower.closedComponentOf(left), narrower.closedComponentOf(right));
  EXPECT_EQ(narrower.closedComponentOf({Rational(5), Rational(2)}), -1);
  EXPECT_GT(exactGap.closedMargin(), 0);
  EXPECT_LT(exactGap.closedMargin(), 1e-4);
}

TEST(CSpace, ObstaclesMergeWhenTheGapIsBelowTwoR) {
  auto two = [](const Rational& g) {
    const Rational x = 4 + g;
    return boxWith({{{2, 4}, {4, 4}, {4, 6}, {2, 6}}, {{x, 4}, {Rational(x + 2), 4}, {Rational(x + 2), 6}, {x, 6}}}, 12, 10);
  };
  const Rational r(1, 2);
  // the obstacles' union: the band outside the eroded box, plus one or two C-obstacles
  EXPECT_EQ(CSpace(two(Rational(9, 10)), r).obstacles().size(), 2u);
  EXPECT_EQ(CSpace(two(Rational(11, 10)), r).obstacles().size(), 3u);
}

TEST(CSpace, CoarseApproximationLiesInsideTheFineOne) {
  datasets::PolygonWorldSpec s;
  s.count = 10;
  s.shape = datasets::ObstacleShape::kStar;
  s.seed = 5;
  const Workspace w = datasets::generatePolygonWorld(s);
  const Rational r(3, 10);
  const CSpace coarse(w, r, 1e-3), fine(w, r, 1e-9);
  EXPECT_LE(coarse.area(), fine.area());
  EXPECT_NEAR(coarse.area(), fine.area(), 1e-3 * 20 * 200);  // eps × total boundary length, generously
  std::mt19937_64 rng(9);
  for (int i = 0; i < 400; ++i) {
    const Point p{ratio(static_cast<long>(rng() % 2000), 100), ratio(static_cast<long>(rng() % 2000), 100)};
    if (coarse.contains(p)) {
      EXPECT_TRUE(fine.contains(p));
    }
  }
}

TEST(CSpace, RandomPointsFarFromBoundariesMatchTheDistanceTest) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    datasets::PolygonWorldSpec s;
    s.count = 12;
    s.shape = static_cast<datasets::ObstacleShape>(seed % 4);
    s.seed = seed;
    const Workspace w = datasets::generatePolygonWorld(s);
    const double r = 0.4;
    const CSpace cs(w, ratio(2, 5), 1e-6);
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int i = 0; i < 600; ++i) {
      const double x = static_cast<double>(rng() % 20000) / 1000, y = static_cast<double>(rng() % 20000) / 1000;
      double d = 1e300;
      bool inside = false;
      for (const Ring* ring : w.rings())
        for (std::size_t k = 0; k < ring->size(); ++k) {
          const double ax = (*ring)[k].x.get_d(), ay = (*ring)[k].y.get_d();
          const double bx = (*ring)[(k + 1) % ring->size()].x.get_d(), by = (*ring)[(k + 1) % ring->size()].y.get_d();
          const double dx = bx - ax, dy = by - ay, t = std::clamp(((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
          d = std::min(d, std::hypot(x - ax - t * dx, y - ay - t * dy));
          if ((ay > y) != (by > y) && ax + (y - ay) * dx / dy > x) inside = !inside;
        }
      if (std::abs(d - r) < 1e-3) continue;  // near the C-space boundary: no claim
      ++checked;
      EXPECT_EQ(cs.contains({exactFromDouble(x), exactFromDouble(y)}), inside && d > r) << x << "," << y << " d=" << d;
    }
    EXPECT_GT(checked, 500);
  }
}

TEST(CSpace, GridMapAndTheSamePolygonsGiveTheSameCFree) {
  const Workspace g = datasets::parseTextGrid("resolution 0.5\n........\n..##....\n..##....\n........\n", "t.grid");
  const Workspace p = datasets::parseWkt("POLYGON((0 0, 4 0, 4 2, 0 2, 0 0),(1 0.5, 2 0.5, 2 1.5, 1 1.5, 1 0.5))", "t.wkt");
  const CSpace a(g, ratio(1, 5)), b(p, ratio(1, 5));
  EXPECT_NEAR(a.area(), b.area(), 1e-12);
  EXPECT_EQ(a.componentCount(), b.componentCount());
}

TEST(CSpace, RegionsAreSeparate) {
  // two rooms side by side as two polygons: each has its own C-free
  const Workspace w = datasets::parseWkt("MULTIPOLYGON(((0 0, 4 0, 4 4, 0 4, 0 0)),((5 0, 9 0, 9 4, 5 4, 5 0)))", "two.wkt");
  const CSpace cs(w, ratio(1, 2), 1e-15);
  EXPECT_EQ(cs.componentCount(), 2u);
  EXPECT_NEAR(cs.area(), 2 * 9.0, 1e-12);
  // and the band along the walls: W minus C-free
  double band = 0;
  for (const CurveRegion& o : cs.obstacles()) band += o.area;
  EXPECT_NEAR(band, 32 - 18, 1e-12);
}

TEST(CSpace, ComponentOfAPointAndBadRadius) {
  const CSpace cs(boxWith({{{4, 0.5}, {6, 0.5}, {6, 9.5}, {4, 9.5}}}), ratio(1, 2));
  EXPECT_EQ(cs.componentCount(), 2u);  // the gaps of 0.5 above and below the wall are below 2r = 1
  EXPECT_NE(cs.componentOf({Rational(2), Rational(5)}), cs.componentOf({Rational(8), Rational(5)}));
  EXPECT_THROW(CSpace(boxWith({}), Rational(-1)), InputError);
  EXPECT_EQ(cs.componentOf({Rational(5), Rational(5)}), -1);  // inside the obstacle
  EXPECT_EQ(cs.componentOf({Rational(1, 4), Rational(5)}), -1);  // closer than r to the wall
  EXPECT_GE(cs.componentOf({Rational(2), Rational(5)}), 0);
}

TEST(CSpaceCells, AreasAddUpAndStatesAgreeWithPoints) {
  datasets::PolygonWorldSpec s;
  s.count = 8;
  s.shape = datasets::ObstacleShape::kNonConvex;
  s.seed = 4;
  const Workspace w = datasets::generatePolygonWorld(s);
  const Rational r(2, 5);
  const CSpace cs(w, r);
  const CellGrid grid = classifyCells(w, 2 * r);
  const CSpaceCells cc = cs.classify(grid);
  const double D = grid.subSizeD();
  // C-free area = free mega-cells + the pieces of partial ones
  double sum = 0;
  std::size_t partial = 0;
  for (int m = 0; m < grid.megaRows(); ++m)
    for (int c = 0; c < grid.megaCols(); ++c) {
      if (cc.mega(c, m) == CellState::kFree) sum += 4 * D * D;
      if (cc.mega(c, m) == CellState::kPartial) {
        ++partial;
        const auto* mc = cc.contour(c, m);
        ASSERT_NE(mc, nullptr);
        for (const CurveRegion& p : mc->pieces) sum += p.area;
      }
    }
  EXPECT_NEAR(sum, cs.area(), 1e-9 * cs.area());
  EXPECT_EQ(partial, cc.contours.size());
  // free sub-cells: corners and centre in C-free; blocked: centre not strictly inside
  for (int row = 0; row < grid.subRows(); ++row)
    for (int col = 0; col < grid.subCols(); ++col) {
      const Point ctr = grid.subCenter(col, row);
      if (cc.subState(col, row) == CellState::kFree) {
        EXPECT_TRUE(cs.contains(ctr));
        EXPECT_TRUE(cs.contains({grid.originX() + grid.subSize() * col, grid.originY() + grid.subSize() * row}));
      }
      if (cc.subState(col, row) == CellState::kBlocked) {
        // a point a hair inside the cell's centre region is outside C-free or on its boundary:
        // checked with the exact centre; the centre can be on the boundary only in degenerate cases
        if (cs.contains(ctr)) ADD_FAILURE() << "blocked cell " << col << "," << row << " has its centre in C-free";
      }
    }
}

TEST(CSpaceCells, ChainsRunFromBorderToBorder) {
  const Workspace w = boxWith({{{3, 3}, {5, 3}, {4, 5}}}, 8, 8);
  const CSpace cs(w, Rational(1, 2));
  const CellGrid grid = classifyCells(w, Rational(1));
  const CSpaceCells cc = cs.classify(grid);
  ASSERT_FALSE(cc.contours.empty());
  std::size_t chains = 0;
  for (const auto& mc : cc.contours) {
    const double x0 = 2.0 * mc.col, x1 = x0 + 2, y0 = 2.0 * mc.row, y1 = y0 + 2;
    auto onBorder = [&](PointD p) {
      return std::abs(p.x - x0) < 1e-9 || std::abs(p.x - x1) < 1e-9 || std::abs(p.y - y0) < 1e-9 || std::abs(p.y - y1) < 1e-9;
    };
    for (const auto& ch : mc.chains) {
      ++chains;
      ASSERT_FALSE(ch.pieces.empty());
      for (std::size_t i = 1; i < ch.pieces.size(); ++i) {
        EXPECT_NEAR(ch.pieces[i].from.x, ch.pieces[i - 1].to.x, 1e-9);
        EXPECT_NEAR(ch.pieces[i].from.y, ch.pieces[i - 1].to.y, 1e-9);
      }
      if (!ch.closed) {
        EXPECT_TRUE(onBorder(ch.entry)) << mc.col << "," << mc.row;
        EXPECT_TRUE(onBorder(ch.exit)) << mc.col << "," << mc.row;
      }
    }
  }
  EXPECT_GT(chains, 0u);
}

TEST(CSpace, CoverableAreaOfARoomWithAPillar) {
  // an axis-aligned room with a square pillar: the disc reaches everything but the room's four
  // corners, where it leaves (4 - π)r² each; the pillar's corners are convex, reached exactly
  const Rational r(1, 2);
  const CSpace cs(boxWith({{{4, 4}, {6, 4}, {6, 6}, {4, 6}}}), r, 1e-12);
  double err = 0;
  const double a = cs.coverableArea({{Rational(1), Rational(1)}}, err);
  const double expected = 100 - 4 - 4 * (1 - M_PI / 4) * 0.25;
  EXPECT_LE(std::abs(a - expected), err + 1e-9);
  EXPECT_LT(err, 0.01 * expected);
  double err2 = 0;
  EXPECT_DOUBLE_EQ(coverableArea(boxWith({{{4, 4}, {6, 4}, {6, 6}, {4, 6}}}), r, {{Rational(1), Rational(1)}}, err2, 1e-12),
                   a);  // the same without a C-space of radius r
  EXPECT_EQ(cs.coverableArea({{Rational(5), Rational(5)}}, err), 0);  // a start in no component
}

TEST(CSpace, ClearanceAgainstCObstaclesIsConservativeAndExactOnStraightWalls) {
  datasets::PolygonWorldSpec s;
  s.count = 10;
  s.shape = datasets::ObstacleShape::kConvex;
  s.seed = 8;
  const Workspace w = datasets::generatePolygonWorld(s);
  const Rational r(3, 10);
  const CSpace cs(w, r);
  std::mt19937_64 rng(77);
  int clear = 0, blocked = 0;
  for (int i = 0; i < 300; ++i) {
    const Point a{ratio(static_cast<long>(rng() % 2000), 100), ratio(static_cast<long>(rng() % 2000), 100)};
    const Point b{Rational(a.x + ratio(static_cast<long>(rng() % 400) - 200, 100)), Rational(a.y + ratio(static_cast<long>(rng() % 400) - 200, 100))};
    const bool byCSpace = cs.segmentClear(a, b);
    const bool exact = strictlyInside(w, a) && segmentClear(w, r, a, b);
    if (byCSpace) {
      EXPECT_TRUE(exact) << "C-space says clear, the exact test does not";
    }
    (byCSpace ? clear : blocked) += 1;
  }
  EXPECT_GT(clear, 30);
  EXPECT_GT(blocked, 30);
  // straight walls are offset exactly: a segment at distance exactly r from the box wall is clear
  EXPECT_TRUE(cs.segmentClear({Rational(3, 10), Rational(1, 2)}, {Rational(3, 10), Rational(3, 2)}));
  EXPECT_FALSE(cs.segmentClear({Rational(29, 100), Rational(1, 2)}, {Rational(29, 100), Rational(3, 2)}));
}

TEST(CSpace, ArcClearance) {
  const CSpace cs(boxWith({{{4, 4}, {6, 4}, {6, 6}, {4, 6}}}), Rational(1, 2));
  // radius 3 about the square's centre: clear; radius 1.5: meets the rounded corners
  EXPECT_TRUE(cs.arcClear({Rational(8), Rational(5)}, {Rational(2), Rational(5)}, {Rational(5), Rational(5)}, true));
  EXPECT_TRUE(cs.arcClear({Rational(8), Rational(5)}, {Rational(8), Rational(5)}, {Rational(5), Rational(5)}, true));  // full circle
  EXPECT_FALSE(cs.arcClear({Rational(13, 2), Rational(5)}, {Rational(7, 2), Rational(5)}, {Rational(5), Rational(5)}, true));
  // radius 4.6 reaches within 0.4 of the walls: not clear for r = 1/2
  EXPECT_FALSE(cs.arcClear({ratio(96, 10), Rational(5)}, {ratio(4, 10), Rational(5)}, {Rational(5), Rational(5)}, false));
  // the end is the ray through `to`: a far point on the same ray gives the same arc
  EXPECT_TRUE(cs.arcClear({Rational(8), Rational(5)}, {Rational(5), Rational(100)}, {Rational(5), Rational(5)}, true));
}

TEST(CSpace, RadiusZeroGivesTheObstaclesBack) {
  const Workspace w = boxWith({{{4, 4}, {6, 4}, {5, 6}}, {{1, 1}, {2, 1}, {2, 2}, {1, 2}}});
  const CSpace cs(w, Rational(0));
  EXPECT_NEAR(cs.area(), freeArea(w).get_d(), 1e-12);
  EXPECT_EQ(cs.componentCount(), 1u);
  double obstacles = 0;
  for (const CurveRegion& o : cs.obstacles()) obstacles += o.area;
  EXPECT_NEAR(obstacles, 2 + 1, 1e-12);  // the two holes, nothing else
  EXPECT_FALSE(cs.contains({Rational(5), Rational(5)}));
  EXPECT_TRUE(cs.contains({Rational(4), Rational(4)}));  // on an obstacle's boundary: closed C-free
}

// CGAL's approximated_offset_2 returns a boundary that does not close for this 24-gon (a disc of
// radius about 0.26 from the generator) at r = 0.2; the obstacle then vanished from C-free and
// plans crossed it. Such an offset is now replaced by the offsets of the polygon's triangles.
TEST(CSpace, AnOffsetThatDoesNotCloseIsReplaced) {
  const double v[][2] = {{11.55, 3.02}, {11.53, 2.95}, {11.49, 2.9},  {11.44, 2.85}, {11.38, 2.82}, {11.31, 2.81},
                         {11.24, 2.82}, {11.18, 2.84}, {11.12, 2.88}, {11.08, 2.93}, {11.05, 2.99}, {11.04, 3.06},
                         {11.04, 3.13}, {11.06, 3.19}, {11.1, 3.25},  {11.15, 3.29}, {11.22, 3.32}, {11.28, 3.33},
                         {11.35, 3.33}, {11.42, 3.3},  {11.47, 3.27}, {11.52, 3.21}, {11.54, 3.15}, {11.56, 3.09}};
  Ring disc;
  for (const auto& q : v) disc.push_back({parseRational(formatDouble(q[0])), parseRational(formatDouble(q[1]))});
  const Workspace w = testing_helpers::boxWith({disc}, 25, 15);
  const CSpace cs(w, Rational(1, 5));
  EXPECT_FALSE(cs.contains({parseRational("11.2624"), parseRational("2.85")}));   // inside the obstacle
  EXPECT_FALSE(cs.contains({parseRational("11.3"), parseRational("2.65")}));      // 0.16 below it
  EXPECT_TRUE(cs.contains({parseRational("11.3"), parseRational("2.5")}));        // 0.31 below it
  EXPECT_LT(cs.area(), 24.6 * 14.6 - 0.5);                                        // the eroded box minus the obstacle
}

namespace {

int turn(const Point& a, const Point& b, const Point& c) {
  return sgn(Rational((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)));
}

double distanceToRing(const std::vector<PointD>& ring, PointD p) {
  double d = 1e300;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const PointD a = ring[k], b = ring[(k + 1) % ring.size()];
    const double dx = b.x - a.x, dy = b.y - a.y, t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    d = std::min(d, std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy));
  }
  return d;
}

}  // namespace

// Convex obstacles are offset directly (cspace.cpp, convexOffset): tangent roofs over the edges,
// exact arcs about the vertices. Seeded convex polygons of 3-40 vertices, sizes 0.05-20, radii
// 0.001-10, eps 1e-9-1e-3 of the extent: the C-obstacle's boundary lies at distance >= r from the
// polygon (outside the exact offset: C-free stays conservative) and within eps of r (CGAL's
// approximated_offset_2 left up to 93 × eps here), and its area is the exact offset's,
// A + P·r + π·r², up to eps × its perimeter.
TEST(CSpace, ConvexOffsetsLieOutsideTheExactOneWithinEps) {
  std::mt19937_64 rng(2026);
  const double radii[] = {0.001, 0.05, 0.5, 3, 10}, epss[] = {1e-9, 1e-6, 1e-3};
  for (int trial = 0; trial < 150; ++trial) {
    const int n = 3 + static_cast<int>(rng() % 38);
    const double size = std::exp(std::uniform_real_distribution<double>(std::log(0.05), std::log(20))(rng));
    std::vector<double> angles(static_cast<std::size_t>(n));
    for (double& a : angles) a = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
    std::sort(angles.begin(), angles.end());
    Ring ring;
    for (double a : angles) {
      const Point p{ratio(std::lround((50 + size * std::cos(a)) * 1e6), 1000000), ratio(std::lround((50 + size * std::sin(a)) * 1e6), 1000000)};
      if (!ring.empty() && p == ring.back()) continue;
      ring.push_back(p);
    }
    // the vertices where the rounded ring turns left (rounding may dent the circle); a trial whose
    // remaining ring is still not strictly convex is skipped
    Ring hull;
    for (std::size_t i = 0; i < ring.size(); ++i)
      if (turn(ring[(i + ring.size() - 1) % ring.size()], ring[i], ring[(i + 1) % ring.size()]) > 0) hull.push_back(ring[i]);
    if (hull.size() < 3) continue;
    bool convex = true;
    for (std::size_t i = 0; i < hull.size(); ++i)
      convex = convex && turn(hull[(i + hull.size() - 1) % hull.size()], hull[i], hull[(i + 1) % hull.size()]) > 0;
    if (!convex) continue;
    std::vector<PointD> ringD;
    for (const Point& p : hull) ringD.push_back({p.x.get_d(), p.y.get_d()});
    const double r = radii[rng() % 5], relEps = epss[rng() % 3];
    const CSpace cs(testing_helpers::boxWith({hull}, 100, 100), exactFromDouble(r), relEps);
    const double eps = cs.epsilon();
    SCOPED_TRACE("trial " + std::to_string(trial) + ": " + std::to_string(hull.size()) + " vertices, size " + std::to_string(size) +
                 ", r " + std::to_string(r) + ", eps " + std::to_string(eps));
    ASSERT_EQ(cs.componentCount(), 1u);
    const std::vector<CurveRegion> comps = cs.components();
    ASSERT_EQ(comps[0].holes.size(), 1u);
    double A = 0, P = 0;
    for (std::size_t k = 0; k < ringD.size(); ++k) {
      const PointD a = ringD[k], b = ringD[(k + 1) % ringD.size()];
      A += a.x * b.y - b.x * a.y;
      P += std::hypot(b.x - a.x, b.y - a.y);
    }
    A /= 2;
    double lowest = 1e300, highest = -1e300;
    for (const PathSegment& s : comps[0].holes[0].pieces) {
      Path piece;
      piece.start = s.from;
      piece.segments = {s};
      for (const PointD& q : piece.polyline(1e-3 * r)) {
        const double d = distanceToRing(ringD, q) - r;
        lowest = std::min(lowest, d);
        highest = std::max(highest, d);
      }
    }
    const double tol = 1e-9 * (1 + size + r);  // the doubles of the pieces and of the distance
    EXPECT_GE(lowest, -tol);
    EXPECT_LE(highest, eps + tol);
    const double exact = A + P * r + M_PI * r * r, offset = (100 - 2 * r) * (100 - 2 * r) - cs.area();
    EXPECT_GE(offset, exact - 1e-10 * 1e4);
    EXPECT_LE(offset, exact + (P + 2 * M_PI * r) * eps + 1e-10 * 1e4);
  }
}

namespace {

/// Sweep requests over the workspace's box: bases of length D along both axes in both directions,
/// at every D/2 step, with depths 2D and 6D (a mega-cell, and a run of three).
std::vector<CSpace::SweepRequest> sweepRequestsOver(const Workspace& w, const Rational& D) {
  const Box b = w.bbox();
  std::vector<CSpace::SweepRequest> out;
  int k = 0;
  for (Rational y = b.ymin + D / 4; y + D < b.ymax; y += D / 2)
    for (Rational x = b.xmin + D / 4; x + D < b.xmax; x += D / 2, ++k) {
      const Rational depth = k % 5 == 0 ? Rational(6 * D) : Rational(2 * D);
      const Point p{x, y}, px{Rational(x + D), y}, py{x, Rational(y + D)};
      switch (k % 4) {
        case 0: out.push_back({p, px, depth}); break;
        case 1: out.push_back({px, p, depth}); break;
        case 2: out.push_back({p, py, depth}); break;
        default: out.push_back({py, p, depth}); break;
      }
    }
  return out;
}

/// 520 teeth along the bottom of a 52 × 6 room (2,082 vertices, offset as triangles), with `holes`.
Workspace combWorld(std::vector<Ring> holes) {
  Region comb;
  for (int t = 0; t < 520; ++t) {
    const Rational x0 = ratio(t, 10), x1 = ratio(2 * t + 1, 20), x2 = ratio(t + 1, 10);
    comb.outer.push_back({x0, 0});
    comb.outer.push_back({x1, 0});
    comb.outer.push_back({x1, 1});
    comb.outer.push_back({x2, 1});
  }
  comb.outer.push_back({52, 6});
  comb.outer.push_back({0, 6});
  comb.holes = std::move(holes);
  Workspace w;
  w.name = "comb";
  w.regions.push_back(comb);
  normalise(w);
  return w;
}

/// Rooms that are separate regions, on a grid of 1 m.
Workspace roomsWorld() {
  return datasets::parseTextGrid("resolution 1\n"
                                 "###########\n"
                                 "#....#....#\n"
                                 "#.#..#....#\n"
                                 "#....#.#..#\n"
                                 "######....#\n"
                                 "#....######\n"
                                 "#.........#\n"
                                 "###########\n",
                                 "rooms.grid");
}

::testing::AssertionResult sameSweeps(const std::vector<CSpace::Sweep>& a, const std::vector<CSpace::Sweep>& b) {
  if (a.size() != b.size()) return ::testing::AssertionFailure() << a.size() << " against " << b.size() << " sweeps";
  for (std::size_t i = 0; i < a.size(); ++i) {
    const CSpace::Sweep &s = a[i], &t = b[i];
    bool same = s.reached == t.reached && s.farSide == t.farSide && s.pieces.size() == t.pieces.size() && s.entry.x == t.entry.x &&
                s.entry.y == t.entry.y && s.exit.x == t.exit.x && s.exit.y == t.exit.y;
    for (std::size_t j = 0; same && j < s.pieces.size(); ++j) {
      const PathSegment &p = s.pieces[j], &q = t.pieces[j];
      same = p.kind == q.kind && p.from.x == q.from.x && p.from.y == q.from.y && p.to.x == q.to.x && p.to.y == q.to.y &&
             (p.kind == PathSegment::Kind::kLine || (p.center.x == q.center.x && p.center.y == q.center.y && p.ccw == q.ccw));
    }
    if (!same) return ::testing::AssertionFailure() << "sweep " << i << " differs (" << s.pieces.size() << " and " << t.pieces.size() << " pieces)";
  }
  return ::testing::AssertionSuccess();
}

}  // namespace

// CSpace::localSweeps builds U ∩ C-free from the C-obstacle pieces near U: the same exact set as
// the whole C-space's, so the same sweeps to the bit, for any number of threads (the direct trace
// off: TracedSweepsAreTheExactOnesUpToRounding compares it). Worlds: seeded
// polygon worlds (every shape), a clustered grid map (obstacles on the border: a ragged outer
// ring), rooms that are separate regions, and an outer ring of more than 2,000 vertices (offset
// as triangles, only those near the strip's requests).
TEST(CSpace, LocalSweepsAreTheWholeCSpacesSweeps) {
  std::vector<std::pair<Workspace, Rational>> worlds;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) worlds.emplace_back(testing_helpers::mixedWorld(seed, 12, 8), ratio(1, 4));
  datasets::GridMapSpec g;
  g.width = g.height = 40;
  g.density = 0.2;
  g.clustered = true;
  g.seed = 7;
  worlds.emplace_back(datasets::gridToWorkspace(datasets::generateGridMap(g), "clustered"), ratio(1, 2));
  worlds.emplace_back(roomsWorld(), ratio(1, 4));
  const Workspace comb = combWorld({{{10, 2}, {12, 2}, {12, 4}, {10, 4}}, {{40, 2}, {43, 4}, {41, 5}}});
  ASSERT_GT(comb.regions.at(0).outer.size(), 2000u);
  worlds.emplace_back(comb, ratio(1, 2));
  for (const auto& [w, r] : worlds) {
    const std::vector<CSpace::SweepRequest> requests = sweepRequestsOver(w, Rational(2 * r));
    ASSERT_GT(requests.size(), 50u) << w.name;
    const std::vector<CSpace::Sweep> whole = CSpace(w, r).sweeps(requests);
    std::size_t reached = 0, arcs = 0;
    for (const CSpace::Sweep& s : whole) {
      reached += s.reached;
      for (const PathSegment& p : s.pieces) arcs += p.kind == PathSegment::Kind::kArc;
    }
    EXPECT_GT(reached, requests.size() / 4) << w.name;
    EXPECT_GT(arcs, 0u) << w.name;
    EXPECT_TRUE(sameSweeps(whole, CSpace::localSweeps(w, r, requests, 1e-6, 1, false))) << w.name;
    EXPECT_TRUE(sameSweeps(whole, CSpace::localSweeps(w, r, requests, 1e-6, 3, false))) << w.name << ", 3 threads";
  }
  // A small robot in a huge map: requests of 0.04 m spread over 100 km would ask for 10^13 buckets;
  // their count is capped (coarser buckets, the same sweeps).
  const Workspace huge = boxWith({{{10, 10}, {11, 10}, {11, 11}, {10, 11}}, {{99000, 99000}, {99001, 99000}, {99000, 99001}}}, 100000, 100000);
  const Rational small(1, 100), D(1, 50);
  std::vector<CSpace::SweepRequest> requests;
  for (const Rational& at : {Rational(10), Rational(99000)})
    for (int k = -3; k <= 3; ++k) {
      const Point p{Rational(at + k * D), Rational(at - D / 2)}, q{Rational(at + k * D + D), Rational(at - D / 2)};
      requests.push_back({q, p, Rational(2 * D)});
    }
  const std::vector<CSpace::Sweep> whole = CSpace(huge, small).sweeps(requests);
  EXPECT_TRUE(sameSweeps(whole, CSpace::localSweeps(huge, small, requests, 1e-6, 1, false))) << "huge map";
  std::size_t reached = 0;
  for (const CSpace::Sweep& sw : whole) reached += sw.reached;
  EXPECT_GT(reached, 4u);
}

namespace {

/// The radius Smooth-STC sweeps with: r + ε + δ (planners/src/smooth_stc.cpp, slackOf).
Rational sweepRadius(const Workspace& w, const Rational& r) {
  const Box b = w.bbox();
  const double extent = std::max(Rational(b.xmax - b.xmin).get_d(), Rational(b.ymax - b.ymin).get_d());
  return Rational(r + exactFromDouble(std::ldexp(1.0, std::ilogb(1e-6 * extent) + 1)) + exactFromDouble(std::ldexp(1.0, std::ilogb(extent) - 36)));
}

}  // namespace

// The direct trace among axis-parallel edges (CSpace::localSweeps with `trace`) against the exact
// Boolean operations, at the radius Smooth-STC sweeps with. Grid maps (pixels of 1 and of 0.05, a
// clustered map, rooms): every request is traced (requests over the whole box, bases in obstacles
// too); an outer ring of 2,000 vertices, teeth narrower than r touching one offset line: 99 %.
// Every traced sweep is the exact one to within 1e-9 of the extent (the same pieces, kinds, arcs'
// centres, entry, exit, reach and far side); the others are the exact ones to the bit. Polygon
// worlds with slanted edges: the requests whose edges within reach are all axis-parallel (about
// three quarters) are traced. The trace does not depend on the threads.
TEST(CSpace, TracedSweepsAreTheExactOnesUpToRounding) {
  struct World {
    Workspace w;
    Rational r;
    double tracedAtLeast;  // share of the requests traced
  };
  std::vector<World> worlds;
  datasets::GridMapSpec g;
  g.width = g.height = 40;
  g.density = 0.2;
  g.clustered = true;
  g.seed = 7;
  worlds.push_back({datasets::gridToWorkspace(datasets::generateGridMap(g), "clustered"), ratio(1, 2), 0.99});
  g.density = 0.1;
  g.seed = 3;
  g.resolution = Rational(1, 20);
  worlds.push_back({datasets::gridToWorkspace(datasets::generateGridMap(g), "clustered 0.05"), ratio(3, 40), 0.99});
  worlds.push_back({roomsWorld(), ratio(1, 4), 0.99});
  worlds.push_back({combWorld({{{10, 2}, {12, 2}, {12, 4}, {10, 4}}}), ratio(1, 2), 0.9});
  for (std::uint64_t seed = 1; seed <= 2; ++seed) worlds.push_back({testing_helpers::mixedWorld(seed, 12, 8), ratio(1, 4), 0.5});
  for (const World& world : worlds) {
    const Rational R = sweepRadius(world.w, world.r);
    const std::vector<CSpace::SweepRequest> requests = sweepRequestsOver(world.w, Rational(2 * world.r));
    ASSERT_GT(requests.size(), 50u) << world.w.name;
    const std::vector<CSpace::Sweep> exact = CSpace::localSweeps(world.w, R, requests, 1e-6, 1, false);
    const std::vector<CSpace::Sweep> traced = CSpace::localSweeps(world.w, R, requests, 1e-6, 1, true);
    EXPECT_TRUE(sameSweeps(traced, CSpace::localSweeps(world.w, R, requests, 1e-6, 3, true))) << world.w.name << ", 3 threads";
    const Box b = world.w.bbox();
    const double tol = 1e-9 * std::max(Rational(b.xmax - b.xmin).get_d(), Rational(b.ymax - b.ymin).get_d());
    auto near = [&](PointD p, PointD q) { return std::abs(p.x - q.x) <= tol && std::abs(p.y - q.y) <= tol; };
    std::size_t count = 0, reached = 0;
    for (std::size_t i = 0; i < requests.size(); ++i) {
      const CSpace::Sweep &s = traced[i], &t = exact[i];
      if (!s.traced) {
        EXPECT_TRUE(sameSweeps({s}, {t})) << world.w.name << ", request " << i << " (not traced)";
        continue;
      }
      ++count;
      reached += s.reached;
      ASSERT_EQ(s.reached, t.reached) << world.w.name << ", request " << i;
      if (!s.reached) continue;
      EXPECT_EQ(s.farSide, t.farSide) << world.w.name << ", request " << i;
      EXPECT_TRUE(near(s.entry, t.entry) && near(s.exit, t.exit)) << world.w.name << ", request " << i;
      ASSERT_EQ(s.pieces.size(), t.pieces.size()) << world.w.name << ", request " << i;
      for (std::size_t j = 0; j < s.pieces.size(); ++j) {
        const PathSegment &p = s.pieces[j], &q = t.pieces[j];
        EXPECT_EQ(p.kind, q.kind) << world.w.name << ", request " << i << ", piece " << j;
        EXPECT_TRUE(near(p.from, q.from) && near(p.to, q.to)) << world.w.name << ", request " << i << ", piece " << j;
        if (p.kind == PathSegment::Kind::kArc) {
          EXPECT_TRUE(near(p.center, q.center) && p.ccw == q.ccw) << world.w.name << ", request " << i;
        }
      }
    }
    EXPECT_GE(static_cast<double>(count), world.tracedAtLeast * static_cast<double>(requests.size())) << world.w.name;
    if (world.tracedAtLeast > 0) {
      EXPECT_GT(reached, count / 4) << world.w.name;
    }
    std::cout << world.w.name << ": " << count << " of " << requests.size() << " requests traced\n";
  }
}
