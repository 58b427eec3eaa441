// Benchmarks of issue 2: one right-hand-side evaluation and the 60 s two-bar run.
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

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

// Issue 3: the two-bar whose D–D strut is a network: "k|c|b" (the same law as the three elements)
// and the tuned inerter damper "b-(k|c)" (two internal states), against the plain two-bar above.
static mbs::Model twobar_with(const std::string& network) {
  std::ifstream in(INERTA_SOURCE_DIR "/models/twobar_network.yaml");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const std::string key = "network: \"k|c|b\"";
  text.replace(text.find(key), key.size(), "network: \"" + network + "\"");
  return io::parse_model(text, "twobar_network(" + network + ")");
}

static void BM_TwoBarNetwork60s(benchmark::State& state) {
  static const mbs::Model kcb = twobar_with("k|c|b"), tid = twobar_with("b-(k|c)");
  const mbs::Model& model = state.range(0) == 0 ? kcb : tid;
  solve::IntegratorOptions opt;
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
  state.SetLabel(state.range(0) == 0 ? "k|c|b" : "b-(k|c)");
}
BENCHMARK(BM_TwoBarNetwork60s)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// One right-hand side of the two-bar with the network strut (0: k|c|b, 1: b-(k|c)).
static void BM_TwoBarNetworkRhs(benchmark::State& state) {
  static const mbs::Model kcb = twobar_with("k|c|b"), tid = twobar_with("b-(k|c)");
  const mbs::Model& model = state.range(0) == 0 ? kcb : tid;
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
  state.SetLabel(state.range(0) == 0 ? "k|c|b" : "b-(k|c)");
}
BENCHMARK(BM_TwoBarNetworkRhs)->Arg(0)->Arg(1);

BENCHMARK_MAIN();
