#pragma once
// The mega-cell grid as a graph: nodes are mega-cells (id = row·cols + col, row 0 at the bottom),
// edges join 4-neighbours that are both active and whose shared border is open (edge mask).
// No geometry here: planners fill `active` (and, for Smooth-STC, the edge masks) from a CellGrid.
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
  int cols = 0, rows = 0;
  std::vector<std::uint8_t> active;   ///< per node
  std::vector<std::uint8_t> open;     ///< per node: bit d set when the border towards d may be crossed

  GridGraph() = default;
  GridGraph(int c, int r) : cols(c), rows(r), active(static_cast<std::size_t>(c) * r, 0), open(active.size(), 0xF) {}
  int id(int col, int row) const { return row * cols + col; }
  int col(int v) const { return v % cols; }
  int row(int v) const { return v / cols; }
  std::size_t size() const { return active.size(); }
  /// Neighbour of v in direction d when the edge exists, else -1.
  int neighbour(int v, int d) const {
    const int c = v % cols + kDx[d], r = v / cols + kDy[d];
    if (c < 0 || r < 0 || c >= cols || r >= rows) return -1;
    const int u = r * cols + c;
    if (!active[static_cast<std::size_t>(u)] || !active[static_cast<std::size_t>(v)]) return -1;
    if (!(open[static_cast<std::size_t>(v)] >> d & 1) || !(open[static_cast<std::size_t>(u)] >> opposite(d) & 1)) return -1;
    return u;
  }
};

}  // namespace coverkit::graph
