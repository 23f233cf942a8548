#pragma once
// Map readers. Every reader returns a normalised Workspace (free regions; obstacles are holes) with
// exact rational coordinates, or throws InputError naming the file, the place and the problem.
//
// Formats (details in docs/formats.md):
//  - ROS map_server YAML + PGM/PNG (.yaml/.yml)     - Moving AI grid (.map)
//  - WKT POLYGON / MULTIPOLYGON (.wkt)                - GeoJSON Polygon / MultiPolygon (.geojson, .json)
//  - coverkit text grid (.grid, .txt)
#include <coverkit/geometry/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace coverkit::datasets {

struct MapOptions {
  bool unknownIsFree = false;   ///< ROS maps: unknown pixels are obstacles unless set
};

/// The largest grid any grid reader accepts (ROS image, Moving AI, text grid): 2^28 cells, a
/// 16384 × 16384 image. Checked on the header, before anything of that size is allocated.
constexpr std::int64_t kMaxGridCells = std::int64_t{1} << 28;
/// InputError (naming `file`, `place` and the limit) unless 1 <= width, height and
/// width · height <= kMaxGridCells.
void checkGridSize(const std::string& file, const std::string& place, std::int64_t width, std::int64_t height);

/// A binary occupancy grid: cell (col, row) with row 0 at the BOTTOM; true = obstacle.
struct OccupancyGrid {
  int width = 0, height = 0;
  std::vector<std::uint8_t> blocked;
  Rational resolution = 1, originX = 0, originY = 0;
  bool at(int col, int row) const { return blocked[static_cast<std::size_t>(row) * width + col] != 0; }
};

/// The whole file as bytes; InputError when it is missing, a directory or unreadable.
std::string readTextFile(const std::string& path);

/// Dispatches on the file extension.
Workspace loadMap(const std::string& path, const MapOptions& options = {});

Workspace readRosMap(const std::string& yamlPath, const MapOptions& options = {});
/// The ROS map's grid before it becomes polygons: how every pixel was read (docs/formats.md).
OccupancyGrid readRosGrid(const std::string& yamlPath, const MapOptions& options = {});
Workspace readMovingAi(const std::string& path);
Workspace readWkt(const std::string& path);
Workspace parseWkt(const std::string& text, const std::string& name);
Workspace readGeoJson(const std::string& path);
Workspace parseGeoJson(const std::string& text, const std::string& name);
Workspace readTextGrid(const std::string& path);
Workspace parseTextGrid(const std::string& text, const std::string& name);

/// Free pixels become 4-connected free regions; occupied pixels become merged polygon holes
/// (a vertex only where the boundary turns). Exact; O(pixels).
Workspace gridToWorkspace(const OccupancyGrid& grid, const std::string& name);

/// Polygon input is checked with coverkit::checkWorkspace (geometry/types.h) before anything uses it.

}  // namespace coverkit::datasets
