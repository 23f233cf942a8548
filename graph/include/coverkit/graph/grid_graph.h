#pragma once
// The mega-cell grid as a graph: nodes are mega-cells (id = row·cols + col, row 0 at the bottom),
// edges join 4-neighbours that are both active and whose shared border is open (edge mask).
// No geometry here: planners fill `active` (and, for Smooth-STC, the edge masks) from a CellGrid.
//
// Node doubling (Full-STC): a mega-cell whose free sub-cells are not 4-connected inside it holds
// two nodes, one per layer (id = layer·cols·rows + row·cols + col). Such a graph lists its edges
// explicitly in `links` (per node, the neighbour in each direction or -1); there is still at most
// one neighbour per direction, so the trees and walks keep their four-direction logic.
#include <cstdint>
#include <string>
#include <vector>

namespace coverkit::graph {

/// Directions in counter-clockwise order; (d + 1) % 4 is the next one counter-clockwise.
enum Dir : int { kEast = 0, kNorth = 1, kWest = 2, kSouth = 3 };
constexpr int kDx[4] = {1, 0, -1, 0};
constexpr int kDy[4] = {0, 1, 0, -1};
inline int opposite(int d) { return (d + 2) & 3; }

struct GridGraph {
  int cols = 0, rows = 0, layers = 1;
  std::vector<std::uint8_t> active;   ///< per node
  std::vector<std::uint8_t> open;     ///< per node: bit d set when the border towards d may be crossed
  std::vector<int> links;             ///< empty (grid adjacency) or 4 per node: neighbour in direction d, or -1

  GridGraph() = default;
  GridGraph(int c, int r, int l = 1)
      : cols(c), rows(r), layers(l), active(static_cast<std::size_t>(c) * r * l, 0), open(active.size(), 0xF) {}
  int id(int col, int row, int layer = 0) const { return (layer * rows + row) * cols + col; }
  int plane() const { return cols * rows; }
  int col(int v) const { return v % cols; }
  int row(int v) const { return (v / cols) % rows; }
  int layer(int v) const { return v / plane(); }
  std::size_t size() const { return active.size(); }
  /// Neighbour of v in direction d when the edge exists, else -1.
  int neighbour(int v, int d) const {
    if (!links.empty()) {
      const int u = links[static_cast<std::size_t>(v) * 4 + static_cast<std::size_t>(d)];
      return u >= 0 && active[static_cast<std::size_t>(u)] && active[static_cast<std::size_t>(v)] ? u : -1;
    }
    const int c = v % cols + kDx[d], r = v / cols + kDy[d];
    if (c < 0 || r < 0 || c >= cols || r >= rows) return -1;
    const int u = r * cols + c;
    if (!active[static_cast<std::size_t>(u)] || !active[static_cast<std::size_t>(v)]) return -1;
    if (!(open[static_cast<std::size_t>(v)] >> d & 1) || !(open[static_cast<std::size_t>(u)] >> opposite(d) & 1)) return -1;
    return u;
  }
};

}  // namespace coverkit::graph
