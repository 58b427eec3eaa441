// Lanes (issue 50 item 1): 8 HSX designs on the calibrated stitched line at 250 km/h, the whole
// line, stepped together as lanes of one modal solve against the same 8 runs one after the other,
// on one thread, in the same benchmark run (the line's modes decomposed beforehand). Counters: both
// wall times and the throughput ratio. The designs: the stock suspension and 7 others (other
// networks and head uplifts) — each lane's results are its lone run's bit for bit
// (tests/catenary/fe_lanes_test.cpp).
#include <benchmark/benchmark.h>

#include <chrono>

#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/pantograph/suspension.hpp"

using namespace inerta;

namespace {

std::vector<std::vector<catenary::PantographOnLine>> designs(const catenary::Contact& contact, int n) {
  const pantograph::Pantograph p = io::load_pantograph(INERTA_SOURCE_DIR "/models/hsx.yaml");
  const std::vector<std::pair<std::string, network::Params>> nets = {
      {"", {}},
      {"k|(k2-c)", {{"k", 5e3}, {"k2", 1e5}, {"c", 3e3}}},
      {"c-(k|(k2-b))", {{"c", 5e4}, {"k", 2e5}, {"k2", 1e5}, {"b", 10}}},
      {"(k1-c1)|(k2-c2)", {{"k1", 1e6}, {"c1", 5e4}, {"k2", 1.8e5}, {"c2", 1e5}}},
  };
  std::vector<std::vector<catenary::PantographOnLine>> out;
  for (int i = 0; i < n; ++i) {
    pantograph::Pantograph d = p;
    const auto& [layout, params] = nets[static_cast<std::size_t>(i) % nets.size()];
    if (!layout.empty()) d.model = pantograph::with_suspension(p.model, network::resolve(layout, params));
    if (!d.aero.active()) d.aero.body = d.contact().body;
    d.aero.c += 5.0 * (i / static_cast<int>(nets.size()));
    out.push_back({{d, 0.0, contact}});
  }
  return out;
}

double run_to_end(catenary::Coupled& sys, double dt, double& sum) {
  sys.equilibrate();
  sys.advance(sys.end_time(), dt, {}, [&](const catenary::Sample& s) { sum += s.force; });
  return sum;
}

}  // namespace

static void BM_LockstepStitched8(benchmark::State& state) {
  const io::CatenaryFile c = io::load_catenary(INERTA_SOURCE_DIR "/models/catenary-fe-stitched.yaml", {});
  const auto trains = designs(c.contact, static_cast<int>(state.range(0)));
  const double v = 250 / 3.6, dt = c.catenary->span() / v / 200;
  c.catenary->prepare(trains.front());
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<double> alone(trains.size(), 0.0), together(trains.size(), 0.0);  // Σ F of each lane
    for (std::size_t i = 0; i < trains.size(); ++i) {
      auto sys = c.catenary->couple(trains[i], v);
      run_to_end(*sys, dt, alone[i]);
    }
    const auto t1 = std::chrono::steady_clock::now();
    auto L = c.catenary->couple_lanes(trains, v);
    for (int i = 0; i < L->lanes(); ++i) L->lane(i).equilibrate();
    L->advance(L->lane(0).end_time(), dt, {}, [&](int i, const catenary::Sample& s) { together[static_cast<std::size_t>(i)] += s.force; });
    const auto t2 = std::chrono::steady_clock::now();
    if (together != alone) state.SkipWithError("the lanes' forces differ from the lone runs'");
    const double a = std::chrono::duration<double>(t1 - t0).count(), b = std::chrono::duration<double>(t2 - t1).count();
    state.counters["one_at_a_time_s"] = a;
    state.counters["lanes_s"] = b;
    state.counters["throughput_x"] = a / b;
  }
}
BENCHMARK(BM_LockstepStitched8)->Arg(8)->Arg(4)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
