// Fillets between two pieces of a path (see fillet.h).
#include <coverkit/geometry/fillet.h>

#include <algorithm>
#include <cmath>

namespace coverkit {

namespace {
double dist(PointD a, PointD b) { return std::hypot(a.x - b.x, a.y - b.y); }
double wrapAngle(double a) { return std::remainder(a, 2 * M_PI); }
}  // namespace

double headingOf(const PathSegment& s, bool atEnd) {
  if (s.kind == PathSegment::Kind::kLine) return std::atan2(s.to.y - s.from.y, s.to.x - s.from.x);
  const PointD p = atEnd ? s.to : s.from;
  const double a = std::atan2(p.y - s.center.y, p.x - s.center.x);
  return a + (s.ccw ? M_PI / 2 : -M_PI / 2);
}

double turnAt(const PathSegment& a, const PathSegment& b) { return wrapAngle(headingOf(b, false) - headingOf(a, true)); }

PathSegment reversedPiece(const PathSegment& s) {
  return s.kind == PathSegment::Kind::kLine ? PathSegment::line(s.to, s.from) : PathSegment::arc(s.to, s.from, s.center, !s.ccw);
}

bool lineCircleCrossings(PointD p, PointD d, PointD c, double R, double& s0, double& s1) {
  const PointD w{p.x - c.x, p.y - c.y};
  const double bq = w.x * d.x + w.y * d.y, disc = bq * bq - (w.x * w.x + w.y * w.y - R * R);
  if (!(disc >= 0)) return false;
  s0 = -bq - std::sqrt(disc);
  s1 = -bq + std::sqrt(disc);
  return true;
}

bool circleCrossings(PointD c1, double r1, PointD c2, double r2, PointD& left, PointD& right) {
  const double d = dist(c1, c2);
  if (!(d > 0) || d > r1 + r2 || d < std::abs(r1 - r2)) return false;
  const double l = (r1 * r1 - r2 * r2 + d * d) / (2 * d), h = std::sqrt(std::max(0.0, r1 * r1 - l * l));
  const PointD e{(c2.x - c1.x) / d, (c2.y - c1.y) / d}, q{c1.x + l * e.x, c1.y + l * e.y};
  left = {q.x - h * e.y, q.y + h * e.x};
  right = {q.x + h * e.y, q.y - h * e.x};
  return true;
}

namespace {

/// Two arcs: the fillet's centre is at R ∓ rho from each arc's centre (− where the arc turns the
/// same way as the corner), where those two circles cross nearest the joint.
bool filletArcs(const PathSegment& a, const PathSegment& b, double rho, PathSegment& a2, PathSegment& f, PathSegment& b2) {
  const double theta = turnAt(a, b);
  if (theta == 0) return false;
  const bool left = theta > 0;
  const PointD oa = a.center, ob = b.center, p = a.to;
  const double Ra = dist(a.from, oa), Rb = dist(b.from, ob);
  const double ra = a.ccw == left ? Ra - rho : Ra + rho, rb = b.ccw == left ? Rb - rho : Rb + rho;
  PointD c1, c2;
  if (ra <= 0 || rb <= 0 || !circleCrossings(oa, ra, ob, rb, c1, c2)) return false;
  const PointD c = dist(c1, p) <= dist(c2, p) ? c1 : c2;
  const PointD t1{oa.x + (c.x - oa.x) * Ra / ra, oa.y + (c.y - oa.y) * Ra / ra};
  const PointD t2{ob.x + (c.x - ob.x) * Rb / rb, ob.y + (c.y - ob.y) * Rb / rb};
  const PathSegment na = PathSegment::arc(a.from, t1, oa, a.ccw), nf = PathSegment::arc(t1, t2, c, left),
                    nb = PathSegment::arc(t2, b.to, ob, b.ccw);
  // tangent at both ends, each arc shortened (not wrapped round), less than a half turn
  if (std::abs(turnAt(na, nf)) > 1e-6 || std::abs(turnAt(nf, nb)) > 1e-6) return false;
  if (!(na.length() < a.length()) || !(nb.length() < b.length()) || !(nf.length() < rho * M_PI)) return false;
  a2 = na;
  f = nf;
  b2 = nb;
  return true;
}

}  // namespace

bool filletCorner(const PathSegment& a, const PathSegment& b, double rho, PathSegment& a2, PathSegment& f, PathSegment& b2) {
  if (!(rho > 0)) return false;
  if (a.kind != PathSegment::Kind::kLine && b.kind != PathSegment::Kind::kLine) return filletArcs(a, b, rho, a2, f, b2);
  if (a.kind != PathSegment::Kind::kLine) {
    // an arc then a line: the line then the arc, travelled backwards
    PathSegment ra, rf, rb;
    if (b.kind != PathSegment::Kind::kLine || !filletCorner(reversedPiece(b), reversedPiece(a), rho, rb, rf, ra)) return false;
    b2 = reversedPiece(rb);
    f = reversedPiece(rf);
    a2 = reversedPiece(ra);
    return true;
  }
  const PointD p = a.to;
  const double len = dist(a.from, a.to);
  if (!(len > 0) || !(b.length() > 0)) return false;
  const PointD d{(a.to.x - a.from.x) / len, (a.to.y - a.from.y) / len};
  const double theta = turnAt(a, b);
  if (theta == 0) return false;
  const bool left = theta > 0;
  const PointD n = left ? PointD{-d.y, d.x} : PointD{d.y, -d.x};
  PointD c, t2;
  double s;
  if (b.kind == PathSegment::Kind::kLine) {
    s = -rho * std::tan(std::abs(theta) / 2);
    c = {p.x + d.x * s + n.x * rho, p.y + d.y * s + n.y * rho};
    const double lb = dist(b.from, b.to);
    t2 = {p.x + (b.to.x - b.from.x) / lb * -s, p.y + (b.to.y - b.from.y) / lb * -s};
  } else {
    // the centre on the line parallel to a at rho, at R − rho from b's centre when b turns the
    // same way as the corner, R + rho when it turns the other way
    const PointD o = b.center;
    const double R = dist(b.from, o);
    const double rf = b.ccw == left ? R - rho : R + rho;
    if (rf <= 0) return false;
    double s0, s1;
    if (!lineCircleCrossings({p.x + n.x * rho, p.y + n.y * rho}, d, o, rf, s0, s1)) return false;
    s = s1 > 0 ? s0 : s1;   // the root nearer the joint from behind, when it is behind
    if (s > 0) return false;
    c = {p.x + d.x * s + n.x * rho, p.y + d.y * s + n.y * rho};
    t2 = {o.x + (c.x - o.x) * R / rf, o.y + (c.y - o.y) * R / rf};
  }
  if (-s >= len) return false;
  const PointD t1{p.x + d.x * s, p.y + d.y * s};
  const PathSegment na = PathSegment::line(a.from, t1), nf = PathSegment::arc(t1, t2, c, left);
  const PathSegment nb = b.kind == PathSegment::Kind::kLine ? PathSegment::line(t2, b.to) : PathSegment::arc(t2, b.to, b.center, b.ccw);
  // tangent at both ends, t2 inside b, less than a half turn: otherwise it is the wrong circle
  if (std::abs(turnAt(na, nf)) > 1e-6 || std::abs(turnAt(nf, nb)) > 1e-6) return false;
  if (!(nb.length() < b.length()) || !(nf.length() < rho * M_PI)) return false;
  a2 = na;
  f = nf;
  b2 = nb;
  return true;
}

FilletCount roundCorners(std::vector<PathSegment>& segs, std::size_t from, const FilletSearch& search,
                         const std::function<double(std::size_t, const PathSegment&, const PathSegment&, bool)>& room,
                         const std::function<bool(std::size_t, const PathSegment&, const PathSegment&, const PathSegment&, const PathSegment&,
                                                  const PathSegment&)>& accept,
                         const std::function<void(std::size_t, const PathSegment&, const PathSegment&, const PathSegment&, double)>& rounded) {
  FilletCount count;
  if (segs.size() < from + 2) return count;
  const double minTurn = search.minTurnDeg * M_PI / 180, maxTurn = search.maxTurnDeg * M_PI / 180;
  std::vector<PathSegment> out;   // what replaces segs[from, end)
  PathSegment cur = segs[from];
  for (std::size_t i = from; i + 1 < segs.size(); ++i) {
    PathSegment next = segs[i + 1];
    const double theta = std::abs(turnAt(cur, next));
    count.corners += theta > minTurn;
    const bool line = search.arcPairs || cur.kind == PathSegment::Kind::kLine || next.kind == PathSegment::Kind::kLine;
    if (theta > minTurn && theta < maxTurn && line && cur.length() > 0 && next.length() > 0) {
      const double room1 = std::min(cur.length(), room(i, cur, next, true)), room2 = room(i + 1, next, cur, false);
      auto attempt = [&](double rho, PathSegment& a2, PathSegment& f, PathSegment& b2) {
        return filletCorner(cur, next, rho, a2, f, b2) && cur.length() - a2.length() <= room1 && next.length() - b2.length() <= room2 &&
               accept(i, cur, next, a2, f, b2);
      };
      PathSegment a2, f, b2;
      double ok = 0, bad = 0;
      for (double rho = search.maxRadius; rho >= search.minRadius && rho > 0; rho /= 2) {
        if (attempt(rho, a2, f, b2)) {
          ok = rho;
          break;
        }
        bad = rho;
      }
      if (ok > 0) {
        for (int step = 0; step < search.bisections && bad > 0; ++step) {
          const double mid = (ok + bad) / 2;
          PathSegment ma, mf, mb;
          if (attempt(mid, ma, mf, mb)) {
            ok = mid;
            a2 = ma;
            f = mf;
            b2 = mb;
          } else {
            bad = mid;
          }
        }
        out.push_back(a2);
        out.push_back(f);
        if (rounded) rounded(i, a2, f, b2, ok);
        ++count.rounded;
        cur = b2;
        continue;
      }
    }
    out.push_back(cur);
    cur = next;
  }
  out.push_back(cur);
  segs.resize(from);
  segs.insert(segs.end(), out.begin(), out.end());
  return count;
}

}  // namespace coverkit
