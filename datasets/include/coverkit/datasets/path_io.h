#pragma once
// Path files: JSON "coverkit.path/1", CSV (robot,seq,x,y) and GeoJSON LineStrings. Spec: docs/formats.md.
// Writers never leave a partial file: they write to a temporary file and rename it on success.
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/path.h>

#include <map>
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

/// Cell decompositions ("coverkit.cells/1" JSON, or GeoJSON with one Polygon per cell, arcs sampled
/// inside the cell), docs/formats.md. Everything in the workspace's frame.
struct CellsDocument {
  std::string map, method;
  Rational robotRadius;
  std::map<std::string, std::string> params;
  double directionDegrees = 0;             ///< the sweep direction used (sweep models)
  std::string rotationCos = "1", rotationSin = "0";   ///< the exact rotation (rationals as text)
  double cfreeArea = 0;
  std::size_t unwalledVertices = 0;
  struct Cell {
    CurveRegion region;
    std::vector<int> neighbours;
  };
  std::vector<Cell> cells;
  struct Wall {
    int a = -1, b = -1;
    PointD from, to;
  };
  std::vector<Wall> walls;
  /// The cells as checked line polygons (geometry/decomposition.h, sampledCells), for GeoJSON; when
  /// empty, the cells' arcs are replaced on their inside, unchecked.
  std::vector<SampledRegion> sampled;
  std::vector<std::size_t> unplaced;   ///< per cell: vertices of `sampled` that could not be put inside it
};
std::string cellsFileContent(const std::string& file, const CellsDocument& doc);

/// The content of a path file as `writePathFile` writes it (by extension; InputError for an unknown one).
std::string pathFileContent(const std::string& file, const PathDocument& doc);
/// The content of a C-space file as `writeCSpaceFile` writes it.
std::string cspaceFileContent(const std::string& file, const CSpaceDocument& doc);

/// Writes `content` to `file` atomically: a temporary file with a unique name in the same folder,
/// renamed into place only when it is complete (an OutputBatch of one file).
void writeFileAtomically(const std::string& file, const std::string& content);

/// The extension of `file` in lower case, with its dot ("" when it has none).
std::string extensionOf(const std::string& file);

/// Checks, before any work, that `file` can be written: a name is given, its extension (compared
/// in lower case) is one of `extensions` (with the dot; empty: any), its folder exists, is a folder
/// and is writable, and `file` itself is not a folder or a special file. InputError(file, option,
/// problem) otherwise; nothing is created.
void checkOutputFile(const std::string& file, const std::string& option, const std::vector<std::string>& extensions);

/// Checks, before any work, that `folder` can receive the files `names`: it is a writable folder,
/// or it does not exist and can be created (its nearest existing ancestor is a writable folder);
/// none of `names` is an existing folder or special file in it. Nothing is created.
void checkOutputFolder(const std::string& folder, const std::string& option, const std::vector<std::string>& names = {});

/// The output files of one command, written together at the end: every file goes to a temporary
/// file with a unique name (mkstemp) in its own folder, and the temporary files are renamed into
/// place only when all of them are complete. If anything fails, no file of the batch is left:
/// files already renamed are removed, or restored when they replaced an existing file, and
/// folders the batch created are removed; then InputError names the file and the reason (errno).
class OutputBatch {
public:
  /// `folder`, when not empty, is created (with its missing parents) when the batch is committed.
  explicit OutputBatch(std::string folder = "") : folder_(std::move(folder)) {}
  void add(std::string file, std::string content);
  /// A file of `folder` by its name.
  void addInFolder(const std::string& name, std::string content);
  void commit();
  std::size_t size() const { return files_.size(); }

private:
  std::string folder_;
  std::vector<std::pair<std::string, std::string>> files_;
};

}  // namespace coverkit::datasets
