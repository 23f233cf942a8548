#pragma once
// Turning measures of a polyline, the quantity smoothing reduces (Eigen inside).
#include <coverkit/geometry/path.h>

#include <vector>

namespace coverkit::optimise {

/// Sum of squared discrete curvature (heading change per unit length) over the vertices of a polyline.
double bendingEnergy(const std::vector<PointD>& polyline);

}  // namespace coverkit::optimise
