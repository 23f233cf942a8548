// Grid → exact polygons, and exact validation of polygon input.
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/error.h>
#include <coverkit/graph/grid_search.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace coverkit::datasets {

namespace {
// Directions: 0 east, 1 north, 2 west, 3 south.
constexpr int kDx[4] = {1, 0, -1, 0};
constexpr int kDy[4] = {0, 1, 0, -1};
}  // namespace


Workspace gridToWorkspace(const OccupancyGrid& g, const std::string& name) {
  const int W = g.width, H = g.height;
  auto freeAt = [&](int c, int r) { return c >= 0 && r >= 0 && c < W && r < H && !g.at(c, r); };
  // 4-connected free components
  const std::vector<int> label = graph::gridComponents(W, H, [&](int v) { return !g.at(v % W, v / W); });
  const int comps = label.empty() ? 0 : *std::max_element(label.begin(), label.end()) + 1;
  // Directed boundary edges, free pixel on the left (counter-clockwise around each free pixel).
  // out[v]: bit d when an edge leaves lattice vertex v in direction d.
  const int VW = W + 1;
  std::vector<std::uint8_t> out(static_cast<std::size_t>(VW) * (H + 1), 0);
  auto vid = [&](int x, int y) { return static_cast<std::size_t>(y) * VW + x; };
  for (int r = 0; r < H; ++r)
    for (int c = 0; c < W; ++c) {
      if (!freeAt(c, r)) continue;
      if (!freeAt(c, r - 1)) out[vid(c, r)] |= 1 << 0;          // bottom side, eastwards
      if (!freeAt(c + 1, r)) out[vid(c + 1, r)] |= 1 << 1;      // right side, northwards
      if (!freeAt(c, r + 1)) out[vid(c + 1, r + 1)] |= 1 << 2;  // top side, westwards
      if (!freeAt(c - 1, r)) out[vid(c, r + 1)] |= 1 << 3;      // left side, southwards
    }
  Workspace w;
  w.name = name;
  std::vector<std::vector<Ring>> outers(static_cast<std::size_t>(comps)), holes(static_cast<std::size_t>(comps));
  auto pt = [&](int x, int y) { return Point{Rational(g.originX + g.resolution * x), Rational(g.originY + g.resolution * y)}; };
  for (int y = 0; y <= H; ++y)
    for (int x = 0; x <= VW - 1; ++x) {
      while (out[vid(x, y)]) {
        int d0 = 0;
        while (!(out[vid(x, y)] >> d0 & 1)) ++d0;
        // the free pixel left of the first edge tells the component
        const int pc = d0 == 0 ? x : d0 == 1 ? x - 1 : d0 == 2 ? x - 1 : x;
        const int pr = d0 == 0 ? y : d0 == 1 ? y : d0 == 2 ? y - 1 : y - 1;
        const int comp = label[static_cast<std::size_t>(pr) * W + pc];
        std::vector<std::pair<int, int>> ring;  // lattice corners
        int cx = x, cy = y, d = d0;
        bool first = true;
        while (true) {
          // take edge d from (cx, cy)
          out[vid(cx, cy)] &= static_cast<std::uint8_t>(~(1u << d));
          cx += kDx[d];
          cy += kDy[d];
          // choose the next edge: left turn first (free pixels 4-connected), then straight, then right
          int next = -1;
          for (int t : {1, 0, 3}) {
            const int nd = (d + t) & 3;
            const bool available = (out[vid(cx, cy)] >> nd & 1) || (cx == x && cy == y && nd == d0 && !first);
            if (available) {
              next = nd;
              break;
            }
          }
          first = false;
          if (next != d) ring.emplace_back(cx, cy);  // a corner
          if (cx == x && cy == y && next == d0) break;
          if (next < 0) throw InputError(name, "grid", "internal error: open boundary");  // cannot happen
          d = next;
        }
        // A ring that passes a pinch vertex twice is split there into simple loops (rings may then
        // touch at that vertex, which checkWorkspace and CGAL accept; a self-touching ring is not).
        std::vector<std::pair<int, int>> stack;
        std::map<std::pair<int, int>, std::size_t> at;
        auto emit = [&](std::vector<std::pair<int, int>> loop) {
          if (loop.size() < 3) return;
          Ring r;
          for (auto [lx, ly] : loop) r.push_back(pt(lx, ly));
          (signedArea2(r) > 0 ? outers : holes)[static_cast<std::size_t>(comp)].push_back(std::move(r));
        };
        for (const auto& v : ring) {
          auto it = at.find(v);
          if (it == at.end()) {
            at[v] = stack.size();
            stack.push_back(v);
            continue;
          }
          std::vector<std::pair<int, int>> loop(stack.begin() + static_cast<long>(it->second), stack.end());
          for (std::size_t k = it->second + 1; k < stack.size(); ++k) at.erase(stack[k]);
          stack.resize(it->second + 1);
          emit(std::move(loop));
        }
        emit(std::move(stack));
      }
    }
  // Regions: a component with one outer loop keeps all its holes; a component whose outer boundary
  // was split at pinch vertices becomes several regions, each hole going to the loop around it.
  for (int c = 0; c < comps; ++c) {
    auto& os = outers[static_cast<std::size_t>(c)];
    auto& hs = holes[static_cast<std::size_t>(c)];
    if (os.size() == 1) {
      w.regions.push_back({std::move(os[0]), std::move(hs)});
      continue;
    }
    const std::size_t first = w.regions.size();
    for (Ring& o : os) w.regions.push_back({std::move(o), {}});
    for (Ring& h : hs) {
      const Point m{Rational((h[0].x + h[1].x) / 2), Rational((h[0].y + h[1].y) / 2)};
      for (std::size_t k = first; k < w.regions.size(); ++k)
        if (insideRing(w.regions[k].outer, m)) {
          w.regions[k].holes.push_back(std::move(h));
          break;
        }
    }
  }
  return w;
}


}  // namespace coverkit::datasets
