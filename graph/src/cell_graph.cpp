// Cell graphs on Boost.Graph (cell_graph.h).
#include <coverkit/graph/cell_graph.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>

#include <algorithm>
#include <limits>
#include <map>
#include <stdexcept>

namespace coverkit::graph {

using BGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                     boost::property<boost::edge_weight_t, double>>;

struct CellGraph::Impl {
  BGraph g;
};

CellGraph::CellGraph(int n, const std::vector<WeightedEdge>& edges) : impl_(std::make_unique<Impl>()) {
  if (n < 0) throw std::invalid_argument("CellGraph: negative vertex count");
  impl_->g = BGraph(static_cast<std::size_t>(n));
  std::map<std::pair<int, int>, double> lightest;   // ordered: the same graph for the same input
  for (const WeightedEdge& e : edges) {
    if (e.a < 0 || e.b < 0 || e.a >= n || e.b >= n || e.a == e.b) throw std::invalid_argument("CellGraph: bad edge");
    const auto key = std::make_pair(std::min(e.a, e.b), std::max(e.a, e.b));
    auto it = lightest.find(key);
    if (it == lightest.end()) lightest.emplace(key, e.weight);
    else it->second = std::min(it->second, e.weight);
  }
  for (const auto& [k, w] : lightest) boost::add_edge(static_cast<std::size_t>(k.first), static_cast<std::size_t>(k.second), w, impl_->g);
}
CellGraph::~CellGraph() = default;
CellGraph::CellGraph(CellGraph&&) noexcept = default;
CellGraph& CellGraph::operator=(CellGraph&&) noexcept = default;

int CellGraph::vertexCount() const { return static_cast<int>(boost::num_vertices(impl_->g)); }
std::size_t CellGraph::edgeCount() const { return boost::num_edges(impl_->g); }

std::vector<int> CellGraph::neighbours(int v) const {
  std::vector<int> out;
  for (auto [it, end] = boost::adjacent_vertices(static_cast<std::size_t>(v), impl_->g); it != end; ++it) out.push_back(static_cast<int>(*it));
  std::sort(out.begin(), out.end());
  return out;
}

double CellGraph::weight(int a, int b) const {
  const auto [e, found] = boost::edge(static_cast<std::size_t>(a), static_cast<std::size_t>(b), impl_->g);
  return found ? boost::get(boost::edge_weight, impl_->g, e) : std::numeric_limits<double>::infinity();
}

std::vector<int> CellGraph::components() const {
  std::vector<int> comp(boost::num_vertices(impl_->g));
  if (!comp.empty()) boost::connected_components(impl_->g, comp.data());
  return comp;
}

void CellGraph::shortestPaths(int source, std::vector<double>& distance, std::vector<int>& predecessor) const {
  const std::size_t n = boost::num_vertices(impl_->g);
  std::vector<std::size_t> pred(n);
  distance.assign(n, std::numeric_limits<double>::infinity());
  boost::dijkstra_shortest_paths(impl_->g, static_cast<std::size_t>(source),
                                 boost::predecessor_map(pred.data()).distance_map(distance.data()));
  predecessor.assign(n, -1);
  for (std::size_t v = 0; v < n; ++v)
    if (pred[v] != v && distance[v] < std::numeric_limits<double>::infinity()) predecessor[v] = static_cast<int>(pred[v]);
}

std::vector<int> CellGraph::shortestPath(int a, int b) const {
  std::vector<double> dist;
  std::vector<int> pred;
  shortestPaths(a, dist, pred);
  if (!(dist[static_cast<std::size_t>(b)] < std::numeric_limits<double>::infinity())) return {};
  std::vector<int> path{b};
  while (path.back() != a) path.push_back(pred[static_cast<std::size_t>(path.back())]);
  std::reverse(path.begin(), path.end());
  return path;
}

std::vector<int> CellGraph::depthFirstOrder(int start) const {
  // BGL's depth_first_search visits out-edges in stored order; "nearest first" needs a sorted scan,
  // so the walk is explicit (the neighbours come from the adjacency_list)
  const std::size_t n = boost::num_vertices(impl_->g);
  std::vector<char> seen(n, 0);
  std::vector<int> order;
  std::vector<std::pair<int, std::vector<int>>> stack;
  auto sortedNeighbours = [&](int v) {
    std::vector<int> nb = neighbours(v);
    std::stable_sort(nb.begin(), nb.end(), [&](int x, int y) { return weight(v, x) < weight(v, y); });
    std::reverse(nb.begin(), nb.end());   // popped from the back: nearest first
    return nb;
  };
  seen[static_cast<std::size_t>(start)] = 1;
  order.push_back(start);
  stack.emplace_back(start, sortedNeighbours(start));
  while (!stack.empty()) {
    auto& [v, todo] = stack.back();
    if (todo.empty()) {
      stack.pop_back();
      continue;
    }
    const int w = todo.back();
    todo.pop_back();
    if (seen[static_cast<std::size_t>(w)]) continue;
    seen[static_cast<std::size_t>(w)] = 1;
    order.push_back(w);
    stack.emplace_back(w, sortedNeighbours(w));
  }
  return order;
}

}  // namespace coverkit::graph
