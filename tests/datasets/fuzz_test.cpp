// Never a crash: mutated map files (bytes flipped, lines cut, duplicated or dropped, digits changed)
// either load into a workspace that the cells, STC and the validator then handle, or are rejected
// with an InputError. Any other exception, or a crash, fails. Seeded, so every run is the same.
#include "helpers/checkers.h"

#include <coverkit/datasets/readers.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/error.h>
#include <coverkit/planners/registry.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <fstream>
#include <random>
#include <sstream>

using namespace coverkit;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string mutate(std::string s, std::mt19937_64& rng) {
  const int kind = static_cast<int>(rng() % 6);
  if (s.empty()) return s;
  const std::size_t at = rng() % s.size();
  switch (kind) {
    case 0: s[at] = static_cast<char>(rng() % 256); break;                       // any byte
    case 1: s[at] = "0123456789.-e,() #@\n"[rng() % 20]; break;                  // plausible characters
    case 2: s.resize(at); break;                                                // truncated
    case 3: s.insert(at, s.substr(at, rng() % 40)); break;                      // duplicated run
    case 4: s.erase(at, rng() % 40); break;                                     // dropped run
    default: {                                                                  // a number changed
      const std::size_t d = s.find_first_of("0123456789", at);
      if (d != std::string::npos) s.insert(d, std::to_string(rng() % 1000));
    }
  }
  return s;
}

}  // namespace

TEST(Fuzz, MutatedMapsLoadOrAreRejectedCleanly) {
  const fs::path data = COVERKIT_DATA_DIR;
  const fs::path dir = fs::path(COVERKIT_TEST_TMP) / "fuzz";
  fs::create_directories(dir);
  std::mt19937_64 rng(2024);
  std::size_t loaded = 0, rejected = 0, planned = 0;
  struct Case {
    std::string file, mutateName;  // the file given to loadMap, and the one that is mutated
  };
  // the ROS case mutates the YAML and, separately, the PGM it names
  fs::copy_file(data / "office.pgm", dir / "office.pgm", fs::copy_options::overwrite_existing);
  fs::copy_file(data / "office.yaml", dir / "office.yaml", fs::copy_options::overwrite_existing);
  const std::vector<Case> cases = {{"rooms.grid", "rooms.grid"},   {"maze.map", "maze.map"},       {"pillars.wkt", "pillars.wkt"},
                                   {"field_ring.geojson", "field_ring.geojson"}, {"office.yaml", "office.yaml"}, {"office.yaml", "office.pgm"}};
  // COVERKIT_FUZZ_ITERATIONS raises the count for a longer hunt; the suite runs 150 per file.
  const char* env = std::getenv("COVERKIT_FUZZ_ITERATIONS");
  const int iterations = env ? std::max(1, std::atoi(env)) : 150;
  for (const Case& c : cases) {
    const std::string original = slurp(data / c.mutateName);
    for (int k = 0; k < iterations; ++k) {
      std::string text = original;
      const int rounds = 1 + static_cast<int>(rng() % 3);
      for (int i = 0; i < rounds; ++i) text = mutate(text, rng);
      std::ofstream(dir / c.mutateName, std::ios::binary) << text;
      SCOPED_TRACE(c.mutateName + " mutation " + std::to_string(k));
      try {
        const Workspace w = datasets::loadMap((dir / c.file).string());
        ++loaded;
        const Box b = w.bbox();
        const Rational r = Rational(std::min(Rational(b.xmax - b.xmin), Rational(b.ymax - b.ymin)) / 20);
        if (r <= 0) continue;
        try {
          const auto ctx = testing_helpers::contextFor(w, r);
          const CSpace cs(w, r);  // the exact C-space must cope with whatever loaded
          EXPECT_LE(cs.area(), freeArea(w).get_d() + 1e-9);
          const Plan plan = planners::runPlanner("stc", ctx, {});
          ++planned;
          if (succeeded(plan.status)) {
            EXPECT_TRUE(testing_helpers::planIsValid(ctx, plan));
          }
        } catch (const InputError&) {
          // e.g. a cell size that would make too many cells
        }
      } catch (const InputError& e) {
        ++rejected;
        EXPECT_FALSE(e.problem().empty());
      } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what();
      }
    }
    std::ofstream(dir / c.mutateName, std::ios::binary) << original;
  }
  std::cout << "fuzz: " << loaded << " loaded, " << rejected << " rejected, " << planned << " planned\n";
  EXPECT_GT(loaded, 50u);
  EXPECT_GT(rejected, 50u);
}
