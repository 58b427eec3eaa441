// Benchmarks of issue 4: the HSX pantograph under the lumped catenary.
#include <benchmark/benchmark.h>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/periodic.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"

using namespace inerta;

static const pantograph::Pantograph& hsx() {
  static pantograph::Pantograph m = io::load_pantograph(INERTA_SOURCE_DIR "/models/hsx.yaml");
  return m;
}
static std::vector<double> speeds() {
  std::vector<double> v;
  for (int k = 50; k <= 300; k += 5) v.push_back(k / 3.6);
  return v;
}

// One 180 km/h run of 12 spans (the acceptance command's simulate).
static void BM_Hsx180kmh12Spans(benchmark::State& state) {
  io::CatenaryFile c = io::load_catenary(INERTA_SOURCE_DIR "/models/catenary.yaml");
  for (auto _ : state) {
    auto sys = c.catenary->couple(hsx(), c.contact, 50.0);
    analysis::RunOptions o;
    o.min_spans = 12;
    o.fixed_spans = true;
    auto r = analysis::run_speed(*sys, o);
    benchmark::DoNotOptimize(r.stats.std);
  }
}
BENCHMARK(BM_Hsx180kmh12Spans)->Unit(benchmark::kMillisecond);

// One sweep of 51 speeds (50:5:300 km/h), parallel on the machine's cores.
static void BM_HsxSweep51(benchmark::State& state) {
  io::CatenaryFile c = io::load_catenary(INERTA_SOURCE_DIR "/models/catenary.yaml");
  for (auto _ : state) {
    auto r = analysis::sweep(hsx(), *c.catenary, c.contact, speeds(), analysis::RunOptions{});
    benchmark::DoNotOptimize(r.data());
  }
}
BENCHMARK(BM_HsxSweep51)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

// The thesis's cost J2: 3 catenaries (k_c0 = 5000, 7000, 10 000 N/m) × 51 speeds.
static void BM_HsxJ2(benchmark::State& state) {
  double J2 = 0;
  for (auto _ : state) {
    J2 = 0;
    for (const char* kc0 : {"catenary.kc0=5000", "catenary.kc0=7000", "catenary.kc0=10000"}) {
      io::CatenaryFile c = io::load_catenary(INERTA_SOURCE_DIR "/models/catenary.yaml", {kc0});
      for (const auto& r : analysis::sweep(hsx(), *c.catenary, c.contact, speeds(), analysis::RunOptions{}))
        J2 = std::max(J2, r.stats.std);
    }
  }
  state.counters["J2_N"] = J2;
}
BENCHMARK(BM_HsxJ2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

// Issue 5: J2 with the periodic fast path (harmonic balance, 8 harmonics), 3 catenaries × 51 speeds.
static void BM_HsxJ2Periodic(benchmark::State& state) {
  double J2 = 0;
  std::vector<io::CatenaryFile> cats;
  for (const char* kc0 : {"catenary.kc0=5000", "catenary.kc0=7000", "catenary.kc0=10000"})
    cats.push_back(io::load_catenary(INERTA_SOURCE_DIR "/models/catenary.yaml", {kc0}));
  for (auto _ : state) {
    J2 = 0;
    for (const auto& c : cats)
      for (const auto& r : analysis::sweep_periodic(hsx(), *c.catenary, c.contact, speeds(), 8))
        J2 = std::max(J2, r.stats.std);
  }
  state.counters["J2_N"] = J2;
}
BENCHMARK(BM_HsxJ2Periodic)->Unit(benchmark::kMillisecond)->UseRealTime();
