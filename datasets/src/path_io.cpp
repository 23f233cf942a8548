#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/sampling.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

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

void writeFileAtomically(const std::string& file, const std::string& content) {
  const fs::path target(file);
  const fs::path tmp = target.string() + ".tmp-coverkit";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(file, "", "cannot be written (does the folder exist?)");
    out << content;
    out.flush();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw InputError(file, "", "write failed");
    }
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw InputError(file, "", "cannot be written: " + ec.message());
  }
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

void writePathFile(const std::string& file, const PathDocument& doc) {
  const std::string e = ext(file);
  std::ostringstream os;
  os.precision(17);
  if (e == ".json") {
    writeFileAtomically(file, pathJson(doc));
  } else if (e == ".csv") {
    os << "robot,seq,x,y\n";
    for (std::size_t r = 0; r < doc.paths.size(); ++r) {
      const auto pts = pointsOf(file, doc, r);
      for (std::size_t i = 0; i < pts.size(); ++i) os << r << ',' << i << ',' << pts[i].x << ',' << pts[i].y << '\n';
    }
    writeFileAtomically(file, os.str());
  } else if (e == ".geojson") {
    json fc{{"type", "FeatureCollection"}, {"features", json::array()}};
    for (std::size_t r = 0; r < doc.paths.size(); ++r) {
      json coords = json::array();
      for (PointD p : pointsOf(file, doc, r)) coords.push_back(pt(p));
      fc["features"].push_back({{"type", "Feature"},
                                {"properties", {{"robot", r}, {"planner", doc.planner}, {"arc_tolerance", kArcSampleTolerance}}},
                                {"geometry", {{"type", "LineString"}, {"coordinates", coords}}}});
    }
    writeFileAtomically(file, fc.dump(1) + "\n");
  } else {
    throw InputError(file, "--out", "unknown output format '" + e + "' (expected .json, .csv or .geojson)");
  }
}

void writeCSpaceFile(const std::string& file, const CSpaceDocument& doc) {
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
    writeFileAtomically(file, j.dump(1) + "\n");
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
    writeFileAtomically(file, fc.dump(1) + "\n");
  } else {
    throw InputError(file, "--out", "unknown output format '" + e + "' (expected .json or .geojson)");
  }
}

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
