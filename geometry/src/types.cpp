#include <coverkit/geometry/path.h>
#include <coverkit/geometry/types.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace coverkit {

Box Workspace::bbox() const {
  Box b;
  bool first = true;
  for (const Ring* r : rings()) {
    for (const Point& p : *r) {
      if (first) {
        b = {p.x, p.y, p.x, p.y};
        first = false;
      }
      if (p.x < b.xmin) b.xmin = p.x;
      if (p.y < b.ymin) b.ymin = p.y;
      if (p.x > b.xmax) b.xmax = p.x;
      if (p.y > b.ymax) b.ymax = p.y;
    }
  }
  return b;
}

std::vector<const Ring*> Workspace::rings() const {
  std::vector<const Ring*> out;
  for (const Region& r : regions) {
    out.push_back(&r.outer);
    for (const Ring& h : r.holes) out.push_back(&h);
  }
  return out;
}

std::size_t Workspace::vertexCount() const {
  std::size_t n = 0;
  for (const Ring* r : rings()) n += r->size();
  return n;
}

bool insideRing(const Ring& r, const Point& p) {
  // Which edges cross the horizontal line is decided exactly; on which side of p a crossing lies
  // is decided in doubles when it is far from p (margin far above double error), exactly otherwise.
  bool in = false;
  const double px = p.x.get_d(), py = p.y.get_d();
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Point& a = r[i];
    const Point& b = r[(i + 1) % r.size()];
    if ((a.y > p.y) == (b.y > p.y)) continue;
    const double ax = a.x.get_d(), ay = a.y.get_d(), bx = b.x.get_d(), by = b.y.get_d();
    const double xd = ax + (py - ay) * (bx - ax) / (by - ay);
    const double margin = 1e-9 * (1 + std::abs(ax) + std::abs(bx) + std::abs(px));
    bool right;
    if (xd > px + margin) right = true;
    else if (xd < px - margin) right = false;
    else right = Rational(a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) > p.x;
    if (right) in = !in;
  }
  return in;
}

Rational signedArea2(const Ring& ring) {
  Rational a = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = ring[i];
    const Point& q = ring[(i + 1) % n];
    a += p.x * q.y - q.x * p.y;
  }
  return a;
}

Rational freeArea(const Workspace& w) {
  Rational a = 0;
  for (const Region& r : w.regions) {
    a += abs(signedArea2(r.outer));
    for (const Ring& h : r.holes) a -= abs(signedArea2(h));
  }
  return Rational(a / 2);
}

void normalise(Workspace& w) {
  for (Region& r : w.regions) {
    if (signedArea2(r.outer) < 0) std::reverse(r.outer.begin(), r.outer.end());
    for (Ring& h : r.holes)
      if (signedArea2(h) > 0) std::reverse(h.begin(), h.end());
  }
}

const char* toString(PlanStatus s) {
  switch (s) {
    case PlanStatus::kExactSolution: return "exact_solution";
    case PlanStatus::kPartialCoverage: return "partial_coverage";
    case PlanStatus::kInvalidStart: return "invalid_start";
    case PlanStatus::kNoFreeSpace: return "no_free_space";
    case PlanStatus::kTimeout: return "timeout";
  }
  return "unknown";
}

namespace {
double arcSweep(const PathSegment& s) {
  double a0 = std::atan2(s.from.y - s.center.y, s.from.x - s.center.x);
  double a1 = std::atan2(s.to.y - s.center.y, s.to.x - s.center.x);
  double d = s.ccw ? a1 - a0 : a0 - a1;
  while (d < 0) d += 2 * M_PI;
  if (d == 0 && (s.from.x != s.to.x || s.from.y != s.to.y)) d = 0;
  return d;
}
}  // namespace

double PathSegment::length() const {
  if (kind == Kind::kLine) return std::hypot(to.x - from.x, to.y - from.y);
  double rad = std::hypot(from.x - center.x, from.y - center.y);
  return rad * arcSweep(*this);
}

Path Path::fromPoints(const std::vector<PointD>& pts) {
  Path p;
  if (pts.empty()) return p;
  p.start = pts.front();
  for (std::size_t i = 1; i < pts.size(); ++i) p.segments.push_back(PathSegment::line(pts[i - 1], pts[i]));
  return p;
}

double Path::length() const {
  double l = 0;
  for (const auto& s : segments) l += s.length();
  return l;
}

std::vector<PointD> Path::polyline(double tolerance) const {
  std::vector<PointD> pts{start};
  for (const auto& s : segments) {
    if (s.kind == PathSegment::Kind::kArc) {
      double rad = std::hypot(s.from.x - s.center.x, s.from.y - s.center.y);
      double sweep = arcSweep(s);
      // chord error rad(1 - cos(h/2)) <= tol  =>  h <= 2 acos(1 - tol/rad)
      double h = rad > tolerance ? 2 * std::acos(1 - tolerance / rad) : sweep;
      int n = std::max(1, static_cast<int>(std::ceil(sweep / std::max(h, 1e-9))));
      double a0 = std::atan2(s.from.y - s.center.y, s.from.x - s.center.x);
      for (int i = 1; i < n; ++i) {
        double a = a0 + (s.ccw ? 1 : -1) * sweep * i / n;
        pts.push_back({s.center.x + rad * std::cos(a), s.center.y + rad * std::sin(a)});
      }
    }
    pts.push_back(s.to);
  }
  return pts;
}

}  // namespace coverkit
