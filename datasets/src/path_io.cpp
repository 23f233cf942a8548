#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/sampling.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace coverkit::datasets {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {
json pt(PointD p) { return json::array({p.x, p.y}); }
json segmentJson(const PathSegment& s) {
  if (s.kind == PathSegment::Kind::kLine) return {{"type", "line"}, {"from", pt(s.from)}, {"to", pt(s.to)}};
  return {{"type", "arc"}, {"from", pt(s.from)}, {"to", pt(s.to)}, {"center", pt(s.center)}, {"ccw", s.ccw}};
}
/// A sampled ring as a GeoJSON ring: first point repeated.
json ringJson(const std::vector<PointD>& points) {
  json ring = json::array();
  for (PointD q : points) ring.push_back(pt(q));
  if (ring.size() > 1 && ring.front() != ring.back()) ring.push_back(ring.front());
  return ring;
}
/// The path as points for the line-only formats: arcs on their safe side (docs/formats.md).
std::vector<PointD> pointsOf(const std::string& file, const PathDocument& doc, std::size_t robot) {
  const Path& p = doc.paths[robot];
  if (!doc.workspace || doc.robotRadius <= 0) return outerPolyline(p, kArcSampleTolerance);
  SafePolyline s = safePolyline(p, *doc.workspace, doc.robotRadius, kArcSampleTolerance);
  if (s.unsafeSegment >= 0)
    throw InputError(file, "robots[" + std::to_string(robot) + "].segments[" + std::to_string(s.unsafeSegment) + "]",
                     "this arc keeps clearance r, but no lines found to replace it do; write the path as .json");
  return std::move(s.points);
}
}  // namespace

std::string extensionOf(const std::string& file) {
  std::string e = fs::path(file).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

std::vector<std::pair<std::string, double>> metricFields(const Metrics& m) {
  std::vector<std::pair<std::string, double>> f = {{"subcell_coverage", m.subcellCoverage},
          {"free_subcells", static_cast<double>(m.freeSubcells)},
          {"covered_subcells", static_cast<double>(m.coveredSubcells)},
          {"entered_subcells", static_cast<double>(m.enteredSubcells)},
          {"revisited_subcells", static_cast<double>(m.revisitedSubcells)},
          {"overlap_ratio", m.overlapRatio}};
  if (m.hasArea) {
    f.emplace_back("free_area", m.freeArea);
    f.emplace_back("covered_area", m.coveredArea);
    f.emplace_back("area_coverage", m.areaCoverage);
    f.emplace_back("area_coverage_error", m.areaCoverageError);
    f.emplace_back("area_exact", m.areaMethod == "exact" ? 1.0 : 0.0);
    f.emplace_back("swept_area_overlap", m.sweptAreaOverlap);
  }
  for (auto& kv : std::vector<std::pair<std::string, double>>{{"length", m.length},
          {"turns", static_cast<double>(m.turns)},
          {"turning_angle_deg", m.turningAngleDeg},
          {"time_s", m.time},
          {"reversals", static_cast<double>(m.reversals)},
          {"max_curvature", m.maxCurvature},
          {"robot_time_s", m.robotTime},
          {"segments", static_cast<double>(m.segments)}})
    f.push_back(std::move(kv));
  if (m.hasCoverable) {
    f.emplace_back("coverable_area", m.coverableArea);
    f.emplace_back("coverable_area_error", m.coverableAreaError);
    f.emplace_back("coverable_coverage", m.coverableCoverage);
  }
  if (m.hasTeam) {
    for (auto& kv : std::vector<std::pair<std::string, double>>{{"robots", static_cast<double>(m.robots)},
            {"makespan_s", m.makespan},
            {"sum_of_times_s", m.sumOfTimes},
            {"steps", static_cast<double>(m.steps)},
            {"repeated_steps", static_cast<double>(m.repeatedSteps)},
            {"coverage_rate", m.coverageRate},
            {"iteration_rate", m.iterationRate},
            {"most_cells", static_cast<double>(m.mostCells)},
            {"least_cells", static_cast<double>(m.leastCells)},
            {"balance", m.balance}})
      f.push_back(std::move(kv));
  }
  return f;
}

namespace {

std::string errnoText(int e) { return std::strerror(e); }

/// The folder of `file` as a path to use ("." for a bare name).
fs::path folderOf(const std::string& file) {
  const fs::path parent = fs::path(file).parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

/// InputError unless `folder` is an existing, writable folder.
void requireWritableFolder(const fs::path& folder, const std::string& file, const std::string& option, const std::string& what) {
  struct stat st {};
  if (::stat(folder.c_str(), &st) != 0) {
    const int e = errno;
    throw InputError(file, option, what + " '" + folder.string() + "' " + (e == ENOENT ? std::string("does not exist") : "cannot be used: " + errnoText(e)));
  }
  if (!S_ISDIR(st.st_mode)) throw InputError(file, option, what + " '" + folder.string() + "' is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    const int e = errno;
    throw InputError(file, option, what + " '" + folder.string() + "' is not writable: " + errnoText(e));
  }
}

/// InputError when `file` exists and is not a regular file (a folder, a device, a socket...).
void requireReplaceable(const std::string& file, const std::string& option) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return;  // does not exist (or a dangling link: replaced)
  if (S_ISDIR(st.st_mode)) throw InputError(file, option, "is a folder, not a file");
  if (!S_ISREG(st.st_mode)) throw InputError(file, option, "exists and is not a regular file");
}

/// A new empty file with a unique name beside `target` (mkstemps); returns its path and open descriptor.
std::pair<std::string, int> uniqueFileBeside(const std::string& target, const char* kind) {
  std::string name = (folderOf(target) / fs::path(target).filename()).string() + "." + kind + "-XXXXXX.tmp-coverkit";
  const int suffix = static_cast<int>(std::strlen(".tmp-coverkit"));
  std::vector<char> buf(name.begin(), name.end());
  buf.push_back('\0');
  const int fd = ::mkstemps(buf.data(), suffix);
  if (fd < 0) {
    const int e = errno;
    throw InputError(target, "", "cannot be written: " + errnoText(e));
  }
  return {std::string(buf.data()), fd};
}

/// Writes all of `content` to `fd`; returns 0 or the errno of the failure.
int writeAll(int fd, const std::string& content) {
  const char* p = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return 0;
}

mode_t fileMode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return static_cast<mode_t>(0666 & ~mask);
}

}  // namespace

void checkOutputFile(const std::string& file, const std::string& option, const std::vector<std::string>& extensions) {
  if (file.empty()) throw InputError(option, "", "no file name given");
  if (!extensions.empty()) {
    const std::string e = extensionOf(file);
    if (std::find(extensions.begin(), extensions.end(), e) == extensions.end()) {
      std::string known;
      for (std::size_t i = 0; i < extensions.size(); ++i) known += (i == 0 ? "" : i + 1 == extensions.size() ? " or " : ", ") + extensions[i];
      throw InputError(file, option, "unknown output format '" + e + "' (expected " + known + ")");
    }
  }
  if (fs::path(file).filename().empty() || fs::path(file).filename() == "." || fs::path(file).filename() == "..")
    throw InputError(file, option, "names a folder, not a file");
  requireWritableFolder(folderOf(file), file, option, "folder");
  requireReplaceable(file, option);
}

void checkOutputFolder(const std::string& folder, const std::string& option, const std::vector<std::string>& names) {
  if (folder.empty()) throw InputError(option, "", "no folder name given");
  struct stat st {};
  if (::stat(folder.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode)) throw InputError(folder, option, "exists and is not a folder (the output is a folder of files)");
    requireWritableFolder(folder, folder, option, "folder");
    for (const std::string& n : names) requireReplaceable((fs::path(folder) / n).string(), option);
    return;
  }
  if (errno != ENOENT) {
    const int e = errno;
    throw InputError(folder, option, "cannot be used: " + errnoText(e));
  }
  // to be created: the nearest existing ancestor must be a writable folder
  fs::path p = fs::path(folder).lexically_normal();
  if (p.has_filename() == false) p = p.parent_path();
  fs::path ancestor = p.parent_path();
  while (!ancestor.empty() && ::stat(ancestor.c_str(), &st) != 0) {
    if (errno != ENOENT) {
      const int e = errno;
      throw InputError(folder, option, "cannot be created: '" + ancestor.string() + "': " + errnoText(e));
    }
    ancestor = ancestor.parent_path();
  }
  if (ancestor.empty()) ancestor = p.is_absolute() ? fs::path("/") : fs::path(".");
  requireWritableFolder(ancestor, folder, option, "cannot be created: folder");
}

void OutputBatch::add(std::string file, std::string content) { files_.emplace_back(std::move(file), std::move(content)); }

void OutputBatch::addInFolder(const std::string& name, std::string content) {
  files_.emplace_back((fs::path(folder_) / name).string(), std::move(content));
}

void OutputBatch::commit() {
  struct Staged {
    std::string target, temp, backup;
    bool renamed = false;
  };
  std::vector<Staged> staged;
  std::vector<fs::path> createdFolders;  // outermost first
  auto cleanUp = [&]() {
    // undo in reverse order: restore or remove what was renamed, remove temporary files and folders
    for (auto it = staged.rbegin(); it != staged.rend(); ++it) {
      if (it->renamed) {
        if (!it->backup.empty()) {
          if (::rename(it->backup.c_str(), it->target.c_str()) == 0) it->backup.clear();
        } else {
          ::unlink(it->target.c_str());
        }
      } else if (!it->temp.empty()) {
        ::unlink(it->temp.c_str());
      }
      if (!it->backup.empty()) ::unlink(it->backup.c_str());
    }
    for (auto it = createdFolders.rbegin(); it != createdFolders.rend(); ++it) ::rmdir(it->c_str());
  };
  auto fail = [&](const std::string& file, const std::string& problem) {
    cleanUp();
    throw InputError(file, "", problem);
  };
  if (!folder_.empty()) {
    struct stat st {};
    std::vector<fs::path> missing;
    for (fs::path p = fs::path(folder_).lexically_normal(); !p.empty() && p != p.root_path(); p = p.parent_path()) {
      if (!p.has_filename()) continue;
      if (::stat(p.c_str(), &st) == 0) break;
      missing.push_back(p);
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
      if (::mkdir(it->c_str(), 0777) != 0) {
        const int e = errno;
        fail(folder_, "folder cannot be created: '" + it->string() + "': " + errnoText(e));
      }
      createdFolders.push_back(*it);
    }
    if (::stat(folder_.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) fail(folder_, "exists and is not a folder");
  }
  const mode_t mode = fileMode();
  // 1. every file complete in its temporary file
  for (const auto& [file, content] : files_) {
    Staged s;
    s.target = file;
    int fd = -1;
    try {
      std::tie(s.temp, fd) = uniqueFileBeside(file, "new");
    } catch (const InputError& e) {
      fail(file, e.problem());
    }
    staged.push_back(s);
    int e = writeAll(fd, content);
    if (e == 0 && ::fchmod(fd, mode) != 0) e = errno;
    if (::close(fd) != 0 && e == 0) e = errno;
    if (e != 0) fail(file, "cannot be written: " + errnoText(e));
  }
  // 2. a hard link to every file about to be replaced, so that it can be restored
  for (Staged& s : staged) {
    struct stat st {};
    if (::lstat(s.target.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
    std::string backup;
    int fd = -1;
    try {
      std::tie(backup, fd) = uniqueFileBeside(s.target, "old");
    } catch (const InputError& e) {
      fail(s.target, e.problem());
    }
    ::close(fd);
    // rename the existing file's link over the placeholder: the placeholder's unique name is kept
    if (::unlink(backup.c_str()) != 0 || ::link(s.target.c_str(), backup.c_str()) != 0) {
      const int e = errno;
      ::unlink(backup.c_str());
      // no hard links on this file system: keep a copy instead
      std::error_code ec;
      if (!fs::copy_file(s.target, backup, fs::copy_options::overwrite_existing, ec))
        fail(s.target, "cannot be replaced safely: " + errnoText(e) + (ec ? "; " + ec.message() : std::string()));
    }
    s.backup = backup;
  }
  // 3. into place, all or nothing
  for (Staged& s : staged) {
    if (::rename(s.temp.c_str(), s.target.c_str()) != 0) {
      const int e = errno;
      fail(s.target, "cannot be written: " + errnoText(e));
    }
    s.renamed = true;
    s.temp.clear();
  }
  for (Staged& s : staged)
    if (!s.backup.empty()) ::unlink(s.backup.c_str());
}

void writeFileAtomically(const std::string& file, const std::string& content) {
  OutputBatch batch;
  batch.add(file, content);
  batch.commit();
}

namespace {

/// What nlohmann's dump(1) writes for `v` at depth `depth` of a document.
void appendDumped(std::string& out, const json& v, int depth) {
  const std::string t = v.dump(1);
  for (char c : t) {
    out += c;
    if (c == '\n') out.append(static_cast<std::size_t>(depth), ' ');
  }
}

/// A number as nlohmann writes it (its own shortest round-trip digits; null when not finite).
void appendNumber(std::string& out, double x) {
  if (!std::isfinite(x)) {
    out += "null";
    return;
  }
  std::array<char, 64> buf{};
  const char* end = nlohmann::detail::to_chars(buf.data(), buf.data() + buf.size(), x);
  out.append(buf.data(), static_cast<std::size_t>(end - buf.data()));
}

/// `"key": [x, y]` at depth `depth` (at most 8), as dump(1) writes it; no temporary strings, since
/// this runs three times a segment on path files of a million segments.
void appendPointMember(std::string& out, const char* key, PointD p, int depth) {
  static constexpr const char* kSpaces = "         ";
  const std::size_t d = static_cast<std::size_t>(depth);
  out.append(kSpaces, d);
  out += '"';
  out += key;
  out += "\": [\n";
  out.append(kSpaces, d + 1);
  appendNumber(out, p.x);
  out += ",\n";
  out.append(kSpaces, d + 1);
  appendNumber(out, p.y);
  out += '\n';
  out.append(kSpaces, d);
  out += ']';
}

/// The robots array at depth 1, as dump(1) of robotsJson would write it: written directly, because
/// building a JSON tree of a million segments first took most of `plan`'s time on large maps.
void appendRobots(std::string& out, const std::vector<Path>& paths) {
  if (paths.empty()) {
    out += "[]";
    return;
  }
  std::size_t pieces = 0;
  for (const Path& p : paths) pieces += p.segments.size();
  out.reserve(out.size() + 160 * pieces + 256);   // a line piece takes about 130 bytes, an arc 190
  out += "[\n";
  for (std::size_t r = 0; r < paths.size(); ++r) {
    const Path& p = paths[r];
    out += "  {\n   \"segments\": ";
    if (p.segments.empty()) out += "[]";
    else {
      out += "[\n";
      for (std::size_t i = 0; i < p.segments.size(); ++i) {
        const PathSegment& g = p.segments[i];
        out += "    {\n";
        if (g.kind == PathSegment::Kind::kArc) {
          out += g.ccw ? "     \"ccw\": true,\n" : "     \"ccw\": false,\n";
          appendPointMember(out, "center", g.center, 5);
          out += ",\n";
        }
        appendPointMember(out, "from", g.from, 5);
        out += ",\n";
        appendPointMember(out, "to", g.to, 5);
        out += g.kind == PathSegment::Kind::kArc ? ",\n     \"type\": \"arc\"\n    }" : ",\n     \"type\": \"line\"\n    }";
        out += i + 1 < p.segments.size() ? ",\n" : "\n";
      }
      out += "   ]";
    }
    out += ",\n";
    appendPointMember(out, "start", p.start, 3);
    if (!p.timeline.empty()) {   // [[t, x, y], ...] at depth 3, as dump(1) writes it
      out += ",\n   \"timeline\": [\n";
      for (std::size_t k = 0; k < p.timeline.size(); ++k) {
        const TimedPoint& e = p.timeline[k];
        out += "    [\n     ";
        appendNumber(out, e.t);
        out += ",\n     ";
        appendNumber(out, e.p.x);
        out += ",\n     ";
        appendNumber(out, e.p.y);
        out += k + 1 < p.timeline.size() ? "\n    ],\n" : "\n    ]\n";
      }
      out += "   ]";
    }
    out += r + 1 < paths.size() ? "\n  },\n" : "\n  }\n";
  }
  out += " ]";
}

}  // namespace

std::string pathJson(const PathDocument& doc) {
  json j;
  j["format"] = "coverkit.path/1";
  j["planner"] = doc.planner;
  j["status"] = doc.status;
  j["robot_radius"] = doc.robotRadius.get_d();
  j["robot_radius_exact"] = doc.robotRadius.get_str();
  j["cell_size"] = doc.cellSize.get_d();
  j["cell_size_exact"] = doc.cellSize.get_str();
  j["robots"] = nullptr;   // written by appendRobots, in its place among the sorted keys
  json m = json::object();
  for (auto& [k, v] : doc.metrics) m[k] = v;
  j["metrics"] = m;
  json st = json::object();
  for (auto& [k, v] : doc.statistics) st[k] = v;
  j["statistics"] = st;
  // j.dump(1), with the robots written directly
  std::string out = "{\n";
  std::size_t k = 0;
  for (auto it = j.begin(); it != j.end(); ++it, ++k) {
    out += " " + json(it.key()).dump() + ": ";
    if (it.key() == "robots") appendRobots(out, doc.paths);
    else appendDumped(out, it.value(), 1);
    out += k + 1 < j.size() ? ",\n" : "\n";
  }
  out += "}\n";
  return out;
}

std::string pathFileContent(const std::string& file, const PathDocument& doc) {
  const std::string e = extensionOf(file);
  std::ostringstream os;
  os.precision(17);
  if (e == ".json") {
    return pathJson(doc);
  } else if (e == ".csv") {
    os << "robot,seq,x,y\n";
    for (std::size_t r = 0; r < doc.paths.size(); ++r) {
      const auto pts = pointsOf(file, doc, r);
      for (std::size_t i = 0; i < pts.size(); ++i) os << r << ',' << i << ',' << pts[i].x << ',' << pts[i].y << '\n';
    }
    return os.str();
  } else if (e == ".geojson") {
    json fc{{"type", "FeatureCollection"}, {"features", json::array()}};
    for (std::size_t r = 0; r < doc.paths.size(); ++r) {
      json coords = json::array();
      for (PointD p : pointsOf(file, doc, r)) coords.push_back(pt(p));
      fc["features"].push_back({{"type", "Feature"},
                                {"properties", {{"robot", r}, {"planner", doc.planner}, {"arc_tolerance", kArcSampleTolerance}}},
                                {"geometry", {{"type", "LineString"}, {"coordinates", coords}}}});
    }
    return fc.dump(1) + "\n";
  } else {
    throw InputError(file, "--out", "unknown output format '" + e + "' (expected .json, .csv or .geojson)");
  }
}

void writePathFile(const std::string& file, const PathDocument& doc) { writeFileAtomically(file, pathFileContent(file, doc)); }

/// A region's area, outer boundary and holes (segments and arcs), as the C-space and cell files write it.
json regionJson(const CurveRegion& r) {
  json outer = json::array(), holes = json::array();
  for (const PathSegment& s : r.outer.pieces) outer.push_back(segmentJson(s));
  for (const CurveLoop& h : r.holes) {
    json hole = json::array();
    for (const PathSegment& s : h.pieces) hole.push_back(segmentJson(s));
    holes.push_back(hole);
  }
  return {{"area", r.area}, {"outer", outer}, {"holes", holes}};
}

std::string cspaceFileContent(const std::string& file, const CSpaceDocument& doc) {
  const std::string e = extensionOf(file);
  auto regions = [](const std::vector<CurveRegion>& rs) {
    json out = json::array();
    for (const CurveRegion& r : rs) out.push_back(regionJson(r));
    return out;
  };
  if (e == ".json") {
    json j{{"format", "coverkit.cspace/1"},
           {"map", doc.map},
           {"robot_radius", doc.robotRadius.get_d()},
           {"robot_radius_exact", doc.robotRadius.get_str()},
           {"epsilon", doc.epsilon},
           {"free_area", doc.freeArea},
           {"cfree_area", doc.cfreeArea},
           {"start", doc.start ? pt(*doc.start) : json()},
           {"start_component", doc.startComponent},
           {"components", regions(doc.components)},
           {"obstacles", regions(doc.obstacles)}};
    return j.dump(1) + "\n";
  } else if (e == ".geojson") {
    json fc{{"type", "FeatureCollection"}, {"features", json::array()}};
    // C-free inside the exact C-free (every edge checked exactly when the workspace is known),
    // C-obstacles with their arcs replaced outside (docs/formats.md)
    std::vector<std::size_t> index;  // sampled piece → its component in doc.components
    std::vector<SampledRegion> cfree;
    if (doc.cspace) {
      for (CSpace::SampledComponent& c : doc.cspace->sampledComponents(kArcSampleTolerance)) {
        if (c.component < 0 || static_cast<std::size_t>(c.component) >= doc.components.size()) continue;
        index.push_back(static_cast<std::size_t>(c.component));
        cfree.push_back(std::move(c.region));
      }
    } else {
      cfree = sampleRegions(doc.components, kArcSampleTolerance, true);
      for (std::size_t i = 0; i < cfree.size(); ++i) index.push_back(i);
    }
    const std::vector<SampledRegion> cobs = sampleRegions(doc.obstacles, kArcSampleTolerance, false);
    auto add = [&](const SampledRegion& s, std::size_t i, double area, const char* kind) {
      json rings = json::array({ringJson(s.outer)});
      for (const auto& h : s.holes) rings.push_back(ringJson(h));
      fc["features"].push_back({{"type", "Feature"},
                                {"properties", {{"kind", kind}, {"index", i}, {"area", area}, {"arc_tolerance", kArcSampleTolerance},
                                                {"start_component", std::string(kind) == "cfree" && static_cast<int>(i) == doc.startComponent}}},
                                {"geometry", {{"type", "Polygon"}, {"coordinates", rings}}}});
    };
    for (std::size_t k = 0; k < cfree.size(); ++k) add(cfree[k], index[k], doc.components[index[k]].area, "cfree");
    for (std::size_t i = 0; i < cobs.size(); ++i) add(cobs[i], i, doc.obstacles[i].area, "cobstacle");
    return fc.dump(1) + "\n";
  } else {
    throw InputError(file, "--out", "unknown output format '" + e + "' (expected .json or .geojson)");
  }
}

std::string cellsFileContent(const std::string& file, const CellsDocument& doc) {
  const std::string e = extensionOf(file);
  if (e == ".json") {
    json cells = json::array();
    for (std::size_t i = 0; i < doc.cells.size(); ++i) {
      json cell = regionJson(doc.cells[i].region);
      cell["index"] = i;
      cell["neighbours"] = doc.cells[i].neighbours;
      cells.push_back(cell);
    }
    json walls = json::array();
    for (const auto& w : doc.walls) walls.push_back({{"a", w.a}, {"b", w.b}, {"from", pt(w.from)}, {"to", pt(w.to)}});
    json params = json::object();
    for (const auto& [k, v] : doc.params) params[k] = v;
    json j{{"format", "coverkit.cells/1"},
           {"map", doc.map},
           {"method", doc.method},
           {"params", params},
           {"robot_radius", doc.robotRadius.get_d()},
           {"robot_radius_exact", doc.robotRadius.get_str()},
           {"direction_degrees", doc.directionDegrees},
           {"rotation_exact", {{"cos", doc.rotationCos}, {"sin", doc.rotationSin}}},
           {"cfree_area", doc.cfreeArea},
           {"cell_count", doc.cells.size()},
           {"unwalled_vertices", doc.unwalledVertices},
           {"cells", cells},
           {"walls", walls}};
    return j.dump(1) + "\n";
  } else if (e == ".geojson") {
    std::vector<CurveRegion> regions;
    for (const auto& c : doc.cells) regions.push_back(c.region);
    const std::vector<SampledRegion> sampled = doc.sampled.size() == doc.cells.size() ? doc.sampled : sampleRegions(regions, kArcSampleTolerance, true);
    json fc{{"type", "FeatureCollection"}, {"features", json::array()}};
    for (std::size_t i = 0; i < sampled.size(); ++i) {
      json rings = json::array({ringJson(sampled[i].outer)});
      for (const auto& h : sampled[i].holes) rings.push_back(ringJson(h));
      fc["features"].push_back({{"type", "Feature"},
                                {"properties", {{"kind", "cell"}, {"index", i}, {"area", doc.cells[i].region.area},
                                                {"neighbours", doc.cells[i].neighbours}, {"method", doc.method},
                                                {"arc_tolerance", kArcSampleTolerance},
                                                {"vertices_outside", i < doc.unplaced.size() ? doc.unplaced[i] : 0}}},
                                {"geometry", {{"type", "Polygon"}, {"coordinates", rings}}}});
    }
    return fc.dump(1) + "\n";
  }
  throw InputError(file, "--out", "unknown output format '" + e + "' (expected .json or .geojson)");
}

void writeCSpaceFile(const std::string& file, const CSpaceDocument& doc) { writeFileAtomically(file, cspaceFileContent(file, doc)); }

// Reading path files. Every member is checked for its JSON type before it is used; a problem is an
// InputError naming the file, the place as a path into the document ("robots[0].segments[3].ccw")
// and the problem. Decisions (docs/formats.md):
//  * `format` must be the string "coverkit.path/1"; `planner` and `status`, when present, strings;
//  * `robot_radius_exact` / `cell_size_exact`, when present, rational strings > 0 (preferred);
//    `robot_radius` / `cell_size`, when present, finite numbers > 0;
//  * `robots` an array of objects with a `segments` array, an optional `start` [x, y] and an
//    optional `timeline` of finite [t, x, y] (whether it is a valid motion is the validator's
//    verdict, kind "timeline", not a reading error);
//  * a segment: `type` "line" or "arc", `from`, `to` (and an arc's `center`) finite [x, y], an
//    arc's `ccw` a boolean (true when absent, as before);
//  * `metrics` and `statistics`, when present, objects of numbers (null stands for a NaN written);
//    they are not read back. Other members are ignored.
// CSV: the header `robot,seq,x,y`, then rows of exactly four fields: robots numbered 0, 1, 2, ... in
// order, each robot's rows contiguous with `seq` 0, 1, 2, ...; x and y finite decimals. Empty lines
// and a '\r' before the line end are ignored.
namespace {

PathDocument readPathCsv(const std::string& file, const std::string& text) {
  PathDocument doc;
  std::istringstream ls(text);
  std::string line;
  long lineNo = 0;
  auto fail = [&](const std::string& why) { throw InputError(file, "line " + std::to_string(lineNo), why); };
  ++lineNo;
  if (!std::getline(ls, line)) line.clear();
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line != "robot,seq,x,y") fail("expected the header 'robot,seq,x,y'");
  long seq = 0;  // rows read so far for the current robot
  auto integer = [&](const std::string& f, const char* what, long max) {
    if (f.empty() || f.size() > 12 || f.find_first_not_of("0123456789") != std::string::npos)
      fail(std::string("bad ") + what + " '" + f + "' (expected an integer >= 0)");
    const long v = std::stol(f);
    if (v > max) fail(std::string("bad ") + what + " '" + f + "' (at most " + std::to_string(max) + ")");
    return v;
  };
  auto coordinate = [&](const std::string& f, const char* what) {
    char* end = nullptr;
    const double v = f.empty() ? 0 : std::strtod(f.c_str(), &end);
    if (f.empty() || *end || std::isspace(static_cast<unsigned char>(f[0]))) fail(std::string("bad ") + what + " '" + f + "' (expected a number)");
    if (!std::isfinite(v)) fail(std::string("non-finite ") + what + " '" + f + "'");
    return v;
  };
  while (std::getline(ls, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string> f;
    std::size_t b = 0;
    for (std::size_t e; (e = line.find(',', b)) != std::string::npos; b = e + 1) f.push_back(line.substr(b, e - b));
    f.push_back(line.substr(b));
    if (f.size() != 4) fail("expected 4 fields robot,seq,x,y, found " + std::to_string(f.size()));
    const long robot = integer(f[0], "robot", 1000);
    const long sq = integer(f[1], "seq", 1'000'000'000'000L);
    const double x = coordinate(f[2], "x"), y = coordinate(f[3], "y");
    const long current = static_cast<long>(doc.paths.size()) - 1;
    if (robot == current + 1) {
      doc.paths.emplace_back();
      doc.paths.back().start = {x, y};
      seq = 0;
    } else if (robot != current) {
      fail("robot " + std::to_string(robot) + " after robot " + std::to_string(current) + ": robots are numbered 0, 1, 2, ... in order, each in one run of rows");
    }
    if (sq != seq) fail("seq " + std::to_string(sq) + ", expected " + std::to_string(seq));
    ++seq;
    if (sq == 0) continue;
    Path& p = doc.paths.back();
    const PointD from = p.segments.empty() ? p.start : p.segments.back().to;
    p.segments.push_back(PathSegment::line(from, {x, y}));
  }
  return doc;
}

class PathJsonReader {
public:
  explicit PathJsonReader(const std::string& file) : file_(file) {}

  PathDocument read(const json& j) {
    PathDocument doc;
    if (!j.is_object()) fail("", "not a coverkit.path/1 file (expected a JSON object, found " + std::string(j.type_name()) + ")");
    const json* format = member(j, "format");
    if (!format) fail("format", "missing: not a coverkit.path/1 file");
    if (!format->is_string()) fail("format", "expected the string \"coverkit.path/1\", found " + std::string(format->type_name()));
    if (format->get<std::string>() != "coverkit.path/1") fail("format", "'" + format->get<std::string>() + "': not a coverkit.path/1 file");
    doc.planner = optionalString(j, "planner", "");
    doc.status = optionalString(j, "status", "");
    doc.robotRadius = positive(j, "robot_radius", "");
    doc.cellSize = positive(j, "cell_size", "");
    for (const char* key : {"metrics", "statistics"})
      if (const json* m = member(j, key)) {
        if (!m->is_object()) fail(key, "expected an object, found " + std::string(m->type_name()));
        for (const auto& [k, v] : m->items())
          if (!v.is_number() && !v.is_null()) fail(std::string(key) + "." + k, "expected a number, found " + std::string(v.type_name()));
      }
    const json* robots = member(j, "robots");
    if (!robots) fail("robots", "missing robots array");
    if (!robots->is_array()) fail("robots", "expected an array, found " + std::string(robots->type_name()));
    for (std::size_t r = 0; r < robots->size(); ++r) doc.paths.push_back(robot((*robots)[r], "robots[" + std::to_string(r) + "]"));
    return doc;
  }

private:
  [[noreturn]] void fail(const std::string& place, const std::string& why) const { throw InputError(file_, place, why); }
  static std::string join(const std::string& place, const std::string& key) { return place.empty() ? key : place + "." + key; }
  static const json* member(const json& obj, const char* key) {
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }
  std::string optionalString(const json& obj, const char* key, const std::string& place) const {
    const json* v = member(obj, key);
    if (!v) return "";
    if (!v->is_string()) fail(join(place, key), "expected a string, found " + std::string(v->type_name()));
    return v->get<std::string>();
  }
  double number(const json& v, const std::string& place) const {
    if (!v.is_number()) fail(place, "expected a number, found " + std::string(v.type_name()));
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(place, "non-finite number");
    return x;
  }
  /// `key_exact` (a rational string) preferred, else `key` (a number, read through its shortest
  /// decimal); 0 when neither is there. Either must be > 0.
  Rational positive(const json& obj, const std::string& key, const std::string& place) const {
    Rational q = 0;
    const std::string exactKey = key + "_exact";
    const json* e = member(obj, exactKey.c_str());
    const json* d = member(obj, key.c_str());
    if (d) q = decimalFromDouble(number(*d, join(place, key)));
    if (d && q <= 0) fail(join(place, key), "must be > 0");
    if (e) {
      if (!e->is_string()) fail(join(place, exactKey), "expected a rational as a string (\"1/4\"), found " + std::string(e->type_name()));
      q = parseRational(e->get<std::string>(), file_, join(place, exactKey));
      if (q <= 0) fail(join(place, exactKey), "must be > 0");
    }
    return q;
  }
  PointD point(const json& obj, const char* key, const std::string& place) const {
    const json* v = member(obj, key);
    const std::string at = join(place, key);
    if (!v) fail(at, "missing");
    if (!v->is_array() || v->size() != 2) fail(at, "expected [x, y], found " + (v->is_array() ? "an array of " + std::to_string(v->size()) : std::string(v->type_name())));
    return {number((*v)[0], at + "[0]"), number((*v)[1], at + "[1]")};
  }
  Path robot(const json& rj, const std::string& place) const {
    if (!rj.is_object()) fail(place, "expected an object, found " + std::string(rj.type_name()));
    const json* segs = member(rj, "segments");
    if (!segs) fail(join(place, "segments"), "missing segments");
    if (!segs->is_array()) fail(join(place, "segments"), "expected an array, found " + std::string(segs->type_name()));
    Path p;
    const bool hasStart = member(rj, "start") != nullptr;
    if (hasStart) p.start = point(rj, "start", place);
    else if (segs->empty()) fail(place, "no start and no segments");
    for (std::size_t k = 0; k < segs->size(); ++k) {
      const json& s = (*segs)[k];
      const std::string sp = join(place, "segments") + "[" + std::to_string(k) + "]";
      if (!s.is_object()) fail(sp, "expected a segment object, found " + std::string(s.type_name()));
      const json* type = member(s, "type");
      if (!type) fail(join(sp, "type"), "missing (\"line\" or \"arc\")");
      if (!type->is_string()) fail(join(sp, "type"), "expected \"line\" or \"arc\", found " + std::string(type->type_name()));
      const std::string t = type->get<std::string>();
      if (t == "line") {
        p.segments.push_back(PathSegment::line(point(s, "from", sp), point(s, "to", sp)));
      } else if (t == "arc") {
        bool ccw = true;
        if (const json* c = member(s, "ccw")) {
          if (!c->is_boolean()) fail(join(sp, "ccw"), "expected true or false, found " + std::string(c->type_name()));
          ccw = c->get<bool>();
        }
        p.segments.push_back(PathSegment::arc(point(s, "from", sp), point(s, "to", sp), point(s, "center", sp), ccw));
      } else {
        fail(join(sp, "type"), "unknown segment type '" + t + "' (\"line\" or \"arc\")");
      }
    }
    if (!hasStart) p.start = p.segments.front().from;
    if (const json* tl = member(rj, "timeline")) {   // a timed plan: [[t, x, y], ...]
      const std::string tp = join(place, "timeline");
      if (!tl->is_array()) fail(tp, "expected an array of [t, x, y], found " + std::string(tl->type_name()));
      for (std::size_t k = 0; k < tl->size(); ++k) {
        const json& e = (*tl)[k];
        const std::string at = tp + "[" + std::to_string(k) + "]";
        if (!e.is_array() || e.size() != 3) fail(at, "expected [t, x, y], found " + (e.is_array() ? "an array of " + std::to_string(e.size()) : std::string(e.type_name())));
        p.timeline.push_back({number(e[0], at + "[0]"), {number(e[1], at + "[1]"), number(e[2], at + "[2]")}});
      }
    }
    return p;
  }
  std::string file_;
};

}  // namespace

PathDocument readPathFile(const std::string& file) {
  const std::string text = readTextFile(file);
  if (extensionOf(file) == ".csv") return readPathCsv(file, text);
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(file, "byte " + std::to_string(e.byte), std::string("JSON does not parse: ") + e.what());
  } catch (const json::exception& e) {
    throw InputError(file, "", std::string("JSON does not parse: ") + e.what());
  }
  try {
    return PathJsonReader(file).read(j);
  } catch (const json::exception& e) {  // a type not checked above: still bad input
    throw InputError(file, "", std::string("JSON: ") + e.what());
  }
}

}  // namespace coverkit::datasets
