// The planners, the two sweep decompositions, the validator and the metrics run on several threads
// at once (as the experiment engine's --jobs runs cases), each thread with its own Problem and
// context, and every result is the same, byte for byte, as the same run done on one thread.
// Shared mutable state in the library (a static cache, a lazy initialisation that is not
// thread-safe, a shared random generator) would make results differ here, or ThreadSanitizer
// report a race: `bash .ci/bootstrap tsan` runs these tests built with -fsanitize=thread
// (docs/fuzzing.md, "ThreadSanitizer").
#include "helpers/checkers.h"

#include <coverkit/datasets/generators.h>
#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/validate.h>
#include <coverkit/planners/registry.h>

#include <gtest/gtest.h>

#include <condition_variable>
#include <functional>
#include <mutex>
#include <sstream>
#include <thread>

using namespace coverkit;

namespace {

/// Small seeded worlds in the contract test's style: a grid map (radius 1/10) or a polygon world
/// (radius 1/4), each a fraction of a second to plan in Release.
struct World {
  Workspace workspace;
  Rational radius;
};

World world(bool grid) {
  datasets::GridMapSpec g;
  g.width = 16;
  g.height = 12;
  g.density = 0.08;
  g.clustered = true;
  g.resolution = Rational(1, 10);
  g.seed = 2;
  datasets::PolygonWorldSpec p;
  p.width = 6;
  p.height = 5;
  p.count = 3;
  p.shape = datasets::ObstacleShape::kRectangle;
  p.seed = 3;
  if (grid) return {datasets::gridToWorkspace(datasets::generateGridMap(g), "grid"), Rational(1, 10)};
  return {datasets::generatePolygonWorld(p), Rational(1, 4)};
}

/// What a run calls at the end of each of its phases: nothing on one thread; on the threads, a
/// barrier, so that they start each phase together.
using PhaseEnd = std::function<void()>;

/// One run: a name for messages, how many times it calls its PhaseEnd, and the work, which returns
/// everything it produced as text.
struct Case {
  std::string label;
  int phases = 0;
  std::function<std::string(unsigned metricThreads, const PhaseEnd& phaseEnd)> run;
};

/// Holds each of `count` threads in wait() until all of them are there (C++17 has no std::barrier).
class Barrier {
public:
  explicit Barrier(unsigned count) : count_(count) {}
  void wait() {
    std::unique_lock<std::mutex> lock(mutex_);
    const unsigned long generation = generation_;
    if (++arrived_ == count_) {
      arrived_ = 0;
      ++generation_;
      everyone_.notify_all();
    } else {
      everyone_.wait(lock, [&] { return generation_ != generation; });
    }
  }

private:
  std::mutex mutex_;
  std::condition_variable everyone_;
  const unsigned count_;
  unsigned arrived_ = 0;
  unsigned long generation_ = 0;
};

constexpr int kPlanRunPhases = 3;

/// The world generated (each run its own), makeContext, the planner, the validator and the metrics,
/// as the engine's runOnce does them, in four phases (phaseEnd after the first three): the
/// validator's verdict with its violations, then the path file's JSON (paths, status, statistics,
/// metrics). `coverable`: with the coverable region.
std::string planRun(bool grid, const std::string& planner, bool coverable, unsigned metricThreads, const PhaseEnd& phaseEnd) {
  const World w = world(grid);
  Problem problem;
  problem.workspace = w.workspace;
  problem.robots.push_back({w.radius, std::nullopt});
  const planners::PlanningContext ctx = planners::makeContext(problem);
  phaseEnd();
  const Plan plan = planners::runPlanner(planner, ctx, {});
  phaseEnd();
  ValidationReport rep;
  if (succeeded(plan.status)) rep = validatePaths(ctx.problem, plan.paths);
  phaseEnd();
  datasets::PathDocument doc;
  doc.planner = plan.planner;
  doc.status = toString(plan.status);
  doc.robotRadius = w.radius;
  doc.cellSize = ctx.cells.subSize();
  doc.paths = plan.paths;
  for (const auto& [k, v] : plan.statistics) doc.statistics.emplace_back(k, v);
  std::ostringstream out;
  out << "message: " << plan.message << "\n";
  if (succeeded(plan.status)) {
    out << "valid: " << rep.valid << ", segments " << rep.segmentsChecked << ", exact tests " << rep.exactTests << "\n";
    for (const Violation& v : rep.violations) out << "[" << v.kind << "] " << v.robot << " " << v.segment << " " << v.detail << "\n";
    MetricOptions mo;
    mo.coverable = coverable;
    mo.pathsKnownClear = rep.valid;
    mo.threads = metricThreads;
    const Metrics m = computeMetrics(ctx.problem, ctx.cells, plan.paths, mo);
    doc.metrics = datasets::metricFields(m);
    out << "area method: " << m.areaMethod << ", coverable skipped: " << m.coverableSkipped << "\n";
  }
  return out.str() + datasets::pathJson(doc);
}

/// runDecomposition on the polygon world: the cells file's JSON of the cells and walls (in the
/// decomposition's frame), the exact rotation and the C-space's area.
std::string decompositionRun(const std::string& method, const std::string& direction) {
  const World w = world(false);
  const Problem problem{w.workspace, {{w.radius, std::nullopt}}, std::nullopt, {}};
  const planners::Decomposed d = planners::runDecomposition(method, problem, {{"direction", direction}});
  datasets::CellsDocument doc;
  doc.method = method;
  doc.robotRadius = w.radius;
  doc.rotationCos = d.cells.rotation.c.get_str();
  doc.rotationSin = d.cells.rotation.s.get_str();
  doc.cfreeArea = d.space ? d.space->area() : -1;
  doc.unwalledVertices = d.cells.unwalledVertices;
  for (const DecomposedCell& c : d.cells.cells) doc.cells.push_back({c.region, c.neighbours});
  for (const CellWall& k : d.cells.walls)
    doc.walls.push_back({k.a, k.b, k.vertical ? PointD{k.at, k.lo} : PointD{k.lo, k.at}, k.vertical ? PointD{k.at, k.hi} : PointD{k.hi, k.at}});
  return datasets::cellsFileContent("cells.json", doc);
}

/// Every registered planner on both worlds (the metrics of the first with the coverable region: its
/// two C-spaces cost more than the planners), then boustrophedon and trapezoidal on the polygon world.
std::vector<Case> cases() {
  std::vector<Case> out;
  const std::vector<std::string> names = planners::Registry::instance().names();
  for (const bool grid : {true, false})
    for (const std::string& name : names)
      out.push_back({name + (grid ? " on the grid map" : " on the polygon world"), kPlanRunPhases,
                     [grid, name, coverable = name == names.front()](unsigned t, const PhaseEnd& end) {
                       return planRun(grid, name, coverable, t, end);
                     }});
  for (const std::string method : {"boustrophedon", "trapezoidal"})
    for (const std::string direction : {"0", "37"})
      out.push_back({method + " decomposition at " + direction + " degrees", 0,
                     [method, direction](unsigned, const PhaseEnd&) { return decompositionRun(method, direction); }});
  return out;
}

/// Where two results part: the first line that differs, with its number (empty when they are equal).
std::string firstDifference(const std::string& a, const std::string& b) {
  std::istringstream ia(a), ib(b);
  std::string la, lb;
  for (int line = 1;; ++line) {
    const bool moreA = static_cast<bool>(std::getline(ia, la)), moreB = static_cast<bool>(std::getline(ib, lb));
    if (!moreA && !moreB) return "";
    if (moreA != moreB || la != lb)
      return "line " + std::to_string(line) + ": serial '" + (moreA ? la : "(end)") + "', on threads '" + (moreB ? lb : "(end)") + "'";
  }
}

constexpr unsigned kThreads = 3;

}  // namespace

// Each case on kThreads threads at once, then once more on this thread; every result of the
// threads must be the serial one. The threads run first, in a fresh process (ctest runs each test
// on its own), so that a lazy initialisation in the library happens on several threads at once.
// The threads of a case share no data. They wait for each other at the end of each phase of a run
// (context, planning, validation, metrics), so ThreadSanitizer orders the phases, but within a
// phase it sees any two accesses of theirs to the same memory as unordered. Its history is
// bounded, and accesses far apart in time may never be compared: the threads start each phase
// together to run the same code at the same moment. The metrics' own raster threads are on (2)
// where the serial runs use 1.
TEST(Concurrency, PlannersDecompositionsValidatorAndMetricsGiveTheSerialResultsOnThreads) {
  const std::vector<Case> all = cases();
  // a run that throws on a thread gives the message as its result, and still ends its phases
  std::vector<std::vector<std::string>> results(all.size(), std::vector<std::string>(kThreads));
  for (std::size_t i = 0; i < all.size(); ++i) {
    Barrier barrier(kThreads);
    std::vector<std::thread> pool;
    for (std::string& result : results[i])
      pool.emplace_back([&c = all[i], &barrier, &result] {
        int ended = 0;
        const PhaseEnd phaseEnd = [&] {
          ++ended;
          barrier.wait();
        };
        try {
          result = c.run(2, phaseEnd);
        } catch (const std::exception& e) {
          result = std::string("threw: ") + e.what();
        }
        while (ended < c.phases) phaseEnd();
      });
    for (std::thread& th : pool) th.join();
  }
  std::vector<std::string> serial;
  for (const Case& c : all) serial.push_back(c.run(1, [] {}));
  for (std::size_t i = 0; i < all.size(); ++i)
    for (unsigned t = 0; t < kThreads; ++t) {
      const std::string difference = firstDifference(serial[i], results[i][t]);
      EXPECT_TRUE(difference.empty()) << all[i].label << ", thread " << t << ": " << difference;
    }
}

// The phases that split over threads themselves: the C-space's offsets (one per obstacle ring) and
// the validator's ranges of a long path. Their results must be those of one thread, to the bit;
// under ThreadSanitizer (.ci/run) this also checks that the threads share no data.
TEST(Concurrency, CSpaceOffsetsAndValidatorRangesOnThreadsGiveTheOneThreadResults) {
  datasets::PolygonWorldSpec spec;
  spec.width = spec.height = 30;
  spec.count = 40;
  spec.shape = datasets::ObstacleShape::kMixed;
  spec.seed = 9;
  const Workspace w = datasets::generatePolygonWorld(spec);
  auto describe = [](const CSpace& cs) {
    std::ostringstream out;
    out.precision(17);
    out << cs.componentCount() << " " << cs.area() << "\n";
    for (const CurveRegion& c : cs.components())
      for (const PathSegment& s : c.outer.pieces) out << s.from.x << " " << s.from.y << " " << s.to.x << " " << s.to.y << "\n";
    return out.str();
  };
  const std::string one = describe(CSpace(w, Rational(1, 4), 1e-6, 1));
  EXPECT_EQ(describe(CSpace(w, Rational(1, 4), 1e-6, 3)), one);

  // a path back and forth along a free line, long enough for three ranges of 4,096 pieces
  Problem p;
  p.workspace = w;
  p.robots.push_back({Rational(1, 4), std::nullopt});
  std::vector<PointD> pts;
  for (int i = 0; i < 13000; ++i) pts.push_back({0.5 + 29.0 * (i % 2), 0.25 + 0.01 * (i % 2000)});
  const Path path = Path::fromPoints(pts);
  auto report = [&](unsigned threads) {
    ValidationOptions o;
    o.threads = threads;
    const ValidationReport r = validatePaths(p, {path}, o);
    std::ostringstream out;
    out << r.valid << " " << r.segmentsChecked << " " << r.exactTests << "\n";
    for (const Violation& v : r.violations) out << v.kind << " " << v.segment << " " << v.detail << "\n";
    return out.str();
  };
  const std::string serial = report(1);
  EXPECT_NE(serial.find("clearance"), std::string::npos);   // it crosses obstacles: violations in order
  EXPECT_EQ(report(3), serial);
}

// Smooth-STC's sweeps on strips of requests, one per thread (CSpace::localSweeps, each strip with
// its own exact numbers), and the exact checks of their inner pieces in blocks of at least 16
// sweeps, one per thread (each with its own checker): the plan with `threads` 3 is the one-thread
// plan, byte for byte.
TEST(Concurrency, SmoothStcSweepsOnThreadsGiveTheOneThreadPlan) {
  Problem p;
  p.workspace = testing_helpers::mixedWorld(5, 12, 8);
  p.robots.push_back({Rational(1, 4), std::nullopt});
  planners::PlanningContext ctx = planners::makeContext(p);
  double sweeps = 0;
  auto planText = [&](unsigned threads) {
    ctx.threads = threads;
    const Plan plan = planners::runPlanner("smooth_stc", ctx, {{"detours", "every"}});   // every sweep: enough for three blocks
    sweeps = plan.statistics.at("sweeps");
    std::ostringstream out;
    out.precision(17);
    for (const PathSegment& s : plan.paths.at(0).segments) out << s.from.x << " " << s.from.y << " " << s.to.x << " " << s.to.y << "\n";
    return out.str();
  };
  const std::string one = planText(1);
  EXPECT_GT(one.size(), 1000u);
  EXPECT_GE(sweeps, 48) << "too few sweeps for three blocks of checks";
  EXPECT_EQ(planText(3), one);
}
