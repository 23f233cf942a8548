// Every registered decomposition (and the worked example of docs/adding-a-decomposition.md) keeps
// the contract, through the registry: exact cells whose union is C-free, interior-disjoint,
// complete symmetric adjacency, monotone cells for monotone models; boustrophedon never has more
// cells than trapezoidal; the sweep direction is an exact rotation.
#include <coverkit/datasets/generators.h>
#include <coverkit/geometry/error.h>
#include <coverkit/geometry/sampling.h>
#include <coverkit/planners/registry.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "helpers/worlds.h"

namespace example {
void registerStrips();
}

using namespace coverkit;

namespace {

void ensureExampleRegistered() {
  if (!planners::DecompositionRegistry::instance().contains("strips")) example::registerStrips();
}

std::vector<std::pair<std::string, Workspace>> worlds() {
  std::vector<std::pair<std::string, Workspace>> out;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    datasets::PolygonWorldSpec p;
    p.width = 14;
    p.height = 10;
    p.seed = seed;
    p.count = static_cast<int>(3 * seed);
    p.shape = static_cast<datasets::ObstacleShape>((seed + 3) % 7);
    out.emplace_back("poly" + std::to_string(seed), datasets::generatePolygonWorld(p));
  }
  // a wall that splits C-free into two components
  out.emplace_back("split", testing_helpers::boxWith({{{4, 1}, {5, 1}, {5, 9}, {4, 9}}}));
  return out;
}

}  // namespace

TEST(Decompositions, EveryRegisteredModelKeepsTheContract) {
  ensureExampleRegistered();
  const auto& reg = planners::DecompositionRegistry::instance();
  EXPECT_GE(reg.names().size(), 4u);
  for (const std::string& name : reg.names()) {
    auto model = reg.create(name);
    EXPECT_EQ(model->name(), name);
    EXPECT_FALSE(model->description().empty());
    for (const auto& s : model->params()) EXPECT_FALSE(s.help.empty()) << name << " " << s.name;
    const auto caps = model->capabilities();
    for (const auto& [label, w] : worlds())
      for (const std::string direction : {"0", "37"}) {
        if (direction != "0" && !caps.rotatable) continue;
        SCOPED_TRACE(name + " on " + label + " direction " + direction);
        std::map<std::string, std::string> params;
        if (caps.rotatable) params["direction"] = direction;
        Problem problem{w, {{Rational(2, 5), std::nullopt}}, std::nullopt, {}};
        const planners::Decomposed d = planners::runDecomposition(name, problem, params);
        ASSERT_TRUE(d.space);
        const DecompositionCheck k = checkDecomposition(d.cells, *d.space);
        EXPECT_TRUE(k.ok(caps.monotone)) << k.detail << " monotone " << k.monotone;
        EXPECT_GE(d.cells.cells.size(), d.space->componentCount());
        if (caps.rotatable) {
          EXPECT_NEAR(-d.cells.rotation.degrees(), std::stod(direction), 1e-3);
        }
      }
  }
}

TEST(Decompositions, BoustrophedonNeverHasMoreCellsThanTrapezoidal) {
  for (const auto& [label, w] : worlds())
    for (const std::string direction : {"0", "15", "90", "-60"}) {
      Problem problem{w, {{Rational(1, 4), std::nullopt}}, std::nullopt, {}};
      const auto b = planners::runDecomposition("boustrophedon", problem, {{"direction", direction}});
      const auto t = planners::runDecomposition("trapezoidal", problem, {{"direction", direction}});
      EXPECT_LE(b.cells.cells.size(), t.cells.cells.size()) << label << " " << direction;
      EXPECT_LT(b.cells.cells.size(), t.cells.cells.size() + 1);
    }
}

TEST(Decompositions, RotationsAreExactAndNearest) {
  for (double deg : {0.0, 30.0, 45.0, 90.0, -90.0, 180.0, 123.456, -359.0}) {
    const Rotation r = Rotation::nearest(deg);
    EXPECT_EQ(r.c * r.c + r.s * r.s, 1) << deg;   // a rational point of the unit circle
    double diff = std::remainder(r.degrees() - deg, 360.0);
    EXPECT_LT(std::abs(diff), 1e-3) << deg;
    const Point p{3, 7};
    EXPECT_TRUE(r.inverse(r.apply(p)) == p);
  }
  EXPECT_EQ(Rotation::nearest(90).c, 0);
  EXPECT_EQ(Rotation::nearest(90).s, 1);
}

TEST(Decompositions, BadInputIsRefused) {
  Problem problem{testing_helpers::boxWith({}), {{Rational(1, 2), std::nullopt}}, std::nullopt, {}};
  EXPECT_THROW(planners::runDecomposition("no_such_method", problem, {}), InputError);
  EXPECT_THROW(planners::runDecomposition("boustrophedon", problem, {{"direction", "north"}}), InputError);
  EXPECT_THROW(planners::runDecomposition("boustrophedon", problem, {{"direction", "400"}}), InputError);
  EXPECT_THROW(planners::runDecomposition("grid", problem, {{"no_such_parameter", "1"}}), InputError);
  // a robot wider than the workspace: no cells (the command line turns that into an error)
  Problem huge{testing_helpers::boxWith({}), {{Rational(6), std::nullopt}}, std::nullopt, {}};
  EXPECT_TRUE(planners::runDecomposition("boustrophedon", huge, {}).cells.cells.empty());
}

// The GeoJSON cell files sample arcs on the cell's inside and move every vertex into its exact cell;
// the few that no move of a few ulps brings in are counted in the file, never silently left out.
// They are the cusps where an arc's x-extreme meets a wall (the cell there is a horn narrower than
// the doubles beside the wall's line: 2-6 % of the boustrophedon cells' vertices here) and slivers.
TEST(Decompositions, SampledCellsLieInTheirExactCells) {
  for (const auto& [label, w] : worlds()) {
    Problem problem{w, {{Rational(2, 5), std::nullopt}}, std::nullopt, {}};
    for (const std::string method : {"boustrophedon", "grid", "trapezoidal"}) {
      const planners::Decomposed d =
          planners::runDecomposition(method, problem, method == "trapezoidal" ? std::map<std::string, std::string>{{"direction", "25"}}
                                                                               : std::map<std::string, std::string>{});
      std::vector<std::size_t> unplaced;
      const std::vector<SampledRegion> sampled = sampledCells(d.cells, 1e-3, &unplaced);
      ASSERT_EQ(sampled.size(), d.cells.cells.size());
      std::size_t checked = 0, outside = 0, reported = 0;
      for (std::size_t i = 0; i < sampled.size(); ++i) {
        auto check = [&](const std::vector<PointD>& ring) {
          for (const PointD& v : ring) {
            outside += !d.cells.contains(static_cast<int>(i), d.cells.rotation.apply(Point{exactFromDouble(v.x), exactFromDouble(v.y)}));
            ++checked;
          }
        };
        check(sampled[i].outer);
        for (const auto& h : sampled[i].holes) check(h);
        reported += unplaced[i];
      }
      EXPECT_EQ(outside, reported) << label << " " << method;   // every vertex outside its cell is reported
      EXPECT_LE(outside * 10, checked) << label << " " << method;   // cusps and slivers only: a few %
      if (method == "grid") {
        EXPECT_EQ(outside, 0u) << label;
      }
      std::cout << label << " " << method << ": " << outside << " of " << checked << " vertices outside their exact cell\n";
      EXPECT_GT(checked, d.cells.cells.size() * 3);
    }
  }
}

// The worked example in docs/adding-a-decomposition.md is the file this test compiles.
TEST(Decompositions, TheDocumentedExampleIsTheCompiledOne) {
  auto read = [](const std::string& f) {
    std::ifstream in(f);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  const std::string doc = read(std::string(COVERKIT_DOCS_DIR) + "/adding-a-decomposition.md");
  const std::string code = read(std::string(COVERKIT_DOCS_DIR) + "/examples/strips_decomposition.cpp");
  ASSERT_FALSE(code.empty());
  const auto begin = doc.find("```cpp\n");
  ASSERT_NE(begin, std::string::npos);
  const auto end = doc.find("```", begin + 7);
  EXPECT_EQ(doc.substr(begin + 7, end - begin - 7), code);
}
