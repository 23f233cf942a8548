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

/// Throws InputError(file, option, ...) for an unknown extension.
void checkPictureName(const std::string& file, const std::string& option = "--picture");
/// Before any work: the extension is known and the file can be written (datasets::checkOutputFile).
void checkPictureOutput(const std::string& file, const std::string& option = "--picture");
/// The picture's bytes (PNG or SVG by the extension of `file`), drawn in memory; InputError when it
/// cannot be drawn (e.g. coordinates beyond the range of a double).
std::string pictureBytes(const std::string& file, const PictureContent& content);
/// Draws the picture and writes it atomically.
void renderPicture(const std::string& file, const PictureContent& content);

}  // namespace coverkit::experiments
