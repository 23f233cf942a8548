// Safe exports (issue 12, item 6): CSV and GeoJSON replace arcs by lines, and the lines must keep the
// exact guarantees: a sampled path the exact validator accepts wherever it accepts the path, sampled
// C-free polygons inside the exact C-free. Checked here against the exact geometry: the sampled
// path through the validator, the sampled C-free rings as closed paths through the validator
// (every point of them at distance >= r from every obstacle).
#include "helpers/checkers.h"
#include "helpers/worlds.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/sampling.h>
#include <coverkit/planners/registry.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using namespace coverkit;
namespace fs = std::filesystem;

namespace {

std::string tmpFile(const std::string& name) {
  const fs::path d = fs::path(COVERKIT_TEST_TMP) / "export";
  fs::create_directories(d);
  return (d / name).string();
}

std::string slurp(const std::string& f) {
  std::ifstream in(f);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

Problem problemOf(const Workspace& w, const Rational& r) {
  Problem p;
  p.workspace = w;
  p.robots.push_back({r, std::nullopt});
  return p;
}

/// The exact validator on paths (no start constraint): clearance and continuity only.
::testing::AssertionResult validFor(const Workspace& w, const Rational& r, const std::vector<Path>& paths) {
  Problem p = problemOf(w, r);
  p.robots.resize(paths.size(), p.robots.front());
  const ValidationReport rep = validatePaths(p, paths);
  if (rep.valid) return ::testing::AssertionSuccess();
  auto f = ::testing::AssertionFailure() << rep.violations.size() << " violation(s):";
  for (std::size_t i = 0; i < rep.violations.size() && i < 3; ++i) f << " [" << rep.violations[i].kind << "] " << rep.violations[i].detail;
  return f;
}

/// A path file written with `--out F.csv` and F.geojson (the CLI's document: workspace attached),
/// read back as the validator reads it.
std::vector<Path> writtenAndRead(const std::string& name, const Workspace& w, const Rational& r, const std::vector<Path>& paths,
                                 bool withWorkspace = true) {
  datasets::PathDocument doc;
  doc.planner = "test";
  doc.robotRadius = r;
  doc.cellSize = 2 * r;
  doc.paths = paths;
  if (withWorkspace) doc.workspace = &w;
  const std::string csv = tmpFile(name + ".csv"), geo = tmpFile(name + ".geojson");
  datasets::writePathFile(csv, doc);
  datasets::writePathFile(geo, doc);
  std::vector<Path> out = datasets::readPathFile(csv).paths;
  // the GeoJSON LineStrings hold the same points
  const nlohmann::json j = nlohmann::json::parse(slurp(geo));
  EXPECT_EQ(j["features"].size(), paths.size());
  for (std::size_t i = 0; i < j["features"].size() && i < out.size(); ++i) {
    std::vector<PointD> pts;
    for (const auto& c : j["features"][i]["geometry"]["coordinates"]) pts.push_back({c[0].get<double>(), c[1].get<double>()});
    const Path g = Path::fromPoints(pts);
    EXPECT_EQ(g.segments.size(), out[i].segments.size());
    for (std::size_t k = 0; k < g.segments.size() && k < out[i].segments.size(); ++k) {
      EXPECT_EQ(g.segments[k].to.x, out[i].segments[k].to.x);
      EXPECT_EQ(g.segments[k].to.y, out[i].segments[k].to.y);
    }
  }
  return out;
}

std::size_t arcsIn(const Plan& plan) {
  std::size_t n = 0;
  for (const Path& p : plan.paths)
    for (const PathSegment& s : p.segments) n += s.kind == PathSegment::Kind::kArc;
  return n;
}

}  // namespace

TEST(SafeExport, SmoothStcOnPillarsStaysValidAsCsvAndGeoJson) {
  // the case: valid as JSON; its CSV with chords came out at clearance 0.249061 < 0.25
  const Workspace w = datasets::loadMap(std::string(COVERKIT_DATA_DIR) + "/pillars.wkt");
  const Rational r(1, 4);
  const auto ctx = testing_helpers::contextFor(w, r);
  const Plan plan = planners::runPlanner("smooth_stc", ctx, {});
  ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
  ASSERT_GT(arcsIn(plan), 0u);
  // chords (what the exports wrote before) cut the corners the arcs turn about
  EXPECT_FALSE(validFor(w, r, {Path::fromPoints(plan.paths[0].polyline(datasets::kArcSampleTolerance))}));
  EXPECT_TRUE(validFor(w, r, writtenAndRead("pillars", w, r, plan.paths)));
  // without the workspace the arcs go outside their circles: right for arcs about corners
  EXPECT_TRUE(validFor(w, r, writtenAndRead("pillars_outer", w, r, plan.paths, false)));
  // within the stated tolerance of the path: same length up to the sampling
  const auto back = writtenAndRead("pillars", w, r, plan.paths);
  EXPECT_NEAR(back[0].length(), plan.paths[0].length(), 1e-3 * plan.paths[0].length());
}

TEST(SafeExport, SmoothStcOnSeededWorldsStaysValid) {
  for (std::uint64_t seed : {3u, 11u, 29u}) {
    const Workspace w = testing_helpers::mixedWorld(seed, 12, 7);
    for (const Rational& r : {Rational(1, 4), Rational(3, 10)}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " r " + r.get_str());
      const auto ctx = testing_helpers::contextFor(w, r);
      const Plan plan = planners::runPlanner("smooth_stc", ctx, {});
      if (!succeeded(plan.status)) continue;
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, plan));
      EXPECT_TRUE(validFor(w, r, writtenAndRead("seeded", w, r, plan.paths)));
    }
  }
}

TEST(SafeExport, EachArcOnTheSideItsObstacleAllows) {
  // a 10 × 10 room with a 2 × 2 pillar, r = 1/2
  const Workspace w = testing_helpers::boxWith({{{4, 4}, {6, 4}, {6, 6}, {4, 6}}});
  const Rational r(1, 2);
  // about the pillar's corner (6, 6), radius r exactly: only lines outside the circle keep clearance
  const Path corner{{6.5, 5}, {PathSegment::line({6.5, 5}, {6.5, 6}), PathSegment::arc({6.5, 6}, {6, 6.5}, {6, 6}, true),
                               PathSegment::line({6, 6.5}, {5, 6.5})}, {}};
  // a circle about the room's centre touching the right wall (x = 10) at angle 0: only chords do
  const Path wall{{9.5, 5}, {PathSegment::arc({9.5, 5}, {9.5, 5}, {5, 5}, true)}, {}};
  ASSERT_TRUE(validFor(w, r, {corner}));
  ASSERT_TRUE(validFor(w, r, {wall}));
  for (const Path& p : {corner, wall}) {
    EXPECT_FALSE(validFor(w, r, {Path::fromPoints(p.polyline(1e-3))}) && validFor(w, r, {Path::fromPoints(outerPolyline(p, 1e-3))}))
        << "one side must fail, else this test shows nothing";
    const SafePolyline s = safePolyline(p, w, r, 1e-3);
    EXPECT_EQ(s.unsafeSegment, -1);
    EXPECT_TRUE(validFor(w, r, {Path::fromPoints(s.points)}));
    EXPECT_TRUE(validFor(w, r, writtenAndRead("sides", w, r, {p})));
  }
  // both in one path
  Path both = corner;
  both.segments.push_back(PathSegment::line({5, 6.5}, {5, 9.5}));
  both.segments.push_back(PathSegment::arc({5, 9.5}, {0.5, 5}, {5, 5}, true));
  ASSERT_TRUE(validFor(w, r, {both}));
  EXPECT_TRUE(validFor(w, r, writtenAndRead("both", w, r, {both})));
}

TEST(SafeExport, SampledArcsStayWithinTheToleranceOnTheirSide) {
  const PathSegment s = PathSegment::arc({3, 1}, {1, 3}, {1, 1}, true);
  for (double tol : {1e-1, 1e-3, 1e-6}) {
    for (ArcSide side : {ArcSide::kInside, ArcSide::kOutside}) {
      std::vector<PointD> pts;
      sampleArc(s, tol, side, pts);
      ASSERT_FALSE(pts.empty());
      EXPECT_EQ(pts.back().x, 1);
      EXPECT_EQ(pts.back().y, 3);
      PointD a = s.from;
      for (PointD b : pts) {
        for (int k = 0; k <= 8; ++k) {  // points along each line: on their side, within tol
          const double t = k / 8.0, x = a.x + t * (b.x - a.x) - 1, y = a.y + t * (b.y - a.y) - 1;
          const double d = std::hypot(x, y) - 2;
          if (side == ArcSide::kInside) EXPECT_LE(d, 0);
          else EXPECT_GE(d, 0);
          EXPECT_LE(std::abs(d), tol * (1 + 1e-9));
        }
        a = b;
      }
    }
  }
  // the full circle (from == to) is sampled all round
  std::vector<PointD> full;
  sampleArc(PathSegment::arc({2, 0}, {2, 0}, {0, 0}, true), 1e-3, ArcSide::kOutside, full);
  EXPECT_GT(full.size(), 20u);
}

namespace {

/// Every ring of the C-free polygons of `file` (GeoJSON) as a closed path: the validator accepts it
/// (each point at distance >= r from every obstacle, inside W). Returns the polygons' total area and
/// which components have a polygon.
double checkCFreeGeoJson(const std::string& file, const Workspace& w, const Rational& r, std::set<int>& indices) {
  const nlohmann::json j = nlohmann::json::parse(slurp(file));
  double area = 0;
  for (const auto& f : j["features"]) {
    if (f["properties"]["kind"] != "cfree") continue;
    indices.insert(f["properties"]["index"].get<int>());
    bool outer = true;
    for (const auto& ring : f["geometry"]["coordinates"]) {
      std::vector<PointD> pts;
      for (const auto& c : ring) pts.push_back({c[0].get<double>(), c[1].get<double>()});
      EXPECT_GE(pts.size(), 4u);
      EXPECT_EQ(pts.front().x, pts.back().x);
      EXPECT_EQ(pts.front().y, pts.back().y);
      EXPECT_TRUE(validFor(w, r, {Path::fromPoints(pts)})) << file << " feature " << f["properties"]["index"];
      double a2 = 0;
      for (std::size_t i = 0; i + 1 < pts.size(); ++i) a2 += pts[i].x * pts[i + 1].y - pts[i + 1].x * pts[i].y;
      EXPECT_EQ(a2 > 0, outer) << "outer rings counter-clockwise, holes clockwise";
      area += a2 / 2;
      outer = false;
    }
  }
  return area;
}

}  // namespace

TEST(SafeExport, SampledCFreeLiesInTheExactCFree) {
  datasets::PolygonWorldSpec s;
  s.width = s.height = 14;
  s.count = 10;
  s.shape = datasets::ObstacleShape::kMixed;
  s.seed = 17;
  // two rooms joined by a neck exactly 2r wide: C-free has cusps where two C-obstacle arcs touch
  Workspace rooms;
  {
    Region reg;
    reg.outer = {{0, 0}, {4, 0}, {4, ratio(3, 2)}, {6, ratio(3, 2)}, {6, 0}, {10, 0}, {10, 4}, {6, 4}, {6, ratio(5, 2)}, {4, ratio(5, 2)}, {4, 4}, {0, 4}};
    reg.holes.push_back({{ratio(17, 10), ratio(17, 10)}, {ratio(23, 10), ratio(17, 10)}, {2, ratio(23, 10)}});
    rooms.regions.push_back(reg);
    normalise(rooms);
  }
  const std::vector<std::pair<Workspace, Rational>> cases = {
      {datasets::loadMap(std::string(COVERKIT_DATA_DIR) + "/pillars.wkt"), Rational(1, 4)},
      {datasets::loadMap(std::string(COVERKIT_DATA_DIR) + "/pillars.wkt"), Rational(1, 2)},
      {datasets::generatePolygonWorld(s), Rational(3, 10)},
      {rooms, Rational(1, 2)},
  };
  int k = 0;
  for (const auto& [w, r] : cases) {
    SCOPED_TRACE("case " + std::to_string(k));
    const CSpace cs(w, r);
    datasets::CSpaceDocument doc;
    doc.map = "test";
    doc.robotRadius = r;
    doc.components = cs.components();
    doc.obstacles = cs.obstacles();
    doc.cspace = &cs;
    const std::string f = tmpFile("cspace" + std::to_string(k++) + ".geojson");
    datasets::writeCSpaceFile(f, doc);
    std::set<int> indices;
    const double area = checkCFreeGeoJson(f, w, r, indices);
    for (std::size_t i = 0; i < doc.components.size(); ++i)
      if (doc.components[i].area > 1e-3) {
        EXPECT_TRUE(indices.count(static_cast<int>(i))) << "component " << i << " left out";
      }
    // inside: never more than the exact C-free (the C-space's area is at most eps below it), and
    // within the tolerance times the boundary's length of it
    double perimeter = 0;
    for (const CurveRegion& c : doc.components) {
      for (const PathSegment& p : c.outer.pieces) perimeter += p.length();
      for (const CurveLoop& h : c.holes)
        for (const PathSegment& p : h.pieces) perimeter += p.length();
    }
    EXPECT_LE(area, cs.area() + cs.epsilon() * perimeter + 1e-9);
    EXPECT_GE(area, cs.area() - datasets::kArcSampleTolerance * perimeter);
  }
}
