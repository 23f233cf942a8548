// Exact cell decompositions of C-free (see decomposition.h for the contract and the decisions).
#include <coverkit/geometry/decomposition.h>
#include <coverkit/geometry/error.h>

#include <coverkit/geometry/sampling.h>

#include "circle_segment_area.h"
#include "cspace_access.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <type_traits>

namespace coverkit {

using detail::CPolygon;
using detail::CPolygonWithHoles;
using detail::ft;
using detail::K;
using detail::PolygonSet;
using detail::Traits;
using Curve = Traits::X_monotone_curve_2;
using CPoint = Traits::Point_2;
using CoordNT = Traits::CoordNT;

/// A boundary curve of a piece in doubles (nearest doubles of the exact values), made once when the
/// piece is made: the planners' queries (interval, side) read these, not the lazy exact numbers.
struct CurveD {
  SidePiece sp;               ///< x-range, line or circle, half, orientation
  double r2 = 0;              ///< the circle's squared radius as stored (y is computed from it)
  bool vertical = false;
  double ya = 0, yb = 0;      ///< a vertical segment's ends
  bool outer = false;         ///< on the piece's outer boundary
  bool directedRight = false;
  /// y at x, for a non-vertical curve
  double yAt(double x) const {
    if (!sp.arc) return sp.b == 0 ? ya : -(sp.a * x + sp.c) / sp.b;
    const double h = std::sqrt(std::max(0.0, r2 - (x - sp.center.x) * (x - sp.center.x)));
    return sp.upperHalf ? sp.center.y + h : sp.center.y - h;
  }
};

struct detail::ExactCells {
  struct Piece {
    CPolygonWithHoles pwh;
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    std::vector<CurveD> curves;   ///< every boundary curve of pwh, outer boundary first
  };
  std::vector<std::vector<Piece>> cells;            ///< the slab (or box) pieces of each cell
  std::vector<std::vector<CPolygonWithHoles>> joined;  ///< each cell as united regions (one for a connected cell)
};

namespace {

Rational toRational(const K::FT& v) {
  static_assert(std::is_same_v<K::FT::ET, mpq_class>, "the exact kernel's number type is GMP's mpq_class");
  return Rational(CGAL::exact(v));
}

bool perfectSquare(const Rational& q, Rational& root) {
  if (q < 0) return false;
  mpz_class n = q.get_num(), d = q.get_den();
  if (!mpz_perfect_square_p(n.get_mpz_t()) || !mpz_perfect_square_p(d.get_mpz_t())) return false;
  mpz_class rn, rd;
  mpz_sqrt(rn.get_mpz_t(), n.get_mpz_t());
  mpz_sqrt(rd.get_mpz_t(), d.get_mpz_t());
  root = Rational(rn, rd);
  root.canonicalize();
  return true;
}

/// The value of a one-root number when it is rational.
std::optional<Rational> rationalValue(const CoordNT& v) {
  if (!v.is_extended() || CGAL::is_zero(v.a1()) || CGAL::is_zero(v.root())) return toRational(v.a0());
  Rational s;
  if (!perfectSquare(toRational(v.root()), s)) return std::nullopt;
  Rational out = toRational(v.a0()) + toRational(v.a1()) * s;
  out.canonicalize();
  return out;
}

/// Nearest doubles of exact numbers (CGAL::to_double reads the lazy number's interval, which may be
/// far wider than a double's rounding).
double num(const K::FT& v) { return toDouble(toRational(v)); }
double dbl(const CoordNT& v) {
  if (!v.is_extended() || CGAL::is_zero(v.a1())) return num(v.a0());
  return static_cast<double>(static_cast<long double>(num(v.a0())) +
                             static_cast<long double>(num(v.a1())) * std::sqrt(static_cast<long double>(num(v.root()))));
}

bool isHorizontal(const Curve& cv) { return cv.is_linear() && !cv.is_vertical() && CGAL::compare(cv.source().y(), cv.target().y()) == CGAL::EQUAL; }

template <class F>
void forEachLoop(const CPolygonWithHoles& p, F&& f) {
  f(p.outer_boundary());
  for (auto h = p.holes_begin(); h != p.holes_end(); ++h) f(*h);
}

/// A curve in doubles. A circular x-monotone arc is a lower arc when it runs counter-clockwise from
/// left to right (or clockwise from right to left).
CurveD describe(const Curve& cv, bool outer) {
  CurveD d;
  d.outer = outer;
  d.directedRight = cv.is_directed_right();
  d.vertical = cv.is_vertical();
  d.sp.x0 = dbl(cv.left().x());
  d.sp.x1 = dbl(cv.right().x());
  d.ya = dbl(cv.source().y());
  d.yb = dbl(cv.target().y());
  if (cv.is_linear()) {
    const auto l = cv.supporting_line();
    d.sp.a = num(l.a());
    d.sp.b = num(l.b());
    d.sp.c = num(l.c());
  } else {
    const auto circ = cv.supporting_circle();
    d.sp.arc = true;
    d.sp.center = {num(circ.center().x()), num(circ.center().y())};
    d.r2 = num(circ.squared_radius());
    d.sp.rho = std::sqrt(d.r2);
    d.sp.clockwise = cv.orientation() == CGAL::CLOCKWISE;
    d.sp.upperHalf = (cv.orientation() == CGAL::COUNTERCLOCKWISE) != cv.is_directed_right();
  }
  return d;
}

std::vector<CurveD> describeAll(const CPolygonWithHoles& p) {
  std::vector<CurveD> out;
  bool outer = true;
  forEachLoop(p, [&](const CPolygon& loop) {
    for (auto it = loop.curves_begin(); it != loop.curves_end(); ++it) out.push_back(describe(*it, outer));
    outer = false;
  });
  return out;
}

/// y-range of a curve, its top or bottom point included.
void yRange(const CurveD& d, double& lo, double& hi) {
  lo = std::min(d.ya, d.yb);
  hi = std::max(d.ya, d.yb);
  if (!d.sp.arc || d.sp.center.x < d.sp.x0 || d.sp.center.x > d.sp.x1) return;
  const double y = d.yAt(d.sp.center.x);
  lo = std::min(lo, y);
  hi = std::max(hi, y);
}

void bboxOf(const std::vector<CurveD>& curves, double& x0, double& x1, double& y0, double& y1) {
  x0 = y0 = HUGE_VAL;
  x1 = y1 = -HUGE_VAL;
  for (const CurveD& d : curves) {
    double lo, hi;
    yRange(d, lo, hi);
    x0 = std::min(x0, d.sp.x0);
    x1 = std::max(x1, d.sp.x1);
    y0 = std::min(y0, lo);
    y1 = std::max(y1, hi);
  }
}

CPolygon boxPolygon(const K::FT& x0, const K::FT& y0, const K::FT& x1, const K::FT& y1) {
  const K::Point_2 a(x0, y0), b(x1, y0), c(x1, y1), d(x0, y1);
  CPolygon p;
  p.push_back(Curve(a, b));
  p.push_back(Curve(b, c));
  p.push_back(Curve(c, d));
  p.push_back(Curve(d, a));
  return p;
}

/// The vertices of a component's boundary: x, y, whether the boundary has an x-extreme there (the
/// two curves leave on the same side, or one of them is vertical), and whether it is a real vertex
/// (not a split of one supporting curve that runs on).
struct Vertex {
  CPoint p;
  bool extreme = false;
  bool real = false;
};

std::vector<Vertex> verticesOf(const CPolygonWithHoles& comp) {
  std::vector<Vertex> out;
  forEachLoop(comp, [&](const CPolygon& loop) {
    std::vector<Curve> cs(loop.curves_begin(), loop.curves_end());
    const std::size_t n = cs.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Curve &in = cs[i], &outc = cs[(i + 1) % n];
      Vertex v{in.target()};
      v.extreme = in.is_vertical() || outc.is_vertical() || in.is_directed_right() != outc.is_directed_right();
      v.real = v.extreme || !in.has_same_supporting_curve(outc);
      out.push_back(v);
    }
  });
  return out;
}

/// The regions of a set one per face of its arrangement: each the closure of one connected open
/// set. (The set's own polygons_with_holes joins pieces that touch at a point, such as the parts
/// above and below an obstacle whose extreme point touches a cutting line.) The outer boundary of a
/// face runs counter-clockwise, its holes clockwise (the face lies left of its halfedges).
// The walk below calls members of the arrangement's Vertex / Halfedge / Face classes on CGAL's DCEL
// records, which CGAL builds as the base classes (cmake/ubsan-ignorelist.txt: its design): UBSan's
// vptr check would report each call, so it is off in these two functions, and only there.
#if defined(__clang__) || (defined(__GNUC__) && __GNUC__ >= 8)
#define COVERKIT_NO_VPTR_CHECK __attribute__((no_sanitize("vptr")))
#else
#define COVERKIT_NO_VPTR_CHECK
#endif

template <class Ccb>
COVERKIT_NO_VPTR_CHECK CPolygon loopOfCcb(Ccb ccb) {
  const auto opposite = Traits().construct_opposite_2_object();
  CPolygon pg;
  auto cur = ccb;
  do {
    const Curve& cv = cur->curve();
    const bool rightward = cur->direction() == CGAL::ARR_LEFT_TO_RIGHT;
    pg.push_back(rightward == cv.is_directed_right() ? cv : opposite(cv));
  } while (++cur != ccb);
  return pg;
}

COVERKIT_NO_VPTR_CHECK std::vector<CPolygonWithHoles> faceRegions(const PolygonSet& S) {
  const auto& arr = S.arrangement();
  std::vector<CPolygonWithHoles> out;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (!f->contained() || f->is_unbounded()) continue;
    std::vector<CPolygon> holes;
    for (auto h = f->holes_begin(); h != f->holes_end(); ++h) holes.push_back(loopOfCcb(*h));
    out.emplace_back(loopOfCcb(f->outer_ccb()), holes.begin(), holes.end());
  }
  return out;
}

struct LeafPiece {
  CPolygonWithHoles pwh;
  int col = 0, row = 0;
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  std::vector<CurveD> curves;
};

/// C-free ∩ each box of the line grid X × Y, by recursive halving (decomposition.h).
struct Cutter {
  const std::vector<K::FT>& X;
  const std::vector<K::FT>& Y;
  K::FT xlo, xhi, ylo, yhi;
  std::vector<LeafPiece>& out;

  void recurse(const PolygonSet& S, int c0, int c1, int r0, int r1) {
    if (S.is_empty()) return;
    if (c0 == c1 && r0 == r1) {
      for (auto& p : faceRegions(S)) {
        LeafPiece lp;
        lp.pwh = std::move(p);
        lp.col = c0;
        lp.row = r0;
        lp.curves = describeAll(lp.pwh);
        bboxOf(lp.curves, lp.x0, lp.x1, lp.y0, lp.y1);
        out.push_back(std::move(lp));
      }
      return;
    }
    if (c1 - c0 >= r1 - r0) {
      const int cm = (c0 + c1) / 2;   // line X[cm] between columns cm and cm + 1
      PolygonSet left(CPolygonWithHoles(boxPolygon(xlo, ylo, X[static_cast<std::size_t>(cm)], yhi)));
      left.intersection(S);
      recurse(left, c0, cm, r0, r1);
      PolygonSet right(CPolygonWithHoles(boxPolygon(X[static_cast<std::size_t>(cm)], ylo, xhi, yhi)));
      right.intersection(S);
      recurse(right, cm + 1, c1, r0, r1);
    } else {
      const int rm = (r0 + r1) / 2;
      PolygonSet below(CPolygonWithHoles(boxPolygon(xlo, ylo, xhi, Y[static_cast<std::size_t>(rm)])));
      below.intersection(S);
      recurse(below, c0, c1, r0, rm);
      PolygonSet above(CPolygonWithHoles(boxPolygon(xlo, Y[static_cast<std::size_t>(rm)], xhi, yhi)));
      above.intersection(S);
      recurse(above, c0, c1, rm + 1, r1);
    }
  }
};

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int a) {
    while (parent[static_cast<std::size_t>(a)] != a) a = parent[static_cast<std::size_t>(a)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
    return a;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
};

/// An edge of a piece on a cutting line: the piece and the interval it covers along the line.
struct LineEdge {
  int piece;
  CoordNT lo, hi;
};

/// A pair of pieces meeting across a line along an interval of positive length.
struct Contact {
  int a, b;      ///< a below/left of the line, b above/right
  int line;
  bool vertical;
  CoordNT lo, hi;
};

void matchLine(std::vector<LineEdge>& A, std::vector<LineEdge>& B, int line, bool vertical, std::vector<Contact>& out) {
  auto byLo = [](const LineEdge& u, const LineEdge& v) { return CGAL::compare(u.lo, v.lo) == CGAL::SMALLER; };
  std::sort(A.begin(), A.end(), byLo);
  std::sort(B.begin(), B.end(), byLo);
  std::size_t i = 0, j = 0;
  while (i < A.size() && j < B.size()) {
    const CoordNT& lo = CGAL::compare(A[i].lo, B[j].lo) == CGAL::LARGER ? A[i].lo : B[j].lo;
    const bool aFirst = CGAL::compare(A[i].hi, B[j].hi) != CGAL::LARGER;
    const CoordNT& hi = aFirst ? A[i].hi : B[j].hi;
    if (CGAL::compare(lo, hi) == CGAL::SMALLER) {
      // one contact per stretch: extend the last one when the same pair meets again right where it
      // ended (an edge split at a vertex); a pair meeting along two stretches apart (an obstacle
      // touches the line between them) has two contacts, and a wall
      if (!out.empty() && out.back().a == A[i].piece && out.back().b == B[j].piece && out.back().line == line &&
          out.back().vertical == vertical && CGAL::compare(out.back().hi, lo) != CGAL::SMALLER)
        out.back().hi = hi;
      else
        out.push_back({A[i].piece, B[j].piece, line, vertical, lo, hi});
    }
    if (aFirst) ++i;
    else ++j;
  }
}

double perimeter(const std::vector<CPolygonWithHoles>& ps) {
  double len = 0;
  for (const auto& p : ps)
    forEachLoop(p, [&](const CPolygon& loop) {
      for (auto it = loop.curves_begin(); it != loop.curves_end(); ++it) len += detail::toSegment(*it).length();
    });
  return len;
}

CurveRegion regionOf(const CPolygonWithHoles& pwh) {
  CurveRegion r;
  for (auto it = pwh.outer_boundary().curves_begin(); it != pwh.outer_boundary().curves_end(); ++it)
    r.outer.pieces.push_back(detail::toSegment(*it));
  r.area = detail::polygonArea(pwh.outer_boundary());
  for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) {
    CurveLoop l;
    for (auto it = h->curves_begin(); it != h->curves_end(); ++it) l.pieces.push_back(detail::toSegment(*it));
    r.holes.push_back(std::move(l));
    r.area += detail::polygonArea(*h);
  }
  return r;
}

}  // namespace

namespace {
CellDecomposition decomposeImpl(const CSpace& space, DecompositionRule rule, const std::string& method, const Rational& gridSize,
                                const Point& gridOrigin, const std::vector<Rational>* givenX, const std::vector<Rational>* givenY);
}

CellDecomposition decomposeCSpace(const CSpace& space, DecompositionRule rule, const std::string& method, const Rational& gridSize,
                                  const Point& gridOrigin) {
  if (rule == DecompositionRule::kGrid && gridSize <= 0) throw std::invalid_argument("decomposeCSpace: grid size must be > 0");
  return decomposeImpl(space, rule, method, gridSize, gridOrigin, nullptr, nullptr);
}

CellDecomposition decomposeAlongLines(const CSpace& space, const std::vector<Rational>& xs, const std::vector<Rational>& ys,
                                      const std::string& method) {
  return decomposeImpl(space, DecompositionRule::kGrid, method, 0, Point{}, &xs, &ys);
}

namespace {
CellDecomposition decomposeImpl(const CSpace& space, DecompositionRule rule, const std::string& method, const Rational& gridSize,
                                const Point& gridOrigin, const std::vector<Rational>* givenX, const std::vector<Rational>* givenY) {
  CellDecomposition d;
  d.method = method;
  auto exact = std::make_shared<detail::ExactCells>();
  const auto& parts = detail::CSpaceAccess::parts(space);

  std::vector<LeafPiece> pieces;
  std::vector<int> pieceComponent;
  std::vector<Contact> contacts;
  // per vertical line (global numbering over components): the y of the real vertices on it
  std::vector<std::vector<CoordNT>> lineVertexY;

  for (std::size_t ci = 0; ci < parts.size(); ++ci) {
    const CPolygonWithHoles& comp = parts[ci];
    double bx0, bx1, by0, by1;
    bboxOf(describeAll(comp), bx0, bx1, by0, by1);
    const std::vector<Vertex> verts = verticesOf(comp);
    // exact extent: the leftmost / rightmost vertex (curves are x-monotone)
    CoordNT xmin = verts.front().p.x(), xmax = xmin, ymin = verts.front().p.y(), ymax = ymin;
    for (const Vertex& v : verts) {
      if (CGAL::compare(v.p.x(), xmin) == CGAL::SMALLER) xmin = v.p.x();
      if (CGAL::compare(v.p.x(), xmax) == CGAL::LARGER) xmax = v.p.x();
      if (CGAL::compare(v.p.y(), ymin) == CGAL::SMALLER) ymin = v.p.y();
      if (CGAL::compare(v.p.y(), ymax) == CGAL::LARGER) ymax = v.p.y();
    }
    std::vector<Rational> xs, ys;
    std::map<Rational, std::vector<CoordNT>> vertexY;   // real vertices by rational x
    auto inside = [](const Rational& v, const CoordNT& lo, const CoordNT& hi) {
      return CGAL::compare(CoordNT(ft(v)), lo) == CGAL::LARGER && CGAL::compare(CoordNT(ft(v)), hi) == CGAL::SMALLER;
    };
    if (givenX) {
      for (const Rational& x : *givenX)
        if (inside(x, xmin, xmax)) xs.push_back(x);
      for (const Rational& y : *givenY)
        if (inside(y, ymin, ymax)) ys.push_back(y);
    } else if (rule == DecompositionRule::kGrid) {
      // grid lines strictly inside the component's extent
      const Rational lo = Rational(std::floor(bx0)) - 1, hi = Rational(std::ceil(bx1)) + 1;
      Rational k0 = (lo - gridOrigin.x) / gridSize;
      mpz_class k = k0.get_num() / k0.get_den();
      for (Rational x = gridOrigin.x + Rational(k) * gridSize; x <= hi; x += gridSize)
        if (inside(x, xmin, xmax)) xs.push_back(x);
      const Rational ylo = Rational(std::floor(by0)) - 1, yhi = Rational(std::ceil(by1)) + 1;
      Rational m0 = (ylo - gridOrigin.y) / gridSize;
      mpz_class m = m0.get_num() / m0.get_den();
      for (Rational y = gridOrigin.y + Rational(m) * gridSize; y <= yhi; y += gridSize)
        if (inside(y, ymin, ymax)) ys.push_back(y);
    } else {
      for (const Vertex& v : verts) {
        if (!v.real) continue;
        const std::optional<Rational> x = rationalValue(v.p.x());
        if (!x) {
          if (!v.extreme) ++d.unwalledVertices;
          continue;
        }
        vertexY[*x].push_back(v.p.y());
        if (rule == DecompositionRule::kBoustrophedon && !v.extreme) continue;
        if (inside(*x, xmin, xmax)) xs.push_back(*x);
      }
    }
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
    d.lines += xs.size() + ys.size();
    std::vector<K::FT> X, Y;
    for (const Rational& x : xs) X.push_back(ft(x));
    for (const Rational& y : ys) Y.push_back(ft(y));
    const Rational fx0 = Rational(std::floor(bx0)) - 2, fx1 = Rational(std::ceil(bx1)) + 2;
    const Rational fy0 = Rational(std::floor(by0)) - 2, fy1 = Rational(std::ceil(by1)) + 2;
    std::vector<LeafPiece> leaves;
    Cutter cut{X, Y, ft(fx0), ft(fx1), ft(fy0), ft(fy1), leaves};
    cut.recurse(PolygonSet(comp), 0, static_cast<int>(X.size()), 0, static_cast<int>(Y.size()));

    // edges of the pieces on the cutting lines
    const int base = static_cast<int>(pieces.size());
    std::vector<std::vector<LineEdge>> vLeftOf(X.size()), vRightOf(X.size()), hBelow(Y.size()), hAbove(Y.size());
    for (std::size_t pi = 0; pi < leaves.size(); ++pi) {
      const LeafPiece& lp = leaves[pi];
      const int id = base + static_cast<int>(pi);
      forEachLoop(lp.pwh, [&](const CPolygon& loop) {
        for (auto it = loop.curves_begin(); it != loop.curves_end(); ++it) {
          const Curve& cv = *it;
          if (cv.is_vertical()) {
            const CoordNT& x = cv.source().x();
            const bool up = CGAL::compare(cv.source().y(), cv.target().y()) == CGAL::SMALLER;
            LineEdge e{id, up ? cv.source().y() : cv.target().y(), up ? cv.target().y() : cv.source().y()};
            if (lp.col > 0 && CGAL::compare(x, CoordNT(X[static_cast<std::size_t>(lp.col - 1)])) == CGAL::EQUAL)
              vRightOf[static_cast<std::size_t>(lp.col - 1)].push_back(e);
            if (lp.col < static_cast<int>(X.size()) && CGAL::compare(x, CoordNT(X[static_cast<std::size_t>(lp.col)])) == CGAL::EQUAL)
              vLeftOf[static_cast<std::size_t>(lp.col)].push_back(e);
          } else if (isHorizontal(cv)) {
            const CoordNT& y = cv.source().y();
            LineEdge e{id, cv.left().x(), cv.right().x()};
            if (lp.row > 0 && CGAL::compare(y, CoordNT(Y[static_cast<std::size_t>(lp.row - 1)])) == CGAL::EQUAL)
              hAbove[static_cast<std::size_t>(lp.row - 1)].push_back(e);
            if (lp.row < static_cast<int>(Y.size()) && CGAL::compare(y, CoordNT(Y[static_cast<std::size_t>(lp.row)])) == CGAL::EQUAL)
              hBelow[static_cast<std::size_t>(lp.row)].push_back(e);
          }
        }
      });
    }
    const int lineBase = static_cast<int>(lineVertexY.size());
    for (std::size_t l = 0; l < X.size(); ++l) {
      matchLine(vLeftOf[l], vRightOf[l], lineBase + static_cast<int>(l), true, contacts);
      auto it = vertexY.find(xs[l]);
      std::vector<CoordNT> vy = it == vertexY.end() ? std::vector<CoordNT>() : it->second;
      std::sort(vy.begin(), vy.end(), [](const CoordNT& a, const CoordNT& b) { return CGAL::compare(a, b) == CGAL::SMALLER; });
      lineVertexY.push_back(std::move(vy));
    }
    for (std::size_t l = 0; l < Y.size(); ++l) matchLine(hBelow[l], hAbove[l], -1, false, contacts);
    for (auto& lp : leaves) {
      pieces.push_back(std::move(lp));
      pieceComponent.push_back(static_cast<int>(ci));
    }
  }

  // join pieces into cells by the model's rule
  UnionFind uf(pieces.size());
  if (rule != DecompositionRule::kGrid) {
    std::map<int, int> rightCount, leftCount;
    for (const Contact& c : contacts) {
      ++rightCount[c.a];
      ++leftCount[c.b];
    }
    for (const Contact& c : contacts) {
      if (rightCount[c.a] != 1 || leftCount[c.b] != 1) continue;
      if (rule == DecompositionRule::kTrapezoidal) {
        // a wall when a vertex of C-free lies on the shared interval (closed)
        const auto& vy = lineVertexY[static_cast<std::size_t>(c.line)];
        auto it = std::lower_bound(vy.begin(), vy.end(), c.lo, [](const CoordNT& a, const CoordNT& b) { return CGAL::compare(a, b) == CGAL::SMALLER; });
        if (it != vy.end() && CGAL::compare(*it, c.hi) != CGAL::LARGER) continue;
      }
      uf.unite(c.a, c.b);
    }
  }
  std::map<int, std::vector<int>> groups;   // root → pieces, in piece order
  for (std::size_t i = 0; i < pieces.size(); ++i) groups[uf.find(static_cast<int>(i))].push_back(static_cast<int>(i));

  struct Proto {
    std::vector<int> pieces;
    double x0, x1, y0, y1;
  };
  std::vector<Proto> protos;
  for (auto& [root, ps] : groups) {
    Proto p{ps, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
    for (int i : ps) {
      const LeafPiece& lp = pieces[static_cast<std::size_t>(i)];
      p.x0 = std::min(p.x0, lp.x0);
      p.x1 = std::max(p.x1, lp.x1);
      p.y0 = std::min(p.y0, lp.y0);
      p.y1 = std::max(p.y1, lp.y1);
    }
    protos.push_back(std::move(p));
  }
  std::stable_sort(protos.begin(), protos.end(), [](const Proto& a, const Proto& b) {
    return std::make_tuple(a.x0, a.y0, a.pieces.front()) < std::make_tuple(b.x0, b.y0, b.pieces.front());
  });
  std::vector<int> cellOfPiece(pieces.size(), -1);
  for (std::size_t c = 0; c < protos.size(); ++c) {
    const Proto& p = protos[c];
    DecomposedCell cell;
    cell.xmin = p.x0;
    cell.xmax = p.x1;
    cell.ymin = p.y0;
    cell.ymax = p.y1;
    cell.component = pieceComponent[static_cast<std::size_t>(p.pieces.front())];
    std::vector<detail::ExactCells::Piece> exactPieces;
    std::vector<CPolygonWithHoles> polys;
    for (int i : p.pieces) {
      cellOfPiece[static_cast<std::size_t>(i)] = static_cast<int>(c);
      const LeafPiece& lp = pieces[static_cast<std::size_t>(i)];
      exactPieces.push_back({lp.pwh, lp.x0, lp.x1, lp.y0, lp.y1, lp.curves});
      polys.push_back(lp.pwh);
    }
    std::vector<CPolygonWithHoles> joined;
    if (polys.size() == 1) joined = polys;
    else {
      PolygonSet u;
      u.join(polys.begin(), polys.end());
      u.polygons_with_holes(std::back_inserter(joined));
    }
    for (const auto& j : joined) {
      const CurveRegion r = regionOf(j);
      cell.area += r.area;
      if (cell.region.outer.pieces.empty()) cell.region = r;   // a connected cell has one
    }
    exact->cells.push_back(std::move(exactPieces));
    exact->joined.push_back(std::move(joined));
    d.cells.push_back(std::move(cell));
  }
  // walls between different cells
  for (const Contact& c : contacts) {
    const int a = cellOfPiece[static_cast<std::size_t>(c.a)], b = cellOfPiece[static_cast<std::size_t>(c.b)];
    if (a == b) continue;
    CellWall w;
    w.a = std::min(a, b);
    w.b = std::max(a, b);
    w.vertical = c.vertical;
    const LeafPiece& pa = pieces[static_cast<std::size_t>(c.a)];
    w.lo = dbl(c.lo);
    w.hi = dbl(c.hi);
    w.at = c.vertical ? pa.x1 : pa.y1;   // the piece left of (below) the line ends on it
    d.walls.push_back(w);
  }
  std::sort(d.walls.begin(), d.walls.end(), [](const CellWall& u, const CellWall& v) {
    return std::make_tuple(u.a, u.b, u.vertical, u.at, u.lo) < std::make_tuple(v.a, v.b, v.vertical, v.at, v.lo);
  });
  for (const CellWall& w : d.walls) {
    d.cells[static_cast<std::size_t>(w.a)].neighbours.push_back(w.b);
    d.cells[static_cast<std::size_t>(w.b)].neighbours.push_back(w.a);
  }
  for (DecomposedCell& c : d.cells) {
    std::sort(c.neighbours.begin(), c.neighbours.end());
    c.neighbours.erase(std::unique(c.neighbours.begin(), c.neighbours.end()), c.neighbours.end());
  }
  d.exact = std::move(exact);
  return d;
}

}  // namespace

bool CellDecomposition::interval(int cell, double x, double& lo, double& hi) const {
  lo = HUGE_VAL;
  hi = -HUGE_VAL;
  for (const auto& piece : exact->cells.at(static_cast<std::size_t>(cell))) {
    if (x < piece.x0 || x > piece.x1) continue;
    for (const CurveD& d : piece.curves) {
      if (x < d.sp.x0 || x > d.sp.x1) continue;
      if (d.vertical) {
        lo = std::min({lo, d.ya, d.yb});
        hi = std::max({hi, d.ya, d.yb});
      } else {
        const double y = d.yAt(x);
        lo = std::min(lo, y);
        hi = std::max(hi, y);
      }
    }
  }
  return lo <= hi;
}

double SidePiece::yAt(double x) const {
  if (!arc) return b == 0 ? 0 : -(a * x + c) / b;
  const double h = std::sqrt(std::max(0.0, rho * rho - (x - center.x) * (x - center.x)));
  return upperHalf ? center.y + h : center.y - h;
}

std::vector<SidePiece> CellDecomposition::side(int cell, bool top, double x0, double x1) const {
  std::vector<SidePiece> out;
  if (x0 > x1) std::swap(x0, x1);
  for (const auto& piece : exact->cells.at(static_cast<std::size_t>(cell))) {
    if (piece.x1 < x0 || piece.x0 > x1) continue;
    // the outer boundary runs counter-clockwise: the top from right to left
    for (const CurveD& d : piece.curves)
      if (d.outer && !d.vertical && d.directedRight != top && d.sp.x1 >= x0 && d.sp.x0 <= x1) out.push_back(d.sp);
  }
  std::sort(out.begin(), out.end(), [](const SidePiece& u, const SidePiece& v) { return u.x0 < v.x0; });
  return out;
}

bool CellDecomposition::contains(int cell, const Point& p) const {
  const double px = p.x.get_d(), py = p.y.get_d();
  const double sx = 1e-9 * (1 + std::abs(px)), sy = 1e-9 * (1 + std::abs(py));
  const DecomposedCell& c = cells.at(static_cast<std::size_t>(cell));
  if (px < c.xmin - sx || px > c.xmax + sx || py < c.ymin - sy || py > c.ymax + sy) return false;
  const CPoint q{CoordNT(ft(p.x)), CoordNT(ft(p.y))};
  for (const auto& piece : exact->cells[static_cast<std::size_t>(cell)]) {
    if (px < piece.x0 - sx || px > piece.x1 + sx) continue;
    const PolygonSet s(piece.pwh);
    if (s.oriented_side(q) != CGAL::ON_NEGATIVE_SIDE) return true;
  }
  return false;
}

int CellDecomposition::locate(const Point& p) const {
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (contains(static_cast<int>(c), p)) return static_cast<int>(c);
  return -1;
}

std::vector<SampledRegion> sampledCells(const CellDecomposition& d, double tolerance, std::vector<std::size_t>* unplaced) {
  if (unplaced) unplaced->assign(d.cells.size(), 0);
  std::vector<CurveRegion> regions;
  for (const DecomposedCell& c : d.cells) regions.push_back(c.region);
  std::vector<SampledRegion> out = sampleRegions(regions, tolerance, true);
  const Rotation& rot = d.rotation;
  auto inside = [&](int cell, PointD v) { return d.contains(cell, rot.apply(Point{exactFromDouble(v.x), exactFromDouble(v.y)})); };
  for (std::size_t i = 0; i < out.size(); ++i) {
    auto fix = [&](std::vector<PointD>& ring) {
      // the frame's rings back in the workspace's frame, then each vertex into its cell
      for (PointD& v : ring) v = rot.c == 1 ? v : rot.inverse(v);
      const std::size_t n = ring.size();
      std::vector<PointD> moved = ring;
      for (std::size_t k = 0; k < n; ++k) {
        PointD v = ring[k];
        if (inside(static_cast<int>(i), v)) continue;
        // inward: the left of both edges (outer rings counter-clockwise, holes clockwise: the
        // region is on the left of either); at a cusp (an arc's x-extreme meeting a wall, where
        // the two edges run back on each other) toward the neighbours instead
        const PointD a = ring[(k + n - 1) % n], b = ring[(k + 1) % n];
        const double ex = v.x - a.x, ey = v.y - a.y, fx = b.x - v.x, fy = b.y - v.y;
        const double le = std::hypot(ex, ey), lf = std::hypot(fx, fy);
        std::vector<PointD> dirs{{(le > 0 ? -ey / le : 0) + (lf > 0 ? -fy / lf : 0), (le > 0 ? ex / le : 0) + (lf > 0 ? fx / lf : 0)},
                                 {(a.x + b.x) / 2 - v.x, (a.y + b.y) / 2 - v.y}, {a.x - v.x, a.y - v.y}, {b.x - v.x, b.y - v.y}};
        for (const PointD& dir : dirs) {
          const double ln = std::hypot(dir.x, dir.y);
          if (ln == 0 || inside(static_cast<int>(i), v)) continue;
          double step = 4 * std::numeric_limits<double>::epsilon() * (1 + std::max(std::abs(v.x), std::abs(v.y)));
          for (int t = 0; t < 40 && step < ln / 2; ++t, step *= 2) {
            const PointD w{ring[k].x + dir.x / ln * step, ring[k].y + dir.y / ln * step};
            if (inside(static_cast<int>(i), w)) {
              v = w;
              break;
            }
          }
        }
        if (unplaced && !inside(static_cast<int>(i), v)) ++(*unplaced)[i];
        moved[k] = v;
      }
      ring = std::move(moved);
    };
    fix(out[i].outer);
    for (auto& h : out[i].holes) fix(h);
  }
  return out;
}

DecompositionCheck checkDecomposition(const CellDecomposition& d, const CSpace& space) {
  DecompositionCheck out;
  const auto& cells = d.exact->joined;
  const std::size_t n = cells.size();
  auto fail = [&](bool& flag, const std::string& why) {
    flag = false;
    if (out.detail.empty()) out.detail = why;
  };
  // the union against C-free
  {
    std::vector<CPolygonWithHoles> all;
    for (const auto& c : cells) all.insert(all.end(), c.begin(), c.end());
    PolygonSet u;
    if (!all.empty()) u.join(all.begin(), all.end());
    const auto& parts = detail::CSpaceAccess::parts(space);
    PolygonSet cf;
    cf.insert(parts.begin(), parts.end());
    u.symmetric_difference(cf);
    if (!u.is_empty()) fail(out.unionIsCFree, "the union of the cells differs from C-free");
  }
  // pairs with touching boxes: disjoint interiors, and shared boundary ⇔ listed
  double extent = 0;
  for (const auto& c : d.cells) extent = std::max({extent, std::abs(c.xmin), std::abs(c.xmax), std::abs(c.ymin), std::abs(c.ymax)});
  const double tol = 1e-9 * (1 + extent);
  std::vector<double> per(n);
  for (std::size_t i = 0; i < n; ++i) per[i] = perimeter(cells[i]);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return d.cells[a].xmin < d.cells[b].xmin; });
  std::set<std::pair<int, int>> found;
  for (std::size_t oi = 0; oi < n; ++oi) {
    const std::size_t i = order[oi];
    const DecomposedCell& a = d.cells[i];
    for (std::size_t oj = oi + 1; oj < n; ++oj) {
      const std::size_t j = order[oj];
      const DecomposedCell& b = d.cells[j];
      if (b.xmin > a.xmax + tol) break;
      if (b.ymin > a.ymax + tol || a.ymin > b.ymax + tol) continue;
      PolygonSet inter;
      inter.insert(cells[i].begin(), cells[i].end());
      PolygonSet other;
      other.insert(cells[j].begin(), cells[j].end());
      PolygonSet both = inter;
      inter.intersection(other);
      if (!inter.is_empty()) fail(out.disjoint, "cells " + std::to_string(i) + " and " + std::to_string(j) + " overlap");
      both.join(other);
      std::vector<CPolygonWithHoles> u;
      both.polygons_with_holes(std::back_inserter(u));
      const double shared = (per[i] + per[j] - perimeter(u)) / 2;
      if (shared > tol) found.insert({static_cast<int>(std::min(i, j)), static_cast<int>(std::max(i, j))});
    }
  }
  std::set<std::pair<int, int>> listed;
  for (const CellWall& w : d.walls) listed.insert({w.a, w.b});
  for (const auto& p : found)
    if (!listed.count(p)) fail(out.adjacencyComplete, "cells " + std::to_string(p.first) + " and " + std::to_string(p.second) + " share boundary but are not listed");
  for (const auto& p : listed)
    if (!found.count(p)) fail(out.adjacencyComplete, "cells " + std::to_string(p.first) + " and " + std::to_string(p.second) + " are listed but share no boundary");
  for (std::size_t i = 0; i < n; ++i)
    for (int j : d.cells[i].neighbours) {
      const auto& nb = d.cells[static_cast<std::size_t>(j)].neighbours;
      if (!std::binary_search(nb.begin(), nb.end(), static_cast<int>(i))) fail(out.adjacencySymmetric, "neighbour lists not symmetric");
      if (!listed.count({std::min(static_cast<int>(i), j), std::max(static_cast<int>(i), j)})) fail(out.adjacencySymmetric, "a neighbour without a wall");
    }
  // monotone: one region without holes whose boundary turns back in x twice
  for (std::size_t i = 0; i < n; ++i) {
    if (cells[i].size() != 1 || cells[i].front().number_of_holes() != 0) {
      out.monotone = false;
      continue;
    }
    const CPolygon& outer = cells[i].front().outer_boundary();
    std::vector<bool> dirs;
    for (auto it = outer.curves_begin(); it != outer.curves_end(); ++it)
      if (!it->is_vertical()) dirs.push_back(it->is_directed_right());
    int changes = 0;
    for (std::size_t k = 0; k < dirs.size(); ++k) changes += dirs[k] != dirs[(k + 1) % dirs.size()];
    if (changes > 2) out.monotone = false;
  }
  return out;
}

}  // namespace coverkit
