// geometry/fillet.h: the fillet of a corner between two pieces (lines and arcs), in doubles. Its
// properties: tangent to both pieces at its ends, of the radius asked, on the inner side of the
// turn, each piece only shortened; and roundCorners rounds arc pairs only when asked to.
#include <coverkit/geometry/fillet.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace coverkit;

namespace {

double dist(PointD a, PointD b) { return std::hypot(a.x - b.x, a.y - b.y); }

void expectFillet(const PathSegment& a, const PathSegment& b, double rho) {
  PathSegment a2, f, b2;
  ASSERT_TRUE(filletCorner(a, b, rho, a2, f, b2));
  EXPECT_EQ(f.kind, PathSegment::Kind::kArc);
  EXPECT_NEAR(dist(f.from, f.center), rho, 1e-12);
  EXPECT_NEAR(dist(f.to, f.center), rho, 1e-12);
  // continuous, tangent at both ends, turning the way the corner does
  EXPECT_NEAR(dist(a2.to, f.from), 0, 1e-15);
  EXPECT_NEAR(dist(f.to, b2.from), 0, 1e-15);
  EXPECT_NEAR(turnAt(a2, f), 0, 1e-9);
  EXPECT_NEAR(turnAt(f, b2), 0, 1e-9);
  EXPECT_EQ(f.ccw, turnAt(a, b) > 0);
  // the pieces only shortened, from their far ends unchanged
  EXPECT_EQ(a2.from.x, a.from.x);
  EXPECT_EQ(a2.from.y, a.from.y);
  EXPECT_EQ(b2.to.x, b.to.x);
  EXPECT_EQ(b2.to.y, b.to.y);
  EXPECT_LT(a2.length(), a.length());
  EXPECT_LT(b2.length(), b.length());
  if (a.kind == PathSegment::Kind::kArc) {
    EXPECT_EQ(dist(a2.center, a.center), 0);
  }
  if (b.kind == PathSegment::Kind::kArc) {
    EXPECT_EQ(dist(b2.center, b.center), 0);
  }
}

}  // namespace

TEST(Fillet, LineAndLine) {
  const PathSegment a = PathSegment::line({0, 0}, {2, 0}), b = PathSegment::line({2, 0}, {2, 2});
  expectFillet(a, b, 0.5);
  PathSegment a2, f, b2;
  ASSERT_TRUE(filletCorner(a, b, 0.5, a2, f, b2));
  EXPECT_NEAR(f.center.x, 1.5, 1e-12);   // a right angle: tangent points 0.5 from the corner
  EXPECT_NEAR(f.center.y, 0.5, 1e-12);
  EXPECT_FALSE(filletCorner(a, b, 3, a2, f, b2));   // longer than the pieces
}

TEST(Fillet, LineAndArcBothWays) {
  // a line into an arc that turns left (about (2, 1)), the corner turning left: and reversed
  const PathSegment a = PathSegment::line({0, -1}, {2, 0}), b = PathSegment::arc({2, 0}, {3, 1}, {2, 1}, true);
  expectFillet(a, b, 0.2);
  expectFillet(reversedPiece(b), reversedPiece(a), 0.2);
}

TEST(Fillet, TwoArcs) {
  const double s = std::sqrt(0.5);
  // a on the circle about (0, 0) of radius 1 from 0° to 45° (ccw), b on the circle
  // about (2·cos45°, 0) of radius 1 from 135° onwards (ccw): they meet at (cos45°, sin45°)
  const PointD p{s, s};
  const PathSegment arcA = PathSegment::arc({1, 0}, p, {0, 0}, true);
  const PointD ob{2 * s, 0};
  const PathSegment arcB = PathSegment::arc(p, {ob.x, 1}, ob, true);
  ASSERT_GT(std::abs(turnAt(arcA, arcB)), 0.1);
  expectFillet(arcA, arcB, 0.1);
  // turning the other way at the joint: b clockwise
  const PathSegment arcC = PathSegment::arc(p, {ob.x, -1}, ob, false);
  expectFillet(arcA, arcC, 0.1);
}

TEST(Fillet, RoundCornersTakesArcPairsOnlyWhenAsked) {
  const double s = std::sqrt(0.5);
  const PointD p{s, s}, ob{2 * s, 0};
  const std::vector<PathSegment> path{PathSegment::arc({1, 0}, p, {0, 0}, true), PathSegment::arc(p, {ob.x, 1}, ob, true)};
  auto room = [&](std::size_t, const PathSegment& self, const PathSegment&, bool) { return self.length() / 2; };
  auto accept = [](std::size_t, const PathSegment&, const PathSegment&, const PathSegment&, const PathSegment&, const PathSegment&) { return true; };
  std::vector<PathSegment> off = path, on = path;
  EXPECT_EQ(roundCorners(off, 0, {0.2, 0.01, 0, 1, 179}, room, accept).rounded, 0u);
  EXPECT_EQ(off.size(), 2u);
  EXPECT_EQ(roundCorners(on, 0, {0.2, 0.01, 0, 1, 179, true}, room, accept).rounded, 1u);
  ASSERT_EQ(on.size(), 3u);
  EXPECT_NEAR(turnAt(on[0], on[1]), 0, 1e-9);
  EXPECT_NEAR(turnAt(on[1], on[2]), 0, 1e-9);
}
