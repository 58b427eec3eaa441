// Benchmarks of issue 12: the finite-element catenary (models/catenary-fe.yaml) with the 3-mass and
// the HSX pantographs; cost against the number of spans; a parallel sweep. One iteration each: a
// run is seconds long.
#include <benchmark/benchmark.h>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"

using namespace inerta;

namespace {
const char* kFe = INERTA_SOURCE_DIR "/models/catenary-fe.yaml";

void run_line(benchmark::State& state, const char* model, double kmh, const std::vector<std::string>& sets) {
  const pantograph::Pantograph p = io::load_pantograph(std::string(INERTA_SOURCE_DIR) + "/models/" + model);
  io::CatenaryFile c = io::load_catenary(kFe, sets);
  for (auto _ : state) {
    auto sys = c.catenary->couple(p, c.contact, kmh / 3.6);
    auto r = analysis::run_speed(*sys, analysis::RunOptions{});
    benchmark::DoNotOptimize(r.stats.std);
  }
}
}  // namespace

// The 3-mass pantograph at 250 km/h on the default line (10 spans, 0.25 m elements, h = 0.5 ms).
static void BM_Fe3Mass250kmh(benchmark::State& state) { run_line(state, "pantograph-3mass.yaml", 250, {}); }
BENCHMARK(BM_Fe3Mass250kmh)->Unit(benchmark::kMillisecond)->Iterations(1);

// The same with h = 1 ms.
static void BM_Fe3Mass250kmhStep1ms(benchmark::State& state) {
  run_line(state, "pantograph-3mass.yaml", 250, {"integration.time_step=1e-3"});
}
BENCHMARK(BM_Fe3Mass250kmhStep1ms)->Unit(benchmark::kMillisecond)->Iterations(1);

// The HSX multibody pantograph at 300 km/h.
static void BM_FeHsx300kmh(benchmark::State& state) { run_line(state, "hsx.yaml", 300, {}); }
BENCHMARK(BM_FeHsx300kmh)->Unit(benchmark::kMillisecond)->Iterations(1);

// Cost against the number of spans (3-mass, 250 km/h).
static void BM_Fe3MassSpans(benchmark::State& state) {
  run_line(state, "pantograph-3mass.yaml", 250, {"line.spans=" + std::to_string(state.range(0))});
}
BENCHMARK(BM_Fe3MassSpans)->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond)->Iterations(1);

// The line alone: one structural step of the default line with a moving penalty contact.
static void BM_FeLineStep(benchmark::State& state) {
  const io::CatenaryFile c = io::load_catenary(kFe);
  const catenary::FeLine line(io::read_fe_catenary_data(kFe));
  catenary::FeIntegrator fe(line, 5e-4, 0.0);
  catenary::FeState s = fe.initial({1.0}, {100.0});
  std::vector<double> f;
  double x = 1.0;
  for (auto _ : state) {
    x += 69.4 * 5e-4;
    if (x > 540) x = 1.0;
    catenary::FeLoad ld{x, true, 0, line.static_height(x) + 0.014, 0, 5e4, 0, 69.4};
    fe.step(s, {ld}, f);
    benchmark::DoNotOptimize(f.data());
  }
  state.counters["dofs"] = line.n_dofs();
}
BENCHMARK(BM_FeLineStep)->Unit(benchmark::kMicrosecond);

// The acceptance sweep: HSX, 150:10:350 km/h (21 speeds), parallel on the machine's cores.
static void BM_FeHsxSweep21(benchmark::State& state) {
  const pantograph::Pantograph p = io::load_pantograph(INERTA_SOURCE_DIR "/models/hsx.yaml");
  io::CatenaryFile c = io::load_catenary(kFe);
  std::vector<double> v;
  for (int k = 150; k <= 350; k += 10) v.push_back(k / 3.6);
  for (auto _ : state) {
    auto r = analysis::sweep(p, *c.catenary, c.contact, v, analysis::RunOptions{});
    benchmark::DoNotOptimize(r.data());
  }
}
BENCHMARK(BM_FeHsxSweep21)->Unit(benchmark::kMillisecond)->Iterations(1);
