// Arcs as line segments on the safe side (see sampling.h for the contract, docs/formats.md).
#include <coverkit/geometry/sampling.h>
#include <coverkit/geometry/validate.h>

#include <algorithm>
#include <cmath>

namespace coverkit {

namespace {

constexpr int kMaxPiecesPerArc = 1 << 20;

struct ArcGeom {
  double cx = 0, cy = 0, rho = 0, a0 = 0, sweep = 0, dir = 1;
};

/// The arc as the validator reads it: radius |from − center|, from `from` to the ray through `to`,
/// the full circle when from == to.
bool arcGeom(const PathSegment& s, ArcGeom& g) {
  g.cx = s.center.x;
  g.cy = s.center.y;
  g.rho = std::hypot(s.from.x - g.cx, s.from.y - g.cy);
  if (!(g.rho > 0) || !std::isfinite(g.rho) || (s.to.x == g.cx && s.to.y == g.cy)) return false;
  g.a0 = std::atan2(s.from.y - g.cy, s.from.x - g.cx);
  g.sweep = std::min(2 * M_PI, s.length() / g.rho);  // the validator's angle (exact products, from == to: 2π)
  g.dir = s.ccw ? 1 : -1;
  return true;
}

/// A few dozen ulps of the largest coordinate involved: more than rounding a computed point to
/// doubles (and cos/sin) can move it.
double marginOf(double scale) { return std::ldexp(std::max(scale, 1e-300), -46); }

Point exact(PointD p) { return {exactFromDouble(p.x), exactFromDouble(p.y)}; }
bool same(PointD a, PointD b) { return a.x == b.x && a.y == b.y; }

}  // namespace

void sampleArc(const PathSegment& s, double tolerance, ArcSide side, std::vector<PointD>& out) {
  ArcGeom g;
  if (!arcGeom(s, g) || g.sweep == 0) {
    out.push_back(s.to);
    return;
  }
  const double m = marginOf(std::max(std::abs(g.cx), std::abs(g.cy)) + g.rho);
  const double t = std::max(tolerance, 8 * m);
  if (side == ArcSide::kOutside) {
    // a polygon whose edges are tangent to the circle of radius ρ' = ρ + m, vertices at
    // ρ' / cos(h/2) + m (within t of the circle ρ), except its first and last edges: those run on
    // the tangents at `from` and `to` themselves, so that where those are axis-parallel (grid maps:
    // every arc ends on one) they are exact, and a boundary pinched to a point between two
    // C-obstacles (a gap exactly 2r wide) passes it along the common tangent
    const double rp = g.rho + m;
    const double c = std::min(1.0, rp / (g.rho + t - m));
    const double h = std::min(2 * std::acos(c), M_PI / 2);
    const int n = static_cast<int>(std::min<double>(kMaxPiecesPerArc, std::max(2.0, std::ceil(g.sweep / std::max(h, 1e-300)))));
    const double hh = g.sweep / n;
    const double R = rp / std::cos(hh / 2) + m;
    // along the end tangents far enough that the next edge clears the circle ρ by m as well
    const double d = rp * std::tan(hh / 2) + 2 * m / std::sin(hh);
    auto endVertex = [&](PointD p, double sign) {  // sign +1 at `from` (ahead), −1 at `to` (back)
      const double ex = p.x - g.cx, ey = p.y - g.cy, len = std::hypot(ex, ey);
      const double tx = -g.dir * ey / len, ty = g.dir * ex / len;  // direction of travel
      const double out = (ex == 0 || ey == 0) ? 0 : m / len;          // off axis: a margin outward
      return PointD{p.x + sign * d * tx + out * ex, p.y + sign * d * ty + out * ey};
    };
    out.push_back(endVertex(s.from, 1));
    for (int k = 1; k + 1 < n; ++k) {
      const double a = g.a0 + g.dir * (k + 0.5) * hh;
      out.push_back({g.cx + R * std::cos(a), g.cy + R * std::sin(a)});
    }
    const double ex = s.to.x - g.cx, ey = s.to.y - g.cy;
    if (ex != 0 || ey != 0) out.push_back(endVertex(s.to, -1));
    else {
      const double a = g.a0 + g.dir * (n - 0.5) * hh;
      out.push_back({g.cx + R * std::cos(a), g.cy + R * std::sin(a)});
    }
  } else if (g.rho > 4 * m) {
    // chords between points at radius ρ − m: the sagitta ρ − (ρ − m)·cos(h/2) stays within t
    const double rm = g.rho - m;
    const double c = std::max(-1.0, std::min(1.0, (g.rho - t) / rm));
    const double h = std::min(2 * std::acos(c), M_PI / 2);
    const int n = static_cast<int>(std::min<double>(kMaxPiecesPerArc, std::max(1.0, std::ceil(g.sweep / std::max(h, 1e-300)))));
    const double hh = g.sweep / n;
    for (int k = 1; k < n; ++k) {
      const double a = g.a0 + g.dir * k * hh;
      out.push_back({g.cx + rm * std::cos(a), g.cy + rm * std::sin(a)});
    }
  }
  out.push_back(s.to);
}

std::vector<PointD> outerPolyline(const Path& path, double tolerance) {
  std::vector<PointD> pts{path.start};
  for (const PathSegment& s : path.segments) {
    if (!same(s.from, pts.back())) pts.push_back(s.from);
    if (s.kind == PathSegment::Kind::kLine) pts.push_back(s.to);
    else sampleArc(s, tolerance, ArcSide::kOutside, pts);
  }
  return pts;
}

SafePolyline safePolyline(const Path& path, const Workspace& w, const Rational& r, double tolerance) {
  SafePolyline out;
  out.points.push_back(path.start);
  ClearanceChecker check(w, r);
  std::vector<PointD> trial;
  auto linesClear = [&](PointD from, const std::vector<PointD>& pts) {
    PointD a = from;
    for (PointD b : pts) {
      if (!check.clear(exact(a), exact(b))) return false;
      a = b;
    }
    return true;
  };
  for (std::size_t k = 0; k < path.segments.size(); ++k) {
    const PathSegment& s = path.segments[k];
    if (!same(s.from, out.points.back())) out.points.push_back(s.from);
    if (s.kind == PathSegment::Kind::kLine) {
      out.points.push_back(s.to);
      continue;
    }
    bool found = false;
    constexpr int kDepth = 10;  // tolerance down to 4^-10 of the asked one
    for (int depth = 0; depth <= kDepth && !found; ++depth) {
      for (ArcSide side : {ArcSide::kOutside, ArcSide::kInside}) {
        trial.clear();
        sampleArc(s, std::ldexp(tolerance, -2 * depth), side, trial);
        if (linesClear(s.from, trial)) {
          found = true;
          break;
        }
      }
      // an arc the validator rejects cannot be sampled safely: no point in refining it
      if (!found && depth == 0 && !check.clearArc(exact(s.from), exact(s.to), exact(s.center), s.ccw)) break;
      if (!found && depth == kDepth && out.unsafeSegment < 0) out.unsafeSegment = static_cast<int>(k);
    }
    if (!found) {
      trial.clear();
      sampleArc(s, tolerance, ArcSide::kOutside, trial);
    }
    out.points.insert(out.points.end(), trial.begin(), trial.end());
  }
  return out;
}

namespace {

/// One ring of a loop with its arcs sampled towards the loop's left (`towardLeft`) or right, each
/// arc to its own tolerance; owner[i] is the piece vertex i comes from.
std::vector<PointD> ringOf(const CurveLoop& loop, const std::vector<double>& tols, bool towardLeft, std::vector<int>& owner) {
  std::vector<PointD> ring, tmp;
  owner.clear();
  for (std::size_t j = 0; j < loop.pieces.size(); ++j) {
    const PathSegment& s = loop.pieces[j];
    auto push = [&](PointD p) {
      if (!ring.empty() && same(ring.back(), p)) return;
      ring.push_back(p);
      owner.push_back(static_cast<int>(j));
    };
    push(s.from);
    if (s.kind != PathSegment::Kind::kArc) continue;
    tmp.clear();
    // the left of a counter-clockwise arc is the inside of its circle
    sampleArc(s, tols[j], s.ccw == towardLeft ? ArcSide::kInside : ArcSide::kOutside, tmp);
    for (std::size_t i = 0; i + 1 < tmp.size(); ++i) push(tmp[i]);  // the last is the next piece's from
  }
  while (ring.size() > 1 && same(ring.front(), ring.back())) {
    ring.pop_back();
    owner.pop_back();
  }
  return ring;
}

struct Dir {
  double x = 0, y = 0;
};
Dir unit(PointD a, PointD b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l = std::hypot(dx, dy);
  return l > 0 ? Dir{dx / l, dy / l} : Dir{};
}

/// Where vertex i moves to go `mu` into the region on the ring's left: along the bisector of its two
/// edges' left normals, by the mitre length (capped), or straight back out of a spike.
PointD nudged(const std::vector<PointD>& ring, std::size_t i, double mu) {
  const std::size_t n = ring.size();
  const PointD p = ring[(i + n - 1) % n], v = ring[i], q = ring[(i + 1) % n];
  const Dir ui = unit(p, v), uo = unit(v, q);
  Dir b{-ui.y - uo.y, ui.x + uo.x};  // sum of the left normals
  double len = std::hypot(b.x, b.y), dist = mu;
  if (len > 0.1) {
    dist = mu * std::min(2 / len, 20.0);
    b = {b.x / len, b.y / len};
  } else {  // a spike: the region lies back along the way the boundary came
    b = {uo.x - ui.x, uo.y - ui.y};
    len = std::hypot(b.x, b.y);
    if (len == 0) b = {-ui.y, ui.x}, len = 1;
    b = {b.x / len, b.y / len};
  }
  return {v.x + dist * b.x, v.y + dist * b.y};
}

/// Proper crossing of segments ab and cd (doubles: for the shape of the ring, not for safety).
bool crosses(PointD a, PointD b, PointD c, PointD d) {
  auto orient = [](PointD p, PointD q, PointD r) {
    const double v = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    return (v > 0) - (v < 0);
  };
  return orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
}

/// A ring being repaired: its points, the piece each comes from, and which edges pass the exact test.
struct WorkRing {
  std::vector<PointD> pts;
  std::vector<int> owner;
  std::vector<char> ok;
  std::size_t size() const { return pts.size(); }
  std::size_t next(std::size_t i) const { return (i + 1) % pts.size(); }
  std::size_t prev(std::size_t i) const { return (i + pts.size() - 1) % pts.size(); }
};

/// Cusps and sharp spikes: where two arcs (or an arc and a line) of the boundary meet tangentially
/// with the region between them, the boundary reverses; where they meet at a small angle (a gap a
/// little wider than 2r), it nearly does. Replaced outside their circles, the two sides run along
/// (nearly) the same tangent there and may cross; the tip is cut straight across where the cut
/// passes the exact test and the two sides no longer cross (a sliver of area). A corner of the other
/// kind (the region outside a sharp turn) cannot be cut: the cut would cross the obstacle, and the
/// exact test refuses it.
void cutCusps(WorkRing& w, ClearanceChecker& check, double tolerance, double margin) {
  for (std::size_t i = 0; i < w.size() && w.size() > 4; ++i) {
    const Dir ui = unit(w.pts[w.prev(i)], w.pts[i]), uo = unit(w.pts[i], w.pts[w.next(i)]);
    if (ui.x * uo.x + ui.y * uo.y > -0.866) continue;  // turns by less than 150°
    // walk s back and forth along the ring from the tip
    for (double s = 8 * tolerance; s < 1e6 * tolerance; s *= 2) {
      const std::size_t n = w.size();
      std::size_t a = i, b = i;  // P lies on edge (prev(a), a), Q on edge (b, next(b))
      double left = s;
      while (true) {
        const std::size_t pa = (a + n - 1) % n;
        const double l = std::hypot(w.pts[a].x - w.pts[pa].x, w.pts[a].y - w.pts[pa].y);
        if (l >= left || pa == i) break;
        left -= l;
        a = pa;
      }
      const std::size_t pa = (a + n - 1) % n;
      const double la = std::hypot(w.pts[a].x - w.pts[pa].x, w.pts[a].y - w.pts[pa].y);
      const double ta = la > 0 ? std::min(1.0, left / la) : 0;
      // P and Q a few ulps into the region (left of their edges): the sides may be rounded outward
      const Dir ea = unit(w.pts[pa], w.pts[a]);
      const PointD P{w.pts[a].x + ta * (w.pts[pa].x - w.pts[a].x) - 4 * margin * ea.y,
                     w.pts[a].y + ta * (w.pts[pa].y - w.pts[a].y) + 4 * margin * ea.x};
      double right = s;
      while (true) {
        const std::size_t nb = (b + 1) % n;
        const double l = std::hypot(w.pts[nb].x - w.pts[b].x, w.pts[nb].y - w.pts[b].y);
        if (l >= right || nb == pa) break;
        right -= l;
        b = nb;
      }
      const std::size_t nb = (b + 1) % n;
      const double lb = std::hypot(w.pts[nb].x - w.pts[b].x, w.pts[nb].y - w.pts[b].y);
      const double tb = lb > 0 ? std::min(1.0, right / lb) : 0;
      const Dir eb = unit(w.pts[b], w.pts[nb]);
      const PointD Q{w.pts[b].x + tb * (w.pts[nb].x - w.pts[b].x) - 4 * margin * eb.y,
                     w.pts[b].y + tb * (w.pts[nb].y - w.pts[b].y) + 4 * margin * eb.x};
      // the vertices a … b (cyclically) go; at least 3 must stay besides P and Q
      std::size_t removed = (b + n - a) % n + 1;
      if (removed + 3 > n || pa == nb) break;
      // the cut must leave no spike at its ends (where both sides run along one tangent, a cut
      // shorter than that stretch has length zero) and must not cross the sides or the obstacles
      const Dir up = unit(w.pts[pa], P), pq = unit(P, Q), qn = unit(Q, w.pts[nb]);
      if ((pq.x == 0 && pq.y == 0) || up.x * pq.x + up.y * pq.y < -0.866 || pq.x * qn.x + pq.y * qn.y < -0.866) continue;
      if (crosses(w.pts[pa], P, Q, w.pts[nb]) || !check.clear(exact(P), exact(Q))) continue;
      std::vector<PointD> pts;
      std::vector<int> owner;
      for (std::size_t k = 0, j = nb; k < n - removed; ++k, j = (j + 1) % n) {
        pts.push_back(w.pts[j]);
        owner.push_back(w.owner[j]);
      }
      // pts runs nb … pa; append P, Q
      pts.push_back(P);
      owner.push_back(w.owner[pa]);
      pts.push_back(Q);
      owner.push_back(w.owner[b]);
      w.pts.swap(pts);
      w.owner.swap(owner);
      i = static_cast<std::size_t>(-1);  // indices changed: look again from the start (cuts only shrink the ring)
      break;
    }
  }
}

/// Local repairs of edges the exact test rejects: move an end (or both) a little into the region
/// (vertices rounded to doubles on the wrong side), else drop an end where the shortcut passes. A
/// change is kept only when every edge it touches passes.
void repair(WorkRing& w, ClearanceChecker& check, double tolerance, double mu0) {
  auto edgeOk = [&](const std::vector<PointD>& pts, std::size_t i) {
    return check.clear(exact(pts[i]), exact(pts[(i + 1) % pts.size()]));
  };
  for (std::size_t i = 0; i < w.size() && w.size() > 3; ++i) {
    if (w.ok[i]) continue;
    const std::size_t j = w.next(i), p = w.prev(i), q = w.next(j);
    bool fixed = false;
    for (double mu = mu0; !fixed && mu <= tolerance; mu *= 4) {
      for (int which = 0; which < 3 && !fixed; ++which) {  // move j, move i, move both
        std::vector<PointD> t = w.pts;
        if (which != 1) t[j] = nudged(w.pts, j, mu);
        if (which != 0) t[i] = nudged(w.pts, i, mu);
        const bool good = edgeOk(t, i) && (which == 1 || edgeOk(t, j)) && (which == 0 || edgeOk(t, p));
        if (!good) continue;
        w.pts.swap(t);
        w.ok[i] = 1;
        if (which != 1) w.ok[j] = 1;
        if (which != 0) w.ok[p] = 1;
        fixed = true;
      }
    }
    if (fixed) continue;
    if (check.clear(exact(w.pts[i]), exact(w.pts[q]))) {  // drop j
      w.pts.erase(w.pts.begin() + static_cast<std::ptrdiff_t>(j));
      w.owner.erase(w.owner.begin() + static_cast<std::ptrdiff_t>(j));
      w.ok.erase(w.ok.begin() + static_cast<std::ptrdiff_t>(j));
      w.ok[j < i ? i - 1 : i] = 1;
      i = static_cast<std::size_t>(-1);  // from the start: indices moved
    } else if (check.clear(exact(w.pts[p]), exact(w.pts[j]))) {  // drop i
      w.pts.erase(w.pts.begin() + static_cast<std::ptrdiff_t>(i));
      w.owner.erase(w.owner.begin() + static_cast<std::ptrdiff_t>(i));
      w.ok.erase(w.ok.begin() + static_cast<std::ptrdiff_t>(i));
      w.ok[(i + w.ok.size() - 1) % w.ok.size()] = 1;
      i = static_cast<std::size_t>(-1);
    }
  }
}

/// The ring of `loop` (region on its left) with every edge accepted by `check`, or empty.
std::vector<PointD> safeRing(const CurveLoop& loop, ClearanceChecker& check, double tolerance) {
  if (loop.pieces.empty()) return {};
  std::vector<double> tols(loop.pieces.size(), tolerance);
  WorkRing w;
  auto allOk = [&] { return std::all_of(w.ok.begin(), w.ok.end(), [](char c) { return c != 0; }); };
  auto verify = [&] {
    w.ok.assign(w.size(), 0);
    for (std::size_t i = 0; i < w.size(); ++i) w.ok[i] = check.clear(exact(w.pts[i]), exact(w.pts[w.next(i)]));
  };
  for (int attempt = 0; attempt < 5; ++attempt) {
    w.pts = ringOf(loop, tols, true, w.owner);
    if (w.size() < 3) return {};
    double scale = 0;
    for (PointD p : w.pts) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
    const double m = marginOf(scale);
    verify();
    // vertices rounded to doubles on the wrong side (a whole edge may lie an ulp outside, e.g. a
    // rectangle x = 2.65 whose corners all round outward): move the ends of every failing edge into
    // the region together, a few ulps at first, four times farther each round, up to 2^-36 of the
    // coordinates (far below the tolerance; what rounding cannot explain is left to the steps below)
    for (double mu = m; !allOk() && mu <= std::ldexp(scale, -36); mu *= 4) {
      const std::size_t k = w.size();
      std::vector<char> move(k, 0);
      for (std::size_t i = 0; i < k; ++i)
        if (!w.ok[i]) move[i] = move[w.next(i)] = 1;
      std::vector<PointD> moved = w.pts;
      for (std::size_t i = 0; i < k; ++i)
        if (move[i]) moved[i] = nudged(w.pts, i, mu);
      w.pts.swap(moved);
      for (std::size_t i = 0; i < k; ++i)
        if (move[i]) {
          w.ok[w.prev(i)] = check.clear(exact(w.pts[w.prev(i)]), exact(w.pts[i]));
          w.ok[i] = check.clear(exact(w.pts[i]), exact(w.pts[w.next(i)]));
        }
    }
    cutCusps(w, check, tolerance, m);
    verify();
    if (allOk()) break;
    repair(w, check, tolerance, m);
    if (allOk()) break;
    // lines that still fail cross something near the arc they replace: sample those arcs finer
    bool refined = false;
    std::vector<char> done(loop.pieces.size(), 0);
    for (std::size_t i = 0; i < w.size(); ++i) {
      if (w.ok[i]) continue;
      for (int o : {w.owner[i], w.owner[w.next(i)]}) {
        const auto j = static_cast<std::size_t>(o);
        if (done[j] || loop.pieces[j].kind != PathSegment::Kind::kArc) continue;
        done[j] = 1;
        tols[j] /= 16;
        refined = true;
      }
    }
    if (!refined) break;
  }
  if (!allOk() || w.size() < 3) return {};
  // zero-width spikes left (two edges folding back on one line): cut where the shortcut passes
  std::vector<PointD>& ring = w.pts;
  for (bool changed = true; changed && ring.size() > 3;) {
    changed = false;
    for (std::size_t i = 0; i < ring.size() && ring.size() > 3; ++i) {
      const std::size_t n = ring.size();
      const PointD p = ring[(i + n - 1) % n], v = ring[i], q = ring[(i + 1) % n];
      const double ax = v.x - p.x, ay = v.y - p.y, bx = q.x - v.x, by = q.y - v.y;
      const double cross = ax * by - ay * bx, dot = ax * bx + ay * by;
      const double la = std::hypot(ax, ay), lb = std::hypot(bx, by);
      const bool degenerate = la == 0 || lb == 0 || (dot < 0 && std::abs(cross) <= 1e-9 * la * lb);
      if (degenerate && check.clear(exact(p), exact(q))) {
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
      }
    }
  }
  return ring;
}

}  // namespace

std::vector<SampledRegion> sampleFreeRegions(const std::vector<CurveRegion>& components, const Workspace& w,
                                             const Rational& r, double tolerance) {
  std::vector<SampledRegion> out;
  if (components.empty()) return out;
  ClearanceChecker check(w, r);
  for (const CurveRegion& c : components) {
    SampledRegion s;
    s.outer = safeRing(c.outer, check, tolerance);
    bool ok = !s.outer.empty();
    for (std::size_t h = 0; ok && h < c.holes.size(); ++h) {
      s.holes.push_back(safeRing(c.holes[h], check, tolerance));
      ok = !s.holes.back().empty();
    }
    if (!ok) s = SampledRegion();
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<SampledRegion> sampleRegions(const std::vector<CurveRegion>& regions, double tolerance, bool inside) {
  std::vector<SampledRegion> out;
  std::vector<int> owner;
  for (const CurveRegion& c : regions) {
    SampledRegion s;
    s.outer = ringOf(c.outer, std::vector<double>(c.outer.pieces.size(), tolerance), inside, owner);
    for (const CurveLoop& h : c.holes) s.holes.push_back(ringOf(h, std::vector<double>(h.pieces.size(), tolerance), inside, owner));
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace coverkit
