// Benchmarks of issue 2: one right-hand-side evaluation and the 60 s two-bar run.
#include <benchmark/benchmark.h>

#include "inerta/io/model_file.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/solve/integrator.hpp"

using namespace inerta;

static const mbs::Model& twobar() {
  static mbs::Model m = io::load_model(INERTA_SOURCE_DIR "/models/twobar.yaml");
  return m;
}

static void BM_TwoBarRhs(benchmark::State& state) {
  const mbs::Model& model = twobar();
  mbs::State x = mbs::assemble(model, 0.0);
  x.qd.setConstant(0.3);
  mbs::Workspace ws(model);
  double t = 0.1;
  for (auto _ : state) {
    mbs::accelerations(model, t, x, ws);
    benchmark::DoNotOptimize(ws.qdd.data());
    t += 1e-6;
  }
}
BENCHMARK(BM_TwoBarRhs);

// The 60 s two-bar run at default tolerances, sampled every 1 ms with the C_x, C_y outputs.
static void BM_TwoBar60s(benchmark::State& state) {
  const mbs::Model& model = twobar();
  solve::IntegratorOptions opt;
  opt.method = static_cast<solve::Method>(state.range(0));
  long steps = 0, rhs = 0;
  for (auto _ : state) {
    mbs::State x = mbs::assemble(model, 0.0);
    double sink = 0;
    auto st = solve::integrate(
        model, x, 0.0, 60.0, 1e-3, opt,
        [&](double t, const mbs::State& s, const mbs::Workspace& ws) {
          for (const auto& o : model.outputs) sink += mbs::evaluate_output(o, model, t, s, ws);
        },
        false);
    benchmark::DoNotOptimize(sink);
    steps = st.steps, rhs = st.rhs_evals;
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["rhs_evals"] = static_cast<double>(rhs);
  state.SetLabel(solve::method_name(opt.method));
}
BENCHMARK(BM_TwoBar60s)
    ->Arg(static_cast<int>(solve::Method::Rk))
    ->Arg(static_cast<int>(solve::Method::Bdf))
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
