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
