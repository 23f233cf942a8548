#pragma once
// Searches on a plain grid of cells: cell id = row·cols + col, row 0 at the bottom, which cells may
// be entered is a predicate of the caller's. No geometry here: the planners pass their sub-cell or
// mega-cell states, the grid-map reader its pixels.
//
//  - GridAStar: shortest paths, 4- or 8-connected (TRACC, BSA).
//  - gridComponents: the 4-connected components (the flood fill: the default start's largest
//    component, the grid-map polygoniser's regions, the BSA experiment's walled-in starts).
//  - gridDistances: breadth-first step counts from a set of cells (multi_stc_balanced, spreadStarts).
//
// Plain arrays, not Boost.Graph: on grids Boost.Graph measured 5-12x slower than plain arrays
// (spanning_tree.h; docs/performance.md has the figures), and a grid needs no adjacency lists.
// Header-only: both are templates over the predicate, which inlines.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <queue>
#include <tuple>
#include <vector>

namespace coverkit::graph {

// A* on the sub-cell grid: TRACC's 4-connected detours (Manhattan heuristic) and BSA's
// 8-connected backtracking (octile heuristic, the BSA paper's equation (2):
// h = D·(dx + dy) + (D2 − 2D)·min(dx, dy) with D = 1, D2 = √2). A diagonal step needs both side
// cells passable, so a disc that fits a cell never clips a corner.
//
// The open list is a binary heap with lazy deletion: a cell popped again after it was closed is
// skipped, so nothing is rescanned or re-sorted. Per-search arrays are reset by a stamp, not
// cleared, so a search costs O(k log k) in the k cells it touches, not O(grid).
class GridAStar {
public:
  GridAStar(int cols, int rows, bool eightConnected)
      : cols_(cols), rows_(rows), eight_(eightConnected), stamp_(static_cast<std::size_t>(cols) * rows, 0),
        closed_(stamp_.size(), 0), g_(stamp_.size(), 0.0), next_(stamp_.size(), -1) {}

  /// Cells from `from` to `to` (both included) through cells where `passable(cell)` holds (`to`
  /// itself need not), or empty when there is none. `explored` gets every cell closed.
  template <class Passable>
  std::vector<int> search(int from, int to, Passable passable, std::vector<int>& explored) {
    ++search_;
    explored.clear();
    // search from `to` back to `from`: parents then point along the path from `from`
    using Entry = std::tuple<double, double, int>;  // f, −g (deeper first on ties), cell
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    const int fc = from % cols_, fr = from / cols_;
    auto h = [&](int v) {
      const double dx = std::abs(v % cols_ - fc), dy = std::abs(v / cols_ - fr);
      return eight_ ? (dx + dy) + (std::sqrt(2.0) - 2.0) * std::min(dx, dy) : dx + dy;
    };
    auto touch = [&](int v) {
      if (stamp_[static_cast<std::size_t>(v)] != search_) {
        stamp_[static_cast<std::size_t>(v)] = search_;
        closed_[static_cast<std::size_t>(v)] = 0;
        g_[static_cast<std::size_t>(v)] = -1;
      }
    };
    auto ok = [&](int c, int r) { return c >= 0 && r >= 0 && c < cols_ && r < rows_ && (r * cols_ + c == from || passable(r * cols_ + c)); };
    touch(to);
    g_[static_cast<std::size_t>(to)] = 0;
    next_[static_cast<std::size_t>(to)] = -1;
    open.emplace(h(to), 0.0, to);
    static constexpr int kX[8] = {1, 0, -1, 0, 1, -1, -1, 1}, kY[8] = {0, 1, 0, -1, 1, 1, -1, -1};
    while (!open.empty()) {
      const auto [f, ng, v] = open.top();
      open.pop();
      if (closed_[static_cast<std::size_t>(v)]) continue;
      closed_[static_cast<std::size_t>(v)] = 1;
      explored.push_back(v);
      ++expansions;
      if (v == from) {
        std::vector<int> path;
        for (int u = from; u >= 0; u = next_[static_cast<std::size_t>(u)]) path.push_back(u);
        return path;
      }
      const int c = v % cols_, r = v / cols_;
      for (int d = 0; d < (eight_ ? 8 : 4); ++d) {
        const int nc = c + kX[d], nr = r + kY[d];
        if (!ok(nc, nr)) continue;
        if (d >= 4 && (!ok(nc, r) || !ok(c, nr))) continue;  // both side cells, or no diagonal
        const int u = nr * cols_ + nc;
        touch(u);
        const double gu = g_[static_cast<std::size_t>(v)] + (d >= 4 ? std::sqrt(2.0) : 1.0);
        if (closed_[static_cast<std::size_t>(u)] || (g_[static_cast<std::size_t>(u)] >= 0 && g_[static_cast<std::size_t>(u)] <= gu)) continue;
        g_[static_cast<std::size_t>(u)] = gu;
        next_[static_cast<std::size_t>(u)] = v;
        open.emplace(gu + h(u), -gu, u);
      }
    }
    return {};
  }
  std::size_t expansions = 0;

private:
  int cols_, rows_;
  bool eight_;
  unsigned search_ = 0;
  std::vector<unsigned> stamp_;
  std::vector<std::uint8_t> closed_;
  std::vector<double> g_;
  std::vector<int> next_;
};

/// The 4-connected components of the cells where `passable(cell)` holds (cell = row·cols + col;
/// asked once per cell of the grid, never outside it): per cell its component's label, or -1 where
/// not passable. Components are numbered 0, 1, ... in row order of their first cell (the lowest
/// id), so the labels do not depend on the order of the fill. O(cells) time and memory: one pass,
/// an explicit stack (no recursion, so 10^6 cells in one component are fine).
template <class Passable>
std::vector<int> gridComponents(int cols, int rows, Passable passable) {
  const std::size_t n = static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows);
  std::vector<std::uint8_t> open(n, 0);
  for (std::size_t v = 0; v < n; ++v) open[v] = passable(static_cast<int>(v)) ? 1 : 0;
  std::vector<int> label(n, -1), stack;
  int count = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (!open[v] || label[v] >= 0) continue;
    label[v] = count;
    stack.push_back(static_cast<int>(v));
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      const int c = u % cols, r = u / cols;
      const int nb[4][2] = {{c + 1, r}, {c, r + 1}, {c - 1, r}, {c, r - 1}};
      for (const auto& x : nb) {
        if (x[0] < 0 || x[1] < 0 || x[0] >= cols || x[1] >= rows) continue;
        const std::size_t w = static_cast<std::size_t>(x[1]) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(x[0]);
        if (!open[w] || label[w] >= 0) continue;
        label[w] = count;
        stack.push_back(static_cast<int>(w));
      }
    }
    ++count;
  }
  return label;
}

/// Breadth-first step counts, 4-connected, from the cells `sources` (distance 0) through cells where
/// `passable(cell)` holds (asked only of the neighbours reached; the sources themselves need not be
/// passable): per cell its distance, or -1 where unreached. O(cells reached). A multi-robot planner's
/// travel lengths, its A*'s heuristic, the spread of starts.
template <class Passable>
std::vector<int> gridDistances(int cols, int rows, const std::vector<long>& sources, Passable passable) {
  std::vector<int> dist(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows), -1);
  std::vector<long> queue;
  for (long s : sources)
    if (dist[static_cast<std::size_t>(s)] < 0) dist[static_cast<std::size_t>(s)] = 0, queue.push_back(s);
  for (std::size_t h = 0; h < queue.size(); ++h) {
    const int c = static_cast<int>(queue[h] % cols), r = static_cast<int>(queue[h] / cols);
    const int nb[4][2] = {{c + 1, r}, {c - 1, r}, {c, r + 1}, {c, r - 1}};
    for (const auto& x : nb) {
      if (x[0] < 0 || x[1] < 0 || x[0] >= cols || x[1] >= rows) continue;
      const long w = static_cast<long>(x[1]) * cols + x[0];
      if (dist[static_cast<std::size_t>(w)] >= 0 || !passable(static_cast<int>(w))) continue;
      dist[static_cast<std::size_t>(w)] = dist[static_cast<std::size_t>(queue[h])] + 1;
      queue.push_back(w);
    }
  }
  return dist;
}

}  // namespace coverkit::graph
