#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/error.h>

#include <nlohmann/json.hpp>

#include <algorithm>
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
/// A closed loop as a GeoJSON ring: arcs sampled to the stated tolerance, first point repeated.
json ringJson(const CurveLoop& loop) {
  Path p;
  if (loop.pieces.empty()) return json::array();
  p.start = loop.pieces.front().from;
  p.segments = loop.pieces;
  json ring = json::array();
  for (PointD q : p.polyline(kArcSampleTolerance)) ring.push_back(pt(q));
  if (ring.size() > 1 && ring.front() != ring.back()) ring.push_back(ring.front());
  return ring;
}
std::string ext(const std::string& f) {
  std::string e = fs::path(f).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}
}  // namespace

std::vector<std::pair<std::string, double>> metricFields(const Metrics& m) {
  std::vector<std::pair<std::string, double>> f = {{"subcell_coverage", m.subcellCoverage},
          {"free_subcells", static_cast<double>(m.freeSubcells)},
          {"covered_subcells", static_cast<double>(m.coveredSubcells)},
          {"entered_subcells", static_cast<double>(m.enteredSubcells)},
          {"revisited_subcells", static_cast<double>(m.revisitedSubcells)},
          {"overlap_ratio", m.overlapRatio},
          {"free_area", m.freeArea},
          {"covered_area", m.coveredArea},
          {"area_coverage", m.areaCoverage},
          {"area_coverage_error", m.areaCoverageError},
          {"area_exact", m.areaMethod == "exact" ? 1.0 : 0.0},
          {"swept_area_overlap", m.sweptAreaOverlap},
          {"length", m.length},
          {"turns", static_cast<double>(m.turns)},
          {"turning_angle_deg", m.turningAngleDeg},
          {"time_s", m.time},
          {"segments", static_cast<double>(m.segments)}};
  if (m.hasCoverable) {
    f.emplace_back("coverable_area", m.coverableArea);
    f.emplace_back("coverable_area_error", m.coverableAreaError);
    f.emplace_back("coverable_coverage", m.coverableCoverage);
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
    const std::string e = ext(file);
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

std::string pathJson(const PathDocument& doc) {
  json j;
  j["format"] = "coverkit.path/1";
  j["planner"] = doc.planner;
  j["status"] = doc.status;
  j["robot_radius"] = doc.robotRadius.get_d();
  j["robot_radius_exact"] = doc.robotRadius.get_str();
  j["cell_size"] = doc.cellSize.get_d();
  j["cell_size_exact"] = doc.cellSize.get_str();
  json robots = json::array();
  for (const Path& p : doc.paths) {
    json segs = json::array();
    for (const PathSegment& s : p.segments) segs.push_back(segmentJson(s));
    robots.push_back({{"start", pt(p.start)}, {"segments", segs}});
  }
  j["robots"] = robots;
  json m = json::object();
  for (auto& [k, v] : doc.metrics) m[k] = v;
  j["metrics"] = m;
  json st = json::object();
  for (auto& [k, v] : doc.statistics) st[k] = v;
  j["statistics"] = st;
  return j.dump(1) + "\n";
}

std::string pathFileContent(const std::string& file, const PathDocument& doc) {
  const std::string e = ext(file);
  std::ostringstream os;
  os.precision(17);
  if (e == ".json") {
    return pathJson(doc);
  } else if (e == ".csv") {
    os << "robot,seq,x,y\n";
    for (std::size_t r = 0; r < doc.paths.size(); ++r) {
      const auto pts = doc.paths[r].polyline(kArcSampleTolerance);
      for (std::size_t i = 0; i < pts.size(); ++i) os << r << ',' << i << ',' << pts[i].x << ',' << pts[i].y << '\n';
    }
    return os.str();
  } else if (e == ".geojson") {
    json fc{{"type", "FeatureCollection"}, {"features", json::array()}};
    for (std::size_t r = 0; r < doc.paths.size(); ++r) {
      json coords = json::array();
      for (PointD p : doc.paths[r].polyline(kArcSampleTolerance)) coords.push_back(pt(p));
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

std::string cspaceFileContent(const std::string& file, const CSpaceDocument& doc) {
  const std::string e = ext(file);
  auto regions = [](const std::vector<CurveRegion>& rs) {
    json out = json::array();
    for (const CurveRegion& r : rs) {
      json outer = json::array(), holes = json::array();
      for (const PathSegment& s : r.outer.pieces) outer.push_back(segmentJson(s));
      for (const CurveLoop& h : r.holes) {
        json hole = json::array();
        for (const PathSegment& s : h.pieces) hole.push_back(segmentJson(s));
        holes.push_back(hole);
      }
      out.push_back({{"area", r.area}, {"outer", outer}, {"holes", holes}});
    }
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
    auto add = [&](const std::vector<CurveRegion>& rs, const char* kind) {
      for (std::size_t i = 0; i < rs.size(); ++i) {
        json rings = json::array({ringJson(rs[i].outer)});
        for (const CurveLoop& h : rs[i].holes) rings.push_back(ringJson(h));
        fc["features"].push_back({{"type", "Feature"},
                                  {"properties", {{"kind", kind}, {"index", i}, {"area", rs[i].area}, {"arc_tolerance", kArcSampleTolerance},
                                                  {"start_component", std::string(kind) == "cfree" && static_cast<int>(i) == doc.startComponent}}},
                                  {"geometry", {{"type", "Polygon"}, {"coordinates", rings}}}});
      }
    };
    add(doc.components, "cfree");
    add(doc.obstacles, "cobstacle");
    return fc.dump(1) + "\n";
  } else {
    throw InputError(file, "--out", "unknown output format '" + e + "' (expected .json or .geojson)");
  }
}

void writeCSpaceFile(const std::string& file, const CSpaceDocument& doc) { writeFileAtomically(file, cspaceFileContent(file, doc)); }

PathDocument readPathFile(const std::string& file) {
  const std::string text = readTextFile(file);
  PathDocument doc;
  if (ext(file) == ".csv") {
    std::istringstream ls(text);
    std::string line;
    int lineNo = 0;
    std::getline(ls, line);
    ++lineNo;
    if (line.rfind("robot,seq,x,y", 0) != 0) throw InputError(file, "line 1", "expected the header 'robot,seq,x,y'");
    while (std::getline(ls, line)) {
      ++lineNo;
      if (line.empty()) continue;
      std::istringstream f(line);
      std::string a, b, c, d;
      if (!std::getline(f, a, ',') || !std::getline(f, b, ',') || !std::getline(f, c, ',') || !std::getline(f, d, ','))
        throw InputError(file, "line " + std::to_string(lineNo), "expected 4 columns");
      char* end = nullptr;
      const long robot = std::strtol(a.c_str(), &end, 10);
      if (*end || robot < 0 || robot > 1000) throw InputError(file, "line " + std::to_string(lineNo), "bad robot index");
      const double x = std::strtod(c.c_str(), &end);
      const bool okx = !*end;
      const double y = std::strtod(d.c_str(), &end);
      if (!okx || *end || !std::isfinite(x) || !std::isfinite(y)) throw InputError(file, "line " + std::to_string(lineNo), "bad coordinate");
      if (static_cast<std::size_t>(robot) >= doc.paths.size()) {
        doc.paths.resize(static_cast<std::size_t>(robot) + 1);
        doc.paths[static_cast<std::size_t>(robot)].start = {x, y};
        continue;
      }
      Path& p = doc.paths[static_cast<std::size_t>(robot)];
      const PointD from = p.segments.empty() ? p.start : p.segments.back().to;
      p.segments.push_back(PathSegment::line(from, {x, y}));
    }
    return doc;
  }
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(file, "byte " + std::to_string(e.byte), std::string("JSON does not parse: ") + e.what());
  } catch (const json::exception& e) {
    throw InputError(file, "", std::string("JSON does not parse: ") + e.what());
  }
  auto need = [&](bool ok, const std::string& place, const std::string& why) {
    if (!ok) throw InputError(file, place, why);
  };
  need(j.is_object() && j.value("format", "") == "coverkit.path/1", "format", "not a coverkit.path/1 file");
  auto point = [&](const json& v, const std::string& place) {
    need(v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number(), place, "expected [x, y]");
    const double x = v[0].get<double>(), y = v[1].get<double>();
    need(std::isfinite(x) && std::isfinite(y), place, "non-finite coordinate");
    return PointD{x, y};
  };
  doc.planner = j.value("planner", "");
  doc.status = j.value("status", "");
  if (j.contains("robot_radius_exact") && j["robot_radius_exact"].is_string())
    doc.robotRadius = parseRational(j["robot_radius_exact"].get<std::string>(), file, "robot_radius_exact");
  else if (j.contains("robot_radius") && j["robot_radius"].is_number())
    doc.robotRadius = decimalFromDouble(j["robot_radius"].get<double>());
  if (j.contains("cell_size_exact") && j["cell_size_exact"].is_string())
    doc.cellSize = parseRational(j["cell_size_exact"].get<std::string>(), file, "cell_size_exact");
  else if (j.contains("cell_size") && j["cell_size"].is_number())
    doc.cellSize = decimalFromDouble(j["cell_size"].get<double>());
  need(j.contains("robots") && j["robots"].is_array(), "robots", "missing robots array");
  for (std::size_t r = 0; r < j["robots"].size(); ++r) {
    const json& rj = j["robots"][r];
    const std::string place = "robots[" + std::to_string(r) + "]";
    need(rj.is_object() && rj.contains("segments") && rj["segments"].is_array(), place, "missing segments");
    Path p;
    const json& segs = rj["segments"];
    if (rj.contains("start")) p.start = point(rj["start"], place + ".start");
    else need(!segs.empty(), place, "no start and no segments");
    for (std::size_t k = 0; k < segs.size(); ++k) {
      const json& s = segs[k];
      const std::string sp = place + ".segments[" + std::to_string(k) + "]";
      need(s.is_object() && s.contains("type") && s.contains("from") && s.contains("to"), sp, "segment needs type, from, to");
      const std::string type = s["type"].is_string() ? s["type"].get<std::string>() : "";
      if (type == "line") p.segments.push_back(PathSegment::line(point(s["from"], sp + ".from"), point(s["to"], sp + ".to")));
      else if (type == "arc") {
        need(s.contains("center"), sp, "arc without center");
        p.segments.push_back(PathSegment::arc(point(s["from"], sp + ".from"), point(s["to"], sp + ".to"), point(s["center"], sp + ".center"),
                                              s.value("ccw", true)));
      } else need(false, sp + ".type", "unknown segment type '" + type + "'");
    }
    if (!rj.contains("start")) p.start = p.segments.front().from;
    doc.paths.push_back(std::move(p));
  }
  return doc;
}

}  // namespace coverkit::datasets
