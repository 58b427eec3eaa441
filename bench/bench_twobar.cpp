// Benchmarks of issues 2, 3 and 7: one right-hand-side evaluation and the 60 s two-bar run, plain,
// with its D–D strut written as a network, and built with the spatial engine.
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include "inerta/io/model_file.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/solve/integrator.hpp"

using namespace inerta;

namespace {
const mbs::Model& twobar() {
  static mbs::Model m = io::load_model(INERTA_SOURCE_DIR "/models/twobar.yaml");
  return m;
}

// The two-bar whose D–D strut is the network `network` ("k|c|b" is the same law as twobar.yaml's
// three elements; "b-(k|c)" is the tuned inerter damper with two internal states).
mbs::Model twobar_with(const std::string& network) {
  std::ifstream in(INERTA_SOURCE_DIR "/models/twobar_network.yaml");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const std::string key = "network: \"k|c|b\"";
  text.replace(text.find(key), key.size(), "network: \"" + network + "\"");
  return io::parse_model(text, "twobar_network(" + network + ")");
}
const mbs::Model& kcb() {
  static mbs::Model m = twobar_with("k|c|b");
  return m;
}
const mbs::Model& tid() {
  static mbs::Model m = twobar_with("b-(k|c)");
  return m;
}

// One evaluation of eq. 4.12 at a moving state.
void rhs_loop(benchmark::State& state, const mbs::Model& model) {
  mbs::State x = mbs::assemble(model, 0.0);
  x.qd.setConstant(0.3);
  x.z.setConstant(0.001);
  mbs::Workspace ws(model);
  double t = 0.1;
  for (auto _ : state) {
    mbs::accelerations(model, t, x, ws);
    benchmark::DoNotOptimize(ws.qdd.data());
    t += 1e-6;
  }
}

// The 60 s run at default tolerances, sampled every 1 ms with the C_x, C_y outputs.
void run_loop(benchmark::State& state, const mbs::Model& model, solve::Method method) {
  solve::IntegratorOptions opt;
  opt.method = method;
  long steps = 0, rhs = 0;
  for (auto _ : state) {
    mbs::State x = mbs::assemble(model, 0.0);
    double sink = 0;
    auto st = solve::integrate(
        model, x, 0.0, 60.0, 1e-3, opt,
        [&](double t, const mbs::State& s, const mbs::Workspace& ws) {
          sink += mbs::evaluate_output(model.outputs[0], model, t, s, ws) +
                  mbs::evaluate_output(model.outputs[1], model, t, s, ws);
        },
        false);
    benchmark::DoNotOptimize(sink);
    steps = st.steps, rhs = st.rhs_evals;
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["rhs_evals"] = static_cast<double>(rhs);
}
}  // namespace

static void BM_TwoBarRhs(benchmark::State& state) { rhs_loop(state, twobar()); }
BENCHMARK(BM_TwoBarRhs);

static void BM_TwoBar60s(benchmark::State& state) {
  const auto method = static_cast<solve::Method>(state.range(0));
  run_loop(state, twobar(), method);
  state.SetLabel(solve::method_name(method));
}
BENCHMARK(BM_TwoBar60s)
    ->Arg(static_cast<int>(solve::Method::Rk))
    ->Arg(static_cast<int>(solve::Method::Bdf))
    ->Unit(benchmark::kMillisecond);

// Issue 3: the strut as a network, 0: k|c|b, 1: b-(k|c).
static void BM_TwoBarNetworkRhs(benchmark::State& state) {
  rhs_loop(state, state.range(0) == 0 ? kcb() : tid());
  state.SetLabel(state.range(0) == 0 ? "k|c|b" : "b-(k|c)");
}
BENCHMARK(BM_TwoBarNetworkRhs)->Arg(0)->Arg(1);

static void BM_TwoBarNetwork60s(benchmark::State& state) {
  run_loop(state, state.range(0) == 0 ? kcb() : tid(), solve::Method::Rk);
  state.SetLabel(state.range(0) == 0 ? "k|c|b" : "b-(k|c)");
}
// Issue 7: the same mechanism built with the spatial engine (models/twobar3d.yaml); target < 2× the 2D run.
static void BM_TwoBar3DRhs(benchmark::State& state) {
  static mbs::Model m = io::load_model(INERTA_SOURCE_DIR "/models/twobar3d.yaml");
  rhs_loop(state, m);
}
BENCHMARK(BM_TwoBar3DRhs);

static void BM_TwoBar3D60s(benchmark::State& state) {
  static mbs::Model m = io::load_model(INERTA_SOURCE_DIR "/models/twobar3d.yaml");
  run_loop(state, m, solve::Method::Rk);
}
BENCHMARK(BM_TwoBar3D60s)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_TwoBarNetwork60s)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
