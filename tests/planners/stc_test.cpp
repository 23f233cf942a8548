#include "helpers/checkers.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/registry.h>
#include <coverkit/planners/smooth_stc.h>

#include <gtest/gtest.h>

using namespace coverkit;

namespace {
Workspace openRoom(const Rational& w, const Rational& h) {
  Workspace ws;
  Region r;
  r.outer = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  ws.regions.push_back(r);
  ws.name = "room";
  return ws;
}
}  // namespace

TEST(Stc, ObstacleFreeMapIsOptimal) {
  // m × n mega-cells: every sub-cell once, back to the start, length 4mn·D (D = 0.4: not a double)
  for (auto [m, n] : std::vector<std::pair<int, int>>{{1, 1}, {3, 2}, {7, 5}, {12, 9}}) {
    const Rational r(1, 5), D = 2 * r;
    const auto ctx = testing_helpers::contextFor(openRoom(Rational(2 * m) * D, Rational(2 * n) * D), r);
    for (const char* tree : {"dfs_ccw", "bfs", "kruskal_straight"}) {
      const Plan plan = planners::runPlanner("stc", ctx, {{"tree", tree}});
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan)) << m << "x" << n << " " << tree;
      const Metrics mt = computeMetrics(ctx.problem, ctx.cells, plan.paths);
      EXPECT_NEAR(mt.length, 4.0 * m * n * D.get_d(), 1e-9) << m << "x" << n << " " << tree;
      EXPECT_EQ(mt.coveredSubcells, static_cast<std::size_t>(4 * m * n));
      EXPECT_EQ(mt.enteredSubcells, static_cast<std::size_t>(4 * m * n));
      EXPECT_LE(mt.revisitedSubcells, 1u);  // only the start cell, on the return
      const Path& p = plan.paths[0];
      EXPECT_EQ(p.segments.back().to.x, p.start.x);
      EXPECT_EQ(p.segments.back().to.y, p.start.y);
    }
  }
}

TEST(Stc, StartNotInAFreeMegaCellIsAStatus) {
  const Workspace w = datasets::parseTextGrid("....\n....\n...#\n....\n", "t.grid");
  const auto ctx = testing_helpers::contextFor(w, Rational(1, 2), Point{Rational(5, 2), Rational(3, 2)});
  const Plan plan = planners::runPlanner("stc", ctx, {});
  EXPECT_EQ(plan.status, PlanStatus::kInvalidStart);
  EXPECT_FALSE(plan.message.empty());
}

TEST(Stc, StartOffCentreIsJoinedAndReturnedTo) {
  const auto ctx = testing_helpers::contextFor(openRoom(Rational(4), Rational(4)), Rational(1, 2), Point{Rational(13, 10), Rational(7, 10)});
  const Plan plan = planners::runPlanner("stc", ctx, {});
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
  EXPECT_DOUBLE_EQ(plan.paths[0].start.x, 1.3);
  EXPECT_DOUBLE_EQ(plan.paths[0].segments.back().to.x, 1.3);
}

TEST(Stc, BadInputIsRejectedBeforePlanning) {
  const Workspace w = openRoom(Rational(4), Rational(4));
  EXPECT_THROW(testing_helpers::contextFor(w, Rational(0)), InputError);
  EXPECT_THROW(testing_helpers::contextFor(w, Rational(3)), InputError);   // larger than the workspace
  EXPECT_THROW(testing_helpers::contextFor(w, Rational(1, 2), Point{Rational(5), Rational(1)}), InputError);  // outside
  const Workspace holed = datasets::parseWkt("POLYGON((0 0, 4 0, 4 4, 0 4),(1 1, 2 1, 2 2, 1 2))", "h.wkt");
  EXPECT_THROW(testing_helpers::contextFor(holed, Rational(1, 4), Point{Rational(3, 2), Rational(3, 2)}), InputError);  // in obstacle
  const auto ctx = testing_helpers::contextFor(w, Rational(1, 2));
  EXPECT_THROW(planners::runPlanner("no_such_planner", ctx, {}), InputError);
  EXPECT_THROW(planners::runPlanner("stc", ctx, {{"tree", "random"}}), InputError);
  EXPECT_THROW(planners::runPlanner("stc", ctx, {{"depth", "3"}}), InputError);
}

TEST(Stc, CoversTheStartComponentOnTheBuiltInMaps) {
  for (const char* f : {"rooms.grid", "maze.map", "pillars.wkt", "field_ring.geojson", "office.yaml"}) {
    const Workspace w = datasets::loadMap(std::string(COVERKIT_DATA_DIR) + "/" + f);
    for (const Rational& r : {Rational(1, 10), Rational(1, 4)}) {
      const auto ctx = testing_helpers::contextFor(w, r);
      const Plan plan = planners::runPlanner("stc", ctx, {});
      if (plan.status == PlanStatus::kInvalidStart) continue;
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan)) << f;
      EXPECT_TRUE(testing_helpers::coversStartComponent(ctx, plan)) << f;
    }
  }
}

// tourOfComponent (a component's tree grown in a graph of its box alone, as Smooth-STC tours its
// rooms and pockets) makes the walk tourFrom makes in the whole map's graph: every component of a
// cluttered grid map, from every quadrant of its first mega-cell, with every tree strategy,
// Smooth-STC's `auto` and `longest_runs` among them.
namespace {
template <class Base>
class Exposed : public Base {
public:
  using Base::buildGraph;
  using Base::tourFrom;
  using Base::tourOfComponent;
};
}  // namespace

TEST(Stc, TourOfAComponentIsTheTourInTheWholeMap) {
  datasets::GridMapSpec spec;
  spec.width = spec.height = 48;
  spec.density = 0.3;
  spec.clustered = true;
  spec.seed = 7;
  const auto ctx = testing_helpers::contextFor(datasets::gridToWorkspace(datasets::generateGridMap(spec), "grid"), Rational(1, 2));
  const Exposed<planners::StcPlanner> stc;
  const Exposed<planners::SmoothStcPlanner> smooth;
  const graph::GridGraph g = stc.buildGraph(ctx);
  // the first mega-cell of each component, in row-major order
  std::vector<int> firsts, label(g.size(), -1);
  for (int v = 0; v < static_cast<int>(g.size()); ++v) {
    if (!g.active[static_cast<std::size_t>(v)] || label[static_cast<std::size_t>(v)] >= 0) continue;
    firsts.push_back(v);
    std::vector<int> queue{v};
    label[static_cast<std::size_t>(v)] = v;
    for (std::size_t h = 0; h < queue.size(); ++h)
      for (int d = 0; d < 4; ++d)
        if (const int u = g.neighbour(queue[h], d); u >= 0 && label[static_cast<std::size_t>(u)] < 0)
          label[static_cast<std::size_t>(u)] = v, queue.push_back(u);
  }
  ASSERT_GE(firsts.size(), 5u);   // several rooms, or the test shows nothing
  std::size_t compared = 0;
  for (int v : firsts)
    for (int q = 0; q < 4; ++q) {
      const CellIndex s = planners::subCellOf(g.col(v), g.row(v), q);
      for (const char* tree : {"dfs_ccw", "bfs", "kruskal_straight"}) {
        const planners::ParamSet p(stc.params(), {{"tree", tree}}, "stc");
        EXPECT_EQ(stc.tourOfComponent(ctx, g, s, p), stc.tourFrom(ctx, g, s, p)) << v << " " << q << " " << tree;
        ++compared;
      }
      for (const char* tree : {"auto", "longest_runs", "kruskal_straight"}) {
        const planners::ParamSet p(smooth.params(), {{"tree", tree}}, "smooth_stc");
        EXPECT_EQ(smooth.tourOfComponent(ctx, g, s, p), smooth.tourFrom(ctx, g, s, p)) << v << " " << q << " " << tree;
        ++compared;
      }
    }
  EXPECT_GE(compared, 120u);
}
