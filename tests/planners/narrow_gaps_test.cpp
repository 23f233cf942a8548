// One convention for narrow gaps (issue 12, item 7): C-free is closed (distance >= r), for the
// validator, the C-space's connectivity and the coverable region alike. On worlds whose corridors and
// doors are exactly 2r wide (small mazes and rooms in the manner of Moving AI's maze-32-32-4 and
// room-64-64-8, generated here), every planner's valid path stays in the coverable region: coverable
// coverage <= 1 up to the metrics' stated error bounds.
#include "helpers/checkers.h"

#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/planners/registry.h>

#include <gtest/gtest.h>

#include <random>
#include <sstream>

using namespace coverkit;

namespace {

/// A perfect maze of k × k cells (depth-first, seeded) with corridors `width` pixels wide and walls
/// one pixel thick, as a text grid (resolution 1).
std::string maze(int k, int width, std::uint64_t seed) {
  const int n = k * (width + 1) + 1;
  std::vector<std::string> g(static_cast<std::size_t>(n), std::string(static_cast<std::size_t>(n), '#'));
  auto carve = [&](int x0, int y0, int x1, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) g[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] = '.';
  };
  std::mt19937_64 rng(seed);
  std::vector<char> seen(static_cast<std::size_t>(k * k), 0);
  std::vector<int> stack{0};
  seen[0] = 1;
  auto at = [&](int c) { return std::pair{1 + (c % k) * (width + 1), 1 + (c / k) * (width + 1)}; };
  carve(1, 1, 1 + width, 1 + width);
  while (!stack.empty()) {
    const int c = stack.back(), cx = c % k, cy = c / k;
    std::vector<int> next;
    if (cx > 0 && !seen[static_cast<std::size_t>(c - 1)]) next.push_back(c - 1);
    if (cx + 1 < k && !seen[static_cast<std::size_t>(c + 1)]) next.push_back(c + 1);
    if (cy > 0 && !seen[static_cast<std::size_t>(c - k)]) next.push_back(c - k);
    if (cy + 1 < k && !seen[static_cast<std::size_t>(c + k)]) next.push_back(c + k);
    if (next.empty()) {
      stack.pop_back();
      continue;
    }
    const int d = next[static_cast<std::size_t>(rng() % next.size())];
    seen[static_cast<std::size_t>(d)] = 1;
    const auto [ax, ay] = at(c);
    const auto [bx, by] = at(d);
    carve(std::min(ax, bx), std::min(ay, by), std::max(ax, bx) + width, std::max(ay, by) + width);
    stack.push_back(d);
  }
  std::ostringstream os;
  for (const std::string& row : g) os << row << '\n';
  return os.str();
}

/// k × k rooms of `size` free pixels square, walls one pixel thick, each wall between two rooms with a
/// door one pixel wide at a seeded place (sometimes two).
std::string rooms(int k, int size, std::uint64_t seed) {
  const int n = k * (size + 1) + 1;
  std::vector<std::string> g(static_cast<std::size_t>(n), std::string(static_cast<std::size_t>(n), '.'));
  std::mt19937_64 rng(seed);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (i % (size + 1) == 0 || j % (size + 1) == 0) g[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = '#';
  for (int a = 0; a < k; ++a)
    for (int b = 0; b + 1 < k; ++b) {
      const int wall = (b + 1) * (size + 1);
      for (int doors = 1 + static_cast<int>(rng() % 3 == 0); doors > 0; --doors) {
        const int along = a * (size + 1) + 1 + static_cast<int>(rng() % static_cast<unsigned>(size));
        g[static_cast<std::size_t>(along)][static_cast<std::size_t>(wall)] = '.';  // a vertical wall
        const int along2 = a * (size + 1) + 1 + static_cast<int>(rng() % static_cast<unsigned>(size));
        g[static_cast<std::size_t>(wall)][static_cast<std::size_t>(along2)] = '.';  // a horizontal wall
      }
    }
  std::ostringstream os;
  for (const std::string& row : g) os << row << '\n';
  return os.str();
}

struct Measured {
  double coverage = 0, bound = 0;
};
Measured coverable(const planners::PlanningContext& ctx, const Plan& plan, const CSpace& cs) {
  MetricOptions o;
  o.coverable = true;
  o.cspace = &cs;  // its helper C-spaces are built once for all planners
  const Metrics m = computeMetrics(ctx.problem, ctx.cells, plan.paths, o);
  Measured out;
  out.coverage = m.coverableCoverage;
  // covered area within its error, coverable area within its own
  out.bound = m.coverableArea > 0 ? 1 + (m.areaCoverageError * m.freeArea + m.coverableAreaError) / m.coverableArea : 1;
  return out;
}

}  // namespace

TEST(NarrowGaps, CorridorsExactly2rWideJoinTheClosedCFree) {
  // a maze of corridors one pixel wide, r = 1/2: the polygons of C-free are nearly empty (zero-width
  // centre lines), the closed C-free is one component
  const Workspace w = datasets::parseTextGrid(maze(4, 1, 7), "maze");
  const CSpace cs(w, Rational(1, 2));
  const Point a{ratio(3, 2), ratio(3, 2)}, b{ratio(15, 2), ratio(15, 2)};  // two cell centres far apart
  EXPECT_GE(cs.closedComponentOf(a), 0);
  EXPECT_EQ(cs.closedComponentOf(a), cs.closedComponentOf(b));
  double err = 0;
  const double area = cs.coverableArea({a}, err);
  // every free pixel can be swept but the corners of the turns (each corridor is exactly 2r)
  const double free = freeArea(w).get_d();
  EXPECT_LE(area, free + err);
  EXPECT_GT(area, 0.8 * free);
}

TEST(NarrowGaps, NoPlannerCoversMoreThanTheCoverableRegion) {
  struct World {
    std::string name, text;
    Rational r;
    bool aligned;  // sub-cells on the pixels: Full-STC sweeps (nearly) everything
  };
  const std::vector<World> worlds = {
      {"maze 1 px, r = 1/2", maze(6, 1, 3), Rational(1, 2), true},   // corridors exactly 2r
      {"maze 2 px, r = 1", maze(4, 2, 5), Rational(1), false},       // the same at another scale
      {"maze 4 px, r = 1/2", maze(3, 4, 9), Rational(1, 2), true},   // maze-32-32-4's corridors
      {"rooms, r = 1/2", rooms(3, 5, 11), Rational(1, 2), true},     // doors exactly 2r (room-64-64-8)
  };
  for (const World& wd : worlds) {
    const Workspace w = datasets::parseTextGrid(wd.text, wd.name);
    const auto ctx = testing_helpers::contextFor(w, wd.r);
    const CSpace cs(w, wd.r);
    for (const std::string& name : planners::Registry::instance().names()) {
      SCOPED_TRACE(wd.name + ", " + name);
      const Plan plan = planners::runPlanner(name, ctx, {});
      if (!succeeded(plan.status)) continue;
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
      const Measured m = coverable(ctx, plan, cs);
      EXPECT_GT(m.coverage, 0);
      EXPECT_LE(m.coverage, m.bound + 1e-12);
      if (name == "full_stc" && wd.aligned) {
        EXPECT_GT(m.coverage, 0.9);  // the region is not inflated either
      }
    }
  }
}
