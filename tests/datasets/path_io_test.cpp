// Reading path files (JSON coverkit.path/1 and CSV): a file that coverkit wrote reads back the same;
// every wrong JSON type, missing member, non-finite number or malformed CSV row is an InputError
// naming the file, the place and the problem (never a library exception, exit 3 in the CLI).
#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/error.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace coverkit;
namespace fs = std::filesystem;

namespace {
std::string put(const std::string& name, const std::string& content) {
  const fs::path d = fs::path(COVERKIT_TEST_TMP) / "path_io";
  fs::create_directories(d);
  std::ofstream(d / name, std::ios::binary) << content;
  return (d / name).string();
}
std::string errorOf(const std::string& file) {
  try {
    datasets::readPathFile(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}
const char* kGood = R"({"format":"coverkit.path/1","planner":"stc","status":"exact_solution","robot_radius":0.25,"robot_radius_exact":"1/4",
 "cell_size":0.5,"cell_size_exact":"1/2","robots":[{"start":[0.25,0.25],"segments":[
  {"type":"line","from":[0.25,0.25],"to":[0.75,0.25]},{"type":"arc","from":[1,0],"to":[0,1],"center":[0,0],"ccw":false}]}],
 "metrics":{"length":1.5,"overlap_ratio":null},"statistics":{}})";
}  // namespace

TEST(PathFiles, WrittenFileReadsBack) {
  datasets::PathDocument doc;
  doc.planner = "stc";
  doc.status = "exact_solution";
  doc.robotRadius = Rational(1, 4);
  doc.cellSize = Rational(1, 2);
  Path p;
  p.start = {0.25, 0.25};
  p.segments.push_back(PathSegment::line({0.25, 0.25}, {0.75, 0.25}));
  p.segments.push_back(PathSegment::arc({1, 0}, {0, 1}, {0, 0}, false));
  doc.paths = {p, p};
  doc.metrics = {{"length", 1.5}};
  for (const char* ext : {".json", ".csv"}) {
    const fs::path f = fs::path(COVERKIT_TEST_TMP) / "path_io" / (std::string("back") + ext);
    fs::create_directories(f.parent_path());
    datasets::writePathFile(f.string(), doc);
    const datasets::PathDocument back = datasets::readPathFile(f.string());
    ASSERT_EQ(back.paths.size(), 2u) << ext;
    EXPECT_EQ(back.paths[1].start.x, 0.25);
    if (std::string(ext) == ".json") {
      EXPECT_EQ(back.planner, "stc");
      EXPECT_EQ(back.robotRadius, Rational(1, 4));
      ASSERT_EQ(back.paths[0].segments.size(), 2u);
      EXPECT_FALSE(back.paths[0].segments[1].ccw);
    }
  }
  const datasets::PathDocument g = datasets::readPathFile(put("good.json", kGood));
  EXPECT_EQ(g.cellSize, Rational(1, 2));
}

TEST(PathFiles, JsonWrongTypesNameThePlace) {
  const std::string seg = R"({"type":"line","from":[0,0],"to":[1,0]})";
  auto doc = [&](const std::string& top, const std::string& segments) {
    return R"({"format":"coverkit.path/1",)" + top + R"("robots":[{"start":[0,0],"segments":[)" + segments + "]}]}";
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"format":7,"robots":[]})", "format: expected the string \"coverkit.path/1\", found number"},
      {R"({"robots":[]})", "format: missing: not a coverkit.path/1 file"},
      {R"({"format":"coverkit.path/2","robots":[]})", "format: 'coverkit.path/2': not a coverkit.path/1 file"},
      {R"([1])", "not a coverkit.path/1 file (expected a JSON object, found array)"},
      {doc(R"("planner":3,)", seg), "planner: expected a string, found number"},
      {doc(R"("status":[1],)", seg), "status: expected a string, found array"},
      {doc(R"("robot_radius":"0.25",)", seg), "robot_radius: expected a number, found string"},
      {doc(R"("robot_radius":-1,)", seg), "robot_radius: must be > 0"},
      {doc(R"("robot_radius_exact":0.25,)", seg), "robot_radius_exact: expected a rational as a string"},
      {doc(R"("robot_radius_exact":"x",)", seg), "robot_radius_exact"},
      {doc(R"("cell_size_exact":"0",)", seg), "cell_size_exact: must be > 0"},
      {doc(R"("metrics":[1],)", seg), "metrics: expected an object, found array"},
      {doc(R"("statistics":{"nodes":"many"},)", seg), "statistics.nodes: expected a number, found string"},
      {R"({"format":"coverkit.path/1","robots":{}})", "robots: expected an array, found object"},
      {R"({"format":"coverkit.path/1"})", "robots: missing robots array"},
      {R"({"format":"coverkit.path/1","robots":[3]})", "robots[0]: expected an object, found number"},
      {R"({"format":"coverkit.path/1","robots":[{"start":[0,0]}]})", "robots[0].segments: missing segments"},
      {R"({"format":"coverkit.path/1","robots":[{"start":[0,0],"segments":5}]})", "robots[0].segments: expected an array, found number"},
      {R"({"format":"coverkit.path/1","robots":[{"segments":[]}]})", "robots[0]: no start and no segments"},
      {R"({"format":"coverkit.path/1","robots":[{"start":[0],"segments":[]}]})", "robots[0].start: expected [x, y], found an array of 1"},
      {R"({"format":"coverkit.path/1","robots":[{"start":"here","segments":[]}]})", "robots[0].start: expected [x, y], found string"},
      {doc("", R"({"type":"arc","from":[1,0],"to":[0,1],"center":[0,0],"ccw":"yes"})"), "robots[0].segments[0].ccw: expected true or false, found string"},
      {doc("", R"({"type":"arc","from":[1,0],"to":[0,1]})"), "robots[0].segments[0].center: missing"},
      {doc("", R"({"type":3,"from":[1,0],"to":[0,1]})"), "robots[0].segments[0].type: expected \"line\" or \"arc\", found number"},
      {doc("", R"({"type":"spline","from":[1,0],"to":[0,1]})"), "robots[0].segments[0].type: unknown segment type 'spline'"},
      {doc("", R"({"from":[1,0],"to":[0,1]})"), "robots[0].segments[0].type: missing"},
      {doc("", seg + R"(,{"type":"line","from":[1,0],"to":[1,"a"]})"), "robots[0].segments[1].to[1]: expected a number, found string"},
      {doc("", seg + R"(,{"type":"line","from":[1,0]})"), "robots[0].segments[1].to: missing"},
      {doc("", seg + R"(,[1,2])"), "robots[0].segments[1]: expected a segment object, found array"},
      {doc("", R"({"type":"line","from":[1e999,0],"to":[1,0]})"), "JSON does not parse"},  // nlohmann refuses overflow
  };
  int i = 0;
  for (const auto& [text, want] : cases) {
    const std::string f = put("bad" + std::to_string(i++) + ".json", text);
    const std::string e = errorOf(f);
    EXPECT_NE(e.find(f + ": "), std::string::npos) << e;
    EXPECT_NE(e.find(want), std::string::npos) << "input " << text << "\nmessage " << e << "\nwanted " << want;
  }
}

TEST(PathFiles, CsvRowsAreChecked) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"x,y\n0,0,1,1\n", "line 1: expected the header 'robot,seq,x,y'"},
      {"robot,seq,x,y\n0,0,1\n", "line 2: expected 4 fields robot,seq,x,y, found 3"},
      {"robot,seq,x,y\n0,0,1,2,3\n", "line 2: expected 4 fields robot,seq,x,y, found 5"},
      {"robot,seq,x,y\n,0,1,2\n", "line 2: bad robot '' (expected an integer >= 0)"},
      {"robot,seq,x,y\n-1,0,1,2\n", "line 2: bad robot '-1'"},
      {"robot,seq,x,y\n0,0,1,2\n2,0,1,2\n", "line 3: robot 2 after robot 0: robots are numbered 0, 1, 2, ... in order"},
      {"robot,seq,x,y\n0,0,1,2\n1,0,1,2\n0,1,1,2\n", "line 4: robot 0 after robot 1"},
      {"robot,seq,x,y\n0,0,1,2\n0,2,1,2\n", "line 3: seq 2, expected 1"},
      {"robot,seq,x,y\n0,1,1,2\n", "line 2: seq 1, expected 0"},
      {"robot,seq,x,y\n0,0,,2\n", "line 2: bad x '' (expected a number)"},
      {"robot,seq,x,y\n0,0,1.5x,2\n", "line 2: bad x '1.5x'"},
      {"robot,seq,x,y\n0,0,1,nan\n", "line 2: non-finite y 'nan'"},
      {"robot,seq,x,y\n0,0,inf,1\n", "line 2: non-finite x 'inf'"},
      {"robot,seq,x,y\n0,0,1e999,1\n", "line 2: non-finite x '1e999'"},
      {"robot,seq,x,y\n0,0, 1,1\n", "line 2: bad x ' 1'"},
  };
  int i = 0;
  for (const auto& [text, want] : cases) {
    const std::string f = put("bad" + std::to_string(i++) + ".csv", text);
    const std::string e = errorOf(f);
    EXPECT_NE(e.find(f + ": " + want), std::string::npos) << "input " << text << "\nmessage " << e << "\nwanted " << want;
  }
  // CRLF line ends and empty lines are tolerated
  const datasets::PathDocument d = datasets::readPathFile(put("ok.csv", "robot,seq,x,y\r\n0,0,0,0\r\n0,1,1,0\r\n\r\n1,0,5,5\r\n"));
  ASSERT_EQ(d.paths.size(), 2u);
  EXPECT_EQ(d.paths[0].segments.size(), 1u);
  EXPECT_EQ(d.paths[1].segments.size(), 0u);
  EXPECT_EQ(d.paths[1].start.x, 5);
}

// A timed team plan: each robot's timeline ([t, x, y]) is written beside its segments and reads
// back to the bit; the text is what nlohmann's dump(1) makes of it (the writer writes the robots
// directly, in that layout); a malformed timeline is an InputError naming its place.
TEST(PathFiles, TimelinesReadBackAndKeepTheLayout) {
  datasets::PathDocument doc;
  doc.planner = "multi";
  doc.status = "exact_solution";
  doc.robotRadius = Rational(1, 4);
  doc.cellSize = Rational(1, 2);
  for (int r = 0; r < 2; ++r) {
    Path p = Path::fromPoints({{0.25 + r, 0.25}, {0.25 + r, 1.75}});
    p.timeline = {{0, {0.25 + r, 0.25}}, {0.1, {0.25 + r, 0.25}}, {1.0 / 3, {0.25 + r, 1.75}}};
    doc.paths.push_back(p);
  }
  doc.paths[1].segments.clear();   // a robot that stays where it is
  doc.paths[1].timeline.resize(1);
  const fs::path f = fs::path(COVERKIT_TEST_TMP) / "path_io" / "timed.json";
  fs::create_directories(f.parent_path());
  datasets::writePathFile(f.string(), doc);
  const std::string text = datasets::pathJson(doc);
  EXPECT_EQ(nlohmann::json::parse(text).dump(1) + "\n", text);
  const datasets::PathDocument back = datasets::readPathFile(f.string());
  ASSERT_EQ(back.paths.size(), 2u);
  ASSERT_EQ(back.paths[0].timeline.size(), 3u);
  EXPECT_EQ(back.paths[0].timeline[2].t, 1.0 / 3);
  EXPECT_EQ(back.paths[0].timeline[2].p.y, 1.75);
  EXPECT_EQ(back.paths[1].timeline.size(), 1u);
  // untimed documents keep their bytes: no timeline member at all
  datasets::PathDocument plain = doc;
  for (Path& p : plain.paths) p.timeline.clear();
  EXPECT_EQ(datasets::pathJson(plain).find("timeline"), std::string::npos);
  const std::string head = R"({"format":"coverkit.path/1","robots":[{"segments":[],"start":[0,0],"timeline":)";
  EXPECT_NE(errorOf(put("tl1.json", head + R"(3}]})")).find("robots[0].timeline: expected an array"), std::string::npos);
  EXPECT_NE(errorOf(put("tl2.json", head + R"([[0,0,0],[1,2]]}]})")).find("robots[0].timeline[1]: expected [t, x, y]"), std::string::npos);
  EXPECT_NE(errorOf(put("tl3.json", head + R"([[0,0,"a"]]}]})")).find("robots[0].timeline[0][2]: expected a number"), std::string::npos);
}
