#pragma once
// Private to geometry/src: the exact C-free of a CSpace, for the library's other CGAL files.
#include <coverkit/geometry/cspace.h>

#include "circle_segment_area.h"

#include <vector>

namespace coverkit::detail {

struct CSpaceAccess {
  /// The components of C-free, largest first (the order of CSpace::components()).
  static const std::vector<CPolygonWithHoles>& parts(const CSpace& s);
};

}  // namespace coverkit::detail
