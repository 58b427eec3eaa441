// Linear analysis of any model (issue 13 targets): one rms evaluation (linearisation + Lyapunov) of
// the quarter-car and of the HSX pantograph, one H∞ evaluation over 500 frequencies, and the
// quarter-car study (4 layouts × 4 starts).
#include <benchmark/benchmark.h>

#include "inerta/analysis/state_space.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/io/model_study_file.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/optim/model_study.hpp"
#include "inerta/pantograph/suspension.hpp"
#include "source.hpp"

using namespace inerta;

static void BM_QuarterCarRmsEvaluation(benchmark::State& state) {
  const mbs::Model m = io::load_model(src("models/quarter_car.yaml"));
  mbs::State x = mbs::assemble(m, 0.0);
  analysis::Road road;
  road.speed = 25, road.inputs = {"road"};
  for (auto _ : state) {
    const auto ss = analysis::state_space(m, x, {"road"}, {"a_body", "travel", "tyre_force"});
    benchmark::DoNotOptimize(analysis::road_response(ss, road).rms);
  }
}
BENCHMARK(BM_QuarterCarRmsEvaluation)->Unit(benchmark::kMicrosecond);

static void BM_QuarterCarLyapunovOnly(benchmark::State& state) {
  const mbs::Model m = io::load_model(src("models/quarter_car.yaml"));
  const auto ss = analysis::state_space(m, {"road"}, {"a_body", "travel", "tyre_force"});
  analysis::Road road;
  road.speed = 25, road.inputs = {"road"};
  for (auto _ : state) benchmark::DoNotOptimize(analysis::road_response(ss, road).rms);
}
BENCHMARK(BM_QuarterCarLyapunovOnly)->Unit(benchmark::kMicrosecond);

static void BM_HsxRmsEvaluation(benchmark::State& state) {
  const mbs::Model m = pantograph::release_head(io::load_pantograph(src("models/hsx.yaml")));
  mbs::State x = mbs::assemble(m, 0.0);
  mbs::static_equilibrium(m, 0.0, x);
  for (auto _ : state) {
    const auto ss = analysis::state_space(m, x, {"static_contact"}, {"y_head", "l_act"});
    benchmark::DoNotOptimize(analysis::white_noise_response(ss, Eigen::MatrixXd::Identity(1, 1)).rms);
  }
}
BENCHMARK(BM_HsxRmsEvaluation)->Unit(benchmark::kMicrosecond);

static void BM_TmdHinf500Frequencies(benchmark::State& state) {
  optim::ModelStudy s = io::load_model_study(src("studies/tmd.yaml"));
  s.objective.frequencies.resize(500);
  for (int k = 0; k < 500; ++k) s.objective.frequencies[static_cast<std::size_t>(k)] = 3 + 5.0 * k / 499;
  const network::Network net = optim::default_network(s);
  for (auto _ : state) benchmark::DoNotOptimize(optim::evaluate(s, net).J);
}
BENCHMARK(BM_TmdHinf500Frequencies)->Unit(benchmark::kMicrosecond);

static void BM_QuarterCarStudy(benchmark::State& state) {
  const optim::ModelStudy s = io::load_model_study(src("studies/quarter_car.yaml"));
  for (auto _ : state) {
    std::vector<network::Params> warm;
    for (const auto& l : s.layouts) warm.push_back(optim::optimise_layout(s, l, {}, warm).values);
    benchmark::DoNotOptimize(warm);
  }
}
BENCHMARK(BM_QuarterCarStudy)->Unit(benchmark::kMillisecond)->Iterations(3);
