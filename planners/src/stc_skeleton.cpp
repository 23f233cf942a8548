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

#include "walk_path.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <unordered_set>

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
  // free when its four sub-cells are (CellGrid::mega), tested here: a call per mega-cell was half
  // of this phase (8.5 ms at 10^7 sub-cells)
  auto isFree = [&](int c, int r) { return cells.sub(c, r) == CellState::kFree; };
  for (int r = 0; r < cells.megaRows(); ++r)
    for (int c = 0; c < cells.megaCols(); ++c)
      g.active[static_cast<std::size_t>(g.id(c, r))] =
          isFree(2 * c, 2 * r) & isFree(2 * c + 1, 2 * r) & isFree(2 * c, 2 * r + 1) & isFree(2 * c + 1, 2 * r + 1);
  return g;
}

graph::SpanningTree StcSkeleton::growTree(const graph::GridGraph& g, int root, const ParamSet& params, int rootFirst) const {
  graph::TreeStrategy s = graph::TreeStrategy::kDfsCcw;
  graph::parseTreeStrategy(params.text("tree"), s);
  return graph::buildTree(g, root, s, rootFirst);
}

void StcSkeleton::prepare(const PlanningContext&, const ParamSet&, Plan&) const {}
void StcSkeleton::refinePath(const PlanningContext&, const std::vector<CellIndex>&, const ParamSet&, Path&, Plan&) const {}

bool StcSkeleton::planWithoutTree(const PlanningContext&, const ParamSet&, const Point&, Plan&) const { return false; }

int StcSkeleton::startNode(const PlanningContext&, const graph::GridGraph& g, CellIndex s) const {
  const int v = g.id(s.col / 2, s.row / 2);
  return g.active[static_cast<std::size_t>(v)] ? v : -1;
}

namespace {

/// The skeleton's walk (StcSkeleton::circumnavigate) round the tree whose edge masks are
/// `edges` on a grid of `mcols` mega-cells a row, with `nodes` nodes, from sub-cell `start`.
std::vector<CellIndex> walkAround(const std::uint8_t* edges, int mcols, std::size_t nodes, CellIndex start) {
  // Quadrants counter-clockwise: 0 bottom-left, 1 bottom-right, 2 top-right, 3 top-left.
  // From quadrant q the robot moves in direction q (E, N, W, S) to quadrant q+1 of the same
  // mega-cell, unless the tree has an edge on the arm it would cross (direction q+3): then it moves
  // in that direction into the neighbour, arriving in quadrant q+3.
  int mc = start.col / 2, mr = start.row / 2;
  int q = quadrantOf(start);
  const int q0 = q;
  // Mega-cell by mega-cell rather than move by move: entering at quadrant q, the robot passes the
  // quadrants after q up to the first whose arm has a tree edge, then crosses that arm. A table of
  // the edge mask and q says how many quadrants that is, so each visit costs one dependent table
  // look-up instead of a (mispredicted) branch per move; the four quadrants after q are written
  // and the surplus dropped. At 10^7 sub-cells the walk took 60 ms instead of 90.
  static const auto quadrantsBefore = [] {
    std::array<std::array<std::uint8_t, 4>, 16> t{};  // [edge mask][q]: quadrants passed; 4: no edge at all
    for (int e = 0; e < 16; ++e)
      for (int from = 0; from < 4; ++from) {
        int k = 0;
        while (k < 4 && !(e >> ((from + k + 3) & 3) & 1)) ++k;
        t[static_cast<std::size_t>(e)][static_cast<std::size_t>(from)] = static_cast<std::uint8_t>(k);
      }
    return t;
  }();
  // every quadrant of every tree node once and back to the start, plus room for the surplus
  std::vector<CellIndex> walk(4 * nodes + 5);
  std::size_t n = 0;
  walk[n++] = subCellOf(mc, mr, q);
  int v = mr * mcols + mc;
  const int v0 = v;
  for (;;) {
    if (n + 5 > walk.size()) walk.resize(2 * walk.size());  // never with a tree of `nodes` nodes
    CellIndex* out = walk.data() + n;
    const int k = quadrantsBefore[edges[v]][static_cast<std::size_t>(q)];
    for (int j = 1; j <= 4; ++j) out[j - 1] = subCellOf(mc, mr, (q + j) & 3);
    if (v == v0) {  // the start's quadrant among those passed: the tour is complete
      const int toStart = ((q0 - q - 1) & 3) + 1;
      if (toStart <= k) {
        n += static_cast<std::size_t>(toStart);
        break;
      }
    }
    n += static_cast<std::size_t>(k);
    const int arm = (q + k + 3) & 3;
    mc += graph::kDx[arm];
    mr += graph::kDy[arm];
    v += graph::kDx[arm] + graph::kDy[arm] * mcols;
    q = arm;
    walk[n++] = subCellOf(mc, mr, q);
    if (v == v0 && q == q0) break;
  }
  walk.resize(n);
  return walk;
}

}  // namespace

std::vector<CellIndex> StcSkeleton::circumnavigate(const PlanningContext& ctx, const graph::GridGraph&, graph::SpanningTree& tree,
                                                   CellIndex start, const ParamSet&, Plan&) const {
  return walkAround(tree.edges.data(), ctx.cells.megaCols(), tree.nodes, start);
}

Plan StcSkeleton::plan(const PlanningContext& ctx, const ParamSet& params, const TerminationCondition&) {
  Plan plan;
  plan.planner = name();
  Point start;
  CellIndex s;
  if (!beginOnCells(ctx, name(), false, plan, start, s)) return plan;
  prepare(ctx, params, plan);
  // A move that no double can make safe (a sub-cell squeezed to exactly 2r between obstacles, at a
  // centre that is not a double) leaves its sub-cells out: plan again without them (walk_path.h).
  const bool unsafe = withoutUnplaceableCells(ctx, s, plan, [&](const PlanningContext& c) {
    std::vector<CellIndex> cellsToBlame;
    plan.treeEdges.clear();
    plan.timings.clear();
    planOnce(c, params, start, plan, cellsToBlame);
    return cellsToBlame;
  });
  if (unsafe) {
    plan.status = PlanStatus::kPartialCoverage;
    plan.message += "; " + formatDouble(plan.statistics["moves_unsafe"]) + " moves have no exactly safe double coordinates";
  }
  return plan;
}

StcSkeleton::Outcome StcSkeleton::planOnce(const PlanningContext& ctx, const ParamSet& params, const Point& start, Plan& plan,
                                           std::vector<CellIndex>& unsafe) const {
  const CellGrid& cells = ctx.cells;
  auto t = Clock::now();
  const graph::GridGraph g = buildGraph(ctx);
  plan.timings.emplace_back("graph", since(t));
  std::size_t active = 0;
  for (auto a : g.active) active += a;
  plan.statistics["mega_cells_used"] = static_cast<double>(active);

  CellIndex s;
  const int root = cells.locateSub(start, s) ? startNode(ctx, g, s) : -1;
  if (root < 0 && planWithoutTree(ctx, params, start, plan)) return Outcome::kDone;
  if (root < 0) {
    plan.status = PlanStatus::kInvalidStart;
    plan.message = "the start is not in a cell " + name() + " can use (" + startCells() + ")";
    return Outcome::kDone;
  }
  t = Clock::now();
  graph::SpanningTree tree = growTree(g, root, params, (quadrantOf(s) + 3) & 3);
  plan.timings.emplace_back("tree", since(t));

  t = Clock::now();
  const std::vector<CellIndex> walk = circumnavigate(ctx, g, tree, s, params, plan);
  plan.statistics["tree_nodes"] = static_cast<double>(tree.nodes);
  // tree edges between mega-cell centres, computed once per column and per row
  std::vector<double> megaX(static_cast<std::size_t>(cells.megaCols())), megaY(static_cast<std::size_t>(cells.megaRows()));
  for (int c = 0; c < cells.megaCols(); ++c) megaX[static_cast<std::size_t>(c)] = toDouble(cells.megaCenter(c, 0).x);
  for (int r = 0; r < cells.megaRows(); ++r) megaY[static_cast<std::size_t>(r)] = toDouble(cells.megaCenter(0, r).y);
  plan.treeEdges.reserve(tree.nodes);
  // node by node with its column and row counted along (no division per node); a parent on a plain
  // grid is one of the four neighbours, in a layered graph (links) anywhere
  const bool grid = g.links.empty() && g.layers == 1;
  for (int v = 0, c = 0, r = 0; v < static_cast<int>(g.size()); ++v) {
    const int p = tree.parent[static_cast<std::size_t>(v)];
    if (p >= 0) {
      int pc = c, pr = r;
      if (grid) {
        // vertical first: with a single column, ±1 is a step north or south
        const int north = p - v == g.cols, south = p - v == -g.cols;
        pc += (!north && p - v == 1) - (!south && p - v == -1);
        pr += north - south;
      } else {
        pc = g.col(p);
        pr = g.row(p);
      }
      plan.treeEdges.push_back({{megaX[static_cast<std::size_t>(pc)], megaY[static_cast<std::size_t>(pr)]},
                                {megaX[static_cast<std::size_t>(c)], megaY[static_cast<std::size_t>(r)]}});
    }
    if (++c == g.cols) {
      c = 0;
      if (++r == g.rows) r = 0;
    }
  }
  PlacedWalk placed = placeWalk(ctx, walk, start);
  if (!placed.startClear) {
    plan.status = PlanStatus::kInvalidStart;
    plan.message = "no double start point near the start is clear (its sub-cell is squeezed to exactly 2r at a centre that is not a double), or the disc cannot move straight from the start to the centre of its sub-cell";
    return Outcome::kDone;
  }
  plan.paths[0] = std::move(placed.path);
  if (placed.unsafeCells.empty()) refinePath(ctx, walk, params, plan.paths[0], plan);
  plan.statistics["moves_checked_exactly"] = static_cast<double>(placed.checkedMoves);
  plan.statistics["moves_repaired"] = static_cast<double>(placed.repairedMoves);
  plan.statistics["moves_unsafe"] = static_cast<double>(placed.unsafeMoves);
  plan.timings.emplace_back("path", since(t));
  plan.statistics["subcells_in_tour"] = static_cast<double>(walk.size() - 1);
  plan.status = PlanStatus::kExactSolution;
  plan.message = coverageClaim();
  unsafe = std::move(placed.unsafeCells);
  return unsafe.empty() ? Outcome::kDone : Outcome::kUnsafe;
}

std::vector<CellIndex> StcSkeleton::tourFrom(const PlanningContext& ctx, const graph::GridGraph& g, CellIndex s,
                                             const ParamSet& params) const {
  const int root = startNode(ctx, g, s);
  if (root < 0) return {};
  graph::SpanningTree tree = growTree(g, root, params, (quadrantOf(s) + 3) & 3);
  Plan scratch;  // the walk's statistics belong to the caller's own plan, not to this tour
  return circumnavigate(ctx, g, tree, s, params, scratch);
}

std::vector<CellIndex> StcSkeleton::tourOfComponent(const PlanningContext& ctx, const graph::GridGraph& g, CellIndex s,
                                                    const ParamSet& params) const {
  if (!g.links.empty() || g.layers != 1) return tourFrom(ctx, g, s, params);
  const int root = startNode(ctx, g, s);
  if (root < 0) return {};
  // the component, breadth-first, and its box (a hash set: no array the size of the map)
  std::vector<int> nodes{root};
  std::unordered_set<int> seen{root};
  int c0 = g.col(root), c1 = c0, r0 = g.row(root), r1 = r0;
  for (std::size_t head = 0; head < nodes.size(); ++head)
    for (int d = 0; d < 4; ++d) {
      const int u = g.neighbour(nodes[head], d);
      if (u < 0 || !seen.insert(u).second) continue;
      nodes.push_back(u);
      c0 = std::min(c0, g.col(u)), c1 = std::max(c1, g.col(u)), r0 = std::min(r0, g.row(u)), r1 = std::max(r1, g.row(u));
    }
  // the box as a graph of its own, the component's nodes alone active: the same row-major order of
  // nodes and the same neighbours, so every tree strategy makes the same tree in it
  graph::GridGraph box(c1 - c0 + 1, r1 - r0 + 1);
  for (int v : nodes) {
    const int b = box.id(g.col(v) - c0, g.row(v) - r0);
    box.active[static_cast<std::size_t>(b)] = 1;
    box.open[static_cast<std::size_t>(b)] = g.open[static_cast<std::size_t>(v)];
  }
  const CellIndex local{s.col - 2 * c0, s.row - 2 * r0};
  const graph::SpanningTree tree = growTree(box, box.id(local.col / 2, local.row / 2), params, (quadrantOf(s) + 3) & 3);
  std::vector<CellIndex> walk = walkAround(tree.edges.data(), box.cols, tree.nodes, local);
  for (CellIndex& c : walk) c.col += 2 * c0, c.row += 2 * r0;
  return walk;
}

std::string SpiralStcPlanner::description() const {
  return "Spiral-STC (Gabriely & Rimon 2001), online: senses the four neighbours of its mega-cell, grows the tree "
         "counter-clockwise as it goes, covers every sub-cell of the reachable free mega-cells";
}

std::vector<ParamSpec> SpiralStcPlanner::params() const {
  return {{"tree", ParamType::kChoice, "dfs_ccw", "dfs_ccw|bfs|kruskal_straight",
           "online tree rule: first new free neighbour counter-clockwise (the paper's), claim every new neighbour on arrival "
           "(breadth-first discovery), or claim the neighbour straight ahead first (straight runs)"}};
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
                                                        CellIndex start, const ParamSet& params, Plan& plan) const {
  // The walk of the offline skeleton, with each tree edge decided when the robot first reaches
  // the arm it would cross: a known edge (to the parent) is crossed back; otherwise the robot looks
  // at what it has sensed about the neighbour across the arm, and a new free one that no other
  // cell has claimed becomes a child. The robot remembers every answer (its own map), so it asks
  // each question once: at most four per mega-cell.
  graph::TreeStrategy strategy = graph::TreeStrategy::kDfsCcw;
  graph::parseTreeStrategy(params.text("tree"), strategy);
  MegaCellSensor sensor(world, tree.root);
  const int cols = world.cols;
  std::vector<std::uint8_t> visited(world.size(), 0), known(world.size(), 0);  // known: bit 2d asked, bit 2d+1 free
  std::vector<int> claimedBy(world.size(), -1);
  auto freeNeighbour = [&](int cell, int d) {
    std::uint8_t& k = known[static_cast<std::size_t>(cell)];
    if (!(k >> (2 * d) & 1)) k = static_cast<std::uint8_t>(k | 1u << (2 * d) | (sensor.neighbourFree(cell, d) ? 1u << (2 * d + 1) : 0u));
    return (k >> (2 * d + 1) & 1) != 0;
  };
  auto arrive = [&](int cell, int heading) {  // first arrival: the claims of bfs and kruskal_straight
    visited[static_cast<std::size_t>(cell)] = 1;
    auto claim = [&](int d) {
      if (!freeNeighbour(cell, d)) return;
      const int u = cell + graph::kDx[d] + graph::kDy[d] * cols;
      if (!visited[static_cast<std::size_t>(u)] && claimedBy[static_cast<std::size_t>(u)] < 0) claimedBy[static_cast<std::size_t>(u)] = cell;
    };
    if (strategy == graph::TreeStrategy::kBfs)
      for (int d = 0; d < 4; ++d) claim(d);
    else if (strategy == graph::TreeStrategy::kKruskalStraight && heading >= 0)
      claim(heading);
  };
  arrive(tree.root, -1);
  int mc = start.col / 2, mr = start.row / 2;
  int q = quadrantOf(start);
  const int q0 = q, mc0 = mc, mr0 = mr;
  std::vector<CellIndex> walk{subCellOf(mc, mr, q)};
  // room for every quadrant of every mega-cell: memory only (the robot's decisions use its sensor
  // alone), and no copies as the walk grows (tens of MB at 10^7 sub-cells)
  walk.reserve(4 * world.size() + 1);
  do {
    const int here = mr * cols + mc, arm = (q + 3) & 3;
    bool cross = tree.edges[static_cast<std::size_t>(here)] >> arm & 1;
    if (!cross && freeNeighbour(here, arm)) {
      const int there = (mr + graph::kDy[arm]) * cols + mc + graph::kDx[arm];
      const int owner = claimedBy[static_cast<std::size_t>(there)];
      if (!visited[static_cast<std::size_t>(there)] && (owner < 0 || owner == here)) {
        tree.parent[static_cast<std::size_t>(there)] = here;
        tree.edges[static_cast<std::size_t>(here)] |= static_cast<std::uint8_t>(1u << arm);
        tree.edges[static_cast<std::size_t>(there)] |= static_cast<std::uint8_t>(1u << graph::opposite(arm));
        ++tree.nodes;
        cross = true;
        sensor.moveTo(there);
        arrive(there, arm);
        mc += graph::kDx[arm];
        mr += graph::kDy[arm];
        q = arm;
        walk.push_back(subCellOf(mc, mr, q));
        continue;
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
    walk.push_back(subCellOf(mc, mr, q));
  } while (!(q == q0 && mc == mc0 && mr == mr0));
  plan.statistics["sensor_queries"] = static_cast<double>(sensor.log().size());
  return walk;
}

}  // namespace coverkit::planners
