// STC skeleton and offline STC. See stc_skeleton.h for the reference.
//
// Decisions (where the papers are silent):
//  - Circumnavigation is counter-clockwise around the tree (the robot keeps the tree on its left,
//    i.e. moves "along the right side" of each edge as Gabriely & Rimon put it, and as Algorithm 1
//    of Pham et al. says: "anticlockwise").
//  - Waypoints are sub-cell centres. Their doubles are rounded towards the centre of their
//    mega-cell, never away: a free mega-cell lies in W, the disc at the rounded point stays inside
//    the mega-cell, and a move between adjacent mega-cells stays inside their union (a rectangle),
//    so the path is safe exactly as written even when a centre is not a double (e.g. D = 0.4).
//  - A start that is not a sub-cell centre is joined to its sub-cell's centre by a straight move,
//    checked exactly; if that move is not clear the plan's status is invalid_start.
//  - The tour returns to the start sub-cell and then to the start point.
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/validate.h>
#include <coverkit/planners/sensor.h>
#include <coverkit/planners/stc_skeleton.h>

#include <chrono>

namespace coverkit::planners {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

std::string StcPlanner::description() const {
  return "Spanning Tree Coverage (Gabriely & Rimon 2001), offline: free mega-cells, a spanning tree, "
         "counter-clockwise circumnavigation through sub-cell centres back to the start";
}

std::vector<ParamSpec> StcSkeleton::params() const {
  return {{"tree", ParamType::kChoice, "dfs_ccw", "dfs_ccw|bfs|kruskal_straight",
           "spanning-tree strategy: depth-first counter-clockwise (the papers'), breadth-first, or Kruskal favouring straight runs"}};
}

Capabilities StcSkeleton::capabilities() const { return {}; }

graph::GridGraph StcSkeleton::buildGraph(const PlanningContext& ctx) const {
  const CellGrid& cells = ctx.cells;
  graph::GridGraph g(cells.megaCols(), cells.megaRows());
  for (int r = 0; r < cells.megaRows(); ++r)
    for (int c = 0; c < cells.megaCols(); ++c) g.active[static_cast<std::size_t>(g.id(c, r))] = cells.mega(c, r) == CellState::kFree;
  return g;
}

graph::SpanningTree StcSkeleton::growTree(const graph::GridGraph& g, int root, const ParamSet& params, int rootFirst) const {
  graph::TreeStrategy s = graph::TreeStrategy::kDfsCcw;
  graph::parseTreeStrategy(params.text("tree"), s);
  return graph::buildTree(g, root, s, rootFirst);
}

namespace {
int quadrantOf(CellIndex c) { return (c.row % 2 == 0) ? (c.col % 2 == 0 ? 0 : 1) : (c.col % 2 == 0 ? 3 : 2); }
}  // namespace

std::vector<CellIndex> StcSkeleton::circumnavigate(const PlanningContext& ctx, const graph::GridGraph&, graph::SpanningTree& tree,
                                                   CellIndex start, Plan&) const {
  // Quadrants counter-clockwise: 0 bottom-left, 1 bottom-right, 2 top-right, 3 top-left.
  // From quadrant q the robot moves in direction q (E, N, W, S) to quadrant q+1 of the same
  // mega-cell, unless the tree has an edge on the arm it would cross (direction q+3): then it moves
  // in that direction into the neighbour, arriving in quadrant q+3.
  const int mcols = ctx.cells.megaCols();
  int mc = start.col / 2, mr = start.row / 2;
  int q = quadrantOf(start);
  const int q0 = q, mc0 = mc, mr0 = mr;
  auto sub = [](int c, int r, int quad) { return CellIndex{2 * c + (quad == 1 || quad == 2), 2 * r + (quad >= 2)}; };
  std::vector<CellIndex> walk{sub(mc, mr, q)};
  walk.reserve(4 * tree.nodes + 1);
  do {
    const int arm = (q + 3) & 3;
    if (tree.edges[static_cast<std::size_t>(mr * mcols + mc)] >> arm & 1) {
      mc += graph::kDx[arm];
      mr += graph::kDy[arm];
      q = arm;
    } else {
      q = (q + 1) & 3;
    }
    walk.push_back(sub(mc, mr, q));
  } while (!(q == q0 && mc == mc0 && mr == mr0));
  return walk;
}

Plan StcSkeleton::plan(const PlanningContext& ctx, const ParamSet& params, const TerminationCondition&) {
  Plan plan;
  plan.planner = name();
  const CellGrid& cells = ctx.cells;
  const Robot& robot = ctx.problem.robots.at(0);
  if (cells.subSize() < 2 * robot.radius)
    throw InputError("--cell-size", formatDouble(cells.subSizeD()),
                     "must be at least 2r = " + formatDouble(Rational(2 * robot.radius).get_d()) + " for " + name() +
                         " (the disc must fit in its sub-cell)");
  Path path;
  if (!robot.start) {
    plan.status = PlanStatus::kNoFreeSpace;
    plan.message = "no free sub-cell for a default start";
    plan.paths.push_back(path);
    return plan;
  }
  const Point start = *robot.start;
  path.start = {toDouble(start.x), toDouble(start.y)};
  plan.paths.push_back(path);

  auto t = Clock::now();
  const graph::GridGraph g = buildGraph(ctx);
  plan.timings.emplace_back("graph", since(t));
  std::size_t active = 0;
  for (auto a : g.active) active += a;
  plan.statistics["mega_cells_used"] = static_cast<double>(active);

  CellIndex s;
  if (!cells.locateSub(start, s) || !g.active[static_cast<std::size_t>(g.id(s.col / 2, s.row / 2))]) {
    plan.status = PlanStatus::kInvalidStart;
    plan.message = "the start is not in a mega-cell this planner can use (STC needs a free mega-cell)";
    return plan;
  }
  t = Clock::now();
  graph::SpanningTree tree = growTree(g, g.id(s.col / 2, s.row / 2), params, (quadrantOf(s) + 3) & 3);
  plan.timings.emplace_back("tree", since(t));

  t = Clock::now();
  const std::vector<CellIndex> walk = circumnavigate(ctx, g, tree, s, plan);
  plan.statistics["tree_nodes"] = static_cast<double>(tree.nodes);
  // Waypoint coordinates depend on the column or the row alone: computed once, exactly, per column
  // and per row (sub-cell centres rounded towards their mega-cell's centre), so the walk is O(1) a step.
  std::vector<double> subX(static_cast<std::size_t>(cells.subCols())), subY(static_cast<std::size_t>(cells.subRows()));
  std::vector<double> megaX(static_cast<std::size_t>(cells.megaCols())), megaY(static_cast<std::size_t>(cells.megaRows()));
  for (int c = 0; c < cells.subCols(); ++c) {
    const Point p = cells.subCenter(c, 0), m = cells.megaCenter(c / 2, 0);
    subX[static_cast<std::size_t>(c)] = roundToward(p.x, m.x);
    if (c % 2 == 0) megaX[static_cast<std::size_t>(c / 2)] = toDouble(m.x);
  }
  for (int r = 0; r < cells.subRows(); ++r) {
    const Point p = cells.subCenter(0, r), m = cells.megaCenter(0, r / 2);
    subY[static_cast<std::size_t>(r)] = roundToward(p.y, m.y);
    if (r % 2 == 0) megaY[static_cast<std::size_t>(r / 2)] = toDouble(m.y);
  }
  plan.treeEdges.reserve(tree.nodes);
  for (int v = 0; v < static_cast<int>(g.size()); ++v) {
    const int p = tree.parent[static_cast<std::size_t>(v)];
    if (p < 0) continue;
    plan.treeEdges.push_back({{megaX[static_cast<std::size_t>(g.col(p))], megaY[static_cast<std::size_t>(g.row(p))]},
                              {megaX[static_cast<std::size_t>(g.col(v))], megaY[static_cast<std::size_t>(g.row(v))]}});
  }

  // waypoints, rounded towards their mega-cell's centre
  auto waypoint = [&](CellIndex c) { return PointD{subX[static_cast<std::size_t>(c.col)], subY[static_cast<std::size_t>(c.row)]}; };
  std::vector<PointD> pts;
  pts.reserve(walk.size() + 2);
  pts.push_back(path.start);
  for (CellIndex c : walk) pts.push_back(waypoint(c));
  pts.push_back(path.start);
  const PointD first = pts[1];
  if ((first.x != path.start.x || first.y != path.start.y) &&
      !segmentClear(ctx.problem.workspace, robot.radius, start, Point{exactFromDouble(first.x), exactFromDouble(first.y)})) {
    plan.status = PlanStatus::kInvalidStart;
    plan.message = "the disc cannot move straight from the start to the centre of its sub-cell";
    return plan;
  }
  // merge collinear moves (same axis, same direction, same fixed coordinate)
  Path& out = plan.paths[0];
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const PointD a = out.segments.empty() ? pts[0] : out.segments.back().to, b = pts[i];
    if (a.x == b.x && a.y == b.y) continue;
    if (!out.segments.empty()) {
      PathSegment& last = out.segments.back();
      const bool sameX = last.from.x == last.to.x && last.to.x == b.x && ((last.to.y - last.from.y > 0) == (b.y - last.to.y > 0));
      const bool sameY = last.from.y == last.to.y && last.to.y == b.y && ((last.to.x - last.from.x > 0) == (b.x - last.to.x > 0));
      if (sameX || sameY) {
        last.to = b;
        continue;
      }
    }
    out.segments.push_back(PathSegment::line(a, b));
  }
  plan.timings.emplace_back("path", since(t));
  plan.statistics["subcells_in_tour"] = static_cast<double>(walk.size() - 1);
  plan.status = PlanStatus::kExactSolution;
  plan.message = "covered every sub-cell of the start's component of free mega-cells";
  return plan;
}

std::string SpiralStcPlanner::description() const {
  return "Spiral-STC (Gabriely & Rimon 2001), online: senses the four neighbours of its mega-cell, grows the tree "
         "counter-clockwise as it goes, covers every sub-cell of the reachable free mega-cells";
}

Capabilities SpiralStcPlanner::capabilities() const {
  Capabilities c;
  c.online = true;
  return c;
}

graph::SpanningTree SpiralStcPlanner::growTree(const graph::GridGraph& g, int root, const ParamSet&, int) const {
  graph::SpanningTree t;  // the robot knows only where it starts
  t.root = root;
  t.parent.assign(g.size(), -1);
  t.edges.assign(g.size(), 0);
  t.nodes = 1;
  return t;
}

std::vector<CellIndex> SpiralStcPlanner::circumnavigate(const PlanningContext&, const graph::GridGraph& world, graph::SpanningTree& tree,
                                                        CellIndex start, Plan& plan) const {
  // The walk of the offline skeleton, with each tree edge decided when the robot first reaches
  // the arm it would cross: a known edge (to the parent) is crossed back; otherwise the sensor is
  // asked about the neighbour across the arm, and a new free one becomes a child.
  MegaCellSensor sensor(world, tree.root);
  const int cols = world.cols;
  std::vector<std::uint8_t> visited(world.size(), 0);
  visited[static_cast<std::size_t>(tree.root)] = 1;
  int mc = start.col / 2, mr = start.row / 2;
  int q = quadrantOf(start);
  const int q0 = q, mc0 = mc, mr0 = mr;
  auto sub = [](int c, int r, int quad) { return CellIndex{2 * c + (quad == 1 || quad == 2), 2 * r + (quad >= 2)}; };
  std::vector<CellIndex> walk{sub(mc, mr, q)};
  do {
    const int here = mr * cols + mc, arm = (q + 3) & 3;
    bool cross = tree.edges[static_cast<std::size_t>(here)] >> arm & 1;
    if (!cross && sensor.neighbourFree(here, arm)) {
      const int there = (mr + graph::kDy[arm]) * cols + mc + graph::kDx[arm];
      if (!visited[static_cast<std::size_t>(there)]) {
        visited[static_cast<std::size_t>(there)] = 1;
        tree.parent[static_cast<std::size_t>(there)] = here;
        tree.edges[static_cast<std::size_t>(here)] |= static_cast<std::uint8_t>(1u << arm);
        tree.edges[static_cast<std::size_t>(there)] |= static_cast<std::uint8_t>(1u << graph::opposite(arm));
        ++tree.nodes;
        cross = true;
      }
    }
    if (cross) {
      mc += graph::kDx[arm];
      mr += graph::kDy[arm];
      q = arm;
      sensor.moveTo(mr * cols + mc);
    } else {
      q = (q + 1) & 3;
    }
    walk.push_back(sub(mc, mr, q));
  } while (!(q == q0 && mc == mc0 && mr == mr0));
  plan.statistics["sensor_queries"] = static_cast<double>(sensor.log().size());
  return walk;
}

}  // namespace coverkit::planners
