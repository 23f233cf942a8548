#pragma once
// Private: a uniform bucket grid over the workspace's boundary edges (double bounding boxes), used
// to find the edges near a query box. The decisions themselves are exact; this only filters.
#include <coverkit/geometry/types.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace coverkit::detail {

struct IndexedEdge {
  const Point* a;
  const Point* b;
  double ax, ay, bx, by;
};

class EdgeIndex {
public:
  explicit EdgeIndex(const Workspace& w) {
    for (const Ring* r : w.rings()) {
      const std::size_t n = r->size();
      for (std::size_t i = 0; i < n; ++i) {
        const Point& a = (*r)[i];
        const Point& b = (*r)[(i + 1) % n];
        edges_.push_back({&a, &b, a.x.get_d(), a.y.get_d(), b.x.get_d(), b.y.get_d()});
      }
    }
    const Box box = w.bbox();
    x0_ = box.xmin.get_d();
    y0_ = box.ymin.get_d();
    const double wdt = std::max(box.xmax.get_d() - x0_, 1e-12), hgt = std::max(box.ymax.get_d() - y0_, 1e-12);
    const double target = std::max<double>(1.0, std::sqrt(static_cast<double>(edges_.size())));
    nx_ = std::clamp(static_cast<int>(target * wdt / std::max(wdt, hgt)) + 1, 1, 2048);
    ny_ = std::clamp(static_cast<int>(target * hgt / std::max(wdt, hgt)) + 1, 1, 2048);
    cw_ = wdt / nx_;
    ch_ = hgt / ny_;
    buckets_.assign(static_cast<std::size_t>(nx_) * ny_, {});
    for (std::size_t i = 0; i < edges_.size(); ++i) {
      const auto& e = edges_[i];
      forBuckets(std::min(e.ax, e.bx), std::min(e.ay, e.by), std::max(e.ax, e.bx), std::max(e.ay, e.by),
                 [&](std::vector<std::size_t>& b) { b.push_back(i); });
    }
    stamp_.assign(edges_.size(), 0);
  }

  const std::vector<IndexedEdge>& edges() const { return edges_; }

  /// Calls f(edge) once for every edge whose bucket meets the box.
  template <class F>
  void query(double xmin, double ymin, double xmax, double ymax, F&& f) {
    ++tick_;
    forBuckets(xmin, ymin, xmax, ymax, [&](std::vector<std::size_t>& b) {
      for (std::size_t i : b) {
        if (stamp_[i] == tick_) continue;
        stamp_[i] = tick_;
        f(edges_[i]);
      }
    });
  }

private:
  template <class F>
  void forBuckets(double xmin, double ymin, double xmax, double ymax, F&& f) {
    // NaN bounds (never produced by the callers, which test finiteness first) select the whole range
    const int i0 = std::isnan(xmin) ? 0 : bucketOf((xmin - x0_) / cw_, nx_);
    const int i1 = std::isnan(xmax) ? nx_ - 1 : bucketOf((xmax - x0_) / cw_, nx_);
    const int j0 = std::isnan(ymin) ? 0 : bucketOf((ymin - y0_) / ch_, ny_);
    const int j1 = std::isnan(ymax) ? ny_ - 1 : bucketOf((ymax - y0_) / ch_, ny_);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) f(buckets_[static_cast<std::size_t>(j) * nx_ + i]);
  }

  /// The bucket of a coordinate t (in bucket units), clamped to [0, n - 1] BEFORE the conversion
  /// to int: a query box far outside the workspace (x = 7.2e9, an arc of radius 1e160, an infinity)
  /// must select the border buckets, never wrap past INT_MAX.
  static int bucketOf(double t, int n) {
    if (!(t > 0)) return 0;
    if (t >= n - 1) return n - 1;
    return static_cast<int>(t);
  }

  std::vector<IndexedEdge> edges_;
  std::vector<std::vector<std::size_t>> buckets_;
  std::vector<unsigned> stamp_;
  unsigned tick_ = 0;
  double x0_ = 0, y0_ = 0, cw_ = 1, ch_ = 1;
  int nx_ = 1, ny_ = 1;
};

/// Squared and plain double distances between points and segments (for filtering only, with
/// margins far above an ulp: sums of squares rather than std::hypot, a library call that took 9 %
/// of a large plan; a square that overflows gives +inf for points that far apart, one that
/// underflows gives 0, both safe).
inline double pointSegDist2(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const double ex = px - (ax + t * dx), ey = py - (ay + t * dy);
  return ex * ex + ey * ey;
}
inline double pointSegDist(double px, double py, double ax, double ay, double bx, double by) {
  return std::sqrt(pointSegDist2(px, py, ax, ay, bx, by));
}
inline double segSegDist2(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
  auto orient = [](double px, double py, double qx, double qy, double rx, double ry) {
    return (qx - px) * (ry - py) - (qy - py) * (rx - px);
  };
  const double o1 = orient(ax, ay, bx, by, cx, cy), o2 = orient(ax, ay, bx, by, dx, dy);
  const double o3 = orient(cx, cy, dx, dy, ax, ay), o4 = orient(cx, cy, dx, dy, bx, by);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return 0;
  return std::min({pointSegDist2(ax, ay, cx, cy, dx, dy), pointSegDist2(bx, by, cx, cy, dx, dy),
                   pointSegDist2(cx, cy, ax, ay, bx, by), pointSegDist2(dx, dy, ax, ay, bx, by)});
}

}  // namespace coverkit::detail
