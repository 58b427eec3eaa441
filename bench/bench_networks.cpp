// Every network up to N elements (issue 16): the enumeration, the positive-real test and the
// synthesis of a biquadratic, one J2 evaluation of study 2 (the unit of the structure search's
// cost) and the exhaustive search of the tuned-absorber study over all networks of up to three
// elements. The study-2 searches themselves (minutes) are timed with the CLI (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include "inerta/io/model_study_file.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/network/enumeration.hpp"
#include "inerta/network/positive_real.hpp"
#include "inerta/network/synthesis.hpp"
#include "inerta/optim/structure_search.hpp"
#include "source.hpp"

using namespace inerta;

static void BM_EnumerateNetworks(benchmark::State& state) {
  network::EnumerationOptions o;
  o.max_elements = static_cast<int>(state.range(0));
  std::size_t n = 0;
  for (auto _ : state) benchmark::DoNotOptimize(n = network::enumerate(o).size());
  state.counters["networks"] = static_cast<double>(n);
}
BENCHMARK(BM_EnumerateNetworks)->Arg(4)->Arg(5)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);

static void BM_PositiveRealBicubic(benchmark::State& state) {
  const network::Rational y = network::rational_admittance(
      network::assign(network::parse("k1|(c-(k2|b))|(k3-b2)"), {{"k1", 1e4}, {"c", 300}, {"k2", 5e3}, {"b", 20}, {"k3", 2e4}, {"b2", 5}}));
  for (auto _ : state) benchmark::DoNotOptimize(network::positive_real(y).positive_real);
}
BENCHMARK(BM_PositiveRealBicubic)->Unit(benchmark::kMicrosecond);

static void BM_SynthesiseBottDuffinBiquadratic(benchmark::State& state) {
  const network::Rational y{{1.0, 1.0, 1.0}, {4.0, 1.0, 1.0}};  // a minimum function
  for (auto _ : state) benchmark::DoNotOptimize(network::synthesise(y).elements);
}
BENCHMARK(BM_SynthesiseBottDuffinBiquadratic)->Unit(benchmark::kMicrosecond);

static void BM_Study2J2Evaluation(benchmark::State& state) {
  const optim::Study s = io::load_study(src("studies/hsx-s2-all.yaml"));
  const network::Network net = network::assign(network::parse("k-c-b"), {{"k", 1e5}, {"c", 1e4}, {"b", 2}});
  for (auto _ : state) benchmark::DoNotOptimize(optim::evaluate(s, net).J);
}
BENCHMARK(BM_Study2J2Evaluation)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_TmdAllNetworksUpTo3(benchmark::State& state) {
  optim::ModelStudy s = io::load_model_study(src("studies/tmd-all.yaml"));
  network::EnumerationOptions o;
  o.max_elements = 3;
  s.layouts = network::enumerate(o);
  int evaluations = 0;
  for (auto _ : state) {
    std::vector<optim::ModelLayoutResult> r;
    const auto e = optim::optimise_all(s, r);
    evaluations = 0;
    for (const auto& x : e) evaluations += x.evaluations;
  }
  state.counters["evaluations"] = evaluations;
}
BENCHMARK(BM_TmdAllNetworksUpTo3)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);
