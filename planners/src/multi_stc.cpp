// multi_stc_balanced: k robots share one STC tour, each covering a stretch of it, the stretches
// balanced to minimise the makespan; timed, collision-free by construction and checked by the team
// validator (docs/multi-robot.md).
//
// The baseline of issue 16 (offline, static worlds), in the spirit of MSTC (N. Hazon and G. Kaminka,
// "Redundancy, efficiency and robustness in multi-robot coverage", ICRA 2005) and its balanced
// variants: one STC circumnavigation (a cycle through every sub-cell of the free mega-cells of the
// starts' component, each once) is cut into k disjoint stretches, one around each robot's start.
// Robot i covers b_i cells behind its start and f_i ahead, going first the shorter way and back
// (b + f + min(b, f) steps), so that it needs no travel to reach its stretch. The stretches split
// each gap between neighbouring robots on the cycle; the largest cost is minimised by a binary
// search over it (for a bound T, going round the cycle each robot takes as much of the gap ahead as
// T allows, given what it already takes behind; the cycle closes when robot 0's share behind is a
// fixed point).
//
// With `travel=auto` (the default) a second split is tried, in the spirit of MSTC* (balanced pieces
// reached by travel): the robots, in their order on the cycle, take consecutive pieces, each as long
// as a bound on (shortest travel to its first cell + its length) allows; the least bound is found by
// binary search over offsets and rotations. Each robot is then routed by A* in space and time
// against the robots routed before it, under the rules below, and covers its piece in tour order,
// waiting where the next cell is taken. That split is kept when every robot gets a route and it
// finishes sooner than the stretches; else the stretches stand. Prioritised routing can fail where
// robots are dense (from about 30 robots on a cluttered 256 × 256 map): then the stretches.
//
// Decisions:
//  * time is steps of `step` seconds (default 0.1 s, the Multi-ST paper's 100 ms): one step moves a
//    robot to a 4-neighbouring sub-cell of its stretch or keeps it where it is. In the first step
//    every robot moves from its start to the centre of its start's sub-cell (or stays there).
//  * collisions: from then on every robot is at a sub-cell centre at every step and (stretches) only
//    ever enters cells of its own stretch, or (travel) never enters a cell another robot is in at
//    that step or the next nor leaves one another robot enters at the next, so at each step the
//    cells two robots leave and enter are four distinct lattice points (or one robot waits); two such unit moves between 4-neighbours stay at least one cell
//    (D = 2r) apart throughout (the cases are few: the same direction keeps the distance; opposite
//    or perpendicular directions come nearer than D only when one enters the other's cell). The
//    validator checks every plan exactly anyway; the first step (off-centre starts) is the one it
//    can refuse.
//  * robots side by side at sub-cell centres are exactly D apart: with D = 2r a team needs centres
//    that are doubles (else STC's rounding towards the mega-cell's centre brings two robots of one
//    mega-cell an ulp too near, and no rounding is clear of both walls and robots): InputError with
//    the way out (a dyadic radius, or a cell size a little above 2r).
//  * moving obstacles (coverkit.scenario/1): only routed moves can wait for them or go round, so
//    among them the travel split is used whatever `travel` says; every step and wait, each robot's
//    first step and its parking for good are checked exactly against every obstacle (movesClearOf,
//    the validator's own test). A tour sub-cell that no way reaches (an obstacle parked on it for
//    good) is left out: status partial_coverage, statistic subcells_skipped. Robots enter no cell
//    from which the next step has no clear move or wait; a way to a piece may wait until the last
//    obstacle stops; a robot parks at the first (cell, step) found depth first in time from which
//    it stays clear for good. When no robot order gives every robot a route, multi_st plans the
//    team (statistic split_multi_st): robots left at their starts were run into by the obstacles.
//  * a team of equal discs: the sub-cells are sized for robots[0]; starts must lie in free
//    mega-cells of one component (status invalid_start otherwise).
#include <coverkit/planners/multi_stc.h>

#include "subcell_regions.h"
#include "team_steps.h"
#include "walk_path.h"

#include <coverkit/geometry/error.h>
#include <coverkit/geometry/validate.h>
#include <coverkit/graph/grid_search.h>
#include <coverkit/planners/stc_skeleton.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <functional>
#include <cmath>
#include <numeric>
#include <queue>
#include <random>
#include <unordered_map>

namespace coverkit::planners {

namespace {

/// STC's tour, its hooks made reachable.
class StcTour : public StcPlanner {
public:
  using StcSkeleton::buildGraph;
  using StcSkeleton::tourFrom;
};

/// The stretches: robot j (in cycle order) takes b[j] cells behind its start and f[j] ahead, with
/// f[j] + b[j + 1] = gap[j] (cyclically). Returns the makespan in moves (cost of the worst robot).
long balance(const std::vector<long>& gap, std::vector<long>& b, std::vector<long>& f) {
  const std::size_t k = gap.size();
  b.assign(k, 0);
  f.assign(k, 0);
  if (k == 1) {
    f[0] = gap[0];
    return gap[0];
  }
  auto maxAhead = [](long behind, long T) -> long {   // the most f with behind + f + min(behind, f) <= T
    if (T - 2 * behind >= behind) return T - 2 * behind;
    if (T - behind < 0) return -1;
    return (T - behind) / 2;
  };
  auto feasible = [&](long T, std::vector<long>& bb, std::vector<long>& ff) {
    bb.assign(k, 0);
    ff.assign(k, 0);
    long b0 = 0;
    for (;;) {
      bb[0] = b0;
      for (std::size_t j = 0; j < k; ++j) {
        const long ahead = maxAhead(bb[j], T);
        if (ahead < 0) return false;
        const long next = std::max(0L, gap[j] - ahead);
        if (j + 1 < k) bb[j + 1] = next;
        else if (next <= b0) {   // the cycle closes: robot 0 already takes what is left behind it
          for (std::size_t i = 0; i < k; ++i) ff[i] = gap[i] - (i + 1 < k ? bb[i + 1] : b0);
          return true;
        } else {
          b0 = next;
        }
      }
      if (b0 > gap[k - 1]) return false;
    }
  };
  long lo = 0, hi = 1;
  for (long g : gap) hi += 2 * g;
  std::vector<long> bb, ff;
  while (lo < hi) {
    const long mid = lo + (hi - lo) / 2;
    if (feasible(mid, bb, ff)) hi = mid;
    else lo = mid + 1;
  }
  feasible(lo, b, f);
  long worst = 0;
  for (std::size_t j = 0; j < k; ++j) worst = std::max(worst, b[j] + f[j] + std::min(b[j], f[j]));
  return worst;
}

/// Teams larger than this skip the regions split (its links between regions are a k × k table).
constexpr std::size_t kMaxRegions = 1024;

/// Regions of sub-cells (subcell_regions.h) are tried only on tours of at most this many sub-cells
/// with at most kMaxSubcellsPerRobot each on average (16 mega-cells): with more, whole mega-cells
/// are within ⌈n/k⌉ / (n/k) ≤ 1 + 1/16 of the mean, and the refinement's walks grow long (its cost
/// grows with the regions' size; on maps with obstacles, where the mean cannot be reached, it runs
/// to its work bound).
constexpr std::size_t kMaxSubcellRegions = std::size_t{1} << 14, kMaxSubcellsPerRobot = 64;

/// The longest of the robots' routes: the makespan in steps of a split.
std::size_t longest(const std::vector<std::vector<CellIndex>>& routes) {
  std::size_t n = 0;
  for (const auto& r : routes) n = std::max(n, r.size());
  return n;
}

/// The largest region and the sum of the squared sizes: a split is better when both are smaller
/// (in that order).
std::pair<long, long> spread(const std::vector<long>& sizes) {
  long peak = 0, squares = 0;
  for (long x : sizes) {
    peak = std::max(peak, x);
    squares += x * x;
  }
  return {peak, squares};
}

/// Steps from each start within the graph: k rows of n, -1 where a node is not reached.
std::vector<int> startDistances(const graph::GridGraph& g, const std::vector<int>& root) {
  const std::size_t k = root.size(), n = g.size();
  std::vector<int> dist(k * n, -1);
  std::deque<int> open;
  for (std::size_t i = 0; i < k; ++i) {
    int* d = dist.data() + i * n;
    d[root[i]] = 0;
    open.assign(1, root[i]);
    while (!open.empty()) {
      const int v = open.front();
      open.pop_front();
      for (int e = 0; e < 4; ++e)
        if (const int u = g.neighbour(v, e); u >= 0 && d[u] < 0) {
          d[u] = d[v] + 1;
          open.push_back(u);
        }
    }
  }
  return dist;
}

/// DARP's re-weighting, additively: each mega-cell goes to the region i with the least d_i + w_i
/// (d_i: steps from start i within the component, ties to the lower index), and w_i grows while
/// region i is larger than the mean. Additive weights keep every region connected to its start (a
/// cell's predecessor towards start i is no farther from i, relative to any other start, than the
/// cell), where DARP's multiplicative ones need a connectivity repair. The assignment with the
/// smallest largest region (then the least sum of squares) over 200 rounds replaces the breadth-first
/// one when better; the moves of single mega-cells then go on from it. Memory k × n distances: only
/// for k · n ≤ 2^22 (`dist`: startDistances). `seed` 0: the weights start at 0; else at seeded random
/// offsets (a restart).
void reweighted(const graph::GridGraph& g, const std::vector<int>& root, const std::vector<int>& dist, std::vector<int>& owner,
                std::vector<long>& size, const TerminationCondition& stop, std::uint64_t seed) {
  const std::size_t k = root.size(), n = g.size();
  std::deque<int> open;
  auto best = spread(size);
  long total = 0;
  for (long x : size) total += x;
  const double mean = static_cast<double>(total) / static_cast<double>(k);
  std::vector<double> w(k, 0.0);
  if (seed != 0) {   // a restart: the weights start at random offsets below √mean (std::mt19937_64 is the same everywhere)
    std::mt19937_64 rng(seed);
    for (double& x : w) x = static_cast<double>(rng() >> 11) * 0x1.0p-53 * std::sqrt(mean);
  }
  std::vector<int> mine(n, -1);
  std::vector<long> z(k, 0);
  std::vector<char> reached(n, 0);
  for (int round = 0; round < 200; ++round) {
    if ((round & 15) == 15 && stop.expired()) return;
    std::fill(z.begin(), z.end(), 0);
    for (std::size_t v = 0; v < n; ++v) {
      if (owner[v] < 0) {   // outside the component (or a start's own cell: set below)
        mine[v] = -1;
        continue;
      }
      int arg = -1;
      double least = 0;
      for (std::size_t i = 0; i < k; ++i) {
        const int d = dist[i * n + v];
        if (d < 0) continue;
        const double c = d + w[i];
        if (arg < 0 || c < least) {
          arg = static_cast<int>(i);
          least = c;
        }
      }
      mine[v] = arg;
    }
    for (std::size_t i = 0; i < k; ++i) mine[static_cast<std::size_t>(root[i])] = static_cast<int>(i);
    // connected to its start within its region, else to the region of a neighbour that is (rare: ties)
    std::fill(reached.begin(), reached.end(), 0);
    for (std::size_t i = 0; i < k; ++i) {
      open.assign(1, root[i]);
      reached[static_cast<std::size_t>(root[i])] = 1;
      while (!open.empty()) {
        const int v = open.front();
        open.pop_front();
        for (int e = 0; e < 4; ++e)
          if (const int u = g.neighbour(v, e); u >= 0 && !reached[static_cast<std::size_t>(u)] && mine[static_cast<std::size_t>(u)] == static_cast<int>(i)) {
            reached[static_cast<std::size_t>(u)] = 1;
            open.push_back(u);
          }
      }
    }
    open.clear();
    for (std::size_t v = 0; v < n; ++v)
      if (reached[v]) open.push_back(static_cast<int>(v));
    while (!open.empty()) {   // strays join a reached neighbour's region, breadth first
      const int v = open.front();
      open.pop_front();
      for (int e = 0; e < 4; ++e)
        if (const int u = g.neighbour(v, e); u >= 0 && mine[static_cast<std::size_t>(u)] >= 0 && !reached[static_cast<std::size_t>(u)]) {
          reached[static_cast<std::size_t>(u)] = 1;
          mine[static_cast<std::size_t>(u)] = mine[static_cast<std::size_t>(v)];
          open.push_back(u);
        }
    }
    for (std::size_t v = 0; v < n; ++v)
      if (mine[v] >= 0) ++z[static_cast<std::size_t>(mine[v])];
    const auto s = spread(z);
    if (s < best) {
      best = s;
      owner = mine;
      size = z;
    }
    if (best.first <= static_cast<long>(std::ceil(mean))) return;
    for (std::size_t i = 0; i < k; ++i) w[i] += 0.2 * (static_cast<double>(z[i]) - mean) / std::sqrt(mean);
  }
}

/// DARP-style regions (in the spirit of A. Kapoutsis, S. Chatzichristofis and E. Kosmatopoulos,
/// "DARP: divide areas algorithm for optimal multi-robot coverage path planning", J. Intell. Robot.
/// Syst. 86, 2017): the component's free mega-cells split into k connected regions, region i holding
/// robot i's start mega-cell, as equal in size as moves of single mega-cells can make them. Robot i
/// then goes round an STC tree of its own region: no travel, and no cell another robot ever enters.
///
/// Decision: DARP balances by re-weighting distances until its assignment settles; we start from the
/// breadth-first (Voronoi) assignment and move boundary mega-cells instead, which is deterministic
/// and needs no convergence test. While the largest region has a chain of neighbouring regions,
/// each able to pass one mega-cell to the next, that ends in a region at least two smaller, one
/// mega-cell moves along each link of the chain (the largest loses one, the last gains one, the
/// others keep their size): the sum of squared sizes falls with every chain, so it ends. A mega-cell
/// may leave its region when it is not the start and not an articulation point of its region
/// (Tarjan's depth-first search over the region, redone only for regions a move changed).
/// Returns the owner of each node (-1 outside the regions), or empty when two robots start in one
/// mega-cell or the time limit ends the balancing.
std::vector<int> regionsFrom(const graph::GridGraph& g, const std::vector<int>& root, const TerminationCondition& stop,
                             const std::vector<int>* dist, std::uint64_t seed) {
  const std::size_t k = root.size(), n = g.size();
  std::vector<int> owner(n, -1);
  std::vector<long> size(k, 0);
  std::deque<int> open;
  for (std::size_t i = 0; i < k; ++i) {
    if (owner[static_cast<std::size_t>(root[i])] >= 0) return {};
    owner[static_cast<std::size_t>(root[i])] = static_cast<int>(i);
    size[i] = 1;
    open.push_back(root[i]);
  }
  while (!open.empty()) {   // breadth first from all starts at once
    const int v = open.front();
    open.pop_front();
    for (int d = 0; d < 4; ++d) {
      const int u = g.neighbour(v, d);
      if (u < 0 || owner[static_cast<std::size_t>(u)] >= 0) continue;
      owner[static_cast<std::size_t>(u)] = owner[static_cast<std::size_t>(v)];
      ++size[static_cast<std::size_t>(owner[static_cast<std::size_t>(v)])];
      open.push_back(u);
    }
  }
  if (dist) reweighted(g, root, *dist, owner, size, stop, seed);
  std::vector<char> isRoot(n, 0);
  for (int r : root) isRoot[static_cast<std::size_t>(r)] = 1;
  // cut[v]: v is an articulation point of its region (removing it would split the region), for
  // regions whose rows are not stale; found by Tarjan's depth-first search (iterative)
  std::vector<char> cut(n, 0);
  std::vector<int> disc(n, 0), low(n, 0);
  int clock = 0;
  auto articulate = [&](const std::vector<int>& cells, int R) {
    for (int v : cells) {
      cut[static_cast<std::size_t>(v)] = 0;
      disc[static_cast<std::size_t>(v)] = 0;
    }
    if (cells.empty()) return;
    struct Frame { int v, parent, d; };
    std::vector<Frame> stack{{cells.front(), -1, 0}};
    disc[static_cast<std::size_t>(cells.front())] = low[static_cast<std::size_t>(cells.front())] = ++clock;
    int rootChildren = 0;
    while (!stack.empty()) {
      Frame& f = stack.back();
      if (f.d < 4) {
        const int u = g.neighbour(f.v, f.d++);
        if (u < 0 || owner[static_cast<std::size_t>(u)] != R || u == f.parent) continue;
        if (disc[static_cast<std::size_t>(u)] == 0) {
          disc[static_cast<std::size_t>(u)] = low[static_cast<std::size_t>(u)] = ++clock;
          if (f.parent < 0) ++rootChildren;
          stack.push_back({u, f.v, 0});
        } else {
          low[static_cast<std::size_t>(f.v)] = std::min(low[static_cast<std::size_t>(f.v)], disc[static_cast<std::size_t>(u)]);
        }
        continue;
      }
      const int v = f.v, parent = f.parent;
      stack.pop_back();
      if (parent < 0) continue;
      low[static_cast<std::size_t>(parent)] = std::min(low[static_cast<std::size_t>(parent)], low[static_cast<std::size_t>(v)]);
      if (stack.back().parent >= 0 && low[static_cast<std::size_t>(v)] >= disc[static_cast<std::size_t>(parent)]) cut[static_cast<std::size_t>(parent)] = 1;
    }
    if (rootChildren > 1) cut[static_cast<std::size_t>(cells.front())] = 1;
  };
  // v may leave its region: not a start, and not a cut of its region
  auto mayLeave = [&](int v) { return !isRoot[static_cast<std::size_t>(v)] && !cut[static_cast<std::size_t>(v)]; };
  auto touches = [&](int v, int region) {
    for (int d = 0; d < 4; ++d)
      if (const int u = g.neighbour(v, d); u >= 0 && owner[static_cast<std::size_t>(u)] == region) return true;
    return false;
  };
  std::vector<std::vector<int>> cellsOf(k);   // each region's mega-cells, in node order at first
  for (std::size_t v = 0; v < n; ++v)
    if (owner[v] >= 0) cellsOf[static_cast<std::size_t>(owner[v])].push_back(static_cast<int>(v));
  // link[R·k + S]: a mega-cell region R may pass to region S, or -1; a row (and the region's cuts)
  // is recomputed only when a move could have changed it: the two regions of the move, and those
  // owning a neighbour of the moved cell (whose cells next to it now touch another region)
  std::vector<int> link(k * k, -1);
  std::vector<char> stale(k, 1);
  auto refresh = [&](std::size_t R) {
    articulate(cellsOf[R], static_cast<int>(R));
    std::fill(link.begin() + static_cast<long>(R * k), link.begin() + static_cast<long>((R + 1) * k), -1);
    for (int v : cellsOf[R]) {
      bool checked = false, ok = false;
      for (int d = 0; d < 4; ++d) {
        const int u = g.neighbour(v, d);
        const int S = u < 0 ? -1 : owner[static_cast<std::size_t>(u)];
        if (S < 0 || S == static_cast<int>(R) || link[R * k + static_cast<std::size_t>(S)] >= 0) continue;
        if (!checked) {
          ok = mayLeave(v);
          checked = true;
        }
        if (ok) link[R * k + static_cast<std::size_t>(S)] = v;
      }
    }
    stale[R] = 0;
  };
  auto move = [&](int v, int S) {
    const int R = owner[static_cast<std::size_t>(v)];
    std::vector<int>& mine = cellsOf[static_cast<std::size_t>(R)];
    mine.erase(std::find(mine.begin(), mine.end(), v));
    cellsOf[static_cast<std::size_t>(S)].push_back(v);
    owner[static_cast<std::size_t>(v)] = S;
    --size[static_cast<std::size_t>(R)];
    ++size[static_cast<std::size_t>(S)];
    stale[static_cast<std::size_t>(R)] = stale[static_cast<std::size_t>(S)] = 1;
    for (int d = 0; d < 4; ++d)
      if (const int u = g.neighbour(v, d); u >= 0 && owner[static_cast<std::size_t>(u)] >= 0) stale[static_cast<std::size_t>(owner[static_cast<std::size_t>(u)])] = 1;
  };
  // a mega-cell of region `from` that may leave it for a neighbouring `to`, or -1
  auto witness = [&](int from, int to) {
    for (int v : cellsOf[static_cast<std::size_t>(from)])
      if (touches(v, to) && mayLeave(v)) return v;
    return -1;
  };
  auto squares = [&]() {
    long s = 0;
    for (long z : size) s += z * z;
    return s;
  };
  long before = squares();
  int still = 0;   // chains cut short may leave the sizes as they were: a few such rounds end it
  for (std::size_t round = 0; round < 4 * n + 16 && still < 8; ++round) {
    if ((round & 15) == 15 && stop.expired()) return {};
    // the largest region with a chain to one at least two smaller (the shortest such chain); where
    // the largest has none, the next largest (the sum of squares falls all the same)
    std::vector<std::size_t> bySize(k);
    std::iota(bySize.begin(), bySize.end(), 0);
    std::stable_sort(bySize.begin(), bySize.end(), [&](std::size_t a, std::size_t b) { return size[a] > size[b]; });
    std::size_t A = 0;
    std::vector<int> from(k);
    int B = -1;
    for (std::size_t c = 0; c < k && B < 0; ++c) {
      A = bySize[c];
      std::fill(from.begin(), from.end(), -1);
      from[A] = static_cast<int>(A);
      std::deque<std::size_t> q{A};
      while (!q.empty() && B < 0) {
        const std::size_t R = q.front();
        q.pop_front();
        if (stale[R]) refresh(R);
        for (std::size_t S = 0; S < k; ++S) {
          if (link[R * k + S] < 0 || from[S] >= 0) continue;
          from[S] = static_cast<int>(R);
          if (size[S] + 2 <= size[A]) {
            B = static_cast<int>(S);
            break;
          }
          q.push_back(S);
        }
      }
    }
    if (B < 0) break;
    // pass along the chain from its end, so that each region gives before it receives
    for (int S = B; S != static_cast<int>(A); S = from[static_cast<std::size_t>(S)]) {
      const int R = from[static_cast<std::size_t>(S)];
      int v = link[static_cast<std::size_t>(R) * k + static_cast<std::size_t>(S)];
      if (owner[static_cast<std::size_t>(v)] != R || !touches(v, S) || !mayLeave(v)) v = witness(R, S);
      if (v < 0) break;   // the link is gone (its cell was the one passed on): the chain ends here
      move(v, S);
    }
    const long after = squares();
    still = after < before ? 0 : still + 1;
    before = after;
  }
  return owner;
}

/// The regions from the breadth-first assignment; where their largest is above the mean (rounded
/// up), again from the re-weighted one (reweighted), and the better of the two (the smaller largest
/// region, then the smaller sum of squares). On small maps (k · n ≤ 2^14) still above it: up to 48
/// restarts of the re-weighting from seeded random weights, the best kept (deterministic).
std::vector<int> balancedRegions(const graph::GridGraph& g, const std::vector<int>& root, const TerminationCondition& stop) {
  std::vector<int> owner = regionsFrom(g, root, stop, nullptr, 0);
  const std::size_t k = root.size(), n = g.size();
  if (owner.empty() || k < 2 || k * n > (std::size_t{1} << 22)) return owner;
  auto score = [&](const std::vector<int>& o) {
    std::vector<long> z(k, 0);
    for (int r : o)
      if (r >= 0) ++z[static_cast<std::size_t>(r)];
    return spread(z);
  };
  auto best = score(owner);
  long total = 0;
  for (int r : owner) total += r >= 0 ? 1 : 0;
  const long even = (total + static_cast<long>(k) - 1) / static_cast<long>(k);   // the mean, rounded up
  if (best.first <= even) return owner;
  const std::vector<int> dist = startDistances(g, root);   // the same for every restart
  const std::size_t restarts = k * n <= (std::size_t{1} << 14) ? 48 : 0;
  for (std::size_t r = 0; r <= restarts && best.first > even && !stop.expired(); ++r) {
    std::vector<int> again = regionsFrom(g, root, stop, &dist, r);
    if (again.empty()) continue;
    if (const auto s = score(again); s < best) {
      best = s;
      owner = std::move(again);
    }
  }
  return owner;
}

/// Pieces of the tour reached by travel (in the spirit of MSTC*): the robots, in their order on the
/// tour, take consecutive pieces, each as long as the bound on (shortest travel + piece length)
/// allows; the least bound over offsets and rotations is found by binary search (`fits` below). Each robot then gets, in order of decreasing travel, a route
/// found by A* in space and time over the sub-cells of free mega-cells that keeps every rule the
/// stretches keep by construction, against the robots routed before it: it never enters a cell
/// another robot is in at that step or the next, never leaves a cell another robot enters at the
/// next step, and keeps off robots not routed yet at steps 0 and 1 (they leave their start at the
/// first move) and off cells where routed robots have parked. Its piece is then covered in tour
/// order, waiting where a cell is taken. False when some robot finds no route within its bound or
/// its last cell is entered by another after it parks: the caller keeps the stretches.
/// Moving obstacles: every step (and wait) of a route, each robot's first step from its start to its
/// sub-cell's centre and its parking from its last step on are checked exactly against each obstacle
/// (movesClearOf, as the validator decides); the route then waits or goes round.

bool travelRoutes(const CellGrid& cells, const std::vector<CellIndex>& walk, long L, const std::vector<CellIndex>& startCell,
                  const std::vector<std::size_t>& order, const StepTiming& timing, std::vector<std::vector<CellIndex>>& out,
                  std::size_t& skipped, const TerminationCondition& stop, bool& timedOut) {
  const bool moving = !timing.problem->movingObstacles.empty();
  auto cellOfId = [&](long c) { return CellIndex{static_cast<int>(c % cells.subCols()), static_cast<int>(c / cells.subCols())}; };
  const std::size_t k = startCell.size();
  const int cols = cells.subCols(), rows = cells.subRows();
  auto id = [&](CellIndex c) { return static_cast<long>(c.row) * cols + c.col; };
  auto usable = [&](int c, int r) { return c >= 0 && r >= 0 && c < cols && r < rows && cells.mega(c / 2, r / 2) == CellState::kFree; };
  auto usableId = [&](int v) { return usable(v % cols, v / cols); };
  static constexpr int kDc[4] = {1, -1, 0, 0}, kDr[4] = {0, 0, 1, -1};
  // breadth-first distances from each start over the sub-cells of free mega-cells
  std::vector<std::vector<int>> dist(k);
  for (std::size_t i = 0; i < k; ++i) dist[i] = graph::gridDistances(cols, rows, {id(startCell[i])}, usableId);
  // pieces: piece p = [pieceFirst[p], pieceFirst[p] + pieceLen[p]) on the cycle, taken by robot
  // order[(p + rotation) % k]. For an offset, a rotation and a bound T, each piece in turn is as long
  // as T allows after its robot's travel to its first cell (at least one cell); T is feasible when
  // the pieces reach round the cycle. The least T over the offsets (every one on short tours, 64
  // spread ones on long) and the rotations is kept.
  auto cellAt = [&](long v) { return static_cast<std::size_t>(id(walk[static_cast<std::size_t>(((v % L) + L) % L)])); };
  auto fits = [&](long o, std::size_t rot, long T, std::vector<long>* lens) {
    long first = o;
    for (std::size_t p = 0; p < k; ++p) {
      const int d = dist[order[(p + rot) % k]][cellAt(first)];
      if (d < 0 || T - d < 1) return false;
      // at most what leaves a cell for each robot after it (a robot without a piece would sit in one)
      const long len = std::min<long>(T - d, o + L - first - static_cast<long>(k - 1 - p));
      if (len < 1) return false;
      if (lens) (*lens)[p] = len;
      first += len;
    }
    return first == o + L;
  };
  long bestCost = -1, bestO = 0;
  std::size_t bestRot = 0;
  const long offsets = L * static_cast<long>(k * k) <= 4'000'000L ? L : std::min<long>(L, 64);
  for (long oi = 0; oi < offsets; ++oi) {
    const long o = oi * L / offsets;
    for (std::size_t rot = 0; rot < k; ++rot) {
      long lo = L / static_cast<long>(k), hi = bestCost < 0 ? 4 * L + cols + rows : bestCost - 1;
      if (lo > hi || !fits(o, rot, hi, nullptr)) continue;
      while (lo < hi) {
        const long mid = lo + (hi - lo) / 2;
        if (fits(o, rot, mid, nullptr)) hi = mid;
        else lo = mid + 1;
      }
      bestCost = lo, bestO = o, bestRot = rot;
    }
  }
  if (bestCost < 0) return false;
  std::vector<long> pieceLenOf(k, 0), pieceFirst(k), pieceOf(k);
  fits(bestO, bestRot, bestCost, &pieceLenOf);
  auto pieceLen = [&](std::size_t p) { return pieceLenOf[p]; };
  for (std::size_t p = 0, first = static_cast<std::size_t>(bestO); p < k; first += static_cast<std::size_t>(pieceLen(p)), ++p) {
    pieceFirst[p] = static_cast<long>(first);
    pieceOf[order[(p + bestRot) % k]] = static_cast<long>(p);
  }
  // the step at which the last moving obstacle stops
  long lastStop = 0;
  for (const MovingObstacle& m : timing.problem->movingObstacles)
    if (!m.waypoints.empty() && std::isfinite(m.waypoints.back().t))
      lastStop = std::max(lastStop, static_cast<long>(std::min(m.waypoints.back().t / timing.step, 1e6)) + 1);
  // reservations: (step, cell) → taken; per cell the last step a routed robot is in it; parked cells
  // from their step on; robots not routed yet at steps 0 and 1
  std::unordered_map<long long, int> taken;
  std::unordered_map<long, long> lastTaken, parkedFrom;
  std::vector<char> routed(k, 0);
  const long long W = static_cast<long long>(cols) * rows;
  auto key = [&](long t, long cell) { return static_cast<long long>(t) * W + cell; };
  auto occupied = [&](long t, long cell, std::size_t self) {
    const auto it = taken.find(key(t, cell));
    if (it != taken.end() && static_cast<std::size_t>(it->second) != self) return true;
    const auto pk = parkedFrom.find(cell);
    if (pk != parkedFrom.end() && t >= pk->second) return true;
    if (t <= 1)
      for (std::size_t j = 0; j < k; ++j)
        if (j != self && !routed[j] && id(startCell[j]) == cell) return true;
    return false;
  };
  // a step t → t + 1 from u to v (v == u: a wait); whether it is clear of the moving obstacles is
  // kept (the same for every robot of the team, equal discs; the exact test is the searches' cost)
  std::unordered_map<long long, char> clearOfObstacles;
  auto allowed = [&](long t, long u, long v, std::size_t self) {
    if (occupied(t + 1, v, self) || (v != u && (occupied(t, v, self) || occupied(t + 1, u, self)))) return false;
    if (!moving) return true;
    const long long move = (key(t, u) * 5) + (v == u ? 4 : v == u + 1 ? 0 : v == u - 1 ? 1 : v > u ? 2 : 3);
    const auto known = clearOfObstacles.find(move);
    if (known != clearOfObstacles.end()) return known->second != 0;
    const bool clear = timing.clear(self, timing.centre(cellOfId(u)), timing.centre(cellOfId(v)), static_cast<double>(t) * timing.step,
                                    static_cast<double>(t + 1) * timing.step);
    clearOfObstacles.emplace(move, clear ? 1 : 0);
    return clear;
  };
  // among moving obstacles: a robot in v at step t has a next step (a wait or a move); entering a
  // cell from which an obstacle leaves no way on would trap the robot there
  auto escapable = [&](long t, long v, std::size_t self) {
    if (!moving) return true;
    const int c = static_cast<int>(v % cols), r = static_cast<int>(v / cols);
    for (int d = 0; d <= 4; ++d) {
      const int nc = d < 4 ? c + kDc[d] : c, nr = d < 4 ? r + kDr[d] : r;
      if (usable(nc, nr) && allowed(t, v, static_cast<long>(nr) * cols + nc, self)) return true;
    }
    return false;
  };
  std::vector<std::size_t> byTravel(k);
  std::iota(byTravel.begin(), byTravel.end(), 0);
  auto travel = [&](std::size_t i) {
    return dist[i][static_cast<std::size_t>(id(walk[static_cast<std::size_t>(pieceFirst[static_cast<std::size_t>(pieceOf[i])] % L)]))];
  };
  // A* over (cell, step) from the route's last entry to `target` (waits allowed, h = the static
  // distance), within the step `horizon` and `budget` states; appends the way to `route` (true) or
  // leaves it as it was (false).
  std::vector<int> toGoal;
  long toGoalOf = -1;
  struct Node {
    long f, t, cell;
    long long parent;   // key of the parent state, -1 at the root
  };
  // target < 0: the first state (cell, step) where `parkHere` holds instead, found depth first in
  // time (the latest step first, a wait before a move): the robot waits where that stays clear and
  // steps aside where an obstacle comes, until it can park (a best-first search would spread over
  // every cell and step before the last obstacle stops)
  auto routeTo = [&](std::size_t self, std::vector<long>& route, long target, long horizon, std::size_t budget,
                     const std::function<bool(long, long)>& parkHere = {}) {
    const bool toTarget = target >= 0;
    if (toTarget && toGoalOf != target) {   // breadth-first distances to the target over the usable sub-cells
      toGoal = graph::gridDistances(cols, rows, {target}, usableId);
      toGoalOf = target;
    }
    auto h = [&](long v) { return toTarget ? static_cast<long>(toGoal[static_cast<std::size_t>(v)]) : 0L; };
    // the priority of state (v, t) entered from u: A*'s f towards the target; else depth first
    auto priority = [&](long v, long t, long u) { return toTarget ? t + h(v) : -2 * t + (v != u ? 1 : 0); };
    const long from = route.back(), t0 = static_cast<long>(route.size());
    if (h(from) < 0) return false;
    auto cmp = [](const Node& a, const Node& b) { return a.f > b.f || (a.f == b.f && (a.t < b.t || (a.t == b.t && a.cell > b.cell))); };
    std::priority_queue<Node, std::vector<Node>, decltype(cmp)> open(cmp);
    std::unordered_map<long long, long long> parentOf;   // state → parent state
    open.push({priority(from, t0, from), t0, from, -1});
    long long reached = -1;
    std::size_t expanded = 0;
    while (!open.empty() && reached < 0) {
      if (++expanded > budget) return false;
      if ((expanded & 4095) == 0 && stop.expired()) {
        timedOut = true;
        return false;
      }
      const Node n = open.top();
      open.pop();
      const long long me = key(n.t, n.cell);
      if (parentOf.count(me)) continue;
      parentOf[me] = n.parent;
      if (toTarget ? n.cell == target && n.t > t0 - (from == target ? 1 : 0) : n.t > t0 && parkHere(n.cell, n.t)) {
        reached = me;
        break;
      }
      if (n.t >= horizon) continue;
      const int c = static_cast<int>(n.cell % cols), r = static_cast<int>(n.cell / cols);
      for (int d = 0; d <= 4; ++d) {
        const int nc = d < 4 ? c + kDc[d] : c, nr = d < 4 ? r + kDr[d] : r;
        if (!usable(nc, nr)) continue;
        const long v = static_cast<long>(nr) * cols + nc;
        if (h(v) < 0 || !allowed(n.t, n.cell, v, self) || parentOf.count(key(n.t + 1, v)) || !escapable(n.t + 1, v, self)) continue;
        open.push({priority(v, n.t + 1, n.cell), n.t + 1, v, me});
      }
    }
    if (reached < 0) return false;
    std::vector<long> way;   // the states after the root
    for (long long st = reached; parentOf[st] >= 0; st = parentOf[st]) way.push_back(static_cast<long>(st % W));
    route.insert(route.end(), way.rbegin(), way.rend());
    return true;
  };
  // routed in order of decreasing travel; where that fails, of increasing travel, then in tour order
  auto routeAll = [&](const std::vector<std::size_t>& sequence) -> bool {
    taken.clear();
    lastTaken.clear();
    parkedFrom.clear();
    skipped = 0;
    std::fill(routed.begin(), routed.end(), 0);
    out.assign(k, {});
    for (std::size_t i : sequence) {
      const std::size_t p = static_cast<std::size_t>(pieceOf[i]);
      const long goal = id(walk[static_cast<std::size_t>(pieceFirst[p] % L)]);
      const long s0 = id(startCell[i]);
      if (occupied(1, s0, i)) return false;
      if (moving) {   // the first step, from the start onto its sub-cell's centre
        const Point& st = *timing.problem->robots[i].start;
        if (!timing.clear(i, {toDouble(st.x), toDouble(st.y)}, timing.centre(startCell[i]), 0, timing.step)) return false;
      }
      std::vector<long> cellsAt{s0};   // the route, from step 1
      auto search = [&](long target, long horizon, std::size_t budget) { return routeTo(i, cellsAt, target, horizon, budget); };
      // among moving obstacles a way may have to wait until an obstacle has passed: then up to the
      // step the last obstacle stops, and a margin, beyond the usual bound
      const long bound = 8 + 3 * static_cast<long>(travel(i)) + 4 * static_cast<long>(k);
      if (!search(goal, bound, 4'000'000) && !(moving && search(goal, bound + lastStop + 64, 400'000))) return false;
      // the piece, in tour order: a move where it is free, else a few waits, else a way round; among
      // moving obstacles a cell no way reaches is left out
      for (long m = 1; m < pieceLen(p); ++m) {
        const long v = id(walk[static_cast<std::size_t>((pieceFirst[p] + m) % L)]);
        const long t = static_cast<long>(cellsAt.size()), u = cellsAt.back();
        // a move to the next tour cell when it is a neighbour (after a cell left out it need not be)
        if (std::abs(u % cols - v % cols) + std::abs(u / cols - v / cols) == 1 && allowed(t, u, v, i) && escapable(t + 1, v, i)) {
          cellsAt.push_back(v);
          continue;
        }
        // once every obstacle has stopped, a cell one of them holds is held for good: no search
        const PointD cv = timing.centre(cellOfId(v));
        const bool heldForGood = moving && t >= lastStop && !timing.clear(i, cv, cv, static_cast<double>(t) * timing.step, HUGE_VAL);
        if (!heldForGood && search(v, t + 64 + 4 * static_cast<long>(k), moving ? 50'000 : 200'000)) continue;
        if (!moving) return false;
        ++skipped;
      }
      // parked from its last step on: clear of the obstacles for good, and nobody routed before enters
      // that cell later; else the nearest cell (breadth-first) where that holds
      auto parkable = [&](long cell, long from) {
        if (moving && !timing.clear(i, timing.centre(cellOfId(cell)), timing.centre(cellOfId(cell)), static_cast<double>(from) * timing.step, HUGE_VAL))
          return false;
        if (parkedFrom.count(cell)) return false;
        const auto lt = lastTaken.find(cell);   // robot i is not in it yet: every entry is another's
        return lt == lastTaken.end() || lt->second < from;
      };
      if (!parkable(cellsAt.back(), static_cast<long>(cellsAt.size()))) {
        std::vector<long> near{cellsAt.back()};
        std::unordered_map<long, int> seen{{cellsAt.back(), 0}};
        bool parked = false;
        for (std::size_t h = 0; h < near.size() && h < 200 && !parked; ++h) {
          const int c = static_cast<int>(near[h] % cols), r = static_cast<int>(near[h] / cols);
          for (int d = 0; d < 4 && !parked; ++d) {
            if (!usable(c + kDc[d], r + kDr[d])) continue;
            const long v = static_cast<long>(r + kDr[d]) * cols + c + kDc[d];
            if (seen.count(v)) continue;
            seen[v] = 1;
            near.push_back(v);
            const std::vector<long> before = cellsAt;
            if (search(v, static_cast<long>(cellsAt.size()) + 64 + 4 * static_cast<long>(k), moving ? 20'000 : 200'000) &&
                parkable(cellsAt.back(), static_cast<long>(cellsAt.size())))
              parked = true;
            else
              cellsAt = before;
          }
        }
        // among moving obstacles, where no cell nearby is clear for good once reached: the first
        // (cell, step) found depth first in time from which it is, waiting or stepping aside while
        // obstacles pass (within the step the last one stops and a margin)
        if (!parked && moving)
          parked = routeTo(i, cellsAt, -1, std::max(static_cast<long>(cellsAt.size()), lastStop) + 64 + 4 * static_cast<long>(k), 400'000, parkable);
        if (!parked) return false;
      }
      const long t = static_cast<long>(cellsAt.size());   // the step of the last entry
      const long last = cellsAt.back();
      for (std::size_t m = 0; m < cellsAt.size(); ++m) {
        taken[key(static_cast<long>(m) + 1, cellsAt[m])] = static_cast<int>(i);
        long& lt = lastTaken[cellsAt[m]];
        lt = std::max(lt, static_cast<long>(m) + 1);
      }
      parkedFrom[last] = t;
      routed[i] = 1;
      for (long c : cellsAt) out[i].push_back(cellOfId(c));
    }
    return true;
  };
  std::stable_sort(byTravel.begin(), byTravel.end(), [&](std::size_t x, std::size_t y) { return travel(x) > travel(y); });
  if (routeAll(byTravel)) return true;
  std::reverse(byTravel.begin(), byTravel.end());
  if (routeAll(byTravel)) return true;
  return routeAll(order);
}

}  // namespace

std::string MultiStcBalancedPlanner::description() const {
  return "balanced multi-robot STC (baseline, offline): one STC tour cut into balanced pieces the robots reach by conflict-free "
         "travel, or into a stretch around each robot's start where that is not sooner, or (static worlds) balanced connected regions "
         "with a tour each where that is sooner still; timed in steps, clear of each other and of moving obstacles (--scenario)";
}

std::vector<ParamSpec> MultiStcBalancedPlanner::params() const {
  return {{"tree", ParamType::kChoice, "dfs_ccw", "dfs_ccw|bfs|kruskal_straight", "the shared tour's spanning tree (as stc's)"},
          {"step", ParamType::kDouble, "0.1", "0.001:1000", "seconds per step (one move between neighbouring sub-cells, or a wait)"},
          {"travel", ParamType::kChoice, "auto", "auto|off",
           "auto: equal pieces of the tour reached by conflict-free travel where that finishes sooner than the stretches; off: the stretches only"},
          {"regions", ParamType::kChoice, "auto", "auto|off",
           "auto (static worlds): connected regions of balanced size around the starts, one STC tour each, where that finishes sooner "
           "than the split above; off: never"},
          {"subcells", ParamType::kChoice, "auto", "auto|off",
           "auto (with regions, on tours of at most 16384 sub-cells and 64 per robot): regions refined by passing single sub-cells "
           "where whole mega-cells leave the makespan above the mean, each covered by a walk of its own; off: whole mega-cells only"}};
}

Capabilities MultiStcBalancedPlanner::capabilities() const {
  Capabilities c;
  c.multiRobot = true;
  c.coverage = "free_mega_cells";
  return c;
}

Plan MultiStcBalancedPlanner::plan(const PlanningContext& ctx, const ParamSet& params, const TerminationCondition& stop) {
  const auto t0 = std::chrono::steady_clock::now();
  Plan plan;
  const Problem& problem = ctx.problem;
  const std::size_t k = problem.robots.size();
  checkTeamGrid(ctx, "multi_stc_balanced");
  const CellGrid& cells = ctx.cells;
  if (!everyRobotHasAStart(problem, plan)) return plan;
  auto fail = [&](PlanStatus s, const std::string& why) {
    plan.status = s;
    plan.message = why;
    plan.paths.assign(k, Path{});
    for (std::size_t i = 0; i < k; ++i) plan.paths[i].start = {toDouble(problem.robots[i].start->x), toDouble(problem.robots[i].start->y)};
    return plan;
  };
  // the robots' start sub-cells, in free mega-cells
  std::vector<CellIndex> startCell(k);
  for (std::size_t i = 0; i < k; ++i) {
    if (!cells.locateSub(*problem.robots[i].start, startCell[i]) || cells.mega(startCell[i].col / 2, startCell[i].row / 2) != CellState::kFree)
      return fail(PlanStatus::kInvalidStart, "robot " + std::to_string(i) + "'s start is not in a free mega-cell");
  }
  // the shared tour from robot 0's start
  StcTour stc;
  const ParamSet stcParams(stc.params(), {{"tree", params.text("tree")}}, "stc");
  const graph::GridGraph g = stc.buildGraph(ctx);
  std::vector<CellIndex> walk = stc.tourFrom(ctx, g, startCell[0], stcParams);
  if (walk.size() < 2) walk = {startCell[0], startCell[0]};
  const long L = static_cast<long>(walk.size()) - 1;   // closed: the last is the first
  std::vector<long> indexOf(static_cast<std::size_t>(cells.subCols()) * static_cast<std::size_t>(cells.subRows()), -1);
  for (long j = 0; j < L; ++j) indexOf[static_cast<std::size_t>(walk[static_cast<std::size_t>(j)].row) * static_cast<std::size_t>(cells.subCols()) +
                                       static_cast<std::size_t>(walk[static_cast<std::size_t>(j)].col)] = j;
  std::vector<long> at(k);
  for (std::size_t i = 0; i < k; ++i) {
    at[i] = indexOf[static_cast<std::size_t>(startCell[i].row) * static_cast<std::size_t>(cells.subCols()) + static_cast<std::size_t>(startCell[i].col)];
    if (at[i] < 0) return fail(PlanStatus::kInvalidStart, "robot " + std::to_string(i) + "'s start is not in robot 0's component of free mega-cells");
  }
  // robots in cycle order, the gaps between them
  std::vector<std::size_t> order(k);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return at[a] < at[b]; });
  for (std::size_t j = 1; j < k; ++j)
    if (at[order[j]] == at[order[j - 1]])
      return fail(PlanStatus::kInvalidStart, "robots " + std::to_string(order[j - 1]) + " and " + std::to_string(order[j]) + " start in the same sub-cell");
  std::vector<long> gap(k);
  for (std::size_t j = 0; j < k; ++j) {
    const long next = at[order[(j + 1) % k]];
    gap[j] = k == 1 ? L - 1 : ((next - at[order[j]] - 1) % L + L) % L;
  }
  std::vector<long> behind, ahead;
  balance(gap, behind, ahead);
  const StepTiming timing = makeStepTiming(ctx, params.number("step"));
  // the stretches as cell routes: route[i][m] is robot i's sub-cell at step m + 1 (step 0: its start)
  std::vector<std::vector<CellIndex>> route(k);
  for (std::size_t j = 0; j < k; ++j) {
    const std::size_t i = order[j];
    const long b = behind[j], f = ahead[j], s = at[i];
    // the stretch's cycle indices in the order the robot visits them: the shorter side first, out and back
    std::vector<long> idx{s};
    auto go = [&](long from, long count, int dir) {
      for (long m = 1; m <= count; ++m) idx.push_back(from + dir * m);
    };
    if (b <= f) {
      go(s, b, -1);
      go(s - b, b, 1);
      go(s, f, 1);
    } else {
      go(s, f, 1);
      go(s + f, f, -1);
      go(s, b, -1);
    }
    for (long v : idx) route[i].push_back(walk[static_cast<std::size_t>(((v % L) + L) % L)]);
  }
  std::string split = "stretches";
  std::size_t skipped = 0;   // among moving obstacles: tour sub-cells no way could reach
  bool timedOut = false;     // --time-limit while routing: among moving obstacles the robots stay; else the stretches stand
  const bool moving = !problem.movingObstacles.empty();
  if (moving) {   // only routed moves can wait for and go round the obstacles: travel, whatever `travel` says
    std::vector<std::vector<CellIndex>> travelled;
    if (!travelRoutes(cells, walk, L, startCell, order, timing, travelled, skipped, stop, timedOut)) {
      if (timedOut) {
        plan.status = PlanStatus::kTimeout;
        plan.message = "stopped by the time limit while routing the robots (they stay at their starts)";
        stayAtStarts(problem, plan);
        return plan;
      }
      // no robot order gives every robot a way to its piece and a place to park clear of the
      // obstacles: the team is planned by multi_st instead, whose robots step aside as obstacles come
      // (staying at the starts, as before, let obstacles run into them)
      MultiStPlanner online;
      Plan fallback = online.plan(ctx, ParamSet(online.params(), {{"step", formatDouble(params.number("step"))}}, "multi_st"), stop);
      fallback.statistics["split_multi_st"] = 1;
      fallback.message = "no timing of the balanced pieces keeps every robot clear of the moving obstacles and of each other; planned by multi_st: " +
                         fallback.message;
      return fallback;
    }
    route.swap(travelled);
    split = "travel";
  }
  // pieces reached by travel, when that finishes sooner and can be timed without conflicts
  if (!moving && k > 1 && params.text("travel") == "auto") {
    std::vector<std::vector<CellIndex>> travelled;
    std::size_t none = 0;
    if (travelRoutes(cells, walk, L, startCell, order, timing, travelled, none, stop, timedOut)) {
      if (longest(travelled) < longest(route)) {
        route.swap(travelled);
        split = "travel";
      }
    }
  }
  // connected regions of balanced size, one tour each, when that finishes sooner still
  if (!moving && k > 1 && k <= kMaxRegions && params.text("regions") == "auto") {
    std::vector<int> root(k);
    for (std::size_t i = 0; i < k; ++i) root[i] = g.id(startCell[i].col / 2, startCell[i].row / 2);
    const std::vector<int> owner = balancedRegions(g, root, stop);
    std::vector<std::vector<CellIndex>> own(k);
    if (!owner.empty()) {
      // one graph whose active nodes are, in turn, each region's
      std::vector<std::vector<int>> members(k);
      for (std::size_t v = 0; v < owner.size(); ++v)
        if (owner[v] >= 0) members[static_cast<std::size_t>(owner[v])].push_back(static_cast<int>(v));
      graph::GridGraph mine = g;
      std::fill(mine.active.begin(), mine.active.end(), 0);
      for (std::size_t i = 0; i < k; ++i) {
        for (int v : members[i]) mine.active[static_cast<std::size_t>(v)] = 1;
        std::vector<CellIndex> tour = stc.tourFrom(ctx, mine, startCell[i], stcParams);
        for (int v : members[i]) mine.active[static_cast<std::size_t>(v)] = 0;
        if (tour.size() > 1) tour.pop_back();   // closed: the last is the first
        if (tour.empty()) tour = {startCell[i]};
        own[i] = std::move(tour);
      }
    }
    if (!owner.empty() && longest(own) < longest(route)) {
      route = own;
      split = "regions";
    }
    // crowded small maps: regions of sub-cells, where whole mega-cells leave the makespan above the mean
    const std::size_t even = (static_cast<std::size_t>(L) + k - 1) / k;
    if (params.text("subcells") == "auto" && longest(route) > even && static_cast<std::size_t>(L) <= kMaxSubcellRegions &&
        static_cast<std::size_t>(L) <= kMaxSubcellsPerRobot * k) {
      std::vector<std::vector<CellIndex>> fine = subcellRegions(cells, g, startCell, owner, own, stop);
      if (!fine.empty() && longest(fine) < longest(route)) {
        route.swap(fine);
        split = "subcell regions";
      }
    }
  }
  plan.timings.emplace_back("split", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  writeTimedPaths(problem, timing, route, plan);
  plan.statistics["tour_subcells"] = static_cast<double>(L);
  plan.statistics["travelled"] = split == "travel" ? 1 : 0;
  plan.statistics["regions"] = split == "regions" || split == "subcell regions" ? 1 : 0;
  plan.statistics["subcell_regions"] = split == "subcell regions" ? 1 : 0;
  plan.statistics["subcells_skipped"] = static_cast<double>(skipped);
  plan.status = skipped ? PlanStatus::kPartialCoverage : PlanStatus::kExactSolution;
  plan.message = skipped ? "left out " + std::to_string(skipped) + " sub-cells of the tour that no way could reach past the moving obstacles"
                         : "covered every sub-cell of the starts' component of free mega-cells with " + std::to_string(k) + (k == 1 ? " robot" : " robots");
  plan.timings.emplace_back("paths", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return plan;
}

}  // namespace coverkit::planners
