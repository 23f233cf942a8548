#pragma once
// The cell graph of a decomposition (issue 13): an irregular graph, so Boost.Graph's adjacency_list
// (vecS, undirected, weighted), behind a plain interface. Vertices are cells, edges the walls
// between adjacent cells, weighted by the length of a route between the cells' reference points
// through the wall. No geometry here: the caller gives the weights.
#include <memory>
#include <vector>

namespace coverkit::graph {

struct WeightedEdge {
  int a = -1, b = -1;
  double weight = 0;
};

class CellGraph {
public:
  /// `n` vertices; parallel edges keep the lightest.
  CellGraph(int n, const std::vector<WeightedEdge>& edges);
  ~CellGraph();
  CellGraph(CellGraph&&) noexcept;
  CellGraph& operator=(CellGraph&&) noexcept;

  int vertexCount() const;
  std::size_t edgeCount() const;
  /// Neighbours of v, sorted by index.
  std::vector<int> neighbours(int v) const;
  double weight(int a, int b) const;   ///< +inf when not adjacent
  /// Connected components: component index per vertex, numbered in order of their lowest vertex.
  std::vector<int> components() const;
  /// Dijkstra from `source`: distance per vertex (+inf where unreachable) and the predecessor
  /// (−1 at the source and where unreachable).
  void shortestPaths(int source, std::vector<double>& distance, std::vector<int>& predecessor) const;
  /// The vertices of a shortest path from a to b, both included; empty when b is unreachable.
  std::vector<int> shortestPath(int a, int b) const;
  /// Depth-first preorder of the component of `start`, neighbours taken nearest first (by edge
  /// weight, ties by index): the Reeb-graph order of a boustrophedon decomposition.
  std::vector<int> depthFirstOrder(int start) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace coverkit::graph
