// C-space: C-obstacles of polygons of 10 to 10^4 vertices, worlds of 1 to 1,000 obstacles, cells by
// C-space on 50×50 to 1,000×1,000 mega-cells; side by side with GEOS buffers (8 and 64 segments per
// quarter circle, what Fields2Cover uses). Area errors are against a reference C-space with
// eps = 1e-12 × extent (its own error is below 1e-11 relative).
#include <benchmark/benchmark.h>

#include <coverkit/datasets/generators.h>
#include <coverkit/geometry/cspace.h>

#include <cmath>
#include <map>

#ifdef COVERKIT_HAVE_GEOS
#include <geos_c.h>
#endif

using namespace coverkit;

namespace {

/// A star with n vertices (n even), radius 10 and 4, about (50, 50), in a 100 × 100 box.
Workspace starWorld(int n) {
  Workspace w;
  Region reg;
  reg.outer = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  Ring star;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n, rr = i % 2 == 0 ? 10 : 4;
    star.push_back({ratio(std::lround((50 + rr * std::cos(a)) * 1e6), 1000000), ratio(std::lround((50 + rr * std::sin(a)) * 1e6), 1000000)});
  }
  std::reverse(star.begin(), star.end());
  reg.holes.push_back(star);
  w.regions.push_back(reg);
  return w;
}

Workspace obstacleWorld(int count) {
  datasets::PolygonWorldSpec s;
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count)) * 6)) + 4;
  s.width = s.height = side;
  s.count = count;
  s.minSize = 1.5;
  s.maxSize = 3;
  s.shape = datasets::ObstacleShape::kConvex;
  s.seed = 17;
  return datasets::generatePolygonWorld(s);
}

double referenceArea(const Workspace& w, const Rational& r) {
  static std::map<std::pair<std::string, std::size_t>, double> cache;
  const auto key = std::make_pair(w.name + std::to_string(r.get_d()), w.vertexCount());
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  return cache[key] = CSpace(w, r, 1e-12).area();
}

const Rational kRadius(1, 2);

}  // namespace

static void BM_CSpaceStar(benchmark::State& state) {
  const Workspace w = starWorld(static_cast<int>(state.range(0)));
  double area = 0;
  for (auto _ : state) area = CSpace(w, kRadius).area();
  const double ref = referenceArea(w, kRadius);
  state.counters["vertices"] = static_cast<double>(state.range(0));
  state.counters["area_err_rel"] = std::abs(area - ref) / ref;
}
BENCHMARK(BM_CSpaceStar)->RangeMultiplier(10)->Range(10, 10'000)->Unit(benchmark::kMillisecond);

static void BM_CSpaceWorld(benchmark::State& state) {
  const Workspace w = obstacleWorld(static_cast<int>(state.range(0)));
  double area = 0;
  for (auto _ : state) area = CSpace(w, kRadius).area();
  const double ref = referenceArea(w, kRadius);
  state.counters["obstacles"] = static_cast<double>(w.regions[0].holes.size());
  state.counters["vertices"] = static_cast<double>(w.vertexCount());
  state.counters["area_err_rel"] = std::abs(area - ref) / ref;
}
BENCHMARK(BM_CSpaceWorld)->Arg(1)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

// The same with the obstacles' offsets on every core, as `coverkit cspace` and the planners' C-spaces
// run by default (`--threads 0`); wall time, the C-space the same to the bit.
static void BM_CSpaceWorldAllCores(benchmark::State& state) {
  const Workspace w = obstacleWorld(static_cast<int>(state.range(0)));
  double area = 0;
  for (auto _ : state) area = CSpace(w, kRadius, 1e-6, 0).area();
  state.counters["obstacles"] = static_cast<double>(w.regions[0].holes.size());
  state.counters["area_err_rel"] = std::abs(area - referenceArea(w, kRadius)) / referenceArea(w, kRadius);
}
BENCHMARK(BM_CSpaceWorldAllCores)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_CSpaceCells(benchmark::State& state) {
  // a world of 100 obstacles, the mega-cell grid made finer to reach M × M mega-cells
  const Workspace w = obstacleWorld(100);
  const CSpace cs(w, kRadius);
  const Box b = w.bbox();
  const int m = static_cast<int>(state.range(0));
  const Rational D = Rational(b.xmax - b.xmin) / (2 * m);
  const CellGrid grid = classifyCells(w, D);
  std::size_t partial = 0;
  for (auto _ : state) {
    const CSpaceCells cc = cs.classify(grid, true);
    partial = cc.contours.size();
  }
  state.counters["mega_cells"] = static_cast<double>(grid.megaCount());
  state.counters["partial"] = static_cast<double>(partial);
}
BENCHMARK(BM_CSpaceCells)->Arg(50)->Arg(100)->Arg(200)->Arg(500)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(1);

#ifdef COVERKIT_HAVE_GEOS
namespace {

struct Geos {
  GEOSContextHandle_t h = GEOS_init_r();
  ~Geos() { GEOS_finish_r(h); }
  GEOSGeometry* ring(const Ring& r, bool linear = true) {
    GEOSCoordSequence* cs = GEOSCoordSeq_create_r(h, static_cast<unsigned>(r.size() + 1), 2);
    for (std::size_t i = 0; i <= r.size(); ++i) {
      const Point& p = r[i % r.size()];
      GEOSCoordSeq_setXY_r(h, cs, static_cast<unsigned>(i), p.x.get_d(), p.y.get_d());
    }
    (void)linear;
    return GEOSGeom_createLinearRing_r(h, cs);
  }
  GEOSGeometry* polygon(const Ring& outer) { return GEOSGeom_createPolygon_r(h, ring(outer), nullptr, 0); }
  /// C-free area the way a buffer-based library gets it: eroded outer ring minus buffered obstacles.
  double cfreeArea(const Workspace& w, double r, int quadsegs) {
    double total = 0;
    for (const Region& reg : w.regions) {
      GEOSGeometry* outer = polygon(reg.outer);
      GEOSGeometry* eroded = GEOSBuffer_r(h, outer, -r, quadsegs);
      std::vector<GEOSGeometry*> obs;
      for (const Ring& hole : reg.holes) {
        GEOSGeometry* p = polygon(hole);
        obs.push_back(GEOSBuffer_r(h, p, r, quadsegs));
        GEOSGeom_destroy_r(h, p);
      }
      GEOSGeometry* coll = GEOSGeom_createCollection_r(h, GEOS_GEOMETRYCOLLECTION, obs.data(), static_cast<unsigned>(obs.size()));
      GEOSGeometry* uni = GEOSUnaryUnion_r(h, coll);
      GEOSGeometry* fr = GEOSDifference_r(h, eroded, uni);
      double a = 0;
      GEOSArea_r(h, fr, &a);
      total += a;
      for (GEOSGeometry* g : {outer, eroded, coll, uni, fr}) GEOSGeom_destroy_r(h, g);
    }
    return total;
  }
};

}  // namespace

static void BM_GeosStar(benchmark::State& state) {
  const Workspace w = starWorld(static_cast<int>(state.range(0)));
  Geos g;
  double area = 0;
  for (auto _ : state) area = g.cfreeArea(w, 0.5, static_cast<int>(state.range(1)));
  const double ref = referenceArea(w, kRadius);
  state.counters["vertices"] = static_cast<double>(state.range(0));
  state.counters["area_err_rel"] = std::abs(area - ref) / ref;
  state.counters["unsafe"] = area > ref ? 1 : 0;  // more C-free than exists: the robot may hit obstacles
}
BENCHMARK(BM_GeosStar)->ArgsProduct({{10, 100, 1000, 10000}, {8, 64}})->Unit(benchmark::kMillisecond);

static void BM_GeosWorld(benchmark::State& state) {
  const Workspace w = obstacleWorld(static_cast<int>(state.range(0)));
  Geos g;
  double area = 0;
  for (auto _ : state) area = g.cfreeArea(w, 0.5, static_cast<int>(state.range(1)));
  const double ref = referenceArea(w, kRadius);
  state.counters["obstacles"] = static_cast<double>(w.regions[0].holes.size());
  state.counters["area_err_rel"] = std::abs(area - ref) / ref;
  state.counters["unsafe"] = area > ref ? 1 : 0;
}
BENCHMARK(BM_GeosWorld)->ArgsProduct({{1, 10, 100, 1000}, {8, 64}})->Unit(benchmark::kMillisecond);
#endif
