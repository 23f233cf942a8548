// multi_st: the Multi-ST planner (online, step-synchronous): k robots grow disjoint spanning trees
// on the shared mega-cell grid, each walking round its own tree, with a rule knowledge base for the
// robots and moving obstacles they meet (docs/multi-robot.md).
//
// Reference: H. V. Pham, P. Moore et al., "Multi-ST: a multi-robot coverage path planning model with
// spiral spanning trees and knowledge-based reasoning" (../shared/papers/multi-st_pham-et-al.txt):
// sections 3.2-3.4 (online ST, FSST), 5.1-5.3 (the shared visited array, the stack, the knowledge
// base) and 7 (time = steps × 100 ms, coverage rate (A1 − A2)/A, iteration rate). The paper gives
// pseudo-code but not every rule; where it is vague or inconsistent we decided:
//  * Scan order. The paper says "counter-clockwise (up, left, down, right)" in 3.2 and "clockwise
//    (up-left-down-right)" in 5.2; up-left-down-right is counter-clockwise, so counter-clockwise it
//    is, starting after the parent, as Spiral-STC does. The robot walks round each mega-cell's four
//    sub-cells counter-clockwise and, at the sub-cell where the walk turns away from a side, looks
//    at the mega-cell across that side (sub-cell q = 0 bottom-left … 3 top-left looks in direction
//    q + 3: south, east, north, west); a free, unclaimed one becomes its child: claimed in the
//    shared visited array, entered, walked round, and left back into the parent's next sub-cell.
//    That is STC's walk round the tree, made one step at a time. The root is walked round once and
//    the robot returns to its first sub-cell (the paper's step 4).
//  * Claims. Robots decide in index order within a step; a mega-cell is claimed by the first that
//    decides to enter it, so two trees never share a mega-cell (the paper's Fig 6 rule: a robot
//    does not enter a mega-cell already in the visited array).
//  * Partially occupied mega-cells (FSST). They are never tree nodes. When the walk passes a free
//    sub-cell of a partially occupied neighbour, the robot steps into it and through the free
//    sub-cells of that mega-cell it can reach inside it, and back (Full-STC's single-sided edge to
//    a leaf); everything else is reached by travel (next point).
//  * Travel. A robot whose tree is done goes, by a shortest way over the sub-cells the team has
//    sensed free, to the nearest sub-cell that is either in a sensed free mega-cell nobody has
//    claimed (it claims it there and grows a new tree) or sensed free and never entered; none left:
//    it stays. Targets are reserved, one robot each. Every sub-cell a robot enters gets its
//    mega-cell and the four next to it sensed, so every free sub-cell reachable from the starts
//    becomes known and is entered: the team covers everything reachable (the requirement;
//    the paper's robots stop when their trees are done and leave what the other trees cut off).
//  * Steps. One step moves a robot to a 4-neighbouring sub-cell centre or keeps it in place (as
//    multi_stc_balanced); in the first step each robot moves from its start to its sub-cell's
//    centre. A robot never enters a sub-cell another robot is in or will be in at the next step,
//    nor leaves one another robot enters at the next step, so any two robots stay at least D = 2r
//    apart (the validator checks every plan exactly).
//  * The knowledge base (knowledge_base.h; the shipped rules are planners/data/multi_st_kb.yaml).
//    The paper's Tables 2-3 did not survive; its text names the events (an obstacle or a robot in
//    the cell ahead; blocked for some steps), the ECA form and weights updated from outcomes (its
//    steps 6-7, equation 2 without its membership functions). A refused move is an event; the
//    heaviest matching rule fires; its weight moves towards 1 when the robot moves within
//    outcome_steps steps, towards 0 otherwise (each robot its own weights). Actions: wait; detour
//    (a shortest way of at most 12 moves over sensed free sub-cells round the blocked one to the
//    waypoint after it; on the walk round a tree the blocked sub-cell is left for later); give_way
//    (step to a free neighbour off the other robot's way and come back); skip (leave the blocked
//    cell for later: a child not entered is released, a target given up for 20 steps).
//  * kb=off is the paper's baseline: a blocked robot waits until the cell clears. Two robots that
//    wait for each other then wait for ever: the run stops when no robot has moved for 200 steps
//    after the last obstacle has stopped (status partial_coverage, the deadlock named).
//  * Built-in reflexes, not rules (a wait would be a collision): a robot whose own place is not clear
//    of a moving obstacle over the sensor's horizon leaves at once for the earliest haven (a cell
//    that then stays clear to the horizon's end), found in space and time; waiting until the last
//    step that is still clear (the first version) let obstacles corner robots that had ways out
//    when they first saw them. Where the only ways to a haven pass robots, the robot in the way
//    makes room, whatever it was doing; a robot making room that finds a robot on its own way asks
//    that one in turn, so a row of robots in a corridor moves up like a train (a single level of
//    asking left three robots jammed in a corner for ever). A robot with nothing to do that stands
//    in another's way steps aside, and while obstacles move an idle robot waits in a cell whose
//    four neighbours are free and held by no obstacle, not in a dead end (again after making room).
//    None of this can see past the horizon: an obstacle that comes, through a wall, into a dead end
//    holding a robot, slower than the horizon shows it, can still catch the robot. The default
//    horizon is 30 steps (3 s at 0.1 s a step): with 20, two of team-check's 500 scenarios had a
//    robot caught in a dead end; with 30, none (and 40 is not better: two others, the reflexes
//    then send robots elsewhere). team-check's 500 take 92 s instead of 63 s (--jobs 2).
//  * Stopping. The stall clocks (no new sub-cell for 4 (cols + rows) + 200 steps, no move for 200)
//    start when the last obstacle stops at the latest: a team that waited for the obstacles then
//    still has its time to go round what they left (before, a run could stop 20 steps after them).
//  * What cannot be reached: a target given up three times (an obstacle parked on it) is left;
//    free sub-cells sensed but never entered are counted (statistic subcells_skipped, status
//    partial_coverage).
#include <coverkit/planners/multi_stc.h>

#include "team_steps.h"
#include "walk_path.h"

#include <coverkit/geometry/error.h>
#include <coverkit/planners/knowledge_base.h>
#include <coverkit/planners/sensor.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <chrono>
#include <deque>
#include <map>
#include <memory>

namespace coverkit::planners {

namespace {

constexpr int kDetourMoves = 12;
constexpr long kDeferSteps = 20;
constexpr int kGiveUpAfter = 3;
constexpr long kStallSteps = 200;

// directions 0 east, 1 north, 2 west, 3 south (graph::kDx, kDy)
constexpr int kDc[4] = {1, 0, -1, 0}, kDr[4] = {0, 1, 0, -1};

enum class Tag { kTree, kCross, kSide, kTravel, kDetour, kAside, kEvade, kRoom };

struct Waypoint {
  long cell;
  Tag tag;
};

struct Frame {
  long mega;        ///< mr * megaCols + mc
  int entry;        ///< the quadrant the robot entered it at
  int parentDir;    ///< direction to the parent mega-cell, -1 at a root
  int k = 0;        ///< quadrants processed: the robot is at quadrant (entry + k) % 4
};

enum class Mode { kTree, kTravel, kIdle };

struct RobotState {
  long cell = -1;
  std::deque<Waypoint> queue;
  std::vector<Frame> stack;
  Mode mode = Mode::kTree;
  long target = -1;
  int blocked = 0;
  int pendingRule = -1;
  long pendingSince = 0;
  std::vector<double> weights;
  std::vector<CellIndex> route;   ///< the cell at each step from step 1
  std::map<long, long> deferredUntil;
  std::map<long, int> gaveUp;
  int nudgedBy = -1;              ///< a robot this idle one stands in the way of
  int makeRoomFor = -1;           ///< a robot evading an obstacle whose way out this one stands on
  long lastChecked = -1;          ///< knowledge version of its last target search (idle robots)
  long retryAt = -1;              ///< among moving obstacles: when an idle robot looks for a target again
  bool parked = false;            ///< among moving obstacles: an idle robot has gone to a cell with ways out
  std::size_t cellsEntered = 0;
};

class Team {
public:
  Team(const PlanningContext& ctx, const StepTiming& timing, const KnowledgeBase& kb, bool kbOn, TeamSensor& sensor)
      : ctx_(ctx), cells_(ctx.cells), timing_(timing), kb_(kb), kbOn_(kbOn), sensor_(sensor),
        moving_(!ctx.problem.movingObstacles.empty()), horizon_(sensor.horizon()),
        cols_(cells_.subCols()), rows_(cells_.subRows()), mcols_(cells_.megaCols()),
        known_(static_cast<std::size_t>(cols_) * rows_, -1), entered_(known_.size(), -1),
        megaKnown_(cells_.megaCount(), -1), owner_(cells_.megaCount(), -1), parent_(known_.size(), -1), searchOf_(known_.size(), 0) {}

  /// Runs the team from its start cells; returns the status and fills the statistics.
  PlanStatus run(const std::vector<CellIndex>& starts, const TerminationCondition& stop, Plan& plan);

  const std::vector<RobotState>& robots() const { return robots_; }

private:
  long id(int c, int r) const { return static_cast<long>(r) * cols_ + c; }
  int colOf(long v) const { return static_cast<int>(v % cols_); }
  int rowOf(long v) const { return static_cast<int>(v / cols_); }
  CellIndex cellOf(long v) const { return {colOf(v), rowOf(v)}; }
  long megaOf(long v) const { return static_cast<long>(rowOf(v) / 2) * mcols_ + colOf(v) / 2; }
  static int quadrantOf(int c, int r) {
    const int qc = c & 1, qr = r & 1;
    return qr == 0 ? qc : 3 - qc;
  }
  long subOf(long mega, int q) const {
    const int mc = static_cast<int>(mega % mcols_), mr = static_cast<int>(mega / mcols_);
    return id(2 * mc + (q == 1 || q == 2 ? 1 : 0), 2 * mr + (q >= 2 ? 1 : 0));
  }
  long step(long v, int d) const {
    const int c = colOf(v) + kDc[d], r = rowOf(v) + kDr[d];
    return c >= 0 && r >= 0 && c < cols_ && r < rows_ ? id(c, r) : -1;
  }
  bool knownFree(long v) const { return v >= 0 && known_[static_cast<std::size_t>(v)] == 1; }
  int distance(long a, long b) const { return std::abs(colOf(a) - colOf(b)) + std::abs(rowOf(a) - rowOf(b)); }
  bool megaFull(long m) const { return megaKnown_[static_cast<std::size_t>(m)] == 4; }

  void sense(std::size_t i);
  void enter(std::size_t i, long v);
  void nextWaypoints(std::size_t i);
  void pushMoveOn(std::size_t i);
  bool findTarget(std::size_t i, long t);
  void travelTo(std::size_t i, const std::vector<long>& way);
  bool allowed(std::size_t self, long from, long to) const;
  int blockerOf(std::size_t self, long v) const;
  template <class Pass, class Goal>
  std::vector<long> breadthFirst(long from, const Pass& pass, const Goal& goal, int limit, std::size_t cap);
  std::vector<long> shortestWay(std::size_t self, long from, long goal, long avoid, int limit, long t = -1);
  bool heldByObstacle(std::size_t i, long v, long t);
  static void goVia(RobotState& R, const std::vector<long>& way);
  void passOver(std::size_t i);
  void becomeIdle(std::size_t i);
  bool act(std::size_t i, KbAction a, long t);
  bool detour(std::size_t i, long t);
  bool skip(std::size_t i, long t);
  bool stepAside(std::size_t i, long avoid, bool comeBack, long t);
  bool stayClear(std::size_t i, long cell, long t, int steps);
  bool safeMove(std::size_t i, long from, long to, long t);
  std::vector<long> fleeWay(std::size_t i, long t, bool throughRobots, bool& haven);
  long evade(std::size_t i, long t);
  void release(std::size_t i);
  void repair(std::size_t i, long t);
  void startTree(std::size_t i);
  void clearTheWay(std::size_t i, std::size_t other, long t, bool forEvader);
  void park(std::size_t i, long t);

  const PlanningContext& ctx_;
  const CellGrid& cells_;   // sizes and coordinates only: what is free comes from the sensor
  const StepTiming& timing_;
  const KnowledgeBase& kb_;
  bool kbOn_;
  TeamSensor& sensor_;
  bool moving_;
  int horizon_;
  double lastObstacle_ = 0;   ///< when the last moving obstacle stops (s)
  int cols_, rows_, mcols_;
  std::vector<signed char> known_;    ///< per sub-cell: -1 not sensed, 0 blocked, 1 free (the team's map)
  std::vector<int> entered_;          ///< per sub-cell: the first robot to enter it, -1 none
  std::vector<signed char> megaKnown_;   ///< per mega-cell: -1 not sensed, else its free sub-cells
  std::vector<int> owner_;            ///< per mega-cell: the robot whose tree holds it (the shared visited array)
  std::vector<RobotState> robots_;
  std::vector<long> next_;            ///< this step's decisions: the cell at t + 1, -1 not decided
  std::map<long, std::size_t> targetOf_;   ///< reserved travel targets
  std::vector<long> parent_;          ///< the breadth-first searches' scratch: where each cell was reached from ...
  std::vector<unsigned> searchOf_;    ///< ... in the search of this number
  unsigned search_ = 0;
  long version_ = 0;                  ///< bumps when a new target may have appeared
  std::size_t repeats_ = 0, rulesFired_ = 0, enteredTotal_ = 0;
  std::map<std::string, std::size_t> fired_;
};

void Team::sense(std::size_t i) {
  const long v = robots_[i].cell;
  const int mc = colOf(v) / 2, mr = rowOf(v) / 2;
  for (int d = -1; d < 4; ++d) {
    const int c = d < 0 ? mc : mc + kDc[d], r = d < 0 ? mr : mr + kDr[d];
    if (c < 0 || r < 0 || c >= mcols_ || 2 * r >= rows_) continue;
    const long m = static_cast<long>(r) * mcols_ + c;
    if (megaKnown_[static_cast<std::size_t>(m)] >= 0) continue;
    const std::array<CellState, 4> s = sensor_.megaCell(i, c, r);
    int free = 0;
    for (int q = 0; q < 4; ++q) {
      const bool f = s[static_cast<std::size_t>(q)] == CellState::kFree;
      known_[static_cast<std::size_t>(subOf(m, q))] = f ? 1 : 0;
      free += f ? 1 : 0;
    }
    megaKnown_[static_cast<std::size_t>(m)] = static_cast<signed char>(free);
    if (free > 0) ++version_;
  }
}

void Team::enter(std::size_t i, long v) {
  RobotState& R = robots_[i];
  const long before = R.cell;
  if (v != before) sensor_.moveTo(i, cellOf(v));
  R.cell = v;
  int& e = entered_[static_cast<std::size_t>(v)];
  if (v != before) {
    if (e < 0) {
      e = static_cast<int>(i);
      ++R.cellsEntered;
      ++enteredTotal_;
    } else {
      ++repeats_;
    }
  }
  if (before < 0 || megaOf(before) != megaOf(v)) sense(i);
}

// The move that follows processing the top frame's quadrant k - 1: to quadrant k, or out of the
// mega-cell (to the parent; a root returns to where it began).
void Team::pushMoveOn(std::size_t i) {
  RobotState& R = robots_[i];
  Frame& f = R.stack.back();
  if (f.k < 4) {
    R.queue.push_back({subOf(f.mega, (f.entry + f.k) % 4), Tag::kTree});
    return;
  }
  const Frame done = f;
  R.stack.pop_back();
  if (done.parentDir < 0) {
    R.queue.push_back({subOf(done.mega, done.entry), Tag::kTree});
    return;
  }
  R.queue.push_back({step(subOf(done.mega, (done.entry + 3) % 4), done.parentDir), Tag::kTree});
}

// The walk round the tree, one decision at a time (the robot is where the top frame says).
void Team::nextWaypoints(std::size_t i) {
  RobotState& R = robots_[i];
  while (R.queue.empty() && !R.stack.empty()) {
    Frame& f = R.stack.back();
    if (f.k >= 4) {   // a root walked round and back at its first sub-cell
      R.stack.pop_back();
      continue;
    }
    const int q = (f.entry + f.k) % 4, d = (q + 3) % 4;
    const long here = subOf(f.mega, q);
    ++f.k;
    if (d != f.parentDir) {
      const long a = step(here, d);
      if (a >= 0) {
        const long y = megaOf(a);
        if (megaFull(y) && owner_[static_cast<std::size_t>(y)] < 0) {   // a child: claimed, entered, walked round
          owner_[static_cast<std::size_t>(y)] = static_cast<int>(i);
          R.stack.push_back({y, quadrantOf(colOf(a), rowOf(a)), (d + 2) % 4, 0});
          R.queue.push_back({a, Tag::kCross});
          return;
        }
        if (megaKnown_[static_cast<std::size_t>(y)] > 0 && !megaFull(y) && knownFree(a) && entered_[static_cast<std::size_t>(a)] < 0) {
          // a partially occupied neighbour: through its free sub-cells reachable inside it, and back
          std::vector<long> out{a};
          for (std::size_t h = 0; h < out.size(); ++h)
            for (int e = 0; e < 4; ++e) {
              const long b = step(out[h], e);
              if (b >= 0 && megaOf(b) == y && knownFree(b) && std::find(out.begin(), out.end(), b) == out.end()) out.push_back(b);
            }
          // out-and-back along the (at most three) sub-cells in the order found: each is next to one before it
          std::vector<long> walk{a};
          for (std::size_t h = 1; h < out.size(); ++h) {
            // from the walk's end to out[h] inside y: at most two moves back along the walk
            while (true) {
              const long end = walk.back();
              bool adjacent = false;
              for (int e = 0; e < 4; ++e) adjacent = adjacent || step(end, e) == out[h];
              if (adjacent) break;
              walk.push_back(walk[walk.size() - 2]);
            }
            walk.push_back(out[h]);
          }
          for (std::size_t h = walk.size() - 1; h-- > 0;) walk.push_back(walk[h]);
          walk.push_back(here);
          for (long w : walk) R.queue.push_back({w, Tag::kSide});
        }
      }
    }
    pushMoveOn(i);
  }
}

// The step rules: never into a cell another robot is in now or at the next step, never out of one
// another robot enters at the next step.
bool Team::allowed(std::size_t self, long from, long to) const {
  if (to == from) return true;
  if (blockerOf(self, to) >= 0) return false;
  for (std::size_t j = 0; j < robots_.size(); ++j)
    if (j != self && next_[j] == from) return false;
  return true;
}

int Team::blockerOf(std::size_t self, long v) const {
  for (std::size_t j = 0; j < robots_.size(); ++j)
    if (j != self && (robots_[j].cell == v || next_[j] == v)) return static_cast<int>(j);
  return -1;
}

// Breadth first from `from` over sensed free sub-cells (4-neighbours in direction order) that
// `pass` lets in, at most `limit` moves (0: no limit) and `cap` cells: the way after `from` to the
// first cell reached for which `goal` holds; empty when none.
template <class Pass, class Goal>
std::vector<long> Team::breadthFirst(long from, const Pass& pass, const Goal& goal, int limit, std::size_t cap) {
  ++search_;
  searchOf_[static_cast<std::size_t>(from)] = search_;
  std::deque<std::pair<long, int>> open{{from, 0}};
  std::size_t reached = 1;
  while (!open.empty()) {
    const auto [v, depth] = open.front();
    open.pop_front();
    if (limit > 0 && depth >= limit) continue;
    for (int d = 0; d < 4; ++d) {
      const long w = step(v, d);
      if (w < 0 || !knownFree(w) || searchOf_[static_cast<std::size_t>(w)] == search_ || !pass(w)) continue;
      searchOf_[static_cast<std::size_t>(w)] = search_;
      parent_[static_cast<std::size_t>(w)] = v;
      if (goal(w)) {
        std::vector<long> way;
        for (long x = w; x != from; x = parent_[static_cast<std::size_t>(x)]) way.push_back(x);
        std::reverse(way.begin(), way.end());
        return way;
      }
      if (++reached > cap) return {};
      open.push_back({w, depth + 1});
    }
  }
  return {};
}

// A cell within the sensor's reach that a moving obstacle holds at step t.
bool Team::heldByObstacle(std::size_t i, long v, long t) {
  return moving_ && distance(v, robots_[i].cell) <= horizon_ && !sensor_.moveClear(i, cellOf(v), cellOf(v), t);
}

// A shortest way to `goal` avoiding `avoid`; a way of at most `limit` moves (a way round) also keeps
// off the cells robots are in; with a step t, off cells a moving obstacle holds then.
std::vector<long> Team::shortestWay(std::size_t self, long from, long goal, long avoid, int limit, long t) {
  if (from == goal) return {};
  auto pass = [&](long w) {
    if (w == avoid) return false;
    if (w == goal) return true;
    return !(limit > 0 && blockerOf(self, w) >= 0) && !(t >= 0 && heldByObstacle(self, w, t));
  };
  return breadthFirst(from, pass, [&](long w) { return w == goal; }, limit, static_cast<std::size_t>(-1));
}

// The robot's queue: `way` (after the robot's cell, ending at the queue's first waypoint) in front
// of what follows that waypoint, which keeps its tag; the rest of the way is a way round.
void Team::goVia(RobotState& R, const std::vector<long>& way) {
  const Waypoint goal = R.queue.front();
  R.queue.pop_front();
  for (std::size_t h = way.size(); h-- > 0;) R.queue.push_front({way[h], h + 1 == way.size() ? goal.tag : Tag::kDetour});
}

// The walk round the tree goes on past a waypoint dropped from an empty queue: the quadrant is
// passed over (travel comes back for it).
void Team::passOver(std::size_t i) {
  RobotState& R = robots_[i];
  if (R.queue.empty() && R.mode == Mode::kTree && !R.stack.empty()) {
    if (R.stack.back().k < 4) ++R.stack.back().k;
    pushMoveOn(i);
  }
}

// Nothing to do now: its target (if any) released; it looks for one at its next decision.
void Team::becomeIdle(std::size_t i) {
  RobotState& R = robots_[i];
  release(i);
  R.queue.clear();
  R.mode = Mode::kIdle;
  R.lastChecked = -1;
}

// The nearest sub-cell of an unclaimed sensed free mega-cell, or a sensed free one never entered,
// not reserved by another robot and not deferred; the way there becomes the robot's queue.
bool Team::findTarget(std::size_t i, long t) {
  RobotState& R = robots_[i];
  auto wanted = [&](long v) {   // (in an unclaimed free mega-cell it grows a new tree there)
    if (entered_[static_cast<std::size_t>(v)] >= 0) return false;
    const auto reserved = targetOf_.find(v);
    const auto deferred = R.deferredUntil.find(v);
    const auto given = R.gaveUp.find(v);
    return (reserved == targetOf_.end() || reserved->second == i) && (deferred == R.deferredUntil.end() || deferred->second <= t) &&
           (given == R.gaveUp.end() || given->second < kGiveUpAfter);
  };
  // the way keeps off cells a moving obstacle holds now, as far as the sensor reaches
  const std::vector<long> way = breadthFirst(R.cell, [&](long w) { return !heldByObstacle(i, w, t); }, wanted, 0, static_cast<std::size_t>(-1));
  if (way.empty()) return false;
  travelTo(i, way);
  return true;
}

// The robot reserves the way's last cell as its target and travels there by the way.
void Team::travelTo(std::size_t i, const std::vector<long>& way) {
  RobotState& R = robots_[i];
  R.target = way.back();
  R.parked = false;
  targetOf_[R.target] = i;
  R.queue.clear();
  for (long v : way) R.queue.push_back({v, Tag::kTravel});
  R.mode = Mode::kTravel;
}

// Among moving obstacles an idle robot does not wait in a dead end or a corner, where an obstacle
// coming in would leave it no way out: it goes to the nearest sensed free cell within the sensor's
// reach whose four neighbours are sensed free and held by no obstacle now, and that no robot holds
// (or stays, where there is none). It parks again after it has made room for another robot.
void Team::park(std::size_t i, long t) {
  RobotState& R = robots_[i];
  R.parked = true;
  auto open = [&](long v) {
    for (int d = 0; d < 4; ++d)
      if (const long w = step(v, d); !knownFree(w) || heldByObstacle(i, w, t)) return false;
    return true;
  };
  if (open(R.cell)) return;
  const std::vector<long> way = breadthFirst(
      R.cell, [&](long w) { return !heldByObstacle(i, w, t); }, [&](long v) { return open(v) && blockerOf(i, v) < 0; }, horizon_ - 1, 4096);
  for (long v : way) R.queue.push_back({v, Tag::kAside});
}

void Team::release(std::size_t i) {
  RobotState& R = robots_[i];
  if (R.target >= 0) {
    const auto it = targetOf_.find(R.target);
    if (it != targetOf_.end() && it->second == i) {
      targetOf_.erase(it);
      ++version_;   // free for the others again
    }
  }
  R.target = -1;
}

bool Team::detour(std::size_t i, long t) {
  RobotState& R = robots_[i];
  const Waypoint blocked = R.queue.front();
  if (blocked.tag == Tag::kDetour) {   // a way round that is blocked itself: a new one from here, not one more
    while (R.queue.size() > 1 && R.queue.front().tag == Tag::kDetour) R.queue.pop_front();
    R.queue.push_front(blocked);
  }
  if (R.queue.size() < 2) {
    // on the walk round a tree: leave the blocked quadrant for later and go round it to the next one
    if (blocked.tag != Tag::kTree || R.stack.empty() || R.stack.back().k >= 4 ||
        subOf(R.stack.back().mega, (R.stack.back().entry + R.stack.back().k) % 4) != blocked.cell)
      return false;
    R.queue.pop_front();
    ++R.stack.back().k;
    pushMoveOn(i);
  } else {
    R.queue.pop_front();
  }
  const long goal = R.queue.front().cell;
  const std::vector<long> way = shortestWay(i, R.cell, goal, blocked.cell, kDetourMoves, t);
  if (way.empty()) {
    // nothing round it within reach: back as it was, except a quadrant left for later (travel covers it)
    R.queue.push_front(blocked);
    return false;
  }
  goVia(R, way);
  return true;
}

bool Team::skip(std::size_t i, long t) {
  RobotState& R = robots_[i];
  const Waypoint blocked = R.queue.front();
  switch (blocked.tag) {
    case Tag::kCross: {   // the child is not entered: released for another robot or for later
      const Frame child = R.stack.back();
      R.stack.pop_back();
      owner_[static_cast<std::size_t>(child.mega)] = -1;
      ++version_;
      R.queue.pop_front();
      pushMoveOn(i);
      return true;
    }
    case Tag::kSide: {   // the rest of the side trip is left: straight back to the walk
      while (!R.queue.empty() && R.queue.front().tag == Tag::kSide) R.queue.pop_front();
      if (R.queue.empty()) return false;
      return true;   // the way back to the walk: repair()
    }
    case Tag::kTravel: {
      if (R.target >= 0) {
        R.deferredUntil[R.target] = t + kDeferSteps;
        if (static_cast<double>(t) * timing_.step > lastObstacle_) ++R.gaveUp[R.target];   // given up only once nothing moves any more
      }
      becomeIdle(i);
      return true;
    }
    default: {
      // a cell of the walk (or of a way round): dropped and left for later (travel comes back for
      // it); on the walk round a tree the quadrant is passed over and the robot goes on to the next
      R.queue.pop_front();
      passOver(i);
      if (R.queue.empty()) return true;
      const std::vector<long> way = shortestWay(i, R.cell, R.queue.front().cell, blocked.cell, 0, t);
      if (!way.empty()) goVia(R, way);   // else not reachable now: the next refusal skips on
      return true;
    }
  }
}

// A root where the robot stands, if its mega-cell is free and unclaimed; else the robot is idle.
void Team::startTree(std::size_t i) {
  RobotState& R = robots_[i];
  const long m = megaOf(R.cell);
  if (megaFull(m) && owner_[static_cast<std::size_t>(m)] < 0) {
    owner_[static_cast<std::size_t>(m)] = static_cast<int>(i);
    R.stack.push_back({m, quadrantOf(colOf(R.cell), rowOf(R.cell)), -1, 0});
    R.mode = Mode::kTree;
  } else {
    R.mode = Mode::kIdle;
    R.lastChecked = -1;
  }
}

// The queue's first waypoint must be the robot's cell or next to it (a skip can leave one that is
// not): the way there is put in front of it, or, where there is none over the sensed cells, it is
// dropped (on the walk round a tree the walk goes on; travel comes back for what is left).
void Team::repair(std::size_t i, long t) {
  RobotState& R = robots_[i];
  for (int guard = 0; guard < 64; ++guard) {
    if (R.queue.empty() && R.mode == Mode::kTree) nextWaypoints(i);
    if (R.queue.empty() || distance(R.queue.front().cell, R.cell) <= 1) return;
    const std::vector<long> way = shortestWay(i, R.cell, R.queue.front().cell, -1, 0, t);   // off cells obstacles hold now
    if (!way.empty()) {
      goVia(R, way);
      return;
    }
    R.queue.pop_front();
    passOver(i);
  }
  R.queue.clear();   // nothing of it reachable: the tree is left for travel
  R.stack.clear();
  if (R.mode == Mode::kTravel) release(i);
  R.mode = Mode::kIdle;
  R.lastChecked = -1;
}

// A robot stands in the way of `other` (idle, or on the way out of a robot evading an obstacle): it
// goes to the nearest sensed free cell that is not on other's way (its queue) and that no robot
// holds, by a shortest way that does not pass other; a robot with work goes on afterwards. An idle
// robot with no room to make (a dead end behind it) takes over the other's target when it can
// reach it without passing the other.
void Team::clearTheWay(std::size_t i, std::size_t other, long t, bool forEvader) {
  RobotState& R = robots_[i];
  const RobotState& O = robots_[other];
  std::vector<long> onWay{O.cell};
  for (std::size_t m = 0; m < O.queue.size() && m < 64; ++m) onWay.push_back(O.queue[m].cell);
  auto inWay = [&](long v) { return std::find(onWay.begin(), onWay.end(), v) != onWay.end(); };
  // among moving obstacles: over cells within the sensor's reach that no obstacle holds now, to one
  // that stays clear over the horizon
  auto open = [&](long w) { return !moving_ || (distance(w, R.cell) < horizon_ && sensor_.moveClear(i, cellOf(w), cellOf(w), t)); };
  const std::vector<long> way = breadthFirst(
      R.cell, [&](long w) { return w != O.cell && open(w); },
      [&](long v) { return !inWay(v) && blockerOf(i, v) < 0 && (!moving_ || stayClear(i, v, t, horizon_)); }, 0, 4096);
  if (way.empty() && R.mode == Mode::kIdle && R.queue.empty() && O.mode == Mode::kTravel && O.target >= 0) {
    // no room to make (a dead end behind it): it takes over the other's target, which lies that way
    const long target = O.target;
    const std::vector<long> there = breadthFirst(R.cell, [&](long w) { return w != O.cell && open(w); }, [&](long v) { return v == target; }, 0, 4096);
    if (!there.empty()) {
      becomeIdle(other);
      travelTo(i, there);
      return;
    }
  }
  R.parked = false;   // it moves off: where it ends may be a corner
  if (forEvader) {
    // room for a robot an obstacle is coming at: a way of its own (kRoom), replacing the one asked
    // for the step before; robots standing on it are asked in turn (the move loop), so a row of
    // robots in a corridor moves up like a train
    while (!R.queue.empty() && R.queue.front().tag == Tag::kRoom) R.queue.pop_front();
    for (std::size_t h = way.size(); h-- > 0;) R.queue.push_front({way[h], Tag::kRoom});
  } else if (R.queue.empty()) {
    for (long v : way) R.queue.push_back({v, Tag::kAside});
  } else if (R.queue.front().tag != Tag::kAside) {   // a robot with work of its own: aside first, then on (repair leads it back)
    for (std::size_t h = way.size(); h-- > 0;) R.queue.push_front({way[h], Tag::kAside});
  }
}

// To a free neighbour that no robot is in or enters, not `avoid` and not where the blocking robot
// goes next; then back.
bool Team::stepAside(std::size_t i, long avoid, bool comeBack, long t) {
  RobotState& R = robots_[i];
  const int b = avoid >= 0 ? blockerOf(i, avoid) : -1;
  const long theirs = b >= 0 && !robots_[static_cast<std::size_t>(b)].queue.empty() ? robots_[static_cast<std::size_t>(b)].queue.front().cell : -1;
  for (int d = 0; d < 4; ++d) {
    const long w = step(R.cell, d);
    if (w < 0 || !knownFree(w) || w == avoid || w == theirs || !allowed(i, R.cell, w)) continue;
    if (!safeMove(i, R.cell, w, t)) continue;
    if (comeBack) R.queue.push_front({R.cell, !R.queue.empty() && R.queue.front().tag == Tag::kTravel ? Tag::kTravel : Tag::kAside});
    R.queue.push_front({w, Tag::kAside});
    return true;
  }
  return false;
}

// Staying in `cell` over steps t … t + steps - 1 is clear of the moving obstacles.
bool Team::stayClear(std::size_t i, long cell, long t, int steps) {
  for (int j = 0; j < steps; ++j)
    if (!sensor_.moveClear(i, cellOf(cell), cellOf(cell), t + j)) return false;
  return true;
}

// A move the obstacles allow: clear over its step, and the cell it reaches clear to stay in over the
// sensor's horizon (a robot does not step where an obstacle is about to pass).
bool Team::safeMove(std::size_t i, long from, long to, long t) {
  return !moving_ || (sensor_.moveClear(i, cellOf(from), cellOf(to), t) && stayClear(i, to, t + 1, horizon_));
}

// The robot's place is about to be reached by an obstacle. Its way out, found breadth first in space
// and time over sensed free sub-cells, each move clear of the obstacles: to the earliest haven, a
// cell that then stays clear to the end of the sensor's horizon (the robot leaves at once rather
// than at the last moment, which keeps the most ways open); among the havens of the first three
// depths that have one, the one with the most neighbours that are havens too (not a dead end). The way's cells at steps t + 1, t + 2, …
// (a wait repeats a cell); `haven` says whether it ends in one, else it is the way that stays clear
// longest. The first move keeps the step rules for robots, and the way keeps off the cells robots
// hold or enter now, unless `throughRobots`: then those count as free (the way out of a robot boxed
// in by robots, which are asked to make room).
std::vector<long> Team::fleeWay(std::size_t i, long t, bool throughRobots, bool& haven) {
  const long from = robots_[i].cell;
  std::map<std::pair<long, int>, long> parent{{{from, 0}, -1}};
  std::map<long, int> clearFrom;   // cell → the first step (from t) after which it stays clear to the horizon
  auto havenAt = [&](long v, int j) {
    auto it = clearFrom.find(v);
    if (it == clearFrom.end()) {
      int first = horizon_;
      while (first > 0 && sensor_.moveClear(i, cellOf(v), cellOf(v), t + first - 1)) --first;
      it = clearFrom.emplace(v, first).first;
    }
    return j >= it->second;
  };
  auto wayTo = [&](std::pair<long, int> st) {
    std::vector<long> way;
    for (; st.second > 0; st = {parent[st], st.second - 1}) way.push_back(st.first);
    std::reverse(way.begin(), way.end());
    return way;
  };
  std::deque<std::pair<long, int>> open{{from, 0}};
  std::pair<long, int> deepest{from, 0};
  // ways out of a haven: its sensed free neighbours that are havens too (a corner or a dead end
  // has few; an obstacle coming on after the horizon would trap a robot there)
  auto exits = [&](long v, int j) {
    int n = 0;
    for (int d = 0; d < 4; ++d)
      if (const long u = step(v, d); knownFree(u) && (throughRobots || blockerOf(i, u) < 0) && havenAt(u, std::min(j + 1, horizon_))) ++n;
    return n;
  };
  haven = false;
  std::pair<long, int> best{-1, 0};
  int bestExits = -1, firstHaven = -1;
  while (!open.empty()) {
    const auto [v, j] = open.front();
    open.pop_front();
    if (firstHaven >= 0 && j > firstHaven + 2) break;
    if (j > deepest.second) deepest = {v, j};
    if (j > 0 && havenAt(v, j)) {   // the havens of the first three depths that have one: the most exits, then the earliest
      if (firstHaven < 0) firstHaven = j;
      if (const int e = exits(v, j); e > bestExits) {
        bestExits = e;
        best = {v, j};
      }
      if (bestExits == 4) break;
    }
    if (j == horizon_) continue;
    for (int d = -1; d < 4; ++d) {
      const long w = d < 0 ? v : step(v, d);
      if (w < 0 || !knownFree(w) || parent.count({w, j + 1})) continue;
      if (distance(w, from) > horizon_ - 1) continue;
      if (!throughRobots && (j == 0 ? !allowed(i, from, w) : w != from && blockerOf(i, w) >= 0)) continue;
      if (!sensor_.moveClear(i, cellOf(v), cellOf(w), t + j)) continue;
      parent[{w, j + 1}] = v;
      open.push_back({w, j + 1});
    }
  }
  if (best.first >= 0) {
    haven = true;
    return wayTo(best);
  }
  return wayTo(deepest);
}

// The reflex of a robot whose place an obstacle is about to reach: the move it makes now (its own
// cell to wait). It takes the way to the earliest haven and comes back afterwards. Boxed in by
// robots (a haven only through cells they hold), it queues that way, and the first robot on it,
// when idle, makes room off it (clearTheWay). Where no way leads to a haven, the way that stays
// clear longest.
long Team::evade(std::size_t i, long t) {
  RobotState& R = robots_[i];
  while (!R.queue.empty() && R.queue.front().tag == Tag::kEvade) R.queue.pop_front();   // an earlier way out, replaced
  bool haven = false;
  std::vector<long> way = fleeWay(i, t, false, haven);
  auto comeBack = [&]() {   // back to this cell afterwards (once)
    if (R.queue.empty() || R.queue.front().cell != R.cell) R.queue.push_front({R.cell, R.mode == Mode::kTravel ? Tag::kTravel : Tag::kAside});
  };
  if (!haven) {
    bool through = false;
    std::vector<long> out = fleeWay(i, t, true, through);
    int b = -1;
    for (std::size_t h = 0; through && h < out.size() && b < 0; ++h)
      for (std::size_t j = 0; j < robots_.size() && b < 0; ++j)
        if (j != i && robots_[j].cell == out[h]) b = static_cast<int>(j);
    if (b >= 0) {
      RobotState& B = robots_[static_cast<std::size_t>(b)];
      B.makeRoomFor = static_cast<int>(i);   // whatever it does: an obstacle is coming
      out.erase(std::unique(out.begin(), out.end()), out.end());
      if (!out.empty() && out.front() == R.cell) out.erase(out.begin());
      comeBack();
      for (std::size_t h = out.size(); h-- > 0;) R.queue.push_front({out[h], Tag::kEvade});
      return R.cell;
    }
  }
  if (way.empty() || way.front() == R.cell) return R.cell;
  comeBack();
  return way.front();
}

bool Team::act(std::size_t i, KbAction a, long t) {
  switch (a) {
    case KbAction::kWait: return false;
    case KbAction::kDetour: return detour(i, t);
    case KbAction::kGiveWay: return stepAside(i, robots_[i].queue.front().cell, true, t);
    case KbAction::kSkip: return skip(i, t);
  }
  return false;
}

PlanStatus Team::run(const std::vector<CellIndex>& starts, const TerminationCondition& stop, Plan& plan) {
  const std::size_t k = starts.size();
  robots_.assign(k, RobotState{});
  next_.assign(k, -1);
  for (std::size_t i = 0; i < k; ++i) {
    RobotState& R = robots_[i];
    R.weights.clear();
    for (const KbRule& r : kb_.rules) R.weights.push_back(r.weight);
    enter(i, id(starts[i].col, starts[i].row));
  }
  // the roots: robots in index order claim their start mega-cells
  for (std::size_t i = 0; i < k; ++i) {
    RobotState& R = robots_[i];
    startTree(i);
    R.route.push_back(cellOf(R.cell));   // step 1: onto the start sub-cell's centre
  }
  for (const MovingObstacle& m : ctx_.problem.movingObstacles) lastObstacle_ = std::max(lastObstacle_, m.waypoints.back().t);
  const double lastObstacle = lastObstacle_;
  const long maxSteps = 64L * static_cast<long>(known_.size()) + static_cast<long>(lastObstacle / timing_.step) + 10'000;
  long t = 1, lastMove = 1, lastProgress = 1;
  long stoppedAt = -1;   // the first step after the last obstacle stopped: the stall clocks start there at the latest
  std::size_t enteredBefore = enteredTotal_;
  // a team that enters nothing new for this long is going round in circles (it needs at most a
  // crossing of the map to reach the next target)
  const long noProgress = 4L * (cols_ + rows_) + kStallSteps;
  PlanStatus status = PlanStatus::kExactSolution;
  bool stalled = false;   // stopped because nothing moved or nothing new was entered for long
  std::string why;
  for (;; ++t) {
    if ((t & 63) == 0 && stop.expired()) {
      status = PlanStatus::kTimeout;
      why = "stopped by the time limit at step " + std::to_string(t);
      break;
    }
    if (t > maxSteps) {
      status = PlanStatus::kPartialCoverage;
      why = "stopped after " + std::to_string(maxSteps) + " steps";
      break;
    }
    std::fill(next_.begin(), next_.end(), -1);
    const bool stopped = static_cast<double>(t) * timing_.step > lastObstacle;   // every obstacle has stopped (or there is none)
    if (stopped && stoppedAt < 0) stoppedAt = t;
    bool anyWork = false, moved = false;
    for (std::size_t i = 0; i < k; ++i) {
      RobotState& R = robots_[i];
      // what to do next
      if (R.mode == Mode::kTravel && R.target >= 0 && entered_[static_cast<std::size_t>(R.target)] >= 0) becomeIdle(i);   // entered by another
      // once every obstacle has stopped, a target one of them holds is held for good: given up
      if (R.mode == Mode::kTravel && R.target >= 0 && stopped && heldByObstacle(i, R.target, t)) {
        R.gaveUp[R.target] = kGiveUpAfter;
        becomeIdle(i);
      }
      if (R.queue.empty() && R.mode == Mode::kTree) {
        nextWaypoints(i);
        if (R.queue.empty()) {
          R.mode = Mode::kIdle;
          R.lastChecked = -1;
        }
      }
      if (R.queue.empty() && R.mode != Mode::kTree) {
        if (R.mode == Mode::kTravel) release(i);
        R.mode = Mode::kIdle;
        bool due = R.lastChecked != version_;
        for (auto it = R.deferredUntil.begin(); it != R.deferredUntil.end();)   // a deferral that ends: look again
          if (it->second <= t) {
            it = R.deferredUntil.erase(it);
            due = true;
          } else {
            ++it;
          }
        // among moving obstacles what they hold now may open later: look again every few steps
        // while they move (and once after they stop)
        due = due || (R.retryAt >= 0 && t >= R.retryAt);
        if (due) {
          R.lastChecked = version_;
          R.retryAt = -1;
          if (!findTarget(i, t) && moving_ && static_cast<double>(t - 2 * horizon_) * timing_.step <= lastObstacle) R.retryAt = t + horizon_;
        }
      }
      if (R.mode == Mode::kIdle && R.queue.empty() && moving_ && !R.parked && !stopped) park(i, t);
      // (a robot on its own way out keeps to it: making room would pile ways on ways)
      if (R.makeRoomFor >= 0 && (R.queue.empty() || R.queue.front().tag != Tag::kEvade)) clearTheWay(i, static_cast<std::size_t>(R.makeRoomFor), t, true);
      else if (R.mode == Mode::kIdle && R.nudgedBy >= 0 && R.queue.empty()) clearTheWay(i, static_cast<std::size_t>(R.nudgedBy), t, false);
      R.makeRoomFor = -1;
      R.nudgedBy = -1;
      if (!R.queue.empty() || R.mode != Mode::kIdle || R.retryAt >= 0) anyWork = true;
      // the move (a way out no longer needed, its place clear again, is dropped)
      if (!R.queue.empty() && R.queue.front().tag == Tag::kEvade && stayClear(i, R.cell, t, horizon_))
        while (!R.queue.empty() && R.queue.front().tag == Tag::kEvade) R.queue.pop_front();
      // once every obstacle has stopped, a waypoint one of them holds is held for good: passed over
      for (int guard = 0; guard < 64 && moving_ && stopped && !R.queue.empty() &&
                          heldByObstacle(i, R.queue.front().cell, t);
           ++guard) {
        R.queue.pop_front();
        passOver(i);
      }
      repair(i, t);
      long to = R.cell;
      bool onPlan = false;   // a move to a waypoint of the plan itself, not of a way round
      for (int attempt = 0; attempt < 2 && !R.queue.empty(); ++attempt) {
        const long want = R.queue.front().cell;
        if (want == R.cell) {   // already there (a detour that ends where it began)
          R.queue.pop_front();
          continue;
        }
        const bool robotsOk = allowed(i, R.cell, want);
        // a way out was planned in space and time: its moves need only be clear when made
        const bool obstaclesOk = robotsOk && (R.queue.front().tag == Tag::kEvade
                                                  ? sensor_.moveClear(i, cellOf(R.cell), cellOf(want), t) && stayClear(i, want, t + 1, 1)
                                                  : safeMove(i, R.cell, want, t));
        if (robotsOk && obstaclesOk) {
          to = want;
          onPlan = R.queue.front().tag != Tag::kDetour && R.queue.front().tag != Tag::kAside && R.queue.front().tag != Tag::kEvade &&
                   R.queue.front().tag != Tag::kRoom;
          R.queue.pop_front();
          break;
        }
        // an event: the knowledge base decides (kb=off: wait)
        const int blocker = robotsOk ? -1 : blockerOf(i, want);
        const bool urgent = R.queue.front().tag == Tag::kEvade || R.queue.front().tag == Tag::kRoom;
        if (blocker >= 0 && urgent)   // on a way out, or making room for one: the robot in the way makes room too
          robots_[static_cast<std::size_t>(blocker)].makeRoomFor = static_cast<int>(i);
        else if (blocker >= 0 && robots_[static_cast<std::size_t>(blocker)].mode == Mode::kIdle && robots_[static_cast<std::size_t>(blocker)].queue.empty())
          robots_[static_cast<std::size_t>(blocker)].nudgedBy = static_cast<int>(i);
        if (attempt > 0 || !kbOn_ || urgent) break;   // a way out (or room for one) waits for the cell: no rule
        KbSituation s;
        s.event = robotsOk ? KbEvent::kObstacleAhead : KbEvent::kRobotAhead;
        s.blockedSteps = R.blocked;
        s.otherHasPriority = blocker >= 0 && static_cast<std::size_t>(blocker) < i;
        s.travelling = R.mode == Mode::kTravel;
        const int rule = selectRule(kb_, R.weights, s);
        if (rule < 0) break;
        ++rulesFired_;
        ++fired_[kb_.rules[static_cast<std::size_t>(rule)].name];
        if (R.pendingRule < 0) {
          R.pendingRule = rule;
          R.pendingSince = t;
        }
        if (!act(i, kb_.rules[static_cast<std::size_t>(rule)].action, t)) break;
        repair(i, t);
      }
      if (to == R.cell && moving_ && !stayClear(i, R.cell, t, horizon_)) {   // reflex: an obstacle is coming
        const long w = evade(i, t);
        if (w != R.cell) to = w;
      }
      next_[i] = to;
      // progress is a move along the plan: waiting and ways round count as blocked steps, so that a
      // robot going round and round a cell it never reaches comes to the rules that give it up
      if (to != R.cell) moved = true;
      if (onPlan) {
        R.blocked = 0;
        if (R.pendingRule >= 0) {   // the rule fired worked: the robot is on its way again
          double& w = R.weights[static_cast<std::size_t>(R.pendingRule)];
          w += kb_.learningRate * (1 - w);
          R.pendingRule = -1;
        }
      } else if (!R.queue.empty() || to != R.cell) {
        ++R.blocked;
        if (R.pendingRule >= 0 && t - R.pendingSince >= kb_.outcomeSteps) {
          double& w = R.weights[static_cast<std::size_t>(R.pendingRule)];
          w -= kb_.learningRate * w;
          R.pendingRule = -1;
        }
      }
    }
    for (std::size_t i = 0; i < k; ++i) {
      RobotState& R = robots_[i];
      if (next_[i] != R.cell) {
        enter(i, next_[i]);
        if (R.mode == Mode::kTravel && R.cell == R.target) {   // arrived: a new tree where the mega-cell is free and unclaimed
          release(i);
          R.queue.clear();
          startTree(i);
        }
      }
      R.route.push_back(cellOf(R.cell));
    }
    if (moved) lastMove = t;
    if (!anyWork && !moved && stopped) {
      // every robot idle with nothing left that it could reach: done
      // (a target deferred for a while comes back when its deferral ends)
      bool live = false;
      for (const RobotState& R : robots_)
        for (const auto& [cell, until] : R.deferredUntil) {
          const auto g = R.gaveUp.find(cell);
          live = live || ((g == R.gaveUp.end() || g->second < kGiveUpAfter) && entered_[static_cast<std::size_t>(cell)] < 0);
        }
      if (!live) break;
    }
    if (enteredTotal_ != enteredBefore) {
      enteredBefore = enteredTotal_;
      lastProgress = t;
    }
    // (a team that waited for the obstacles gets the same time after they stop as any other)
    if (stopped && t - std::max(lastProgress, stoppedAt) > noProgress) {
      status = PlanStatus::kPartialCoverage;
      stalled = true;
      why = "no robot entered a new sub-cell for " + std::to_string(noProgress) + " steps";
      break;
    }
    if (stopped && t - std::max(lastMove, stoppedAt) > kStallSteps) {
      status = PlanStatus::kPartialCoverage;
      stalled = true;
      why = kbOn_ ? "no robot could move for " + std::to_string(kStallSteps) + " steps"
                  : "deadlock: the robots wait for each other (kb=off waits until a cell clears; kb=on resolves it)";
      break;
    }
  }
  // what was left: sensed free sub-cells joined to the robots over sensed free ones, never entered
  std::size_t sensedFree = 0, enteredCount = 0;
  std::vector<char> seen(known_.size(), 0);
  std::deque<long> open;
  for (const RobotState& R : robots_)
    if (!seen[static_cast<std::size_t>(R.cell)]) {
      seen[static_cast<std::size_t>(R.cell)] = 1;
      open.push_back(R.cell);
    }
  while (!open.empty()) {
    const long v = open.front();
    open.pop_front();
    ++sensedFree;
    for (int d = 0; d < 4; ++d) {
      const long w = step(v, d);
      if (w >= 0 && knownFree(w) && !seen[static_cast<std::size_t>(w)]) {
        seen[static_cast<std::size_t>(w)] = 1;
        open.push_back(w);
      }
    }
  }
  for (std::size_t v = 0; v < known_.size(); ++v) enteredCount += seen[v] && entered_[v] >= 0 ? 1 : 0;
  const std::size_t skipped = sensedFree - enteredCount;
  if (stalled && skipped == 0) {   // stuck, but with nothing left: every sensed free sub-cell was entered, so every reachable one
    status = PlanStatus::kExactSolution;
    why.clear();
  }
  if (status == PlanStatus::kExactSolution && skipped > 0) {
    status = PlanStatus::kPartialCoverage;
    why = "left " + std::to_string(skipped) + " free sub-cells that no robot could reach" + (moving_ ? " past the moving obstacles" : "");
  }
  plan.message = why.empty() ? "the team entered every free sub-cell reachable from its starts (" + std::to_string(enteredCount) + ")" : why;
  plan.statistics["subcells_entered"] = static_cast<double>(enteredCount);
  plan.statistics["subcells_skipped"] = static_cast<double>(skipped);
  plan.statistics["repeated_steps"] = static_cast<double>(repeats_);
  plan.statistics["rules_fired"] = static_cast<double>(rulesFired_);
  plan.statistics["sensor_queries"] = static_cast<double>(sensor_.queries());
  std::size_t mostCells = 0, leastCells = static_cast<std::size_t>(-1), trees = 0;
  for (const RobotState& R : robots_) {
    mostCells = std::max(mostCells, R.cellsEntered);
    leastCells = std::min(leastCells, R.cellsEntered);
  }
  for (int o : owner_) trees += o >= 0 ? 1 : 0;
  plan.statistics["cells_most"] = static_cast<double>(mostCells);
  plan.statistics["cells_least"] = static_cast<double>(k ? leastCells : 0);
  plan.statistics["tree_mega_cells"] = static_cast<double>(trees);
  for (const auto& [name, n] : fired_) plan.statistics["rule." + name] = static_cast<double>(n);
  for (std::size_t i = 0; i < k; ++i) plan.statistics["cells_robot_" + std::to_string(i)] = static_cast<double>(robots_[i].cellsEntered);
  return status;
}

}  // namespace

std::string MultiStPlanner::description() const {
  return "Multi-ST (online, several robots): disjoint spanning trees grown at once on the shared mega-cell grid, each robot walking "
         "round its own; a rule knowledge base (YAML, kb=on|off|FILE) for the robots and moving obstacles met; travel to what the trees "
         "left";
}

std::vector<ParamSpec> MultiStPlanner::params() const {
  return {{"kb", ParamType::kPath, "on", "on|off|FILE",
           "the knowledge base: on (the shipped rules, planners/data/multi_st_kb.yaml), off (the paper's baseline: wait until the cell "
           "clears) or a coverkit.kb/1 file"},
          {"step", ParamType::kDouble, "0.1", "0.001:1000", "seconds per step (one move between neighbouring sub-cells, or a wait)"},
          {"horizon", ParamType::kInt, "30", "2:200",
           "steps (and sub-cells) over which a robot's sensor predicts the moving obstacles: longer sees an obstacle coming sooner, "
           "and costs more per step"}};
}

Capabilities MultiStPlanner::capabilities() const {
  Capabilities c;
  c.online = true;
  c.multiRobot = true;
  c.coverage = "free_sub_cells";
  return c;
}

Plan MultiStPlanner::plan(const PlanningContext& ctx, const ParamSet& params, const TerminationCondition& stop) {
  return planWith(ctx, params, stop, nullptr);
}

Plan MultiStPlanner::planWith(const PlanningContext& ctx, const ParamSet& params, const TerminationCondition& stop, TeamSensor* given) {
  const auto t0 = std::chrono::steady_clock::now();
  Plan plan;
  const Problem& problem = ctx.problem;
  const std::size_t k = problem.robots.size();
  checkTeamGrid(ctx, "multi_st");
  const std::string kbSpec = params.text("kb");
  const int horizon = static_cast<int>(params.integer("horizon"));
  const bool kbOn = kbSpec != "off";
  const KnowledgeBase kb = kbOn ? loadKnowledgeBase(kbSpec) : KnowledgeBase{};
  const StepTiming timing = makeStepTiming(ctx, params.number("step"));
  const CellGrid& cells = ctx.cells;
  if (cells.subSize() < 2 * problem.robots[0].radius)
    throw InputError("--cell-size", formatDouble(cells.subSizeD()),
                     "must be at least 2r = " + formatDouble(Rational(2 * problem.robots[0].radius).get_d()) + " for multi_st (the disc must fit in its sub-cell)");
  if (!everyRobotHasAStart(problem, plan)) return plan;
  std::vector<CellIndex> starts(k);
  for (std::size_t i = 0; i < k; ++i) {
    if (!cells.locateSub(*problem.robots[i].start, starts[i]) || cells.sub(starts[i].col, starts[i].row) != CellState::kFree) {
      plan.status = PlanStatus::kInvalidStart;
      plan.message = "robot " + std::to_string(i) + "'s start is not in a free sub-cell";
      stayAtStarts(problem, plan);
      return plan;
    }
    for (std::size_t j = 0; j < i; ++j)
      if (starts[j] == starts[i]) {
        plan.status = PlanStatus::kInvalidStart;
        plan.message = "robots " + std::to_string(j) + " and " + std::to_string(i) + " start in the same sub-cell";
        stayAtStarts(problem, plan);
        return plan;
      }
  }
  // the first step (from the start onto its sub-cell's centre) must be clear of the moving obstacles
  for (std::size_t i = 0; i < k; ++i) {
    const PointD s{toDouble(problem.robots[i].start->x), toDouble(problem.robots[i].start->y)};
    if (!timing.clear(i, s, timing.centre(starts[i]), 0, timing.step)) {
      plan.status = PlanStatus::kInvalidStart;
      plan.message = "robot " + std::to_string(i) + "'s first step, onto its sub-cell's centre, is not clear of the moving obstacles";
      stayAtStarts(problem, plan);
      return plan;
    }
  }
  // the step from t to t + 1 (step t of the route: route index t - 1 → t)
  auto moveClear = [&timing](std::size_t robot, CellIndex from, CellIndex to, long t) {
    return timing.clear(robot, timing.centre(from), timing.centre(to), static_cast<double>(t) * timing.step, static_cast<double>(t + 1) * timing.step);
  };
  // One robot in a static world on a grid whose sub-cell centres are not doubles: the walk is placed
  // as the other sub-cell planners place theirs (walk_path.h: each run its own safe double, a path
  // without a timeline, sub-cells no double path can cross left out and the team run again).
  if (k == 1 && problem.movingObstacles.empty() && !given && !centresAreDoubles(cells)) {
    const bool unsafe = withoutUnplaceableCells(ctx, starts[0], plan, [&](const PlanningContext& c) -> std::vector<CellIndex> {
      TeamSensor sensor(c.cells, starts, moveClear, horizon);
      Team team(c, timing, kb, kbOn, sensor);
      plan.statistics.clear();
      plan.status = team.run(starts, stop, plan);
      std::vector<CellIndex> walk{starts[0]};
      for (const CellIndex& v : team.robots()[0].route)
        if (!(v == walk.back())) walk.push_back(v);
      PlacedWalk placed = placeWalk(c, walk, *problem.robots[0].start, false);
      if (!placed.startClear) {
        plan.status = PlanStatus::kInvalidStart;
        plan.message = "no double start point near the start is clear, or the disc cannot move straight from the start to its sub-cell's centre";
        return {};
      }
      plan.paths.assign(1, std::move(placed.path));
      plan.statistics["robots"] = 1;
      plan.statistics["moves_total"] = static_cast<double>(walk.size() - 1);
      plan.statistics["moves_unsafe"] = static_cast<double>(placed.unsafeMoves);
      return placed.unsafeCells;
    });
    if (unsafe && plan.status != PlanStatus::kInvalidStart) {
      plan.status = PlanStatus::kPartialCoverage;
      plan.message = formatDouble(plan.statistics["moves_unsafe"]) + " moves have no exactly safe double coordinates";
    }
  } else {
    // A robot caught by a moving obstacle (a step of its route not clear of it, or its last cell
    // not clear for good): the team runs again with the sensor's horizon doubled, then four and
    // eight times, and the first run nobody is caught in is the plan (else the one with the fewest
    // such steps, the first among equals); `horizon_used` and `horizon_runs` say which. Only the
    // robots' own sensor is replaced: a sensor given by the caller (tests) is run once.
    const std::vector<int> ladder = given || problem.movingObstacles.empty() ? std::vector<int>{horizon}
                                                                            : std::vector<int>{horizon, 2 * horizon, 4 * horizon, 8 * horizon};
    auto caughtSteps = [&](const std::vector<std::vector<CellIndex>>& route) {
      std::size_t n = 0;
      for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t m = 1; m < route[i].size(); ++m) n += moveClear(i, route[i][m - 1], route[i][m], static_cast<long>(m)) ? 0 : 1;
        if (!route[i].empty()) {
          const PointD last = timing.centre(route[i].back());
          n += timing.clear(i, last, last, static_cast<double>(route[i].size()) * timing.step, HUGE_VAL) ? 0 : 1;
        }
      }
      return n;
    };
    Plan best;
    std::vector<std::vector<CellIndex>> bestRoute;
    std::size_t bestCaught = 0, runs = 0;
    int used = horizon;
    for (const int h : ladder) {
      ++runs;
      Plan attempt;
      std::unique_ptr<TeamSensor> own;
      if (!given) own = std::make_unique<TeamSensor>(cells, starts, moveClear, h);
      TeamSensor& sensor = given ? *given : *own;
      Team team(ctx, timing, kb, kbOn, sensor);
      attempt.status = team.run(starts, stop, attempt);
      std::vector<std::vector<CellIndex>> route(k);
      for (std::size_t i = 0; i < k; ++i) route[i] = team.robots()[i].route;
      const std::size_t caught = problem.movingObstacles.empty() ? 0 : caughtSteps(route);
      if (runs == 1 || caught < bestCaught) {
        best = std::move(attempt);
        bestRoute = std::move(route);
        bestCaught = caught;
        used = h;
      }
      if (bestCaught == 0 || stop.expired()) break;
    }
    plan = std::move(best);
    writeTimedPaths(problem, timing, bestRoute, plan);
    if (!problem.movingObstacles.empty()) {
      plan.statistics["horizon_used"] = used;
      plan.statistics["horizon_runs"] = static_cast<double>(runs);
      plan.statistics["steps_caught"] = static_cast<double>(bestCaught);
      if (bestCaught > 0)
        plan.message = "robots caught by moving obstacles in " + std::to_string(bestCaught) + " steps with every horizon tried (" +
                       std::to_string(ladder.front()) + "-" + std::to_string(ladder.back()) + " steps)" + (plan.message.empty() ? "" : "; " + plan.message);
    }
  }
  if (plan.message.empty()) plan.message = "covered";
  plan.timings.emplace_back("team", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return plan;
}

}  // namespace coverkit::planners
