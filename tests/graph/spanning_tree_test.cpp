#include <coverkit/graph/spanning_tree.h>

#include <gtest/gtest.h>

#include <random>

using namespace coverkit::graph;

namespace {
GridGraph randomGrid(int w, int h, std::uint64_t seed) {
  GridGraph g(w, h);
  std::mt19937_64 rng(seed);
  for (auto& a : g.active) a = rng() % 100 >= 25;
  g.active[0] = 1;
  return g;
}
std::size_t componentSize(const GridGraph& g, int root) {
  std::vector<char> seen(g.size(), 0);
  std::vector<int> st{root};
  seen[static_cast<std::size_t>(root)] = 1;
  std::size_t n = 0;
  while (!st.empty()) {
    int v = st.back();
    st.pop_back();
    ++n;
    for (int d = 0; d < 4; ++d) {
      int u = g.neighbour(v, d);
      if (u >= 0 && !seen[static_cast<std::size_t>(u)]) { seen[static_cast<std::size_t>(u)] = 1; st.push_back(u); }
    }
  }
  return n;
}
::testing::AssertionResult isSpanningTree(const GridGraph& g, const SpanningTree& t) {
  const std::size_t n = componentSize(g, t.root);
  if (t.nodes != n) return ::testing::AssertionFailure() << "tree has " << t.nodes << " nodes, component " << n;
  std::size_t edges = 0;
  for (int v = 0; v < static_cast<int>(g.size()); ++v) {
    const int p = t.parent[static_cast<std::size_t>(v)];
    if (p < 0) continue;
    ++edges;
    bool adjacent = false;
    for (int d = 0; d < 4; ++d) adjacent = adjacent || g.neighbour(p, d) == v;
    if (!adjacent) return ::testing::AssertionFailure() << "tree edge " << p << "-" << v << " is not a graph edge";
  }
  if (edges + 1 != n) return ::testing::AssertionFailure() << edges << " edges for " << n << " nodes";
  return ::testing::AssertionSuccess();
}
}  // namespace

TEST(SpanningTree, BoostGraphAndPlainArraysGiveTheSameTree) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const GridGraph g = randomGrid(23, 17, seed);
    EXPECT_EQ(dfsTreeBgl(g, 0), dfsTreePlain(g, 0)) << seed;
    EXPECT_EQ(bfsTreeBgl(g, 0), bfsTreePlain(g, 0)) << seed;
    EXPECT_EQ(kruskalTreeBgl(g, 0), kruskalTreePlain(g, 0)) << seed;
  }
}

TEST(SpanningTree, EveryStrategySpansTheRootsComponent) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const GridGraph g = randomGrid(31, 12, seed);
    for (TreeStrategy s : {TreeStrategy::kDfsCcw, TreeStrategy::kBfs, TreeStrategy::kKruskalStraight, TreeStrategy::kLongestRuns})
      EXPECT_TRUE(isSpanningTree(g, buildTree(g, 0, s))) << toString(s) << " seed " << seed;
  }
}

TEST(SpanningTree, DfsCcwOrderOnAnOpenGrid) {
  // From the root (virtual parent south) the first branch goes east; at the east end the scan
  // starts after the parent (west): north first.
  GridGraph g(3, 2);
  for (auto& a : g.active) a = 1;
  const SpanningTree t = dfsCcwTree(g, 0);
  EXPECT_EQ(t.parent[1], 0);
  EXPECT_EQ(t.parent[2], 1);
  EXPECT_EQ(t.parent[5], 2);
  EXPECT_EQ(t.parent[4], 5);
  EXPECT_EQ(t.parent[3], 4);
}

TEST(SpanningTree, KruskalStraightPrefersRows) {
  GridGraph g(6, 4);
  for (auto& a : g.active) a = 1;
  const SpanningTree t = kruskalTreeBgl(g, 0);
  int vertical = 0;
  for (int v = 0; v < static_cast<int>(g.size()); ++v)
    if (t.parent[static_cast<std::size_t>(v)] >= 0 && g.col(t.parent[static_cast<std::size_t>(v)]) == g.col(v)) ++vertical;
  EXPECT_EQ(vertical, 3);  // rows joined by the fewest vertical edges
}

// longest_runs: a room 12 wide with a strip 2 wide and 10 tall below its east end (an L). The
// room's nodes prefer rows (runs of 12 against 3 or 11), the strip's columns (runs of 11 against 2):
// the strip becomes two vertical branches, where kruskal_straight makes a comb of 10 rows of 2. On
// an open grid (every node prefers rows) the tree is kruskal_straight's.
TEST(SpanningTree, LongestRunsTurnsStripsAlongTheirLength) {
  GridGraph g(12, 11);
  for (int v = 0; v < static_cast<int>(g.size()); ++v) g.active[static_cast<std::size_t>(v)] = g.row(v) == 10 || g.col(v) >= 10;
  const int root = g.id(0, 10);
  const SpanningTree runs = longestRunsTree(g, root), straight = kruskalTreePlain(g, root);
  ASSERT_TRUE(isSpanningTree(g, runs));
  auto verticalInStrip = [&](const SpanningTree& t) {
    int n = 0;
    for (int v = 0; v < static_cast<int>(g.size()); ++v) {
      const int p = t.parent[static_cast<std::size_t>(v)];
      if (p >= 0 && g.row(v) < 10 && g.row(p) < 10 && g.col(p) == g.col(v)) ++n;
    }
    return n;
  };
  EXPECT_EQ(verticalInStrip(runs), 18);     // 2 columns of 10 strip nodes: 9 edges each
  EXPECT_EQ(verticalInStrip(straight), 9);  // one between each two rows of 2: a comb
  GridGraph open(9, 5);
  for (auto& a : open.active) a = 1;
  EXPECT_EQ(longestRunsTree(open, 0), kruskalTreePlain(open, 0));
  // a weight that makes every edge equal gives kruskal_straight's order too
  EXPECT_EQ(kruskalTreeWeighted(open, 0, [](int, int) { return 0; }), kruskalTreePlain(open, 0));
}

TEST(SpanningTree, StrategyNames) {
  TreeStrategy s;
  for (const auto& n : treeStrategyNames()) {
    ASSERT_TRUE(parseTreeStrategy(n, s));
    EXPECT_EQ(n, toString(s));
  }
  EXPECT_FALSE(parseTreeStrategy("dfs", s));
}
