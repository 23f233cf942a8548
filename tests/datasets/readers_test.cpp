#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/cell_grid.h>
#include <coverkit/geometry/error.h>

#include <gtest/gtest.h>
#include <png.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <tuple>
#include <utility>

using namespace coverkit;
namespace fs = std::filesystem;

namespace {
fs::path tmpDir() {
  fs::path d = fs::path(COVERKIT_TEST_TMP) / "readers";
  fs::create_directories(d);
  return d;
}
std::string write(const std::string& name, const std::string& content) {
  const fs::path p = tmpDir() / name;
  std::ofstream(p, std::ios::binary) << content;
  return p.string();
}
std::string pgm(int w, int h, const std::vector<int>& px) {
  std::string s = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
  for (int v : px) s += static_cast<char>(v);
  return s;
}
/// Expects an InputError whose message contains `what`.
template <class F>
void expectInputError(F&& f, const std::string& what) {
  try {
    f();
    ADD_FAILURE() << "no error; expected: " << what;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(RosMap, PixelSquaresFollowMapServer) {
  // 4x3 image, one occupied pixel at row 0 (top), column 1
  std::vector<int> px(12, 254);
  px[1] = 0;
  write("one.pgm", pgm(4, 3, px));
  const std::string yaml = write("one.yaml", "image: one.pgm\nresolution: 0.05\norigin: [-1.0, 2.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const Workspace w = datasets::readRosMap(yaml);
  ASSERT_EQ(w.regions.size(), 1u);
  // free area: 11 pixels of 1/400
  EXPECT_EQ(freeArea(w), Rational(11, 400));
  const Box b = w.bbox();
  EXPECT_EQ(b.xmin, Rational(-1));
  EXPECT_EQ(b.ymin, Rational(2));
  EXPECT_EQ(b.xmax, Rational(-1) + ratio(4, 20));
  // the occupied pixel is the square origin + res·[1,2] × res·[H-1-0, H-0] = x [-0.95,-0.9], y [2.1, 2.15]
  EXPECT_FALSE(strictlyInside(w, {ratio(-925, 1000), ratio(2125, 1000)}));
  EXPECT_TRUE(strictlyInside(w, {ratio(-975, 1000), ratio(2125, 1000)}));
}

TEST(RosMap, ThresholdsNegateAndUnknown) {
  // values: free (254), occupied (0), unknown (205)
  write("three.pgm", pgm(3, 1, {254, 0, 205}));
  const std::string y = write("three.yaml", "image: three.pgm\nresolution: 1\norigin: [0, 0, 0]\n");
  EXPECT_EQ(freeArea(datasets::readRosMap(y)), Rational(1));
  datasets::MapOptions o;
  o.unknownIsFree = true;
  EXPECT_EQ(freeArea(datasets::readRosMap(y, o)), Rational(2));
  const std::string yn = write("threen.yaml", "image: three.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 1\n");
  EXPECT_EQ(freeArea(datasets::readRosMap(yn)), Rational(1));  // now 0 is free, 254 occupied
}

TEST(RosMap, RgbaPngWithTransparentUnknown) {
  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  img.width = 2;
  img.height = 2;
  img.format = PNG_FORMAT_RGBA;
  const unsigned char px[16] = {255, 255, 255, 255, 0, 0, 0, 255, 255, 255, 255, 0, 250, 250, 250, 255};
  const std::string png = (tmpDir() / "rgba.png").string();
  ASSERT_TRUE(png_image_write_to_file(&img, png.c_str(), 0, px, 0, nullptr));
  const std::string y = write("rgba.yaml", "image: rgba.png\nresolution: 0.5\norigin: [0, 0, 0]\n");
  EXPECT_EQ(freeArea(datasets::readRosMap(y)), ratio(2, 4));  // white and near-white; black occupied; transparent unknown
}

TEST(RosMap, BadInput) {
  write("ok.pgm", pgm(2, 2, {254, 254, 254, 254}));
  expectInputError([] { datasets::readRosMap((tmpDir() / "missing.yaml").string()); }, "file not found");
  expectInputError([] { datasets::readRosMap(write("nores.yaml", "image: ok.pgm\norigin: [0,0,0]\n")); }, "resolution: missing");
  expectInputError([] { datasets::readRosMap(write("zero.yaml", "image: ok.pgm\nresolution: 0\n")); }, "resolution: must be > 0");
  expectInputError([] { datasets::readRosMap(write("neg.yaml", "image: ok.pgm\nresolution: -0.1\n")); }, "must be > 0");
  expectInputError([] { datasets::readRosMap(write("noimg.yaml", "image: nothere.pgm\nresolution: 0.1\n")); }, "not found");
  write("trunc.pgm", "P5\n10 10\n255\nabc");
  expectInputError([] { datasets::readRosMap(write("trunc.yaml", "image: trunc.pgm\nresolution: 0.1\n")); }, "truncated PGM");
  write("notpgm.pgm", "hello world");
  expectInputError([] { datasets::readRosMap(write("notpgm.yaml", "image: notpgm.pgm\nresolution: 0.1\n")); }, "not a PGM");
  write("notpng.png", "hello world, not a png");
  expectInputError([] { datasets::readRosMap(write("notpng.yaml", "image: notpng.png\nresolution: 0.1\n")); }, "not a PNG");
  write("black.pgm", pgm(2, 2, {0, 0, 0, 0}));
  expectInputError([] { datasets::readRosMap(write("black.yaml", "image: black.pgm\nresolution: 0.1\n")); }, "empty free space");
  expectInputError([] { datasets::readRosMap(write("bad.yaml", "image: ok.pgm\nresolution: [1, 2\n")); }, "YAML does not parse");
}

TEST(MovingAi, ReadsAndRejects) {
  const std::string ok = write("m.map", "type octile\nheight 2\nwidth 3\nmap\n.@.\n...\n");
  const Workspace w = datasets::readMovingAi(ok);
  EXPECT_EQ(freeArea(w), Rational(5));
  // cell (row 0, col 1) is the unit square [1,2] × [1,2] (first row on top)
  EXPECT_FALSE(strictlyInside(w, {Rational(3, 2), Rational(3, 2)}));
  expectInputError([] { datasets::readMovingAi(write("h.map", "type octile\nheigth 2\nwidth 3\nmap\n...\n...\n")); }, "bad Moving AI header");
  expectInputError([] { datasets::readMovingAi(write("s.map", "type octile\nheight 2\nwidth 3\nmap\n...\n..\n")); }, "row has 2 cells, width is 3");
  expectInputError([] { datasets::readMovingAi(write("t.map", "type octile\nheight 3\nwidth 3\nmap\n...\n...\n")); }, "missing map row 3");
  expectInputError([] { datasets::readMovingAi(write("c.map", "type octile\nheight 1\nwidth 3\nmap\n.x.\n")); }, "unknown terrain");
}

TEST(Wkt, PolygonsWithHolesAndErrors) {
  const Workspace w = datasets::parseWkt("MULTIPOLYGON(((0 0, 4 0, 4 4, 0 4, 0 0),(1 1, 1 2, 2 2, 2 1, 1 1)),((10 0, 12 0, 12 1, 10 0)))", "x.wkt");
  ASSERT_EQ(w.regions.size(), 2u);
  EXPECT_EQ(freeArea(w), Rational(16 - 1 + 1));
  EXPECT_GT(signedArea2(w.regions[0].outer), 0);
  EXPECT_LT(signedArea2(w.regions[0].holes[0]), 0);
  expectInputError([] { datasets::parseWkt("POLYGON((0 0, 1 0, 1 1", "a.wkt"); }, "WKT does not parse");
  expectInputError([] { datasets::parseWkt("LINESTRING(0 0, 1 1)", "a.wkt"); }, "expected POLYGON");
  expectInputError([] { datasets::parseWkt("POLYGON((0 0, 2 2, 2 0, 0 2, 0 0))", "a.wkt"); }, "self-intersecting");
  expectInputError([] { datasets::parseWkt("POLYGON((0 0, 4 0, 4 4, 0 4),(5 5, 6 5, 6 6, 5 5))", "a.wkt"); }, "hole is outside");
  expectInputError([] { datasets::parseWkt("POLYGON((0 0, nan 0, 4 4, 0 4))", "a.wkt"); }, "not finite");
  expectInputError([] { datasets::parseWkt("POLYGON((0 0, inf 0, 4 4, 0 4))", "a.wkt"); }, "not finite");
  expectInputError([] { datasets::parseWkt("POLYGON((0 0, 4 0, 4 0, 4 4, 0 4))", "a.wkt"); }, "repeated vertex");
  expectInputError([] { datasets::parseWkt("POLYGON((0 0, 4 0, 8 0))", "a.wkt"); }, "zero area");
  expectInputError([] { datasets::parseWkt("POLYGON((0 0, 4 0, 4 4, 0 4),(1 1, 3 1, 3 5, 1 1))", "a.wkt"); }, "rings intersect");
}

TEST(GeoJson, MetricAndLonLat) {
  const Workspace m = datasets::parseGeoJson(R"({"type":"Polygon","coordinates":[[[0,0],[10,0],[10,10],[0,10],[0,0]],[[1,1],[9,1],[9,9],[1,9],[1,1]]]})", "r.geojson");
  EXPECT_EQ(freeArea(m), Rational(100 - 64));
  // a 0.001° × 0.001° square at latitude 60: about 55.6 m × 111.2 m
  const Workspace ll = datasets::parseGeoJson(
      R"({"type":"Feature","geometry":{"type":"Polygon","coordinates":[[[10,60],[10.001,60],[10.001,60.001],[10,60.001],[10,60]]]}})", "ll.geojson");
  const Box b = ll.bbox();
  EXPECT_NEAR(Rational(b.xmax - b.xmin).get_d(), 6371008.8 * std::cos(60.0005 * M_PI / 180) * 0.001 * M_PI / 180, 0.002);
  EXPECT_NEAR(Rational(b.ymax - b.ymin).get_d(), 6371008.8 * 0.001 * M_PI / 180, 0.002);
  // a named metric CRS keeps small numbers as metres; a lon/lat CRS projects even a wide extent
  const Workspace metric = datasets::parseGeoJson(
      R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"urn:ogc:def:crs:EPSG::3857"}},"features":[{"type":"Feature","geometry":{"type":"Polygon","coordinates":[[[10,60],[10.001,60],[10.001,60.001],[10,60.001],[10,60]]]}}]})",
      "m.geojson");
  EXPECT_NEAR(Rational(metric.bbox().xmax - metric.bbox().xmin).get_d(), 0.001, 1e-12);
  expectInputError([] { datasets::parseGeoJson("{\"type\": \"Polygon\", ", "b.geojson"); }, "GeoJSON does not parse");
  expectInputError([] { datasets::parseGeoJson(R"({"type":"Point","coordinates":[1,2]})", "b.geojson"); }, "unsupported geometry");
  expectInputError([] { datasets::parseGeoJson(R"({"type":"Polygon","coordinates":[[[0,0],[2,2],[2,0],[0,2],[0,0]]]})", "b.geojson"); }, "self-intersecting");
}

TEST(TextGrid, SameWorldAsPolygonsGivesSameCells) {
  const Workspace g = datasets::parseTextGrid("resolution 0.5\n........\n..##....\n..##....\n........\n", "t.grid");
  const Workspace p = datasets::parseWkt("POLYGON((0 0, 4 0, 4 2, 0 2, 0 0),(1 0.5, 2 0.5, 2 1.5, 1 1.5, 1 0.5))", "t.wkt");
  EXPECT_EQ(freeArea(g), freeArea(p));
  for (const Rational& D : {Rational(1, 4), Rational(1, 2), Rational(1, 3)}) {
    const CellGrid a = classifyCells(g, D), b = classifyCells(p, D);
    ASSERT_EQ(a.subCount(), b.subCount());
    for (int r = 0; r < a.subRows(); ++r)
      for (int c = 0; c < a.subCols(); ++c) EXPECT_EQ(a.sub(c, r), b.sub(c, r));
  }
  expectInputError([] { datasets::parseTextGrid("...\n..\n", "t.grid"); }, "row has 2 cells");
  expectInputError([] { datasets::parseTextGrid("###\n###\n", "t.grid"); }, "empty free space");
}

TEST(GridPolygons, DiagonalPinchesKeepFreeSpace4Connected) {
  // two free pixels touching at a corner are separate regions
  const Workspace w = datasets::parseTextGrid(".#\n#.\n", "pinch.grid");
  EXPECT_EQ(w.regions.size(), 2u);
  EXPECT_EQ(freeArea(w), Rational(2));
  // a ring of free cells around an obstacle: one region with one hole; vertices only at corners
  const Workspace ring = datasets::parseTextGrid("....\n.##.\n.##.\n....\n", "ring.grid");
  ASSERT_EQ(ring.regions.size(), 1u);
  ASSERT_EQ(ring.regions[0].holes.size(), 1u);
  EXPECT_EQ(ring.regions[0].outer.size(), 4u);
  EXPECT_EQ(ring.regions[0].holes[0].size(), 4u);
}

TEST(GridPolygons, RingsTouchingThemselvesAreSplitAtThePinch) {
  // two obstacle pixels meeting at a corner inside one free region: two holes touching at a vertex
  const Workspace w = datasets::parseTextGrid(".....\n.#...\n..#..\n.....\n", "pinch.grid");
  ASSERT_EQ(w.regions.size(), 1u);
  EXPECT_EQ(w.regions[0].holes.size(), 2u);
  EXPECT_NO_THROW(checkWorkspace(w));
  // an obstacle touching the outside at a corner: the outer ring is not self-touching either
  const Workspace v = datasets::parseTextGrid("#....\n.#...\n.....\n", "corner.grid");
  EXPECT_NO_THROW(checkWorkspace(v));
  EXPECT_EQ(freeArea(v), Rational(13));
}

// checkWorkspace tests each hole against its outer ring over the edges the workspace's edge index
// lists on the ray to the hole's right (a scan's outer ring may have tens of thousands of edges,
// and it has as many holes). A comb of 400 teeth: holes in the teeth and in the body pass; a hole
// between two teeth (inside the ring's box, outside the ring) is refused; and the parity over a
// list of edges agrees with the parity over the whole ring at points in teeth, in gaps and below.
TEST(WorkspaceCheck, HolesAreTestedAgainstALargeOuterRingThroughTheEdgeIndex) {
  const int teeth = 400;
  auto comb = [&] {
    Ring r{Point{Rational(0), Rational(0)}, Point{Rational(2 * teeth), Rational(0)}};
    for (int t = teeth - 1; t >= 0; --t)   // from right to left along the top: up a tooth, down into the gap
      for (const auto& [x, y] : {std::pair<int, int>{2 * t + 1, 10}, {2 * t + 1, 20}, {2 * t, 20}, {2 * t, 10}})
        if (!(t == 0 && x == 0 && y == 10)) r.push_back(Point{Rational(x), Rational(y)});
    r.push_back(Point{Rational(0), Rational(10)});
    return r;
  };
  auto square = [](Rational x, Rational y, Rational s) {
    return Ring{Point{x, y}, Point{x, y + s}, Point{x + s, y + s}, Point{x + s, y}};   // clockwise: a hole
  };
  Workspace w;
  w.name = "comb";
  w.regions.push_back(Region{comb(), {}});
  for (int t = 0; t < teeth; t += 7) w.regions[0].holes.push_back(square(Rational(2 * t) + Rational(1, 4), Rational(15), Rational(1, 2)));
  w.regions[0].holes.push_back(square(Rational(5), Rational(3), Rational(2)));
  EXPECT_NO_THROW(checkWorkspace(w));
  Workspace gap = w;
  gap.regions[0].holes.push_back(square(Rational(2 * 200 + 1) + Rational(1, 4), Rational(15), Rational(1, 2)));
  expectInputError([&] { checkWorkspace(gap); }, "hole is outside its outer ring");
  std::vector<std::size_t> all(w.regions[0].outer.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  for (const auto& [x, y, in] : {std::tuple<Rational, Rational, bool>{Rational(2 * 17) + Rational(1, 2), Rational(18), true},
                                 {Rational(2 * 17 + 1) + Rational(1, 2), Rational(18), false},
                                 {Rational(401, 3), Rational(5), true},
                                 {Rational(401, 3), Rational(-1), false}}) {
    const Point p{x, y};
    EXPECT_EQ(insideRing(w.regions[0].outer, p), in);
    EXPECT_EQ(insideRing(w.regions[0].outer, p, all), in);
  }
}

// Rings of almost no height (a fuzzer's reproducer: a vertex at y = 2e-308) are checked exactly and
// without a double sent past an integer's range on the way (a grid of rows over the ring's height
// once did, which the UBSan build aborts on): the ring is accepted, a hole inside it too, and a hole
// above it is refused.
TEST(WorkspaceCheck, RingsOfAlmostNoHeightAreChecked) {
  const Workspace z = datasets::parseWkt("polygon zm ((5 0 1 2, 1e1 0 1 2, 0.5 2e-308, 0 0 1 2))", "z.wkt");
  ASSERT_EQ(z.regions.size(), 1u);
  EXPECT_GT(freeArea(z), Rational(0));
  const Workspace t = datasets::parseWkt("POLYGON((0 0, 10 0, 10 1e-300, 0 1e-300),(1 2e-301, 1 4e-301, 2 4e-301, 2 2e-301))", "t.wkt");
  ASSERT_EQ(t.regions[0].holes.size(), 1u);
  expectInputError([] { datasets::parseWkt("POLYGON((0 0, 10 0, 10 1e-300, 0 1e-300),(1 2e-300, 1 4e-300, 2 4e-300, 2 2e-300))", "a.wkt"); },
                   "hole is outside its outer ring");
}

TEST(LoadMap, UnknownExtensionAndMissingFile) {
  expectInputError([] { datasets::loadMap(write("x.xyz", "")); }, "unknown map format");
  expectInputError([] { datasets::loadMap((tmpDir() / "nope.map").string()); }, "file not found");
}

// ---------------------------------------------------------------- issue 12: refused, not accepted
TEST(RosMap, OriginMustBeThreeNumbers) {
  write("o.pgm", pgm(2, 2, {254, 254, 254, 254}));
  expectInputError([] { datasets::readRosMap(write("o4.yaml", "image: o.pgm\nresolution: 1\norigin: [0, 0, 0, 0]\n")); },
                   "o4.yaml: origin: expected [x, y, yaw], found 4 numbers");
  expectInputError([] { datasets::readRosMap(write("o2.yaml", "image: o.pgm\nresolution: 1\norigin: [0, 0]\n")); }, "expected [x, y, yaw], found 2 numbers");
  expectInputError([] { datasets::readRosMap(write("os.yaml", "image: o.pgm\nresolution: 1\norigin: 3\n")); }, "origin: expected [x, y, yaw]");
  expectInputError([] { datasets::readRosMap(write("ox.yaml", "image: o.pgm\nresolution: 1\norigin: [0, a, 0]\n")); }, "origin[1]");
  expectInputError([] { datasets::readRosMap(write("om.yaml", "image: o.pgm\nresolution: 1\nmode: [raw]\n")); }, "mode: unknown mode");
  expectInputError([] { datasets::readRosMap(write("oi.yaml", "image: [o.pgm]\nresolution: 1\n")); }, "image: expected a file name");
  EXPECT_EQ(freeArea(datasets::readRosMap(write("o3.yaml", "image: o.pgm\nresolution: 1\norigin: [1, 2, 0]\n"))), Rational(4));
  EXPECT_EQ(freeArea(datasets::readRosMap(write("o0.yaml", "image: o.pgm\nresolution: 1\n"))), Rational(4));  // missing: [0, 0, 0]
}

TEST(MovingAi, SizesRowsAndLimits) {
  expectInputError([] { datasets::readMovingAi(write("junk.map", "type octile\nheight 2\nwidth 12junk\nmap\n............\n............\n")); },
                   "junk.map: line 3: bad width '12junk' (expected a positive integer)");
  expectInputError([] { datasets::readMovingAi(write("frac.map", "type octile\nheight 2\nwidth 12.5\nmap\n............\n............\n")); },
                   "frac.map: line 3: bad width '12.5'");
  expectInputError([] { datasets::readMovingAi(write("neg.map", "type octile\nheight -2\nwidth 3\nmap\n...\n...\n")); }, "line 2: bad height '-2'");
  expectInputError([] { datasets::readMovingAi(write("zero.map", "type octile\nheight 0\nwidth 3\nmap\n")); }, "line 2: bad height '0'");
  expectInputError([] { datasets::readMovingAi(write("big.map", "type octile\nheight 100000\nwidth 100000\nmap\n....\n")); },
                   "big.map: header: grid of 100000 x 100000 cells is too large (the limit is 268435456 = 2^28 cells)");
  expectInputError([] { datasets::readMovingAi(write("long.map", "type octile\nheight 99999999\nwidth 2\nmap\n..\n")); }, "long.map: line 6: missing map row 2 of 99999999");
  expectInputError([] { datasets::readMovingAi(write("extra.map", "type octile\nheight 2\nwidth 3\nmap\n...\n...\n...\n")); },
                   "extra.map: line 7: extra row beyond the height of 2 rows");
  expectInputError([] { datasets::readMovingAi(write("extra2.map", "type octile\nheight 2\nwidth 3\nmap\n...\n...\n\n@@@\n")); }, "extra2.map: line 8: extra row");
  expectInputError([] { datasets::readMovingAi(write("wide.map", "type octile\nheight 2\nwidth 3\nmap\n....\n...\n")); }, "wide.map: line 5: row has 4 cells, width is 3");
  // tolerated: trailing empty (or blank) lines, CRLF line ends, spaces around the numbers
  EXPECT_EQ(freeArea(datasets::readMovingAi(write("trail.map", "type octile\r\nheight  2 \r\nwidth 3\r\nmap\r\n...\r\n.@.\r\n\r\n  \n\n"))), Rational(5));
}

TEST(TextGrid, LimitIsShared) {
  EXPECT_EQ(datasets::kMaxGridCells, std::int64_t{1} << 28);
  expectInputError([] { datasets::checkGridSize("x", "header", 16385, 16384); }, "x: header: grid of 16385 x 16384 cells is too large");
  EXPECT_NO_THROW(datasets::checkGridSize("x", "header", 16384, 16384));
  EXPECT_NO_THROW(datasets::checkGridSize("x", "header", 1, datasets::kMaxGridCells));
  expectInputError([] { datasets::checkGridSize("x", "header", 2, datasets::kMaxGridCells); }, "too large");
}

TEST(GeoJson, EveryWrongTypeIsAnInputErrorNamingThePlace) {
  const std::string sq = R"([[[0,0],[4,0],[4,4],[0,4],[0,0]]])";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"type":"GeometryCollection"})", "g.geojson: geometries: missing: GeometryCollection without geometries"},
      {R"({"type":"GeometryCollection","geometries":3})", "g.geojson: geometries: expected an array (geometries), found number"},
      {R"({"type":"GeometryCollection","geometries":[{"type":"Polygon","coordinates":"x"}]})",
       "g.geojson: geometries[0].coordinates: expected an array (rings), found string"},
      {R"({"type":"GeometryCollection","geometries":[7]})", "geometries[0]: expected a geometry object, found number"},
      {R"({"type":"Feature"})", "g.geojson: geometry: missing (a Feature without a location"},
      {R"({"type":"Feature","geometry":null})", "no Polygon in the GeoJSON: empty free space"},
      {R"({"type":"FeatureCollection","features":[{"type":"Feature","geometry":null},{"type":"Feature"}]})", "features[1].geometry: missing"},
      {R"({"type":"FeatureCollection","features":[3]})", "features[0]: expected a Feature object, found number"},
      {R"({"type":"FeatureCollection","features":[{"type":"Polygon","coordinates":)" + sq + "}]}", "features[0].type: expected 'Feature', found 'Polygon'"},
      {R"({"type":"FeatureCollection","features":{}})", "features: expected an array of Features"},
      {R"({"type":"FeatureCollection"})", "features: missing"},
      {R"({"type":5})", "g.geojson: type: expected a string, found number"},
      {R"({"coordinates":[]})", "g.geojson: type: missing"},
      {R"([1,2])", "not GeoJSON: expected an object"},
      {R"({"type":"Polygon"})", "coordinates: missing: Polygon without rings"},
      {R"({"type":"MultiPolygon","coordinates":[3]})", "coordinates[0]: expected an array of rings, found number"},
      {R"({"type":"Polygon","coordinates":[3]})", "coordinates[0]: expected a ring (an array of positions), found number"},
      {R"({"type":"Polygon","coordinates":[[[0,0],[4,"a"],[4,4]]]})", "coordinates[0][1]: position is not [x, y]"},
      {R"({"type":"Polygon","coordinates":[[[0,0],[4,0,"z"],[4,4]]]})", "coordinates[0][1][2]: expected a number (an altitude)"},
      {R"({"type":"LineString","coordinates":[[0,0],[1,1]]})", "type: unsupported geometry type 'LineString'"},
      {R"({"type":"Polygon","crs":"EPSG:4326","coordinates":)" + sq + "}", "crs: expected an object"},
  };
  for (const auto& c : cases) expectInputError([&] { datasets::parseGeoJson(c.first, "g.geojson"); }, c.second);
  // GeometryCollections nested deeper than 64: refused, not a stack overflow
  std::string deep = sq;
  deep = R"({"type":"Polygon","coordinates":)" + sq + "}";
  for (int i = 0; i < 200; ++i) deep = R"({"type":"GeometryCollection","geometries":[)" + deep + "]}";
  expectInputError([&] { datasets::parseGeoJson(deep, "deep.geojson"); }, "nested more than 64 deep");
  // null crs: as if absent; a null-geometry feature beside a located one adds nothing
  EXPECT_EQ(freeArea(datasets::parseGeoJson(R"({"type":"FeatureCollection","crs":null,"features":[{"type":"Feature","geometry":null},)"
                                            R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":)" + sq + "}}]}",
                                            "ok.geojson")),
            Rational(16));
}

TEST(GeoJson, FrameRule) {
  // no crs, a position out of the longitude range: metric as written (documented), whatever the extent
  const Workspace m = datasets::parseGeoJson(R"({"type":"Polygon","coordinates":[[[200,10],[200.1,10],[200.1,10.1],[200,10.1],[200,10]]]})", "m.geojson");
  EXPECT_EQ(m.units, "m");
  EXPECT_EQ(freeArea(m), ratio(1, 100));
  // no crs, in range, extent below half a degree: longitude/latitude, projected
  const Workspace ll = datasets::parseGeoJson(R"({"type":"Polygon","coordinates":[[[179.8,10],[179.9,10],[179.9,10.1],[179.8,10.1],[179.8,10]]]})", "ll.geojson");
  EXPECT_EQ(ll.units, "m (projected from lon/lat)");
  // in range, extent of half a degree or more: metric
  EXPECT_EQ(datasets::parseGeoJson(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,1],[0,0]]]})", "w.geojson").units, "m");
  // a crs that says longitude/latitude: a position out of range is an error naming it
  const std::string crs = R"("crs":{"type":"name","properties":{"name":"urn:ogc:def:crs:OGC:1.3:CRS84"}})";
  expectInputError(
      [&] {
        datasets::parseGeoJson(R"({"type":"FeatureCollection",)" + crs +
                                   R"(,"features":[{"type":"Feature","geometry":{"type":"Polygon","coordinates":[[[179.9,10],[180.1,10],[180.1,10.1],[179.9,10]]]}}]})",
                               "c.geojson");
      },
      "c.geojson: features[0].geometry.coordinates[0][1]: longitude 180.1 outside [-180, 180] (the crs says longitude/latitude)");
  expectInputError([&] { datasets::parseGeoJson(R"({"type":"Polygon",)" + crs + R"(,"coordinates":[[[10,89.9],[10.1,90.5],[10.1,89.9],[10,89.9]]]})", "c.geojson"); },
                   "c.geojson: coordinates[0][1]: latitude 90.5 outside [-90, 90]");
}
