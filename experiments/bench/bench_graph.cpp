// Boost.Graph (compressed_sparse_row_graph) against plain arrays on the same grids, same binary.
#include <benchmark/benchmark.h>

#include <coverkit/graph/spanning_tree.h>

#include <random>

using namespace coverkit::graph;

static GridGraph makeGrid(int side) {
  GridGraph g(side, side);
  std::mt19937_64 rng(11);
  for (auto& a : g.active) a = (rng() % 100) >= 10;  // 10 % blocked
  g.active[0] = 1;
  return g;
}

#define COVERKIT_TREE_BENCH(NAME, FN)                                              \
  static void NAME(benchmark::State& state) {                                      \
    const GridGraph g = makeGrid(static_cast<int>(state.range(0)));                \
    for (auto _ : state) benchmark::DoNotOptimize(FN(g, 0));                       \
    state.counters["nodes"] = static_cast<double>(g.size());                       \
    state.SetComplexityN(static_cast<long>(g.size()));                             \
  }                                                                                \
  BENCHMARK(NAME)->RangeMultiplier(4)->Range(64, 1024)->Unit(benchmark::kMillisecond)->Complexity();

static std::size_t csrBuild(const GridGraph& g, int) { return buildCsrOnly(g); }
COVERKIT_TREE_BENCH(BM_CsrBuildOnly, csrBuild)
COVERKIT_TREE_BENCH(BM_DfsBgl, dfsTreeBgl)
COVERKIT_TREE_BENCH(BM_DfsPlain, dfsTreePlain)
COVERKIT_TREE_BENCH(BM_DfsCcw, dfsCcwTree)
COVERKIT_TREE_BENCH(BM_BfsBgl, bfsTreeBgl)
COVERKIT_TREE_BENCH(BM_BfsPlain, bfsTreePlain)
COVERKIT_TREE_BENCH(BM_KruskalBgl, kruskalTreeBgl)
COVERKIT_TREE_BENCH(BM_KruskalPlain, kruskalTreePlain)
