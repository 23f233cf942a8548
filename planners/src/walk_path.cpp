// See walk_path.h.
#include "walk_path.h"

#include <coverkit/geometry/error.h>
#include <coverkit/geometry/validate.h>
#include <coverkit/graph/grid_graph.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace coverkit::planners {

namespace {

/// The candidate doubles of one centre coordinate: the preferred one first.
struct Candidates {
  double v[2] = {0, 0};
  int side[2] = {0, 0};  ///< sign of v − centre: which neighbour the disc leans into
  int n = 1;
};

Candidates candidates(const Rational& centre, const Rational& toward) {
  Candidates c;
  c.v[0] = roundToward(centre, toward);
  if (exactFromDouble(c.v[0]) == centre) return c;
  c.side[0] = exactFromDouble(c.v[0]) < centre ? -1 : 1;
  c.v[1] = std::nextafter(c.v[0], c.side[0] < 0 ? HUGE_VAL : -HUGE_VAL);
  c.side[1] = -c.side[0];
  c.n = 2;
  return c;
}

struct Var {
  bool isX = false;
  int index = 0;   ///< column (isX) or row
  int pick = 0;
  int firstPoint = -1, lastPoint = -1;
};

struct Pt {
  int xv = -1, yv = -1;  ///< variables; -1 on both: the start point
  CellIndex cell;
};

bool horizontal(int dir) { return dir == 0 || dir == 2; }

/// The path of a walk whose every cell lies in a free mega-cell, each 4-adjacent to the next
/// (repeats aside), when the preferred doubles increase strictly along the columns and rows and the
/// start point is the first waypoint (and, back to the start, the last): false, `path` untouched,
/// for any other walk.
///
/// Such a walk is STC's and Spiral-STC's (and Smooth-STC's tour of the free mega-cells), and the
/// general construction in placeWalk gives it this
/// very path: every rounded centre leans towards its mega-cell's centre, into the free cells of
/// that mega-cell, so every variable keeps its preferred double and no move is tested or refused;
/// the moves to and from the start point have zero length. The path is then the polyline through
/// the rounded centres with a vertex where the direction changes (strictly increasing coordinates:
/// no zero-length moves, and the merge of collinear moves does not depend on where runs were cut).
/// Built in two passes over the walk (check and count the segments, then write them into a vector
/// of that size) without the variables, points and exact-test bookkeeping, which at 10^7 sub-cells
/// took most of STC's time.
bool placeInFreeMegaCells(const CellGrid& cells, const std::vector<CellIndex>& walk, const std::vector<Candidates>& colC,
                          const std::vector<Candidates>& rowC, PointD s0, bool backToStart, Path& path) {
  if (walk.empty()) return false;
  // they do unless D is about a unit in the last place of the coordinates; then the general
  // construction decides
  for (const auto* cs : {&colC, &rowC})
    for (std::size_t i = 1; i < cs->size(); ++i)
      if (!((*cs)[i - 1].v[0] < (*cs)[i].v[0])) return false;
  // the four states or-ed (free is 0): one branch, not four
  static_assert(static_cast<int>(CellState::kFree) == 0, "free cells are 0");
  auto freeQuad = [&](int c0, int r0) {
    return (static_cast<int>(cells.sub(c0, r0)) | static_cast<int>(cells.sub(c0 + 1, r0)) | static_cast<int>(cells.sub(c0, r0 + 1)) |
            static_cast<int>(cells.sub(c0 + 1, r0 + 1))) == 0;
  };
  auto at = [&](CellIndex c) { return PointD{colC[static_cast<std::size_t>(c.col)].v[0], rowC[static_cast<std::size_t>(c.row)].v[0]}; };
  auto isStart = [&](PointD p) { return p.x == s0.x && p.y == s0.y; };
  const CellIndex first = walk.front();
  if (!cells.insideSub(first.col, first.row) || !freeQuad(first.col & ~1, first.row & ~1) || !isStart(at(first))) return false;
  // A walk with at least one cell per mega-cell gets the free mega-cells as bits first: a move's
  // look-up then stays within a few hundred kB, where its four states lie in two rows of the whole
  // sub-cell grid (3162 bytes apart at 10^7 sub-cells), whose cache misses made this pass take
  // 40 ms instead of 22. A shorter walk (Smooth-STC's pockets) checks its cells directly.
  const std::size_t mcols = static_cast<std::size_t>(cells.megaCols());
  std::vector<std::uint64_t> freeBits;
  if (walk.size() >= cells.megaCount()) {
    freeBits.assign((cells.megaCount() + 63) / 64, 0);
    for (int r = 0; r < cells.megaRows(); ++r)
      for (int c = 0; c < cells.megaCols(); ++c) {
        const std::size_t m = static_cast<std::size_t>(r) * mcols + static_cast<std::size_t>(c);
        freeBits[m >> 6] |= static_cast<std::uint64_t>(freeQuad(2 * c, 2 * r)) << (m & 63);
      }
  }
  auto freeMega = [&](CellIndex c) {
    if (!cells.insideSub(c.col, c.row)) return false;
    if (freeBits.empty()) return freeQuad(c.col & ~1, c.row & ~1);
    const std::size_t m = static_cast<std::size_t>(c.row >> 1) * mcols + static_cast<std::size_t>(c.col >> 1);
    return (freeBits[m >> 6] >> (m & 63) & 1) != 0;
  };
  // (dc + 1)·3 + dr + 1 → direction as graph::Dir, 4 for a repeat, -1 for a diagonal
  static constexpr int kDirOf[9] = {-1, graph::kWest, -1, graph::kSouth, 4, graph::kNorth, -1, graph::kEast, -1};
  auto dirOf = [&](std::size_t i) {
    const int dc = walk[i].col - walk[i - 1].col, dr = walk[i].row - walk[i - 1].row;
    return dc < -1 || dc > 1 || dr < -1 || dr > 1 ? -1 : kDirOf[(dc + 1) * 3 + dr + 1];
  };
  std::size_t segments = 0;
  int dir = -1;
  for (std::size_t i = 1; i < walk.size(); ++i) {
    const int d = dirOf(i);
    if (d < 0) return false;
    if (d == 4) continue;
    if (!freeMega(walk[i])) return false;
    segments += d != dir;
    dir = d;
  }
  if (backToStart && !isStart(at(walk.back()))) return false;
  path.start = s0;
  path.segments.clear();
  path.segments.reserve(segments);
  PointD a = s0;
  dir = -1;
  for (std::size_t i = 1; i < walk.size(); ++i) {
    const int d = dirOf(i);
    if (d == 4) continue;
    const PointD b = at(walk[i]);
    if (d == dir) path.segments.back().to = b;
    else path.segments.push_back(PathSegment::line(a, b));
    a = b;
    dir = d;
  }
  return true;
}

}  // namespace

PlacedWalk placeWalk(const PlanningContext& ctx, const std::vector<CellIndex>& rawWalk, const Point& start, bool backToStart, bool direct) {
  const CellGrid& cells = ctx.cells;
  std::vector<Candidates> colC(static_cast<std::size_t>(cells.subCols())), rowC(static_cast<std::size_t>(cells.subRows()));
  for (int c = 0; c < cells.subCols(); ++c)
    colC[static_cast<std::size_t>(c)] = candidates(cells.subCenter(c, 0).x, cells.megaCenter(c / 2, 0).x);
  for (int r = 0; r < cells.subRows(); ++r)
    rowC[static_cast<std::size_t>(r)] = candidates(cells.subCenter(0, r).y, cells.megaCenter(0, r / 2).y);
  if (direct) {
    PlacedWalk out;
    if (placeInFreeMegaCells(cells, rawWalk, colC, rowC, {toDouble(start.x), toDouble(start.y)}, backToStart, out.path)) return out;
  }

  // consecutive repeats dropped (a copy only when there are any)
  bool repeats = false;
  for (std::size_t i = 1; i < rawWalk.size() && !repeats; ++i) repeats = rawWalk[i] == rawWalk[i - 1];
  std::vector<CellIndex> deduplicated;
  if (repeats)
    for (CellIndex c : rawWalk)
      if (deduplicated.empty() || !(deduplicated.back() == c)) deduplicated.push_back(c);
  const std::vector<CellIndex>& walk = repeats ? deduplicated : rawWalk;

  // variables and points
  std::vector<Var> vars;
  std::vector<Pt> pts;
  // Room for a point (and a variable) per cell: Full-STC's walks need about 0.4, a walk with more
  // (reversals, straight runs cut next to obstacles) grows once. From empty the arrays were copied
  // some twenty times at 10^7 sub-cells, each copy into freshly mapped pages.
  vars.reserve(walk.size() + 2);
  pts.reserve(walk.size() + 2);
  std::vector<std::pair<int, int>> parallel;  // fixed coordinates on both sides of a straight-on or reversal point
  auto var = [&](bool isX, int index) {
    vars.push_back(Var{isX, index, 0, -1, -1});
    return static_cast<int>(vars.size()) - 1;
  };
  auto point = [&](int xv, int yv, CellIndex cell) {
    const int p = static_cast<int>(pts.size());
    pts.push_back(Pt{xv, yv, cell});
    for (int v : {xv, yv}) {
      if (v < 0) continue;
      Var& w = vars[static_cast<std::size_t>(v)];
      if (w.firstPoint < 0) w.firstPoint = p;
      w.lastPoint = p;
    }
  };
  auto along = [&](int dir, CellIndex c) { return horizontal(dir) ? var(true, c.col) : var(false, c.row); };
  auto at = [&](int dir, int fixed, int alongVar, CellIndex c) {  // a point on a run: its fixed and its along coordinate
    if (horizontal(dir)) point(alongVar, fixed, c);
    else point(fixed, alongVar, c);
  };
  point(-1, -1, walk.front());
  if (walk.size() == 1) {
    point(var(true, walk[0].col), var(false, walk[0].row), walk[0]);
  } else {
    // directions 0-3 as graph::Dir; 4-7 the diagonals NE, NW, SW, SE
    static constexpr int kDiagX[4] = {1, -1, -1, 1}, kDiagY[4] = {1, 1, -1, -1};
    std::vector<int> dirs(walk.size() - 1);
    for (std::size_t k = 0; k + 1 < walk.size(); ++k) {
      const int dc = walk[k + 1].col - walk[k].col, dr = walk[k + 1].row - walk[k].row;
      int d = -1;
      for (int e = 0; e < 4; ++e) {
        if (graph::kDx[e] == dc && graph::kDy[e] == dr) d = e;
        if (kDiagX[e] == dc && kDiagY[e] == dr) d = 4 + e;
      }
      if (d < 0) throw std::logic_error("placeWalk: consecutive sub-cells are not adjacent");
      dirs[k] = d;
    }
    auto fixedVar = [&](int dir, CellIndex c) { return horizontal(dir) ? var(false, c.row) : var(true, c.col); };
    // Near a cell that is not free a straight run is cut at every sub-cell, so that each move
    // there can take its own side (a jog of one ulp joins two pieces); in the open it stays whole.
    auto nearObstacle = [&](CellIndex c) {
      for (int r = c.row - 1; r <= c.row + 1; ++r)
        for (int q = c.col - 1; q <= c.col + 1; ++q)
          if (!cells.insideSub(q, r) || cells.sub(q, r) != CellState::kFree) return true;
      return false;
    };
    // A diagonal move is a piece of its own between two points with coordinates of their own.
    int runDir = -1, fixed = -1;  // the axis run under way (runDir < 0: the last piece was diagonal)
    int px = -1, py = -1;         // after a diagonal: the variables of its end point
    auto cornerPoint = [&](CellIndex c) {
      px = var(true, c.col);
      py = var(false, c.row);
      point(px, py, c);
    };
    if (dirs[0] >= 4) {
      cornerPoint(walk[0]);
    } else {
      runDir = dirs[0];
      fixed = fixedVar(runDir, walk[0]);
      at(runDir, fixed, along(runDir, walk[0]), walk[0]);
    }
    for (std::size_t k = 1; k < dirs.size(); ++k) {
      const CellIndex t = walk[k];
      if (runDir < 0) {  // the end of a diagonal
        cornerPoint(t);
        if (dirs[k] < 4) {
          runDir = dirs[k];
          fixed = horizontal(runDir) ? py : px;
        }
        continue;
      }
      if (dirs[k] >= 4) {  // a run ends where a diagonal begins
        const int g = along(runDir, t);
        at(runDir, fixed, g, t);
        runDir = -1;
        continue;
      }
      if (dirs[k] == runDir && !nearObstacle(t)) continue;
      const int nextFixed = fixedVar(dirs[k], t);
      if (horizontal(dirs[k]) != horizontal(runDir)) {  // a turn: the corner takes both fixed coordinates
        at(runDir, fixed, nextFixed, t);
      } else {  // straight on or a reversal: a coordinate of its own along the axis
        const int g = along(runDir, t);
        at(runDir, fixed, g, t);
        at(dirs[k], nextFixed, g, t);
        parallel.emplace_back(fixed, nextFixed);
      }
      runDir = dirs[k];
      fixed = nextFixed;
    }
    if (runDir < 0) cornerPoint(walk.back());
    else at(runDir, fixed, along(runDir, walk.back()), walk.back());
  }
  if (backToStart) point(-1, -1, walk.back());

  PlacedWalk out;
  // The start point as doubles: the nearest, or a neighbouring double (one ulp, well within the
  // validator's start tolerance) when the nearest puts the disc into an obstacle that touches the
  // exact start's disc; chosen below by the exact test of the move to the first waypoint.
  PointD s0{toDouble(start.x), toDouble(start.y)};
  auto value = [&](int v) {
    const Var& w = vars[static_cast<std::size_t>(v)];
    return (w.isX ? colC : rowC)[static_cast<std::size_t>(w.index)].v[w.pick];
  };
  auto coord = [&](const Pt& p) { return p.xv < 0 ? s0 : PointD{value(p.xv), value(p.yv)}; };

  // moves that need an exact check: next to a cell that is not free, or from/to the start point
  const std::size_t nSeg = pts.size() - 1;
  std::vector<std::uint8_t> need(nSeg, 0);
  for (std::size_t k = 0; k < nSeg; ++k) {
    const Pt &a = pts[k], &b = pts[k + 1];
    if (a.xv < 0 || b.xv < 0) {
      need[k] = 1;
      continue;
    }
    const int c0 = std::min(a.cell.col, b.cell.col) - 1, c1 = std::max(a.cell.col, b.cell.col) + 1;
    const int r0 = std::min(a.cell.row, b.cell.row) - 1, r1 = std::max(a.cell.row, b.cell.row) + 1;
    bool allFree = true;
    for (int r = r0; r <= r1 && allFree; ++r)
      for (int c = c0; c <= c1 && allFree; ++c) allFree = cells.insideSub(c, r) && cells.sub(c, r) == CellState::kFree;
    need[k] = !allFree;
  }
  auto nonFree = [&](int c, int r) { return !cells.insideSub(c, r) || cells.sub(c, r) != CellState::kFree; };
  auto cand = [&](int v) -> const Candidates& {
    const Var& w = vars[static_cast<std::size_t>(v)];
    return (w.isX ? colC : rowC)[static_cast<std::size_t>(w.index)];
  };
  auto side = [&](int v) { return cand(v).side[vars[static_cast<std::size_t>(v)].pick]; };
  // The cells a disc leaning to `dir` (−1 or +1) of variable v's line would enter, all free?
  auto leanFree = [&](int v, int dir) {
    const Var& w = vars[static_cast<std::size_t>(v)];
    const CellIndex a = pts[static_cast<std::size_t>(w.firstPoint)].cell, b = pts[static_cast<std::size_t>(w.lastPoint)].cell;
    if (w.isX) {
      for (int r = std::min(a.row, b.row); r <= std::max(a.row, b.row); ++r)
        if (nonFree(w.index + dir, r)) return false;
    } else {
      for (int c = std::min(a.col, b.col); c <= std::max(a.col, b.col); ++c)
        if (nonFree(c, w.index + dir)) return false;
    }
    return true;
  };
  // First choice by the cells alone: the preferred side unless it leans into a cell that is not
  // free and the other side does not.
  for (int v = 0; v < static_cast<int>(vars.size()); ++v) {
    const Candidates& c = cand(v);
    if (c.n > 1 && !leanFree(v, c.side[0]) && leanFree(v, c.side[1])) vars[static_cast<std::size_t>(v)].pick = 1;
  }
  // A move is safe without an exact test when its disc leans only into free cells (it then stays
  // in the union of free closed cells), and certainly unsafe when it leans into a blocked cell (no
  // point of W's interior there: the disc would cross W's boundary). Only partial cells, and the
  // moves from and to the start point, need ClearanceChecker.
  enum Lean { kIntoFree, kIntoPartial, kIntoBlocked };
  auto lean = [&](const Pt& a, const Pt& b) {
    const int c0 = std::min(a.cell.col, b.cell.col), c1 = std::max(a.cell.col, b.cell.col);
    const int r0 = std::min(a.cell.row, b.cell.row), r1 = std::max(a.cell.row, b.cell.row);
    Lean worst = kIntoFree;
    auto into = [&](int c, int r) {
      const Lean l = !cells.insideSub(c, r) || cells.sub(c, r) == CellState::kBlocked ? kIntoBlocked
                     : cells.sub(c, r) == CellState::kPartial                          ? kIntoPartial
                                                                                       : kIntoFree;
      worst = std::max(worst, l);
    };
    for (int r = r0; r <= r1; ++r)  // the cells the move spans (a diagonal's side cells too)
      for (int c = c0; c <= c1; ++c)
        if (nonFree(c, r)) return kIntoBlocked;  // not a move between free cells: never taken as safe
    for (const Pt* p : {&a, &b}) {
      const int sx = side(p->xv), sy = side(p->yv);
      if ((sx > 0 && p->cell.col == c1) || (sx < 0 && p->cell.col == c0))
        for (int r = r0; r <= r1; ++r) into(p->cell.col + sx, r);
      if ((sy > 0 && p->cell.row == r1) || (sy < 0 && p->cell.row == r0))
        for (int c = c0; c <= c1; ++c) into(c, p->cell.row + sy);
    }
    return worst;
  };
  std::unique_ptr<ClearanceChecker> checker;  // built at the first exact test (its edge index costs)
  auto clear = [&](std::size_t k) {
    if (!need[k]) return true;
    const PointD a = coord(pts[k]), b = coord(pts[k + 1]);
    const bool fromStart = pts[k].xv < 0, toStart = pts[k + 1].xv < 0;
    if (!fromStart && !toStart) {
      const Lean l = lean(pts[k], pts[k + 1]);
      if (l == kIntoFree) return true;
      if (l == kIntoBlocked) return false;
    } else if (a.x == b.x && a.y == b.y) {  // the start point where it coincides with its waypoint (the default start does)
      const Pt& w = pts[fromStart ? k + 1 : k];
      const Lean l = lean(w, w);
      if (l == kIntoFree) return true;
      if (l == kIntoBlocked) return false;
    }
    ++out.checkedMoves;
    if (!checker) checker = std::make_unique<ClearanceChecker>(ctx.problem.workspace, ctx.problem.robots.at(0).radius);
    return checker->clear(Point{exactFromDouble(a.x), exactFromDouble(a.y)}, Point{exactFromDouble(b.x), exactFromDouble(b.y)});
  };
  std::vector<std::size_t> failing;
  for (std::size_t k = 0; k < nSeg; ++k)
    if (!clear(k)) failing.push_back(k);
  for (std::size_t k : failing) {
    if (clear(k)) continue;  // mended by an earlier repair
    std::vector<int> vs;
    for (const Pt* p : {&pts[k], &pts[k + 1]})
      for (int v : {p->xv, p->yv}) {
        if (v < 0 || std::find(vs.begin(), vs.end(), v) != vs.end()) continue;
        const Var& w = vars[static_cast<std::size_t>(v)];
        if ((w.isX ? colC : rowC)[static_cast<std::size_t>(w.index)].n > 1) vs.push_back(v);
      }
    std::vector<int> orig;
    for (int v : vs) orig.push_back(vars[static_cast<std::size_t>(v)].pick);
    // the checked moves that share a variable, and which of them are clear now: a combination must
    // clear move k and keep those clear (moves failing for other reasons get their own turn)
    std::vector<std::size_t> affected;
    for (int v : vs) {
      const Var& w = vars[static_cast<std::size_t>(v)];
      for (std::size_t j = static_cast<std::size_t>(std::max(0, w.firstPoint - 1)); j <= std::min(nSeg - 1, static_cast<std::size_t>(w.lastPoint)); ++j)
        if (j != k && std::find(affected.begin(), affected.end(), j) == affected.end()) affected.push_back(j);
    }
    std::vector<char> wasClear;
    for (std::size_t j : affected) wasClear.push_back(clear(j));
    bool mended = false;
    for (unsigned mask = 1; mask < (1u << vs.size()) && !mended; ++mask) {
      for (std::size_t i = 0; i < vs.size(); ++i) vars[static_cast<std::size_t>(vs[i])].pick = orig[i] ^ static_cast<int>(mask >> i & 1);
      mended = clear(k);
      for (std::size_t i = 0; i < affected.size() && mended; ++i) mended = !wasClear[i] || clear(affected[i]);
    }
    if (mended) {
      ++out.repairedMoves;
    } else {
      for (std::size_t i = 0; i < vs.size(); ++i) vars[static_cast<std::size_t>(vs[i])].pick = orig[i];
    }
  }
  // One-ulp jogs where two pieces of a line took different sides: align them where every checked
  // move stays clear (fewer pieces and no spurious turns).
  for (auto [u, v] : parallel) {
    Var &a = vars[static_cast<std::size_t>(u)], &b = vars[static_cast<std::size_t>(v)];
    if (a.isX != b.isX || a.index != b.index || a.pick == b.pick) continue;
    for (Var* w : {&b, &a}) {
      const int old = w->pick;
      w->pick = (w == &b) ? a.pick : b.pick;
      bool ok = true;
      const std::size_t lo = static_cast<std::size_t>(std::max(0, w->firstPoint - 1));
      const std::size_t hi = std::min(nSeg - 1, static_cast<std::size_t>(w->lastPoint));
      for (std::size_t j = lo; j <= hi && ok; ++j) ok = clear(j);
      if (ok) break;
      w->pick = old;
    }
  }
  // a side of cell (c, r) in direction (dc, dr) is closed when one of the three cells along it is
  // not free (a corner counts: the disc passes a corner only at the exact centre line too)
  auto closedSide = [&](int c, int r, int dc, int dr) {
    for (int k = -1; k <= 1; ++k)
      if (nonFree(c + dc + k * dr, r + dr + k * dc)) return true;
    return false;
  };
  for (std::size_t k : failing) {
    if (clear(k)) continue;
    if (k == 0) {  // try the start's neighbouring doubles before giving up
      const PointD nearest = s0;
      bool found = false;
      for (int dx = -1; dx <= 1 && !found; ++dx)
        for (int dy = -1; dy <= 1 && !found; ++dy) {
          if (dx == 0 && dy == 0) continue;
          s0 = {dx == 0 ? nearest.x : std::nextafter(nearest.x, dx * HUGE_VAL), dy == 0 ? nearest.y : std::nextafter(nearest.y, dy * HUGE_VAL)};
          found = clear(0) && (pts.back().xv >= 0 || clear(nSeg - 1));
        }
      if (found) {
        ++out.repairedMoves;
        continue;
      }
      s0 = nearest;
      out.startClear = false;
      continue;
    }
    ++out.unsafeMoves;
    const CellIndex a = pts[k].cell, b = pts[k + 1].cell;
    const std::size_t before = out.unsafeCells.size();
    for (int c = std::min(a.col, b.col); c <= std::max(a.col, b.col); ++c)
      for (int r = std::min(a.row, b.row); r <= std::max(a.row, b.row); ++r) {
        const bool squeezed = (rowC[static_cast<std::size_t>(r)].n > 1 && closedSide(c, r, 0, 1) && closedSide(c, r, 0, -1)) ||
                              (colC[static_cast<std::size_t>(c)].n > 1 && closedSide(c, r, 1, 0) && closedSide(c, r, -1, 0));
        if (squeezed) out.unsafeCells.push_back({c, r});
      }
    if (out.unsafeCells.size() == before) {
      out.unsafeCells.push_back(a);
      out.unsafeCells.push_back(b);
    }
  }

  // the path: zero-length moves dropped, collinear moves in the same direction merged
  Path& path = out.path;
  path.start = s0;
  path.segments.reserve(pts.size() - 1);  // at most a move per pair of points: no copies as it grows
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const PointD a = path.segments.empty() ? s0 : path.segments.back().to, b = coord(pts[i]);
    if (a.x == b.x && a.y == b.y) continue;
    if (!path.segments.empty()) {
      PathSegment& last = path.segments.back();
      const bool sameX = last.from.x == last.to.x && last.to.x == b.x && a.x == b.x && ((last.to.y - last.from.y > 0) == (b.y - last.to.y > 0));
      const bool sameY = last.from.y == last.to.y && last.to.y == b.y && a.y == b.y && ((last.to.x - last.from.x > 0) == (b.x - last.to.x > 0));
      if (sameX || sameY) {
        last.to = b;
        continue;
      }
    }
    path.segments.push_back(PathSegment::line(a, b));
  }
  return out;
}

bool beginOnCells(const PlanningContext& ctx, const std::string& planner, bool needFreeCell, Plan& plan, Point& start, CellIndex& startCell) {
  const Robot& robot = ctx.problem.robots.at(0);
  if (ctx.cells.subSize() < 2 * robot.radius)
    throw InputError("--cell-size", formatDouble(ctx.cells.subSizeD()),
                     "must be at least 2r = " + formatDouble(Rational(2 * robot.radius).get_d()) + " for " + planner +
                         " (the disc must fit in its sub-cell)");
  plan.paths.emplace_back();
  if (!robot.start) {
    plan.status = PlanStatus::kNoFreeSpace;
    plan.message = "no free sub-cell for a default start";
    return false;
  }
  start = *robot.start;
  plan.paths[0].start = {toDouble(start.x), toDouble(start.y)};
  const bool located = ctx.cells.locateSub(start, startCell);
  if (!located || (needFreeCell && ctx.cells.sub(startCell.col, startCell.row) != CellState::kFree)) {
    plan.status = PlanStatus::kInvalidStart;
    plan.message = "the start is not in a free sub-cell";
    return false;
  }
  return true;
}

bool withoutUnplaceableCells(const PlanningContext& ctx, CellIndex keep, Plan& plan,
                             const std::function<std::vector<CellIndex>(const PlanningContext&)>& attempt) {
  PlanningContext reduced;
  const PlanningContext* use = &ctx;
  std::size_t leftOut = 0;
  for (int k = 0;; ++k) {
    const std::vector<CellIndex> unsafe = attempt(*use);
    if (unsafe.empty() || k == 8) {
      plan.statistics["subcells_left_out"] = static_cast<double>(leftOut);
      plan.statistics["attempts"] = k + 1;
      return !unsafe.empty();
    }
    if (use == &ctx) reduced = ctx;
    for (CellIndex c : unsafe)
      if (reduced.cells.sub(c.col, c.row) == CellState::kFree && !(c == keep)) {
        ++leftOut;
        // partial, not blocked: the planners leave it alone, while the geometry there stays free
        // (a move leaning into it is still tested exactly, never refused as into an obstacle)
        reduced.cells.setSub(c.col, c.row, CellState::kPartial);
      }
    use = &reduced;
  }
}

}  // namespace coverkit::planners
