#pragma once
// Path files: JSON "coverkit.path/1", CSV (robot,seq,x,y) and GeoJSON LineStrings. Spec: docs/formats.md.
// Writers never leave a partial file: they write to a temporary file and rename it on success.
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/path.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace coverkit::datasets {

struct PathDocument {
  std::string planner;
  std::string status;
  Rational robotRadius;
  Rational cellSize;
  std::vector<Path> paths;                            ///< one per robot
  std::vector<std::pair<std::string, double>> metrics;   ///< name → value, written in order
  std::vector<std::pair<std::string, double>> statistics;
  /// The workspace the paths were planned in (optional, not owned). CSV and GeoJSON replace arcs by
  /// lines: with the workspace, on the side the exact clearance test accepts; without it, outside
  /// the arcs' circles (docs/formats.md).
  const Workspace* workspace = nullptr;
};

/// Arc sampling tolerance used for CSV and GeoJSON output (map units): every line lies within it of
/// the arc it replaces, on the arc's safe side (geometry/sampling.h).
constexpr double kArcSampleTolerance = 1e-3;

/// Metric name → value, in a fixed order (the keys of the JSON "metrics" object).
std::vector<std::pair<std::string, double>> metricFields(const Metrics& m);

/// Writes by extension (.json, .csv, .geojson); InputError for an unknown extension or unwritable path.
void writePathFile(const std::string& file, const PathDocument& doc);
std::string pathJson(const PathDocument& doc);
/// Reads a JSON path file (or a CSV one: consecutive rows of a robot become line segments).
PathDocument readPathFile(const std::string& file);

/// C-space files ("coverkit.cspace/1" JSON, or GeoJSON with arcs sampled), docs/formats.md.
struct CSpaceDocument {
  std::string map;
  Rational robotRadius;
  double epsilon = 0;
  double freeArea = 0, cfreeArea = 0;
  std::optional<PointD> start;
  int startComponent = -1;
  std::vector<CurveRegion> components, obstacles;
  /// The C-space the components came from (optional, not owned): with it, the GeoJSON's C-free
  /// polygons are CSpace::sampledComponents, checked to lie in the exact C-free (docs/formats.md);
  /// without it, the components' arcs are replaced outside their circles, unchecked.
  const CSpace* cspace = nullptr;
};
void writeCSpaceFile(const std::string& file, const CSpaceDocument& doc);

/// Writes `content` to `file` atomically (temporary file + rename).
void writeFileAtomically(const std::string& file, const std::string& content);

}  // namespace coverkit::datasets
