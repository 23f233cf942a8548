#include <coverkit/graph/spanning_tree.h>

#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/depth_first_search.hpp>
#include <boost/graph/kruskal_min_spanning_tree.hpp>
#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <numeric>
#include <queue>

namespace coverkit::graph {

namespace {

struct EdgeWeight {
  long w = 0;
};
using Csr = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, EdgeWeight>;

SpanningTree emptyTree(const GridGraph& g, int root) {
  SpanningTree t;
  t.root = root;
  t.parent.assign(g.size(), -1);
  t.edges.assign(g.size(), 0);
  return t;
}

int dirBetween(const GridGraph& g, int from, int to) {
  const int dc = g.col(to) - g.col(from), dr = g.row(to) - g.row(from);
  for (int d = 0; d < 4; ++d)
    if (kDx[d] == dc && kDy[d] == dr) return d;
  return -1;
}

/// `child` is the neighbour of `parent` in direction d.
void link(SpanningTree& t, int parent, int child, int d) {
  t.parent[static_cast<std::size_t>(child)] = parent;
  t.edges[static_cast<std::size_t>(parent)] |= static_cast<std::uint8_t>(1u << d);
  t.edges[static_cast<std::size_t>(child)] |= static_cast<std::uint8_t>(1u << opposite(d));
  ++t.nodes;
}

void link(const GridGraph& g, SpanningTree& t, int parent, int child) { link(t, parent, child, dirBetween(g, parent, child)); }

/// Per node, bit d set when g.neighbour(v, d) exists. On a plain grid (one layer, no links) one
/// pass over the rows with the neighbours at fixed offsets: no divisions per node, which
/// GridGraph::neighbour pays on every call.
std::vector<std::uint8_t> neighbourMasks(const GridGraph& g) {
  std::vector<std::uint8_t> m(g.size(), 0);
  if (!g.links.empty() || g.size() != static_cast<std::size_t>(g.cols) * static_cast<std::size_t>(g.rows)) {
    for (int v = 0; v < static_cast<int>(g.size()); ++v)
      for (int d = 0; d < 4; ++d)
        if (g.neighbour(v, d) >= 0) m[static_cast<std::size_t>(v)] |= static_cast<std::uint8_t>(1u << d);
    return m;
  }
  const std::size_t cols = static_cast<std::size_t>(g.cols);
  const std::uint8_t* active = g.active.data();
  const std::uint8_t* open = g.open.data();
  // the edge between v and its east (north) neighbour u: both active, v open east (north), u open west (south)
  for (std::size_t r = 0; r < static_cast<std::size_t>(g.rows); ++r)
    for (std::size_t c = 0, v = r * cols; c < cols; ++c, ++v) {
      if (!active[v]) continue;
      if (c + 1 < cols && active[v + 1] && (open[v] >> kEast & 1) && (open[v + 1] >> kWest & 1)) {
        m[v] |= 1u << kEast;
        m[v + 1] |= 1u << kWest;
      }
      if (r + 1 < static_cast<std::size_t>(g.rows) && active[v + cols] && (open[v] >> kNorth & 1) && (open[v + cols] >> kSouth & 1)) {
        m[v] |= 1u << kNorth;
        m[v + cols] |= 1u << kSouth;
      }
    }
  return m;
}

/// The neighbour of v in direction d, where neighbourMasks says there is one.
struct Step {
  const GridGraph& g;
  int offset[4];
  explicit Step(const GridGraph& graph) : g(graph), offset{1, graph.cols, -1, -graph.cols} {}
  int operator()(int v, int d) const {
    return g.links.empty() ? v + offset[d] : g.links[static_cast<std::size_t>(v) * 4 + static_cast<std::size_t>(d)];
  }
};

bool validRoot(const GridGraph& g, int root) {
  return root >= 0 && static_cast<std::size_t>(root) < g.size() && g.active[static_cast<std::size_t>(root)];
}

/// Both directions of every edge, sorted by source, targets in E, N, W, S order.
Csr makeCsr(const GridGraph& g, bool weighted) {
  std::vector<std::pair<int, int>> el;
  std::vector<EdgeWeight> w;
  el.reserve(g.size() * 4);
  for (int v = 0; v < static_cast<int>(g.size()); ++v)
    for (int d = 0; d < 4; ++d) {
      const int u = g.neighbour(v, d);
      if (u < 0) continue;
      el.emplace_back(v, u);
      if (weighted) {
        // unique weight per undirected edge: straightness class first, then the edge's index
        const long lo = std::min(u, v), horizontal = (d == kEast || d == kWest);
        w.push_back({(horizontal ? 1L : 2L) * 4L * static_cast<long>(g.size()) + 2L * lo + (horizontal ? 0 : 1)});
      } else {
        w.push_back({});
      }
    }
  return Csr(boost::edges_are_sorted, el.begin(), el.end(), w.begin(), g.size());
}

struct TreeRecorder : boost::default_dfs_visitor {
  std::vector<int>* pred;
  template <class E, class G>
  void tree_edge(E e, const G& gr) const {
    (*pred)[static_cast<std::size_t>(boost::target(e, gr))] = static_cast<int>(boost::source(e, gr));
  }
};

SpanningTree fromParents(const GridGraph& g, int root, const std::vector<int>& pred) {
  SpanningTree t = emptyTree(g, root);
  t.nodes = 1;
  for (int v = 0; v < static_cast<int>(g.size()); ++v)
    if (pred[static_cast<std::size_t>(v)] >= 0 && v != root) link(g, t, pred[static_cast<std::size_t>(v)], v);
  return t;
}

/// Orients an undirected edge set (per-node masks) away from the root.
SpanningTree orient(const GridGraph& g, int root, const std::vector<std::uint8_t>& mask) {
  SpanningTree t = emptyTree(g, root);
  t.nodes = 1;
  std::vector<int> stack{root};
  std::vector<std::uint8_t> seen(g.size(), 0);
  seen[static_cast<std::size_t>(root)] = 1;
  const Step step(g);
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    for (int d = 0; d < 4; ++d) {
      if (!(mask[static_cast<std::size_t>(v)] >> d & 1)) continue;
      const int u = step(v, d);
      if (seen[static_cast<std::size_t>(u)]) continue;
      seen[static_cast<std::size_t>(u)] = 1;
      link(t, v, u, d);
      stack.push_back(u);
    }
  }
  return t;
}

void addMask(const GridGraph& g, std::vector<std::uint8_t>& mask, int a, int b) {
  const int d = dirBetween(g, a, b);
  mask[static_cast<std::size_t>(a)] |= static_cast<std::uint8_t>(1u << d);
  mask[static_cast<std::size_t>(b)] |= static_cast<std::uint8_t>(1u << opposite(d));
}

}  // namespace

const char* toString(TreeStrategy s) {
  switch (s) {
    case TreeStrategy::kDfsCcw: return "dfs_ccw";
    case TreeStrategy::kBfs: return "bfs";
    case TreeStrategy::kKruskalStraight: return "kruskal_straight";
    case TreeStrategy::kLongestRuns: return "longest_runs";
  }
  return "?";
}

bool parseTreeStrategy(const std::string& text, TreeStrategy& out) {
  for (TreeStrategy s : {TreeStrategy::kDfsCcw, TreeStrategy::kBfs, TreeStrategy::kKruskalStraight, TreeStrategy::kLongestRuns})
    if (text == toString(s)) {
      out = s;
      return true;
    }
  return false;
}

std::vector<std::string> treeStrategyNames() { return {"dfs_ccw", "bfs", "kruskal_straight", "longest_runs"}; }

SpanningTree buildTree(const GridGraph& g, int root, TreeStrategy s, int rootFirst) {
  switch (s) {
    case TreeStrategy::kDfsCcw: return dfsCcwTree(g, root, rootFirst);
    // Plain arrays on the hot path: Boost.Graph stayed over 2x slower (docs/performance.md); the
    // Boost.Graph versions give the same trees (tests/graph) and stay in the benchmark.
    case TreeStrategy::kBfs: return bfsTreePlain(g, root);
    case TreeStrategy::kKruskalStraight: return kruskalTreePlain(g, root);
    case TreeStrategy::kLongestRuns: return longestRunsTree(g, root);
  }
  return dfsCcwTree(g, root);
}

SpanningTree dfsCcwTree(const GridGraph& g, int root, int rootFirst) {
  SpanningTree t = emptyTree(g, root);
  if (!validRoot(g, root)) return t;
  const std::vector<std::uint8_t> nb = neighbourMasks(g);
  // No stack: a node's scan state is one byte (bit 7 seen, bits 4-5 the direction it scans first,
  // bits 0-2 how many it has scanned) and the way back is its parent. A DFS of a grid goes as deep
  // as the grid is large: the stack of frames grew to tens of MB at 10^7 sub-cells.
  std::vector<std::uint8_t> scan(g.size(), 0);
  // raw pointers: a byte store may alias anything, so through the vectors the compiler reloads
  // every data pointer after each one
  std::uint8_t* state = scan.data();
  const std::uint8_t* masks = nb.data();
  int* parent = t.parent.data();
  std::uint8_t* edges = t.edges.data();
  const int* links = g.links.empty() ? nullptr : g.links.data();
  const int offset[4] = {1, g.cols, -1, -g.cols};
  auto visit = [&](int v, int first) { state[v] = static_cast<std::uint8_t>(0x80 | first << 4); };
  visit(root, rootFirst & 3);
  std::size_t nodes = 1;
  for (int v = root;;) {
    const int s = state[v];
    if ((s & 7) == 4) {
      if (v == root) break;
      v = parent[v];
      continue;
    }
    const int d = ((s >> 4) + (s & 7)) & 3;
    state[v] = static_cast<std::uint8_t>(s + 1);
    if (!(masks[v] >> d & 1)) continue;
    const int u = links ? links[4 * static_cast<std::size_t>(v) + static_cast<std::size_t>(d)] : v + offset[d];
    if (state[u]) continue;
    parent[u] = v;
    edges[v] |= static_cast<std::uint8_t>(1u << d);
    edges[u] |= static_cast<std::uint8_t>(1u << opposite(d));
    ++nodes;
    // at u the parent lies in direction opposite(d): scan from the next direction counter-clockwise
    visit(u, (opposite(d) + 1) & 3);
    v = u;
  }
  t.nodes = nodes;
  return t;
}

SpanningTree dfsTreePlain(const GridGraph& g, int root) {
  SpanningTree t = emptyTree(g, root);
  if (!validRoot(g, root)) return t;
  t.nodes = 1;
  std::vector<std::uint8_t> seen(g.size(), 0);
  seen[static_cast<std::size_t>(root)] = 1;
  std::vector<std::pair<int, int>> stack{{root, 0}};
  while (!stack.empty()) {
    auto& [v, k] = stack.back();
    if (k == 4) {
      stack.pop_back();
      continue;
    }
    const int u = g.neighbour(v, k++);
    if (u < 0 || seen[static_cast<std::size_t>(u)]) continue;
    seen[static_cast<std::size_t>(u)] = 1;
    link(g, t, v, u);
    stack.emplace_back(u, 0);
  }
  return t;
}

SpanningTree dfsTreeBgl(const GridGraph& g, int root) {
  if (!validRoot(g, root)) return emptyTree(g, root);
  const Csr csr = makeCsr(g, false);
  std::vector<int> pred(g.size(), -1);
  TreeRecorder vis;
  vis.pred = &pred;
  std::vector<boost::default_color_type> color(g.size(), boost::white_color);
  boost::depth_first_visit(csr, static_cast<Csr::vertex_descriptor>(root), vis,
                           boost::make_iterator_property_map(color.begin(), boost::get(boost::vertex_index, csr)));
  return fromParents(g, root, pred);
}

SpanningTree bfsTreePlain(const GridGraph& g, int root) {
  SpanningTree t = emptyTree(g, root);
  if (!validRoot(g, root)) return t;
  t.nodes = 1;
  std::vector<std::uint8_t> seen(g.size(), 0);
  std::vector<int> queue{root};
  seen[static_cast<std::size_t>(root)] = 1;
  const std::vector<std::uint8_t> nb = neighbourMasks(g);
  const Step step(g);
  for (std::size_t h = 0; h < queue.size(); ++h) {
    const int v = queue[h];
    for (int d = 0; d < 4; ++d) {
      if (!(nb[static_cast<std::size_t>(v)] >> d & 1)) continue;
      const int u = step(v, d);
      if (seen[static_cast<std::size_t>(u)]) continue;
      seen[static_cast<std::size_t>(u)] = 1;
      link(t, v, u, d);
      queue.push_back(u);
    }
  }
  return t;
}

SpanningTree bfsTreeBgl(const GridGraph& g, int root) {
  if (!validRoot(g, root)) return emptyTree(g, root);
  const Csr csr = makeCsr(g, false);
  std::vector<int> pred(g.size(), -1);
  std::vector<boost::default_color_type> color(g.size(), boost::white_color);
  auto cmap = boost::make_iterator_property_map(color.begin(), boost::get(boost::vertex_index, csr));
  boost::queue<Csr::vertex_descriptor> q;
  boost::breadth_first_visit(
      csr, static_cast<Csr::vertex_descriptor>(root), q,
      boost::make_bfs_visitor(boost::record_predecessors(
          boost::make_iterator_property_map(pred.begin(), boost::get(boost::vertex_index, csr)), boost::on_tree_edge())),
      cmap);
  return fromParents(g, root, pred);
}

SpanningTree kruskalTreeBgl(const GridGraph& g, int root) {
  if (!validRoot(g, root)) return emptyTree(g, root);
  const Csr csr = makeCsr(g, true);
  std::vector<Csr::edge_descriptor> out;
  boost::kruskal_minimum_spanning_tree(csr, std::back_inserter(out), boost::weight_map(boost::get(&EdgeWeight::w, csr)));
  std::vector<std::uint8_t> mask(g.size(), 0);
  for (const auto& e : out) addMask(g, mask, static_cast<int>(boost::source(e, csr)), static_cast<int>(boost::target(e, csr)));
  return orient(g, root, mask);
}

std::size_t buildCsrOnly(const GridGraph& g) { return boost::num_edges(makeCsr(g, false)); }

namespace {

/// Kruskal's sets, with path halving. join(a, b) puts b's set under a's and is true when they were
/// apart: along a row each node then points at the row's first node, one step from its root.
class KruskalSets {
public:
  explicit KruskalSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  bool join(int a, int b) {
    const int ra = find(a), rb = find(b);
    if (ra == rb) return false;
    parent_[static_cast<std::size_t>(rb)] = ra;
    return true;
  }

private:
  int find(int x) {
    while (parent_[static_cast<std::size_t>(x)] != x) {
      parent_[static_cast<std::size_t>(x)] = parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(x)])];
      x = parent_[static_cast<std::size_t>(x)];
    }
    return x;
  }
  std::vector<int> parent_;
};

/// The nodes of root's component, in increasing order: a room's tree on a large map looks at the
/// room alone.
std::vector<int> componentNodes(const GridGraph& g, const std::vector<std::uint8_t>& nb, int root) {
  const Step step(g);
  std::vector<std::uint8_t> seen(g.size(), 0);
  std::vector<int> nodes{root};
  seen[static_cast<std::size_t>(root)] = 1;
  for (std::size_t head = 0; head < nodes.size(); ++head)
    for (int d = 0; d < 4; ++d) {
      if (!(nb[static_cast<std::size_t>(nodes[head])] >> d & 1)) continue;
      const int u = step(nodes[head], d);
      if (!seen[static_cast<std::size_t>(u)]) seen[static_cast<std::size_t>(u)] = 1, nodes.push_back(u);
    }
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

}  // namespace

SpanningTree kruskalTreePlain(const GridGraph& g, int root) {
  if (!validRoot(g, root)) return emptyTree(g, root);
  // The weights (horizontal before vertical, then by the lower node: see makeCsr) are unique and
  // their order is known: every east edge by node, then every north edge by node. So the edges are
  // taken in that order without being listed and sorted (at 10^7 sub-cells the tree took 320 ms
  // with the list and the sort, 40 without). Which edges Kruskal keeps depends only on that order,
  // not on how the sets are merged.
  const std::vector<std::uint8_t> nb = neighbourMasks(g);
  const Step step(g);
  KruskalSets sets(g.size());
  std::vector<std::uint8_t> mask(g.size(), 0);
  for (int d : {kEast, kNorth})
    for (int v = 0; v < static_cast<int>(g.size()); ++v) {
      if (!(nb[static_cast<std::size_t>(v)] >> d & 1)) continue;
      const int u = step(v, d);
      if (!sets.join(v, u)) continue;
      mask[static_cast<std::size_t>(v)] |= static_cast<std::uint8_t>(1u << d);
      mask[static_cast<std::size_t>(u)] |= static_cast<std::uint8_t>(1u << opposite(d));
    }
  return orient(g, root, mask);
}

SpanningTree kruskalTreeWeighted(const GridGraph& g, int root, const std::function<int(int v, int d)>& weight) {
  if (!validRoot(g, root)) return emptyTree(g, root);
  const std::vector<std::uint8_t> nb = neighbourMasks(g);
  const Step step(g);
  struct Edge {
    int weight, v, d;
  };
  // the edges of root's component only (the tree spans no other): O(c log c) for c of its nodes
  const std::vector<int> nodes = componentNodes(g, nb, root);
  std::vector<Edge> edges;
  for (int d : {kEast, kNorth})
    for (int v : nodes)
      if (nb[static_cast<std::size_t>(v)] >> d & 1) edges.push_back({weight(v, d), v, d});
  std::stable_sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.weight < b.weight; });
  KruskalSets sets(g.size());
  std::vector<std::uint8_t> mask(g.size(), 0);
  for (const Edge& e : edges) {
    const int u = step(e.v, e.d);
    if (!sets.join(e.v, u)) continue;
    mask[static_cast<std::size_t>(e.v)] |= static_cast<std::uint8_t>(1u << e.d);
    mask[static_cast<std::size_t>(u)] |= static_cast<std::uint8_t>(1u << opposite(e.d));
  }
  return orient(g, root, mask);
}

SpanningTree longestRunsTree(const GridGraph& g, int root) {
  if (!validRoot(g, root)) return emptyTree(g, root);
  const std::vector<std::uint8_t> nb = neighbourMasks(g);
  const Step step(g);
  // run[d][v]: the length of the run along d's axis that v lies in (1 for a node alone)
  std::vector<int> run[2] = {std::vector<int>(g.size(), 0), std::vector<int>(g.size(), 0)};
  const std::vector<int> component = componentNodes(g, nb, root);
  for (int axis : {kEast, kNorth})
    for (int v : component) {
      if (run[axis][static_cast<std::size_t>(v)]) continue;
      if (nb[static_cast<std::size_t>(v)] >> opposite(axis) & 1) continue;   // not the run's first node
      std::vector<int> nodes{v};
      while (nb[static_cast<std::size_t>(nodes.back())] >> axis & 1) nodes.push_back(step(nodes.back(), axis));
      for (int u : nodes) run[axis][static_cast<std::size_t>(u)] = static_cast<int>(nodes.size());
    }
  // a node prefers the vertical when its column run is more than twice its row run, else the
  // horizontal (kruskal_straight's); an edge weighs the count of its ends that prefer the other axis
  auto prefers = [&](int v, int axis) {
    const bool vertical = run[kNorth][static_cast<std::size_t>(v)] > 2 * run[kEast][static_cast<std::size_t>(v)];
    return vertical == (axis == kNorth);
  };
  return kruskalTreeWeighted(g, root, [&](int v, int d) { return !prefers(v, d) + !prefers(step(v, d), d); });
}

}  // namespace coverkit::graph
