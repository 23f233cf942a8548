#pragma once
// Seeded generators (std::mt19937_64 with our own integer-to-range mapping, so the same seed gives
// the same world on every platform and library version).
#include <coverkit/datasets/readers.h>

#include <cstdint>
#include <string>

namespace coverkit::datasets {

/// Axis-aligned rectangles, convex and non-convex polygons, stars; rotated rectangles and discs (as
/// 24-gons) for worlds whose obstacles are not aligned with the grid; mixed: one of the six drawn
/// per obstacle.
enum class ObstacleShape { kRectangle, kConvex, kNonConvex, kStar, kRotatedRectangle, kDisc, kMixed };
bool parseObstacleShape(const std::string& s, ObstacleShape& out);

struct PolygonWorldSpec {
  int width = 20, height = 20;         ///< workspace box [0,width]×[0,height]
  int count = 10;                      ///< obstacles attempted
  double minSize = 1, maxSize = 3;     ///< obstacle diameter range
  ObstacleShape shape = ObstacleShape::kRectangle;
  std::uint64_t seed = 1;
};
/// Obstacles on a 1/100 lattice, pairwise separated and kept off the border (they are holes).
Workspace generatePolygonWorld(const PolygonWorldSpec& spec);

struct GridMapSpec {
  int width = 32, height = 32;
  double density = 0.2;                ///< fraction of blocked cells aimed at
  bool clustered = false;              ///< grow blobs instead of scattering single cells
  Rational resolution = 1;
  std::uint64_t seed = 1;
};
OccupancyGrid generateGridMap(const GridMapSpec& spec);

}  // namespace coverkit::datasets
