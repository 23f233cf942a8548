// Exact cell classification. See cell_grid.h for the definitions and the cost.
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/error.h>

#include "error_free.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace coverkit {

namespace {

long floorQ(const Rational& q) {
  mpz_class f;
  mpz_fdiv_q(f.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return f.get_si();
}
long ceilQ(const Rational& q) {
  mpz_class c;
  mpz_cdiv_q(c.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
  return c.get_si();
}

struct Edge {
  const Point* a;
  const Point* b;
};

std::vector<Edge> collectEdges(const Workspace& w) {
  std::vector<Edge> edges;
  for (const Ring* r : w.rings()) {
    const std::size_t n = r->size();
    for (std::size_t i = 0; i < n; ++i) edges.push_back({&(*r)[i], &(*r)[(i + 1) % n]});
  }
  return edges;
}

}  // namespace

const char* toString(CellState s) {
  switch (s) {
    case CellState::kFree: return "free";
    case CellState::kPartial: return "partial";
    case CellState::kBlocked: return "blocked";
  }
  return "?";
}

CellGrid::CellGrid(Rational originX, Rational originY, Rational subSize, int megaCols, int megaRows)
    : ox_(std::move(originX)), oy_(std::move(originY)), d_(std::move(subSize)), mc_(megaCols), mr_(megaRows) {
  oxd_ = toDouble(ox_);
  oyd_ = toDouble(oy_);
  dd_ = toDouble(d_);
  exactD_ = Rational(oxd_) == ox_ && Rational(oyd_) == oy_ && Rational(dd_) == d_;
  sub_.assign(static_cast<std::size_t>(subCols()) * subRows(), CellState::kBlocked);
}

CellState CellGrid::mega(int col, int row) const {
  CellState a = sub(2 * col, 2 * row), b = sub(2 * col + 1, 2 * row), c = sub(2 * col, 2 * row + 1),
            d = sub(2 * col + 1, 2 * row + 1);
  if (a == b && b == c && c == d && a != CellState::kPartial) return a;
  return CellState::kPartial;
}

namespace {
/// o + d·(2i + 1)/2 in doubles when every step is exact (fma and TwoSum say so), as on a grid whose
/// origin and sub-cell size are dyadic; false otherwise.
bool exactCentre(double o, double d, int i, double& out) {
  double p;
  return detail::exactProduct(d, 2.0 * i + 1, p, 0x1p-1000) && detail::exactSum(o, p / 2, out);
}
}  // namespace

Point CellGrid::subCenter(int col, int row) const {
  PointD q;   // made from its exact double where there is one (a grid map's): one conversion, no arithmetic
  if (exactD_ && exactCentre(oxd_, dd_, col, q.x) && exactCentre(oyd_, dd_, row, q.y)) return {Rational(q.x), Rational(q.y)};
  return {Rational(ox_ + d_ * (2 * col + 1) / 2), Rational(oy_ + d_ * (2 * row + 1) / 2)};
}
Point CellGrid::megaCenter(int col, int row) const {
  return {Rational(ox_ + d_ * (2 * col + 1)), Rational(oy_ + d_ * (2 * row + 1))};
}

PointD CellGrid::subCenterD(int col, int row) const {
  // the rational centre's double, without rationals where doubles give it exactly
  PointD q;
  if (exactD_ && exactCentre(oxd_, dd_, col, q.x) && exactCentre(oyd_, dd_, row, q.y)) return q;
  Point p = subCenter(col, row);
  return {toDouble(p.x), toDouble(p.y)};
}

bool CellGrid::locateSub(const Point& p, CellIndex& out) const {
  long c = floorQ(Rational((p.x - ox_) / d_)), r = floorQ(Rational((p.y - oy_) / d_));
  if (c < 0 || r < 0 || c >= subCols() || r >= subRows()) return false;
  out = {static_cast<int>(c), static_cast<int>(r)};
  return true;
}

bool CellGrid::locateSubD(PointD p, CellIndex& out) const {
  double fc = std::floor((p.x - oxd_) / dd_), fr = std::floor((p.y - oyd_) / dd_);
  if (!(fc >= 0 && fr >= 0 && fc < subCols() && fr < subRows())) return false;
  out = {static_cast<int>(fc), static_cast<int>(fr)};
  return true;
}

std::size_t CellGrid::count(CellState s) const { return static_cast<std::size_t>(std::count(sub_.begin(), sub_.end(), s)); }

std::size_t CellGrid::countMega(CellState s) const {
  std::size_t n = 0;
  for (int r = 0; r < mr_; ++r)
    for (int c = 0; c < mc_; ++c) n += mega(c, r) == s;
  return n;
}

CellGrid classifyCells(const Workspace& w, const Rational& D) {
  if (D <= 0) throw InputError(w.name, "cell size", "must be > 0");
  if (w.regions.empty()) throw InputError(w.name, "workspace", "has no free region");
  const Box b = w.bbox();
  // counted exactly before converting: a tiny D must not overflow a long into a small grid
  auto megaCount = [&](const Rational& extent) {
    const Rational q = extent / (2 * D);
    mpz_class c;
    mpz_cdiv_q(c.get_mpz_t(), q.get_num_mpz_t(), q.get_den_mpz_t());
    return c < 1 ? mpz_class(1) : c;
  };
  const mpz_class mc = megaCount(b.xmax - b.xmin), mr = megaCount(b.ymax - b.ymin);
  if (mc * mr > 50'000'000L) throw InputError(w.name, "cell size", "too small: more than 2·10^8 sub-cells");
  const long mcols = mc.get_si(), mrows = mr.get_si();
  CellGrid g(b.xmin, b.ymin, D, static_cast<int>(mcols), static_cast<int>(mrows));
  const int cols = g.subCols(), rows = g.subRows();
  const Rational& x0 = b.xmin;
  const Rational& y0 = b.ymin;
  std::vector<std::uint8_t> crossed(static_cast<std::size_t>(cols) * rows, 0);
  const std::vector<Edge> edges = collectEdges(w);

  // 1. Cells whose open interior an edge meets: walk each edge column strip by column strip.
  auto markRows = [&](int col, const Rational& ylo, const Rational& yhi) {
    // open y-interval (ylo, yhi), or the single value ylo == yhi
    long r0, r1;
    if (ylo == yhi) {
      Rational t = (ylo - y0) / D;
      if (t.get_den() == 1) return;  // on a grid line: meets no open cell
      r0 = r1 = floorQ(t);
    } else {
      r0 = floorQ(Rational((ylo - y0) / D));
      r1 = ceilQ(Rational((yhi - y0) / D)) - 1;
    }
    r0 = std::max(r0, 0L);
    r1 = std::min(r1, static_cast<long>(rows) - 1);
    for (long r = r0; r <= r1; ++r) crossed[static_cast<std::size_t>(r) * cols + col] = 1;
  };
  // Fast path: an edge whose two ends lie in the same cell, each certainly inside its open interior
  // (a double computation with a margin above its rounding error), meets that cell only; the rest
  // are decided exactly below. Short edges (long coastlines, dense scans) take this path.
  const double x0d = x0.get_d(), y0d = y0.get_d(), Dd = D.get_d();
  auto certainCell = [&](double v, double v0, long& idx) {
    const double t = (v - v0) / Dd;
    const double err = 8 * 0x1p-53 * ((std::abs(v) + std::abs(v0)) / Dd + std::abs(t));
    const double f = std::floor(t);
    if (!std::isfinite(err) || !(t - f > 2 * err && f + 1 - t > 2 * err)) return false;
    idx = static_cast<long>(f);
    return true;
  };
  for (const Edge& e : edges) {
    const Point& a = *e.a;
    const Point& c = *e.b;
    {
      long ca, ra, cc, rc;
      if (certainCell(a.x.get_d(), x0d, ca) && certainCell(c.x.get_d(), x0d, cc) && ca == cc && certainCell(a.y.get_d(), y0d, ra) &&
          certainCell(c.y.get_d(), y0d, rc) && ra == rc) {
        if (ca >= 0 && ca < cols && ra >= 0 && ra < rows) crossed[static_cast<std::size_t>(ra) * cols + ca] = 1;
        continue;
      }
    }
    if (a.x == c.x) {
      Rational t = (a.x - x0) / D;
      if (t.get_den() == 1) continue;  // along a column line
      long col = floorQ(t);
      if (col < 0 || col >= cols) continue;
      markRows(static_cast<int>(col), a.y < c.y ? a.y : c.y, a.y < c.y ? c.y : a.y);
      continue;
    }
    if (a.y == c.y && Rational((a.y - y0) / D).get_den() == 1) continue;  // along a row line
    const Point& p = a.x < c.x ? a : c;
    const Point& q = a.x < c.x ? c : a;
    const Rational slope = (q.y - p.y) / (q.x - p.x);
    long c0 = std::max(0L, floorQ(Rational((p.x - x0) / D)));
    long c1 = std::min(static_cast<long>(cols) - 1, ceilQ(Rational((q.x - x0) / D)) - 1);
    for (long col = c0; col <= c1; ++col) {
      Rational xa = x0 + D * col, xb = x0 + D * (col + 1);
      Rational lo = xa > p.x ? xa : p.x, hi = xb < q.x ? xb : q.x;
      if (!(lo < hi)) continue;
      Rational ya = p.y + slope * (lo - p.x), yb = p.y + slope * (hi - p.x);
      if (ya > yb) std::swap(ya, yb);
      markRows(static_cast<int>(col), ya, yb);
    }
  }

  // 2. Row parity sweep at each row's centre line, with an active-edge list sorted by ymin.
  std::vector<std::size_t> order(edges.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  auto ymin = [&](const Edge& e) -> const Rational& { return e.a->y < e.b->y ? e.a->y : e.b->y; };
  auto ymax = [&](const Edge& e) -> const Rational& { return e.a->y < e.b->y ? e.b->y : e.a->y; };
  // sorted by ymin in doubles (exact comparisons of a million rationals cost seconds); an edge
  // joins the active list once its double ymin is below the row line plus a margin above the
  // rounding, i.e. possibly a little early, which the exact crossing test below makes harmless
  std::vector<double> yminD(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) yminD[i] = ymin(edges[i]).get_d();
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return yminD[i] < yminD[j]; });
  // Vertical edges (all of them on grid maps) cross every row line at the same x: their column
  // threshold is computed once instead of once per row.
  std::vector<long> verticalC0(edges.size(), -1);
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (edges[i].a->x == edges[i].b->x)
      verticalC0[i] = std::clamp(floorQ(Rational((edges[i].a->x - x0) / D - Rational(1, 2))) + 1, 0L, static_cast<long>(cols));
  std::vector<std::size_t> active;
  std::size_t next = 0;
  std::vector<int> flips(static_cast<std::size_t>(cols) + 1);
  for (int row = 0; row < rows; ++row) {
    const Rational yc = y0 + D * (2 * row + 1) / 2;
    const double ycd = yc.get_d(), margin = 1e-9 * (std::abs(ycd) + Dd);
    while (next < order.size() && yminD[order[next]] <= ycd + margin) active.push_back(order[next++]);
    active.erase(std::remove_if(active.begin(), active.end(), [&](std::size_t i) { return ymax(edges[i]) < yc; }),
                 active.end());
    std::fill(flips.begin(), flips.end(), 0);
    for (std::size_t i : active) {
      const Point& a = *edges[i].a;
      const Point& c = *edges[i].b;
      if ((a.y > yc) == (c.y > yc)) continue;  // half-open rule
      if (verticalC0[i] >= 0) {
        flips[static_cast<std::size_t>(verticalC0[i])] ^= 1;
        continue;
      }
      Rational x = a.x + (yc - a.y) * (c.x - a.x) / (c.y - a.y);
      // cells whose centre lies right of x: col > (x - x0)/D - 1/2
      long c0 = floorQ(Rational((x - x0) / D - Rational(1, 2))) + 1;
      c0 = std::clamp(c0, 0L, static_cast<long>(cols));
      flips[static_cast<std::size_t>(c0)] ^= 1;
    }
    int inside = 0;
    for (int col = 0; col < cols; ++col) {
      inside ^= flips[static_cast<std::size_t>(col)];
      const std::size_t k = static_cast<std::size_t>(row) * cols + col;
      g.setSub(col, row, crossed[k] ? CellState::kPartial : (inside ? CellState::kFree : CellState::kBlocked));
    }
  }
  return g;
}

bool strictlyInside(const Workspace& w, const Point& p) {
  // Parity of crossings of the ray to the right; any point on an edge is not strictly inside.
  bool inside = false;
  for (const Ring* r : w.rings()) {
    const std::size_t n = r->size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point& a = (*r)[i];
      const Point& c = (*r)[(i + 1) % n];
      // both ends strictly above or strictly below p: neither on the edge nor crossing the ray
      // (exact comparisons, no arithmetic: the common case on large maps)
      const int sa = cmp(a.y, p.y), sc = cmp(c.y, p.y);
      if (sa == sc && sa != 0) continue;
      // on segment?
      Rational cross = (c.x - a.x) * (p.y - a.y) - (c.y - a.y) * (p.x - a.x);
      if (cross == 0 && std::min(a.x, c.x) <= p.x && p.x <= std::max(a.x, c.x) && std::min(a.y, c.y) <= p.y &&
          p.y <= std::max(a.y, c.y))
        return false;
      if ((a.y > p.y) != (c.y > p.y)) {
        Rational x = a.x + (p.y - a.y) * (c.x - a.x) / (c.y - a.y);
        if (x > p.x) inside = !inside;
      }
    }
  }
  return inside;
}

}  // namespace coverkit
