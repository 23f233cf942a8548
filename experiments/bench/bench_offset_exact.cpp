// The three ways to build a C-obstacle (polygon ⊕ disc) measured side by side, for the record in
// docs/architecture.md: CGAL's exact offset (conic arcs, CORE algebraic numbers), the approximated
// offset coverkit uses (circle-segment arcs, error <= eps, containing the exact one), on the same
// star polygons as bench_cspace.cpp. Only the offset itself is timed. (The exact offset of the
// 500-vertex star did not finish within 5 minutes: that size is left out.)
#include <benchmark/benchmark.h>

#include <CGAL/Arr_conic_traits_2.h>
#include <CGAL/CORE_algebraic_number_traits.h>
#include <CGAL/Cartesian.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/approximated_offset_2.h>
#include <CGAL/offset_polygon_2.h>

#include <cmath>

namespace {

using NtTraits = CGAL::CORE_algebraic_number_traits;
using RatKernel = CGAL::Cartesian<NtTraits::Rational>;
using AlgKernel = CGAL::Cartesian<NtTraits::Algebraic>;
using ConicTraits = CGAL::Arr_conic_traits_2<RatKernel, AlgKernel, NtTraits>;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

template <class Kernel>
CGAL::Polygon_2<Kernel> star(int n) {
  CGAL::Polygon_2<Kernel> p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n, rr = i % 2 == 0 ? 10 : 4;
    p.push_back(typename Kernel::Point_2(typename Kernel::FT(std::lround((50 + rr * std::cos(a)) * 1e6)) / 1000000,
                                         typename Kernel::FT(std::lround((50 + rr * std::sin(a)) * 1e6)) / 1000000));
  }
  return p;
}

}  // namespace

static void BM_OffsetExactConic(benchmark::State& state) {
  const auto p = star<RatKernel>(static_cast<int>(state.range(0)));
  ConicTraits traits;
  for (auto _ : state) benchmark::DoNotOptimize(CGAL::offset_polygon_2(p, NtTraits::Rational(1) / 2, traits));
  state.counters["vertices"] = static_cast<double>(state.range(0));
}
BENCHMARK(BM_OffsetExactConic)->Arg(10)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond);

static void BM_OffsetApproximated(benchmark::State& state) {
  const auto p = star<Epeck>(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(CGAL::approximated_offset_2(p, Epeck::FT(1) / 2, 1e-4));
  state.counters["vertices"] = static_cast<double>(state.range(0));
}
BENCHMARK(BM_OffsetApproximated)->Arg(10)->Arg(50)->Arg(100)->Arg(500)->Unit(benchmark::kMillisecond);
