// See walk_path.h.
#include "walk_path.h"

#include <coverkit/geometry/validate.h>
#include <coverkit/graph/grid_graph.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace coverkit::planners {

namespace {

/// The candidate doubles of one centre coordinate: the preferred one first.
struct Candidates {
  double v[2] = {0, 0};
  int n = 1;
};

Candidates candidates(const Rational& centre, const Rational& toward) {
  Candidates c;
  c.v[0] = roundToward(centre, toward);
  if (exactFromDouble(c.v[0]) == centre) return c;
  c.v[1] = std::nextafter(c.v[0], exactFromDouble(c.v[0]) < centre ? HUGE_VAL : -HUGE_VAL);
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

}  // namespace

PlacedWalk placeWalk(const PlanningContext& ctx, const std::vector<CellIndex>& rawWalk, const Point& start) {
  const CellGrid& cells = ctx.cells;
  std::vector<Candidates> colC(static_cast<std::size_t>(cells.subCols())), rowC(static_cast<std::size_t>(cells.subRows()));
  for (int c = 0; c < cells.subCols(); ++c)
    colC[static_cast<std::size_t>(c)] = candidates(cells.subCenter(c, 0).x, cells.megaCenter(c / 2, 0).x);
  for (int r = 0; r < cells.subRows(); ++r)
    rowC[static_cast<std::size_t>(r)] = candidates(cells.subCenter(0, r).y, cells.megaCenter(0, r / 2).y);

  std::vector<CellIndex> walk;
  walk.reserve(rawWalk.size());
  for (CellIndex c : rawWalk)
    if (walk.empty() || !(walk.back() == c)) walk.push_back(c);

  // variables and points
  std::vector<Var> vars;
  std::vector<Pt> pts;
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
    std::vector<int> dirs(walk.size() - 1);
    for (std::size_t k = 0; k + 1 < walk.size(); ++k) {
      const int dc = walk[k + 1].col - walk[k].col, dr = walk[k + 1].row - walk[k].row;
      int d = -1;
      for (int e = 0; e < 4; ++e)
        if (graph::kDx[e] == dc && graph::kDy[e] == dr) d = e;
      if (d < 0) throw std::logic_error("placeWalk: consecutive sub-cells are not 4-adjacent");
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
    int runDir = dirs[0];
    int fixed = fixedVar(runDir, walk[0]);
    at(runDir, fixed, along(runDir, walk[0]), walk[0]);
    for (std::size_t k = 1; k < dirs.size(); ++k) {
      const CellIndex t = walk[k];
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
    at(runDir, fixed, along(runDir, walk.back()), walk.back());
  }
  point(-1, -1, walk.back());

  PlacedWalk out;
  const PointD s0{toDouble(start.x), toDouble(start.y)};
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
  ClearanceChecker checker(ctx.problem.workspace, ctx.problem.robots.at(0).radius);
  auto clear = [&](std::size_t k) {
    ++out.checkedMoves;
    const PointD a = coord(pts[k]), b = coord(pts[k + 1]);
    return checker.clear(Point{exactFromDouble(a.x), exactFromDouble(a.y)}, Point{exactFromDouble(b.x), exactFromDouble(b.y)});
  };
  std::vector<std::size_t> failing;
  for (std::size_t k = 0; k < nSeg; ++k)
    if (need[k] && !clear(k)) failing.push_back(k);
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
        if (need[j] && j != k && std::find(affected.begin(), affected.end(), j) == affected.end()) affected.push_back(j);
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
      for (std::size_t j = lo; j <= hi && ok; ++j) ok = !need[j] || clear(j);
      if (ok) break;
      w->pick = old;
    }
  }
  auto nonFree = [&](int c, int r) { return !cells.insideSub(c, r) || cells.sub(c, r) != CellState::kFree; };
  // a side of cell (c, r) in direction (dc, dr) is closed when one of the three cells along it is
  // not free (a corner counts: the disc passes a corner only at the exact centre line too)
  auto closedSide = [&](int c, int r, int dc, int dr) {
    for (int k = -1; k <= 1; ++k)
      if (nonFree(c + dc + k * dr, r + dr + k * dc)) return true;
    return false;
  };
  for (std::size_t k : failing) {
    if (clear(k)) continue;
    if (k == 0) {
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

}  // namespace coverkit::planners
