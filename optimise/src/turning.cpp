#include <coverkit/optimise/turning.h>

#include <Eigen/Core>

#include <cmath>

namespace coverkit::optimise {

double bendingEnergy(const std::vector<PointD>& pts) {
  double e = 0;
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
    const Eigen::Vector2d a(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y), b(pts[i + 1].x - pts[i].x, pts[i + 1].y - pts[i].y);
    const double la = a.norm(), lb = b.norm();
    if (la == 0 || lb == 0) continue;
    const double turn = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    const double k = turn / (0.5 * (la + lb));
    e += k * k;
  }
  return e;
}

}  // namespace coverkit::optimise
