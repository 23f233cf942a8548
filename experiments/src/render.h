#pragma once
// Pictures with Cairo (PNG or SVG by extension): workspace, cells, spanning tree, paths.
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/path.h>

#include <string>
#include <vector>

namespace coverkit::experiments {

struct PictureContent {
  const Workspace* workspace = nullptr;
  const CellGrid* cells = nullptr;                         ///< optional
  const std::vector<std::pair<PointD, PointD>>* tree = nullptr;   ///< optional
  const std::vector<Path>* paths = nullptr;                ///< optional
  double radius = 0;                                       ///< swept disc shown faintly when > 0
  std::string title;
  const std::vector<CurveRegion>* cfree = nullptr;         ///< optional: C-free components (arcs drawn as arcs)
  const std::vector<CurveRegion>* cobstacles = nullptr;    ///< optional: C-obstacles
};

/// Throws InputError for an unknown extension (checked before anything is written).
void checkPictureName(const std::string& file);
/// Writes the picture atomically.
void renderPicture(const std::string& file, const PictureContent& content);

}  // namespace coverkit::experiments
