// Regions at sub-cell level for multi_stc_balanced (subcell_regions.h; docs/multi-robot.md,
// "Regions of sub-cells").
//
// Why: with whole mega-cells a region's walk is 4m sub-cells long for m mega-cells, so k robots on
// n mega-cells finish no sooner than ⌈n/k⌉ / (n/k) × the ideal (1.25 × for 20 robots on 64
// mega-cells), and the shape of the map can cost more (13 robots in an L-shaped room of 64 mega-cells:
// 1.219 ×, proved in docs/multi-robot.md). Passing single sub-cells between regions removes that bound.
//
// Decisions:
//  * a region of sub-cells need not have a Hamiltonian path from its start (a grid region whose two
//    colours differ by more than one has none; other shapes neither): each region's cost is the
//    length of the walk found, a Hamiltonian path where a bounded depth-first search finds one, else
//    a greedy walk with shortest returns; the search, not the region's size, decides.
//  * moves: a sub-cell leaves its region when it is not the start and the rest stays connected (a
//    breadth-first check: regions here are small, see the caller's limits). A chain passes one sub-cell
//    along each link, from its far end first, each link's sub-cell chosen by the walks it leaves (the
//    smaller larger walk of the two regions, then the smaller sum); the chain stands when it lowers
//    (longest walk, sum of squared walks) lexicographically, else it is undone. That pair falls with
//    every chain kept, so the search ends; `stop` and a bound on rounds end it sooner.
//  * two starts: the whole-mega-cell regions (when the caller has them; their tours are Hamiltonian
//    cycles, so their walks are as short as can be) and a breadth-first split of the sub-cells from
//    all starts at once (the only one when two robots start in one mega-cell). The better is kept.
#include "subcell_regions.h"

#include <algorithm>
#include <deque>
#include <memory>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <unordered_map>

namespace coverkit::planners {

namespace {

/// The sub-cells of the free mega-cells, their neighbours, and the state of a split.
class Split {
public:
  Split(const CellGrid& cells, const graph::GridGraph& g, std::size_t& work) : work_(&work), cols_(cells.subCols()), rows_(cells.subRows()) {
    const std::size_t n = static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_);
    owner.assign(n, -1);
    mark_.assign(n, 0);
    dist_.assign(n, -1);
    from_.assign(n, -1);
    auto next = std::make_shared<std::vector<long>>(4 * n, -1);
    for (int r = 0; r < rows_; ++r)
      for (int c = 0; c < cols_; ++c)
        for (int d = 0; d < 4; ++d) {
          const int nc = c + graph::kDx[d], nr = r + graph::kDy[d];
          if (nc < 0 || nr < 0 || nc >= cols_ || nr >= rows_) continue;
          const int m = g.id(c / 2, r / 2), mu = g.id(nc / 2, nr / 2);
          if (!g.active[static_cast<std::size_t>(m)] || !g.active[static_cast<std::size_t>(mu)]) continue;
          if (m != mu && g.neighbour(m, d) != mu) continue;
          (*next)[(static_cast<std::size_t>(r) * static_cast<std::size_t>(cols_) + static_cast<std::size_t>(c)) * 4 + static_cast<std::size_t>(d)] =
              static_cast<long>(nr) * cols_ + nc;
        }
    next_ = std::move(next);
  }

  long id(CellIndex c) const { return static_cast<long>(c.row) * cols_ + c.col; }
  CellIndex cell(long v) const { return {static_cast<int>(v % cols_), static_cast<int>(v / cols_)}; }
  std::size_t count() const { return owner.size(); }

  /// The neighbour of sub-cell v in direction d among the sub-cells of free mega-cells, or -1: in the
  /// same mega-cell always, across a mega-cell border where g links the two mega-cells.
  long neighbour(long v, int d) const { return (*next_)[static_cast<std::size_t>(v) * 4 + static_cast<std::size_t>(d)]; }

  /// Sub-cells reachable from the starts: every one gets the owner -2 (unassigned) in `owner`.
  std::vector<long> component(const std::vector<long>& starts) {
    std::vector<long> all;
    for (long s : starts)
      if (owner[static_cast<std::size_t>(s)] == -1) {
        owner[static_cast<std::size_t>(s)] = -2;
        all.push_back(s);
      }
    for (std::size_t h = 0; h < all.size(); ++h)
      for (int d = 0; d < 4; ++d)
        if (const long u = neighbour(all[h], d); u >= 0 && owner[static_cast<std::size_t>(u)] == -1) {
          owner[static_cast<std::size_t>(u)] = -2;
          all.push_back(u);
        }
    return all;
  }

  /// Unvisited (mark_ != stamp) neighbours of v in region R.
  int freeDegree(long v, int R, int stamp) const {
    int n = 0;
    for (int d = 0; d < 4; ++d)
      if (const long u = neighbour(v, d); u >= 0 && owner[static_cast<std::size_t>(u)] == R && mark_[static_cast<std::size_t>(u)] != stamp) ++n;
    return n;
  }

  /// The walk of region R from s (size: its sub-cells): a Hamiltonian path where hamiltonian() finds
  /// one within `budget` steps of search, else greedy()'s walk.
  std::vector<long> walk(int R, long s, std::size_t size, std::size_t budget) {
    if (size == 0) return {};
    std::vector<long> path = hamiltonian(R, s, size, budget);
    if (!path.empty()) return path;
    return greedy(R, s, size);
  }

  /// True when region R without v is still connected (v is not the start s).
  bool mayLeave(long v, int R, long s) {
    if (v == s) return false;
    const int stamp = ++stamp_;
    mark_[static_cast<std::size_t>(v)] = stamp;
    std::vector<long>& q = queue_;
    q.assign(1, s);
    mark_[static_cast<std::size_t>(s)] = stamp;
    for (std::size_t h = 0; h < q.size(); ++h)
      for (int d = 0; d < 4; ++d)
        if (const long u = neighbour(q[h], d); u >= 0 && owner[static_cast<std::size_t>(u)] == R && mark_[static_cast<std::size_t>(u)] != stamp) {
          mark_[static_cast<std::size_t>(u)] = stamp;
          q.push_back(u);
        }
    *work_ += q.size();
    return q.size() + 1 == static_cast<std::size_t>(size_[static_cast<std::size_t>(R)]);
  }

  std::vector<int> owner;
  std::vector<long> size_;
  std::size_t work() const { return *work_; }

private:
  /// Depth first in Warnsdorff's order; empty when none is found within `budget` steps or the two
  /// colours of the region forbid one (a path alternates colours, starting on s's).
  std::vector<long> hamiltonian(int R, long s, std::size_t size, std::size_t budget) {
    auto colour = [&](long v) { return static_cast<int>((v % cols_ + v / cols_) & 1); };
    // count the colours of the region's cells (a breadth-first pass from s)
    const int stamp = ++stamp_;
    std::vector<long>& q = queue_;
    q.assign(1, s);
    mark_[static_cast<std::size_t>(s)] = stamp;
    long same = 0;
    for (std::size_t h = 0; h < q.size(); ++h) {
      same += colour(q[h]) == colour(s) ? 1 : 0;
      for (int d = 0; d < 4; ++d)
        if (const long u = neighbour(q[h], d); u >= 0 && owner[static_cast<std::size_t>(u)] == R && mark_[static_cast<std::size_t>(u)] != stamp) {
          mark_[static_cast<std::size_t>(u)] = stamp;
          q.push_back(u);
        }
    }
    const long other = static_cast<long>(q.size()) - same;
    if (q.size() != size || !(same == other || same == other + 1)) return {};
    const int visit = ++stamp_;
    struct Frame {
      long v;
      long next[4];
      int count, at;
    };
    std::vector<Frame> stack;
    std::vector<long> path;
    auto push = [&](long v) {
      mark_[static_cast<std::size_t>(v)] = visit;
      path.push_back(v);
      Frame f{v, {-1, -1, -1, -1}, 0, 0};
      int key[4];
      for (int d = 0; d < 4; ++d)
        if (const long u = neighbour(v, d); u >= 0 && owner[static_cast<std::size_t>(u)] == R && mark_[static_cast<std::size_t>(u)] != visit) {
          f.next[f.count] = u;
          key[f.count++] = freeDegree(u, R, visit);
        }
      for (int a = 1; a < f.count; ++a)   // fewest onward cells first (stable: direction order on ties)
        for (int b = a; b > 0 && key[b] < key[b - 1]; --b) {
          std::swap(key[b], key[b - 1]);
          std::swap(f.next[b], f.next[b - 1]);
        }
      stack.push_back(f);
    };
    // a cell left behind with no unvisited neighbour, not next to the robot, can never be entered
    auto strands = [&](long left, long now) {
      for (int d = 0; d < 4; ++d) {
        const long u = neighbour(left, d);
        if (u < 0 || u == now || owner[static_cast<std::size_t>(u)] != R || mark_[static_cast<std::size_t>(u)] == visit) continue;
        if (freeDegree(u, R, visit) == 0) {
          bool near = false;
          for (int e = 0; e < 4 && !near; ++e) near = neighbour(u, e) == now;
          if (!near) return true;
        }
      }
      return false;
    };
    push(s);
    std::size_t steps = 0;
    while (!stack.empty() && path.size() < size) {
      Frame& f = stack.back();
      if (f.at < f.count && steps < budget) {
        const long u = f.next[f.at++];
        ++steps;
        const long left = f.v;
        push(u);
        if (path.size() < size && strands(left, u)) {   // undo at once
          mark_[static_cast<std::size_t>(u)] = 0;
          path.pop_back();
          stack.pop_back();
        }
        continue;
      }
      if (steps >= budget) {
        *work_ += steps + q.size();
        return {};
      }
      mark_[static_cast<std::size_t>(f.v)] = 0;
      path.pop_back();
      stack.pop_back();
    }
    *work_ += steps + q.size();
    if (path.size() < size) return {};
    return path;
  }

  /// To the neighbour with the fewest unvisited neighbours; when there is none, the shortest way
  /// through the region to the nearest unvisited cell.
  std::vector<long> greedy(int R, long s, std::size_t size) {
    const int visit = ++stamp_;
    std::vector<long> path{s};
    mark_[static_cast<std::size_t>(s)] = visit;
    std::size_t seen = 1;
    long at = s;
    while (seen < size) {
      long best = -1;
      int bestKey = 5;
      for (int d = 0; d < 4; ++d)
        if (const long u = neighbour(at, d); u >= 0 && owner[static_cast<std::size_t>(u)] == R && mark_[static_cast<std::size_t>(u)] != visit) {
          const int key = freeDegree(u, R, visit);
          if (key < bestKey) best = u, bestKey = key;
        }
      if (best >= 0) {
        mark_[static_cast<std::size_t>(best)] = visit;
        path.push_back(best);
        ++seen;
        at = best;
        continue;
      }
      // breadth first within R to the nearest unvisited cell, then along the way back
      std::vector<long>& q = queue_;
      q.assign(1, at);
      dist_[static_cast<std::size_t>(at)] = ++bfs_;
      from_[static_cast<std::size_t>(at)] = -1;
      long found = -1;
      for (std::size_t h = 0; h < q.size() && found < 0; ++h)
        for (int d = 0; d < 4 && found < 0; ++d) {
          const long u = neighbour(q[h], d);
          if (u < 0 || owner[static_cast<std::size_t>(u)] != R || dist_[static_cast<std::size_t>(u)] == bfs_) continue;
          dist_[static_cast<std::size_t>(u)] = bfs_;
          from_[static_cast<std::size_t>(u)] = q[h];
          if (mark_[static_cast<std::size_t>(u)] != visit) found = u;
          else q.push_back(u);
        }
      *work_ += q.size();
      if (found < 0) break;   // the region is not connected (the caller keeps it connected)
      std::vector<long> way;
      for (long v = found; v != at; v = from_[static_cast<std::size_t>(v)]) way.push_back(v);
      path.insert(path.end(), way.rbegin(), way.rend());
      mark_[static_cast<std::size_t>(found)] = visit;
      ++seen;
      at = found;
    }
    return path;
  }

  std::shared_ptr<const std::vector<long>> next_;   ///< 4 per sub-cell: neighbour() (shared by copies)
  std::size_t* work_;   ///< cells looked at, in all copies: the caller's bound on the search
  int cols_, rows_;
  std::vector<int> mark_;
  std::vector<long> dist_, from_, queue_;
  int stamp_ = 0;
  long bfs_ = 0;
};

/// Restarts from random weights, for components of k · sub-cells at most kRestartCells.
constexpr std::size_t kRestarts = 32, kRestartCells = std::size_t{1} << 16;

/// The bound on the whole search, in cells looked at (deterministic, unlike a clock), per sub-cell
/// of the component and in all: a refinement past it stops with what it has. 256 sub-cells: about
/// 0.1 s on this machine; the largest (16384): about 1 s.
std::size_t workBound(std::size_t subcells) { return std::min<std::size_t>(4000 * subcells, 4000000); }

/// Steps of depth-first search allowed for a region's Hamiltonian path.
std::size_t walkBudget(std::size_t size) { return 16 * size + 64; }

/// (longest walk, sum of squared walks).
std::pair<long, long> score(const std::vector<std::vector<long>>& walks) {
  long most = 0, squares = 0;
  for (const auto& w : walks) {
    const long n = static_cast<long>(w.size());
    most = std::max(most, n);
    squares += n * n;
  }
  return {most, squares};
}

/// Refines the split in `sp` (owner set for every sub-cell of the component): chains as described
/// at the top. Returns the walks, or empty when `stop` expired.
std::vector<std::vector<long>> refine(Split& sp, const std::vector<long>& start, std::vector<std::vector<long>> walks,
                                      const std::vector<std::vector<long>>& members, std::size_t bound, const TerminationCondition& stop) {
  const std::size_t k = start.size();
  std::vector<std::vector<long>> cellsOf = members;
  sp.size_.assign(k, 0);
  for (std::size_t i = 0; i < k; ++i) sp.size_[i] = static_cast<long>(cellsOf[i].size());
  // walks are asked for the same regions again and again (a chain tried, undone, tried from another
  // end): remembered by a hash of (start, sorted cells), and a remembered walk is used only after a
  // check that it is one of this region (starts at its start, enters only its cells, all of them)
  std::unordered_map<std::uint64_t, std::vector<long>> known;
  std::vector<long> sorted;
  std::vector<int> seenAt(sp.count(), 0);
  int seenStamp = 0;
  auto walkOf = [&](std::size_t R) {
    sorted = cellsOf[R];
    std::sort(sorted.begin(), sorted.end());
    std::uint64_t h = 1469598103934665603ULL ^ static_cast<std::uint64_t>(start[R]);
    for (long v : sorted) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ULL;
    if (const auto it = known.find(h); it != known.end()) {
      const std::vector<long>& w = it->second;
      ++seenStamp;
      std::size_t distinct = 0;
      bool mine = !w.empty() && w.front() == start[R];
      for (std::size_t j = 0; j < w.size() && mine; ++j) {
        mine = sp.owner[static_cast<std::size_t>(w[j])] == static_cast<int>(R);
        if (mine && seenAt[static_cast<std::size_t>(w[j])] != seenStamp) {
          seenAt[static_cast<std::size_t>(w[j])] = seenStamp;
          ++distinct;
        }
      }
      if (mine && distinct == sorted.size()) return w;
    }
    std::vector<long> w = sp.walk(static_cast<int>(R), start[R], sorted.size(), walkBudget(sorted.size()));
    known[h] = w;
    return w;
  };
  auto move = [&](long v, std::size_t R, std::size_t S) {
    auto& mine = cellsOf[R];
    mine.erase(std::find(mine.begin(), mine.end(), v));
    cellsOf[S].push_back(v);
    sp.owner[static_cast<std::size_t>(v)] = static_cast<int>(S);
    --sp.size_[R];
    ++sp.size_[S];
  };
  auto touches = [&](long v, std::size_t S) {
    for (int d = 0; d < 4; ++d)
      if (const long u = sp.neighbour(v, d); u >= 0 && sp.owner[static_cast<std::size_t>(u)] == static_cast<int>(S)) return true;
    return false;
  };
  // the cells of R that may pass to S
  auto candidates = [&](std::size_t R, std::size_t S) {
    std::vector<long> out;
    for (long v : cellsOf[R])
      if (touches(v, S) && sp.mayLeave(v, static_cast<int>(R), start[R])) out.push_back(v);
    return out;
  };
  const std::size_t rounds = 64 * k + 1024, until = sp.work() + bound;
  auto now = score(walks);
  for (std::size_t round = 0; round < rounds; ++round) {
    if (stop.expired()) return {};
    if (sp.work() > until) break;
    std::vector<std::size_t> byWalk(k);
    std::iota(byWalk.begin(), byWalk.end(), 0);
    std::stable_sort(byWalk.begin(), byWalk.end(), [&](std::size_t a, std::size_t b) { return walks[a].size() > walks[b].size(); });
    bool kept = false;
    for (std::size_t c = 0; c < k && !kept; ++c) {
      const std::size_t A = byWalk[c];
      if (sp.work() > until) break;
      if (static_cast<long>(walks[A].size()) < now.first) break;   // chains start at a longest walk
      // breadth first over regions: R links to S when R has a cell that may pass to S
      std::vector<int> from(k, -1);
      from[A] = static_cast<int>(A);
      std::deque<std::size_t> q{A};
      std::vector<std::size_t> ends;
      while (!q.empty() && ends.size() < 8) {
        const std::size_t R = q.front();
        q.pop_front();
        std::vector<char> near(k, 0);
        for (long v : cellsOf[R])
          for (int d = 0; d < 4; ++d)
            if (const long u = sp.neighbour(v, d); u >= 0 && sp.owner[static_cast<std::size_t>(u)] >= 0 && sp.owner[static_cast<std::size_t>(u)] != static_cast<int>(R))
              near[static_cast<std::size_t>(sp.owner[static_cast<std::size_t>(u)])] = 1;
        for (std::size_t S = 0; S < k; ++S) {
          if (!near[S] || from[S] >= 0 || candidates(R, S).empty()) continue;
          from[S] = static_cast<int>(R);
          if (walks[S].size() + 2 <= walks[A].size()) ends.push_back(S);
          q.push_back(S);
        }
      }
      for (std::size_t B : ends) {
        if (sp.work() > until) break;
        // pass along the chain from its far end, each link's cell the one leaving the shortest walks
        std::vector<std::pair<long, std::size_t>> done;   // (cell, region it came from), to undo
        std::vector<std::size_t> touched;
        const auto saved = walks;
        bool whole = true;
        for (std::size_t S = B; S != A; S = static_cast<std::size_t>(from[S])) {
          const std::size_t R = static_cast<std::size_t>(from[S]);
          // one sub-cell, or two (a region's colours must stay balanced for a Hamiltonian path)
          std::vector<long> pick;
          std::pair<std::size_t, std::size_t> pickKey{0, 0};
          std::vector<long> pickR, pickS;
          auto consider = [&](const std::vector<long>& cellsPassed) {
            std::vector<long> wr = walkOf(R), ws = walkOf(S);
            const std::pair<std::size_t, std::size_t> key{std::max(wr.size(), ws.size()), wr.size() + ws.size()};
            if (pick.empty() || key < pickKey) {
              pick = cellsPassed, pickKey = key;
              pickR = std::move(wr);
              pickS = std::move(ws);
            }
          };
          const std::vector<long> singles = candidates(R, S);
          for (long v : singles) {
            move(v, R, S);
            consider({v});
            move(v, S, R);
          }
          // pairs only when no single sub-cell leaves both regions a Hamiltonian walk
          if (pick.empty() || pickR.size() > cellsOf[R].size() - 1 || pickS.size() > cellsOf[S].size() + 1)
            for (long v : singles) {
              move(v, R, S);
              for (long w : candidates(R, S)) {
                move(w, R, S);
                consider({v, w});
                move(w, S, R);
              }
              move(v, S, R);
            }
          if (pick.empty()) {
            whole = false;
            break;
          }
          for (long v : pick) {
            move(v, R, S);
            done.emplace_back(v, R);
          }
          walks[R] = std::move(pickR);
          walks[S] = std::move(pickS);
        }
        const auto after = score(walks);
        if (whole && after < now) {
          now = after;
          kept = true;
          break;
        }
        for (auto it = done.rbegin(); it != done.rend(); ++it) move(it->first, static_cast<std::size_t>(sp.owner[static_cast<std::size_t>(it->first)]), it->second);
        walks = saved;
      }
    }
    if (!kept) break;
  }
  return walks;
}

}  // namespace

std::vector<std::vector<CellIndex>> subcellRegions(const CellGrid& cells, const graph::GridGraph& g, const std::vector<CellIndex>& startCell,
                                                   const std::vector<int>& megaOwner, const std::vector<std::vector<CellIndex>>& megaRoutes,
                                                   const TerminationCondition& stop) {
  const std::size_t k = startCell.size();
  std::size_t work = 0;
  Split base(cells, g, work);
  std::vector<long> start(k);
  for (std::size_t i = 0; i < k; ++i) start[i] = base.id(startCell[i]);
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (start[i] == start[j]) return {};
  const std::vector<long> all = base.component(start);
  std::vector<std::vector<long>> best;
  // each of the two starts may spend workBound; the restarts one more workBound between them
  bool restarting = false;
  std::size_t restartsUntil = 0;
  auto consider = [&](Split& sp, std::vector<std::vector<long>> walks, const std::vector<std::vector<long>>& members) {
    const std::size_t bound = std::min(workBound(all.size()), restarting ? restartsUntil - std::min(restartsUntil, work) : workBound(all.size()));
    std::vector<std::vector<long>> out = refine(sp, start, std::move(walks), members, bound, stop);
    if (!out.empty() && (best.empty() || score(out) < score(best))) best = std::move(out);
  };
  // a split whose regions have no walks yet (refine sets the sizes it needs)
  auto considerWalked = [&](Split& sp, const std::vector<std::vector<long>>& members) {
    std::vector<std::vector<long>> walks(k);
    for (std::size_t i = 0; i < k; ++i) walks[i] = sp.walk(static_cast<int>(i), start[i], members[i].size(), walkBudget(members[i].size()));
    consider(sp, std::move(walks), members);
  };
  // from the whole-mega-cell regions and their tours
  if (!megaOwner.empty() && megaRoutes.size() == k) {
    Split sp = base;
    std::vector<std::vector<long>> members(k), walks(k);
    bool whole = true;
    for (long v : all) {
      const CellIndex c = sp.cell(v);
      const int o = megaOwner[static_cast<std::size_t>(g.id(c.col / 2, c.row / 2))];
      if (o < 0) {
        whole = false;
        break;
      }
      sp.owner[static_cast<std::size_t>(v)] = o;
      members[static_cast<std::size_t>(o)].push_back(v);
    }
    for (std::size_t i = 0; i < k && whole; ++i)
      for (CellIndex c : megaRoutes[i]) walks[i].push_back(sp.id(c));
    if (whole) consider(sp, std::move(walks), members);
  }
  // breadth first from all starts at once
  {
    Split sp = base;
    std::vector<std::vector<long>> members(k);
    std::deque<long> open;
    for (std::size_t i = 0; i < k; ++i) {
      sp.owner[static_cast<std::size_t>(start[i])] = static_cast<int>(i);
      members[i].push_back(start[i]);
      open.push_back(start[i]);
    }
    while (!open.empty()) {
      const long v = open.front();
      open.pop_front();
      for (int d = 0; d < 4; ++d)
        if (const long u = sp.neighbour(v, d); u >= 0 && sp.owner[static_cast<std::size_t>(u)] == -2) {
          sp.owner[static_cast<std::size_t>(u)] = sp.owner[static_cast<std::size_t>(v)];
          members[static_cast<std::size_t>(sp.owner[static_cast<std::size_t>(v)])].push_back(u);
          open.push_back(u);
        }
    }
    considerWalked(sp, members);
  }
  // still above the mean (rounded up): restarts from seeded random additive weights, each sub-cell
  // to the start i with the least steps + w_i (ties to the lower index; additive weights keep each
  // region joined to its start, as in multi_stc.cpp's `reweighted`), the best kept
  const long even = (static_cast<long>(all.size()) + static_cast<long>(k) - 1) / static_cast<long>(k);
  auto settled = [&] { return !best.empty() && score(best).first <= even; };
  restarting = true;
  restartsUntil = work + workBound(all.size());
  if (!settled() && k * all.size() <= kRestartCells) {
    std::vector<std::vector<int>> dist(k, std::vector<int>(base.count(), -1));
    for (std::size_t i = 0; i < k; ++i) {
      std::vector<long> q{start[i]};
      dist[i][static_cast<std::size_t>(start[i])] = 0;
      for (std::size_t h = 0; h < q.size(); ++h)
        for (int d = 0; d < 4; ++d)
          if (const long u = base.neighbour(q[h], d); u >= 0 && dist[i][static_cast<std::size_t>(u)] < 0) {
            dist[i][static_cast<std::size_t>(u)] = dist[i][static_cast<std::size_t>(q[h])] + 1;
            q.push_back(u);
          }
    }
    std::mt19937_64 random(0x5ce11);   // the same sequence on every platform
    const auto spread = static_cast<std::uint64_t>(std::ceil(std::sqrt(static_cast<double>(all.size()) / static_cast<double>(k))));
    for (std::size_t r = 0; r < kRestarts && !settled() && !stop.expired() && work <= restartsUntil; ++r) {
      std::vector<long> w(k);
      for (long& x : w) x = static_cast<long>(random() % (spread + 1));
      Split sp = base;
      std::vector<std::vector<long>> members(k);
      for (long v : all) {
        std::size_t to = 0;
        long least = -1;
        for (std::size_t i = 0; i < k; ++i)
          if (const long key = dist[i][static_cast<std::size_t>(v)] + w[i]; least < 0 || key < least) least = key, to = i;
        sp.owner[static_cast<std::size_t>(v)] = static_cast<int>(to);
        members[to].push_back(v);
      }
      bool joined = true;   // every start its own (a start another start's weight took: no split)
      for (std::size_t i = 0; i < k && joined; ++i) joined = sp.owner[static_cast<std::size_t>(start[i])] == static_cast<int>(i);
      if (!joined) continue;
      considerWalked(sp, members);
    }
  }
  std::vector<std::vector<CellIndex>> routes(best.size());
  for (std::size_t i = 0; i < best.size(); ++i)
    for (long v : best[i]) routes[i].push_back(base.cell(v));
  return routes;
}

}  // namespace coverkit::planners
