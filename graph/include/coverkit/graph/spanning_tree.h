#pragma once
// Spanning trees of the mega-cell graph (the STC family's trees).
//
//  - dfs_ccw: depth-first, neighbours scanned counter-clockwise starting after the parent
//    (Gabriely & Rimon's Spiral-STC order); the root scans from a given direction (E by default;
//    the STC planners pass the arm their walk meets first, so that offline STC and online
//    Spiral-STC give the same tree).
//    BGL's depth_first_search visits out-edges in a fixed stored order, which cannot express a
//    parent-relative order, so this one is plain arrays (O(V)).
//  - bfs: breadth-first, neighbours E, N, W, S.
//  - kruskal_straight: minimum spanning tree with weights that favour straight runs (horizontal
//    edges cost 1, vertical 2, so rows become long branches and the circumnavigation turns less);
//    ties broken by edge index so the tree is unique.
//  - longest_runs: kruskal_straight where a node's straight run of nodes is longer along the column
//    than along the row: a node whose column run is more than twice its row run prefers vertical
//    edges, every other one horizontal ones; an edge weighs how many of its two ends prefer the
//    other axis, ties as kruskal_straight. A strip beside a wall, taller than wide, is then one or
//    two vertical branches instead of a comb of short horizontal ones; where every node prefers the
//    horizontal the tree is kruskal_straight's. O(c log c) for the c nodes of the root's component
//    (and O(V) to clear its arrays).
// Each of BFS, Kruskal and a fixed-order DFS exists twice: with Boost.Graph on a
// compressed_sparse_row_graph and with plain arrays. The tests check both give the same tree; the
// benchmark (experiments/bench/bench_graph.cpp) measured Boost.Graph 8x (DFS) and 10x (BFS)
// slower on 10^6 nodes, over 2x even without building the CSR graph, and its Kruskal 70x slower
// than the plain one, which takes the edges in their known weight order instead of sorting them;
// so buildTree uses the plain ones (docs/performance.md has the figures).
#include <coverkit/graph/grid_graph.h>

#include <functional>
#include <string>
#include <vector>

namespace coverkit::graph {

struct SpanningTree {
  int root = -1;
  std::vector<int> parent;            ///< -1 for the root and for nodes not in the tree
  std::vector<std::uint8_t> edges;    ///< per node: bit d set when the tree joins it to neighbour d
  std::size_t nodes = 0;              ///< nodes in the tree (root's component)
  bool contains(int v) const { return v == root || parent[static_cast<std::size_t>(v)] >= 0; }
  bool operator==(const SpanningTree& o) const { return root == o.root && parent == o.parent; }
};

enum class TreeStrategy { kDfsCcw, kBfs, kKruskalStraight, kLongestRuns };
const char* toString(TreeStrategy s);
/// Parses "dfs_ccw", "bfs", "kruskal_straight", "longest_runs"; false when unknown.
bool parseTreeStrategy(const std::string& text, TreeStrategy& out);
std::vector<std::string> treeStrategyNames();

/// The tree of `root`'s component with the given strategy (the fast implementation of each).
/// `rootFirst`: the direction the root scans first (dfs_ccw only; the others ignore it).
SpanningTree buildTree(const GridGraph& g, int root, TreeStrategy s, int rootFirst = kEast);

/// Counter-clockwise DFS; the root scans from `rootFirst` on (E, N, W, S after it, cyclically).
SpanningTree dfsCcwTree(const GridGraph& g, int root, int rootFirst = kEast);
SpanningTree bfsTreeBgl(const GridGraph& g, int root);
SpanningTree bfsTreePlain(const GridGraph& g, int root);
SpanningTree kruskalTreeBgl(const GridGraph& g, int root);
SpanningTree kruskalTreePlain(const GridGraph& g, int root);
/// Kruskal with a weight per edge: `weight(v, d)` for the edge from v to its neighbour in direction
/// d (East or North, each edge asked once). Edges are taken by weight, ties in kruskal_straight's
/// order (east edges by node, then north edges by node), so the tree is unique. Only the root's
/// component's edges are weighed and sorted: O(c log c) for its c nodes, and O(V) to clear arrays.
SpanningTree kruskalTreeWeighted(const GridGraph& g, int root, const std::function<int(int v, int d)>& weight);
/// longest_runs (above).
SpanningTree longestRunsTree(const GridGraph& g, int root);
/// Fixed-order DFS (E, N, W, S), Boost.Graph and plain: the like-for-like pair for the benchmark.
SpanningTree dfsTreeBgl(const GridGraph& g, int root);
SpanningTree dfsTreePlain(const GridGraph& g, int root);
/// Builds only the compressed_sparse_row_graph the Boost.Graph versions use and returns its edge
/// count: lets the benchmark split construction from search.
std::size_t buildCsrOnly(const GridGraph& g);

}  // namespace coverkit::graph
