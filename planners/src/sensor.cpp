// The online Smooth-STC robot's obstacle sensor (sensor.h).
#include <coverkit/planners/sensor.h>

#include <algorithm>
#include <cmath>

namespace coverkit::planners {

ObstacleSensor::ObstacleSensor(const Workspace& w, const CellGrid& cells) : cells_(cells), near_(cells.megaCount()) {
  const double ox = cells.originX().get_d(), oy = cells.originY().get_d(), d = cells.subSizeD(), mega = 2 * d;
  const double pad = 1e-9 * std::max({1.0, std::abs(ox), std::abs(oy), mega * std::max(cells.megaCols(), cells.megaRows())});
  auto index = [&](double v, double origin, int n) { return std::min(n - 1, std::max(0, static_cast<int>(std::floor((v - origin) / mega)))); };
  for (std::size_t g = 0; g < w.regions.size(); ++g) {
    const Region& reg = w.regions[g];
    for (std::size_t k = 0; k <= reg.holes.size(); ++k) {
      const Ring& ring = k == 0 ? reg.outer : reg.holes[k - 1];
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point &a = ring[i], &b = ring[(i + 1) % ring.size()];
        const double x0 = std::min(a.x.get_d(), b.x.get_d()) - d - pad, x1 = std::max(a.x.get_d(), b.x.get_d()) + d + pad;
        const double y0 = std::min(a.y.get_d(), b.y.get_d()) - d - pad, y1 = std::max(a.y.get_d(), b.y.get_d()) + d + pad;
        if (x1 < ox || y1 < oy || x0 > ox + mega * cells.megaCols() || y0 > oy + mega * cells.megaRows()) continue;
        for (int row = index(y0, oy, cells.megaRows()); row <= index(y1, oy, cells.megaRows()); ++row)
          for (int col = index(x0, ox, cells.megaCols()); col <= index(x1, ox, cells.megaCols()); ++col) {
            std::vector<RingRef>& at = near_[static_cast<std::size_t>(row) * cells.megaCols() + col];
            if (at.empty() || at.back().region != g || at.back().ring != k) at.push_back({g, k});
          }
      }
    }
  }
}

void ObstacleSensor::moveTo(int col, int row) {
  if (!cells_.insideMega(col, row) || cells_.mega(col, row) == CellState::kBlocked)
    throw std::logic_error("sensor: the robot cannot be in a blocked mega-cell or outside the grid");
  col_ = col;
  row_ = row;
}

const std::vector<ObstacleSensor::RingRef>& ObstacleSensor::sense(int col, int row) {
  if (col_ < 0 || std::abs(col - col_) + std::abs(row - row_) > 1 || !cells_.insideMega(col, row))
    throw std::logic_error("sensor: asked about a mega-cell that is neither the robot's nor a neighbour of it");
  ++queries_;
  return near_[static_cast<std::size_t>(row) * cells_.megaCols() + col];
}

}  // namespace coverkit::planners
