// Every planner on cells against a seeded spread of worlds, radii, cell sizes and starts: valid,
// complete as declared, deterministic. COVERKIT_STRESS_WORLDS raises the number of worlds for a
// longer hunt (the suite runs 8).
#include "helpers/checkers.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/path_io.h>
#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/registry.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <random>
#include <sstream>

using namespace coverkit;

namespace {

/// A free point of the world drawn from the seed: the centre of a random free sub-cell, moved
/// off-centre by a quarter of the slack the disc has there.
std::optional<Point> randomStart(const CellGrid& cells, std::mt19937_64& rng) {
  std::vector<CellIndex> free;
  for (int r = 0; r < cells.subRows(); ++r)
    for (int c = 0; c < cells.subCols(); ++c)
      if (cells.sub(c, r) == CellState::kFree) free.push_back({c, r});
  if (free.empty()) return std::nullopt;
  const CellIndex c = free[rng() % free.size()];
  return cells.subCenter(c.col, c.row);
}

}  // namespace

TEST(Stress, EveryPlannerOnCellsOnSeededWorldsRadiiCellSizesAndStarts) {
  int worlds = 8;
  if (const char* env = std::getenv("COVERKIT_STRESS_WORLDS")) worlds = std::max(1, std::atoi(env));
  const std::vector<Rational> radii{Rational(1, 10), Rational(3, 20), Rational(1, 4), Rational(1, 3), Rational(1, 2)};
  std::size_t plans = 0;
  for (int w = 0; w < worlds; ++w) {
    std::mt19937_64 rng(static_cast<std::uint64_t>(1000 + w));
    Workspace world;
    if (w % 2 == 0) {
      datasets::GridMapSpec g;
      g.width = 24 + static_cast<int>(rng() % 30);
      g.height = 20 + static_cast<int>(rng() % 20);
      g.density = 0.02 * static_cast<double>(rng() % 8);
      g.clustered = rng() % 2 == 0;
      g.resolution = (rng() % 2) ? Rational(1, 20) : Rational(1, 10);
      g.seed = rng();
      world = datasets::gridToWorkspace(datasets::generateGridMap(g), "stress-grid");
    } else {
      datasets::PolygonWorldSpec p;
      p.width = 8 + static_cast<int>(rng() % 8);
      p.height = 8 + static_cast<int>(rng() % 6);
      p.count = 3 + static_cast<int>(rng() % 8);
      p.minSize = 0.5;
      p.maxSize = 2;
      p.shape = static_cast<datasets::ObstacleShape>(rng() % 7);
      p.seed = rng();
      world = datasets::generatePolygonWorld(p);
    }
    const Rational r = radii[rng() % radii.size()];
    // the default cell size (2r) or a little more, as a user may set it
    Problem problem;
    problem.workspace = world;
    problem.robots.push_back({r, std::nullopt});
    if (rng() % 3 == 0) problem.cellSize = 2 * r * Rational(11, 10);
    planners::PlanningContext ctx;
    try {
      ctx = planners::makeContext(problem);
    } catch (const InputError&) {
      continue;  // the robot does not fit this world: a checked refusal
    }
    if (rng() % 2 == 0) {
      if (auto s = randomStart(ctx.cells, rng)) {
        problem.robots[0].start = *s;
        ctx = planners::makeContext(problem);
      }
    }
    for (const std::string& name : planners::Registry::instance().names()) {
      SCOPED_TRACE("world " + std::to_string(w) + " r " + r.get_str() + " planner " + name);
      const auto caps = planners::Registry::instance().create(name)->capabilities();
      const Plan a = planners::runPlanner(name, ctx, {});
      if (a.status == PlanStatus::kInvalidStart || a.status == PlanStatus::kNoFreeSpace) {
        EXPECT_FALSE(a.message.empty());
        // every start here is in a free sub-cell: only planners of free mega-cells may refuse it,
        // or any planner when that sub-cell is squeezed (no double start is safe there)
        CellIndex sc;
        const bool squeezedStart = ctx.problem.robots[0].start && ctx.cells.locateSub(*ctx.problem.robots[0].start, sc) &&
                                   testing_helpers::squeezedSubcell(ctx, sc);
        EXPECT_FALSE(caps.coverage == "free_sub_cells" && a.status == PlanStatus::kInvalidStart && !squeezedStart) << a.message;
        continue;
      }
      ++plans;
      ASSERT_TRUE(testing_helpers::planIsValid(ctx, a));
      EXPECT_TRUE(testing_helpers::coversWhatItClaims(ctx, a, caps.coverage));
      EXPECT_EQ(testing_helpers::pathJsonOf(a), testing_helpers::pathJsonOf(planners::runPlanner(name, ctx, {})));
    }
  }
  EXPECT_GT(plans, 0u);
  std::cout << plans << " plans checked\n";
}

// COVERKIT_STRESS_MAPS=DIR (a folder of map files, searched recursively): every planner on cells on each map
// with several radii, validated and checked for coverage. Skipped when unset (the suite ships no
// third-party maps). COVERKIT_STRESS_PLANNERS=a,b,… limits it to those planners.
TEST(Stress, EveryPlannerOnCellsOnTheMapsOfAFolder) {
  const char* dir = std::getenv("COVERKIT_STRESS_MAPS");
  if (!dir) GTEST_SKIP() << "COVERKIT_STRESS_MAPS not set";
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (ext == ".yaml" || ext == ".map" || ext == ".wkt" || ext == ".geojson") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  std::vector<std::string> only;
  if (const char* env = std::getenv("COVERKIT_STRESS_PLANNERS")) {
    std::stringstream in(env);
    for (std::string name; std::getline(in, name, ',');) only.push_back(name);
  }
  std::size_t plans = 0;
  for (const std::string& f : files) {
    const Workspace w = datasets::loadMap(f);
    const Box b = w.bbox();
    const double extent = std::min(toDouble(Rational(b.xmax - b.xmin)), toDouble(Rational(b.ymax - b.ymin)));
    for (const double frac : {0.003, 0.006, 0.01, 0.025}) {
      // radii scaled to the map: 0.3 % to 2.5 % of its shorter side (at least 0.05), as 3-digit decimals
      // (maps in lon/lat or other small units: at least 1 % of the side instead of 0.05)
      const double rd = std::max(std::min(0.05, 0.01 * extent), frac * extent);
      const double scale = std::pow(10.0, 2 - std::floor(std::log10(rd)));
      const Rational r = parseRational(formatDouble(std::round(rd * scale) / scale), "r", "r");
      planners::PlanningContext ctx;
      try {
        ctx = testing_helpers::contextFor(w, r);
      } catch (const InputError&) {
        continue;
      }
      for (const std::string& name : planners::Registry::instance().names()) {
        if (!only.empty() && std::find(only.begin(), only.end(), name) == only.end()) continue;
        SCOPED_TRACE(f + " r " + r.get_str() + " " + name);
        const auto caps = planners::Registry::instance().create(name)->capabilities();
        const Plan a = planners::runPlanner(name, ctx, {});
        if (a.status == PlanStatus::kInvalidStart || a.status == PlanStatus::kNoFreeSpace) continue;
        ++plans;
        EXPECT_TRUE(testing_helpers::planIsValid(ctx, a));
        if (!only.empty())
          std::cout << f << " r " << r.get_str() << " " << name << ": " << toString(a.status) << ", " << a.paths[0].segments.size()
                    << " pieces\n";
        EXPECT_TRUE(testing_helpers::coversWhatItClaims(ctx, a, caps.coverage));
        if (name == "spiral_stc") {
          EXPECT_TRUE(testing_helpers::withinGabrielyRimonBound(ctx, a));
        }
      }
    }
  }
  std::cout << plans << " plans checked on " << files.size() << " maps\n";
}
