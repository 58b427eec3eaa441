// Benchmarks of issues 12 and 23: the finite-element catenary (models/catenary-fe.yaml) with the
// 3-mass and the HSX pantographs, by the direct solve (`solver.type=direct`) and the modal solve (the
// file's default); cost against the number of spans; a parallel sweep. One iteration each: a run is
// seconds long. "Cold" runs include the line's decomposition (a fresh catenary object); "warm"
// runs reuse it (a sweep or a study decomposes once).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/simulate.hpp"
#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/io/study_file.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/optim/study.hpp"
#include "inerta/optim/study_run.hpp"

using namespace inerta;

namespace {
const char* kFe = INERTA_SOURCE_DIR "/models/catenary-fe.yaml";

std::vector<std::string> direct(std::vector<std::string> sets) {
  sets.emplace_back("solver.type=direct");
  return sets;
}

void run_line(benchmark::State& state, const char* model, double kmh, const std::vector<std::string>& sets,
              const char* line = kFe) {
  const pantograph::Pantograph p = io::load_pantograph(std::string(INERTA_SOURCE_DIR) + "/models/" + model);
  io::CatenaryFile c = io::load_catenary(line, sets);
  c.catenary->prepare({{p, 0.0, c.contact}});  // a modal line's decomposition, outside the timing
  for (auto _ : state) {
    auto sys = c.catenary->couple(p, c.contact, kmh / 3.6);
    auto r = analysis::run_speed(*sys, analysis::RunOptions{});
    benchmark::DoNotOptimize(r.stats.std);
  }
}

// Cold: a new catenary object per iteration (its windows decomposed again), as one CLI run.
void run_cold(benchmark::State& state, const char* model, double kmh, const std::vector<std::string>& sets) {
  const pantograph::Pantograph p = io::load_pantograph(std::string(INERTA_SOURCE_DIR) + "/models/" + model);
  for (auto _ : state) {
    io::CatenaryFile c = io::load_catenary(kFe, sets);
    auto sys = c.catenary->couple(p, c.contact, kmh / 3.6);
    auto r = analysis::run_speed(*sys, analysis::RunOptions{});
    benchmark::DoNotOptimize(r.stats.std);
  }
}
}  // namespace

// The 3-mass pantograph at 250 km/h on the default line (10 spans, 0.25 m elements, h = 0.5 ms).
static void BM_Fe3Mass250kmh(benchmark::State& state) { run_line(state, "pantograph-3mass.yaml", 250, direct({"integration.time_step=5e-4"})); }
BENCHMARK(BM_Fe3Mass250kmh)->Unit(benchmark::kMillisecond)->Iterations(1);

// The same with h = 1 ms.
static void BM_Fe3Mass250kmhStep1ms(benchmark::State& state) {
  run_line(state, "pantograph-3mass.yaml", 250, direct({"integration.time_step=1e-3"}));
}
BENCHMARK(BM_Fe3Mass250kmhStep1ms)->Unit(benchmark::kMillisecond)->Iterations(1);

// The HSX multibody pantograph at 300 km/h.
static void BM_FeHsx300kmh(benchmark::State& state) { run_line(state, "hsx.yaml", 300, direct({})); }
BENCHMARK(BM_FeHsx300kmh)->Unit(benchmark::kMillisecond)->Iterations(1);

// Cost against the number of spans (3-mass, 250 km/h).
static void BM_Fe3MassSpans(benchmark::State& state) {
  run_line(state, "pantograph-3mass.yaml", 250, direct({"line.spans=" + std::to_string(state.range(0))}));
}
BENCHMARK(BM_Fe3MassSpans)->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond)->Iterations(1);

// The line alone: one structural step of the default line with a moving penalty contact.
static void BM_FeLineStep(benchmark::State& state) {
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
  io::CatenaryFile c = io::load_catenary(kFe, direct({}));
  std::vector<double> v;
  for (int k = 150; k <= 350; k += 10) v.push_back(k / 3.6);
  for (auto _ : state) {
    auto r = analysis::sweep(p, *c.catenary, c.contact, v, analysis::RunOptions{});
    benchmark::DoNotOptimize(r.data());
  }
}
BENCHMARK(BM_FeHsxSweep21)->Unit(benchmark::kMillisecond)->Iterations(1);

// ---- The modal solve (issue 23), the file's defaults: 2 spans behind, 3 ahead, modes below 100 Hz.

// The acceptance run, cold (decomposition included): 3-mass, 250 km/h.
static void BM_FeModal3Mass250kmhCold(benchmark::State& state) { run_cold(state, "pantograph-3mass.yaml", 250, {}); }
BENCHMARK(BM_FeModal3Mass250kmhCold)->Unit(benchmark::kMillisecond)->Iterations(1);

// The same run with the modes already there (a sweep's or a study's later runs).
static void BM_FeModal3Mass250kmhWarm(benchmark::State& state) { run_line(state, "pantograph-3mass.yaml", 250, {}); }
BENCHMARK(BM_FeModal3Mass250kmhWarm)->Unit(benchmark::kMillisecond)->Iterations(3);

// HSX at 300 km/h, cold and warm.
static void BM_FeModalHsx300kmhCold(benchmark::State& state) { run_cold(state, "hsx.yaml", 300, {}); }
BENCHMARK(BM_FeModalHsx300kmhCold)->Unit(benchmark::kMillisecond)->Iterations(1);
static void BM_FeModalHsx300kmhWarm(benchmark::State& state) { run_line(state, "hsx.yaml", 300, {}); }
BENCHMARK(BM_FeModalHsx300kmhWarm)->Unit(benchmark::kMillisecond)->Iterations(3);

// Cost against the number of spans, cold (3-mass, 250 km/h): linear in the line.
static void BM_FeModalSpans(benchmark::State& state) {
  run_cold(state, "pantograph-3mass.yaml", 250, {"line.spans=" + std::to_string(state.range(0))});
}
BENCHMARK(BM_FeModalSpans)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond)->Iterations(1);

// The decomposition alone: every window of the default line (3 distinct shapes, in parallel).
static void BM_FeModalPrepare(benchmark::State& state) {
  const pantograph::Pantograph p = io::load_pantograph(INERTA_SOURCE_DIR "/models/hsx.yaml");
  for (auto _ : state) {
    io::CatenaryFile c = io::load_catenary(kFe);
    c.catenary->prepare({{p, 0.0, c.contact}});
    benchmark::DoNotOptimize(c.catenary.get());
  }
}
BENCHMARK(BM_FeModalPrepare)->Unit(benchmark::kMillisecond)->Iterations(1);

// The acceptance sweep on the modal solve: HSX, 150:10:350 km/h, decomposition included.
static void BM_FeModalHsxSweep21(benchmark::State& state) {
  const pantograph::Pantograph p = io::load_pantograph(INERTA_SOURCE_DIR "/models/hsx.yaml");
  std::vector<double> v;
  for (int k = 150; k <= 350; k += 10) v.push_back(k / 3.6);
  for (auto _ : state) {
    io::CatenaryFile c = io::load_catenary(kFe);
    auto r = analysis::sweep(p, *c.catenary, c.contact, v, analysis::RunOptions{});
    benchmark::DoNotOptimize(r.data());
  }
}
BENCHMARK(BM_FeModalHsxSweep21)->Unit(benchmark::kMillisecond)->Iterations(1);

// Issue 34: the stitched line (models/catenary-fe-stitched.yaml, 10 spans of 65 m) against the simple
// line with the 3-mass at 300 km/h, modes decomposed outside the timing (as with the mode store);
// an irregular line (5 mm dropper-length std) against the perfect one at 250 km/h.
const char* kFeStitched = INERTA_SOURCE_DIR "/models/catenary-fe-stitched.yaml";
static void BM_FeModal3Mass300kmhWarm(benchmark::State& state) { run_line(state, "pantograph-3mass.yaml", 300, {}); }
BENCHMARK(BM_FeModal3Mass300kmhWarm)->Unit(benchmark::kMillisecond)->Iterations(3);
static void BM_FeStitched3Mass300kmhWarm(benchmark::State& state) {
  run_line(state, "pantograph-3mass.yaml", 300, {}, kFeStitched);
}
BENCHMARK(BM_FeStitched3Mass300kmhWarm)->Unit(benchmark::kMillisecond)->Iterations(3);
static void BM_FeStitchedDisabled3Mass300kmhWarm(benchmark::State& state) {
  run_line(state, "pantograph-3mass.yaml", 300, {"stitch.enabled=false"}, kFeStitched);
}
BENCHMARK(BM_FeStitchedDisabled3Mass300kmhWarm)->Unit(benchmark::kMillisecond)->Iterations(3);
static void BM_FeIrregular3Mass250kmhWarm(benchmark::State& state) {
  run_line(state, "pantograph-3mass.yaml", 250, {"irregularity.dropper_length_std=0.005", "irregularity.seed=7"});
}
BENCHMARK(BM_FeIrregular3Mass250kmhWarm)->Unit(benchmark::kMillisecond)->Iterations(3);
static void BM_FeIrregular3Mass250kmhCold(benchmark::State& state) {
  run_cold(state, "pantograph-3mass.yaml", 250, {"irregularity.dropper_length_std=0.005", "irregularity.seed=7"});
}
BENCHMARK(BM_FeIrregular3Mass250kmhCold)->Unit(benchmark::kMillisecond)->Iterations(1);

// Issue 35: a line of tension sections (models/catenary-fe-overlap.yaml, 2015 m, two 3-span
// overlaps) against one section of the same design (the stitched line, 650 m), the 3-mass at
// 300 km/h, one pantograph and two 200 m apart, the modes decomposed before the timing (as with the
// mode store). Cost per km: divide by the distance run (the CLI's t_end · v).
namespace {
const char* kFeOverlap = INERTA_SOURCE_DIR "/models/catenary-fe-overlap.yaml";
void run_train(benchmark::State& state, const char* line, std::vector<double> positions) {
  const pantograph::Pantograph p = io::load_pantograph(std::string(INERTA_SOURCE_DIR) + "/models/pantograph-3mass.yaml");
  io::CatenaryFile c = io::load_catenary(line, {});
  std::vector<catenary::PantographOnLine> train;
  for (double x : positions) train.push_back({p, x, c.contact});
  c.catenary->prepare(train);
  double distance = 0;
  for (auto _ : state) {
    const analysis::CoupledSimulation r = analysis::simulate_coupled(train, *c.catenary, 300 / 3.6, analysis::CoupledOptions{});
    distance = r.t_end * r.speed;
    benchmark::DoNotOptimize(r.contacts.front().stats.std);
  }
  state.counters["km"] = distance / 1000;
}
}  // namespace
static void BM_FeOverlap3Mass300kmhWarm(benchmark::State& state) { run_train(state, kFeOverlap, {0}); }
BENCHMARK(BM_FeOverlap3Mass300kmhWarm)->Unit(benchmark::kMillisecond)->Iterations(1);
static void BM_FeOverlapTwo3Mass300kmhWarm(benchmark::State& state) { run_train(state, kFeOverlap, {0, 200}); }
BENCHMARK(BM_FeOverlapTwo3Mass300kmhWarm)->Unit(benchmark::kMillisecond)->Iterations(1);
static void BM_FeSectionOne3Mass300kmhWarm(benchmark::State& state) { run_train(state, kFeStitched, {0}); }
BENCHMARK(BM_FeSectionOne3Mass300kmhWarm)->Unit(benchmark::kMillisecond)->Iterations(1);
static void BM_FeSectionTwo3Mass300kmhWarm(benchmark::State& state) { run_train(state, kFeStitched, {0, 200}); }
BENCHMARK(BM_FeSectionTwo3Mass300kmhWarm)->Unit(benchmark::kMillisecond)->Iterations(1);

// Issue 50: one evaluation of studies/hsx-real-line.yaml's stock design (27 runs on the nine stitched,
// irregular lines and its commissioning on the reference line), and 8 designs of that study evaluated
// together (optim::evaluate_batch: lanes) against the same 8 one at a time (optim::evaluate), in one run.
// The lines' modes are decomposed before the timing (as a study's first evaluation does once).
namespace {
const char* kRealLine = INERTA_SOURCE_DIR "/studies/hsx-real-line.yaml";

const optim::Study& real_line_study() {
  static const optim::Study s = [] {
    optim::Study study = io::load_study(kRealLine);
    std::vector<catenary::PantographOnLine> train;
    for (double x0 : study.positions) train.push_back({study.pantograph, x0, study.contact});
    for (const auto& c : study.catenaries) c->prepare(train);
    if (study.reference) study.reference->prepare(train);
    return study;
  }();
  return s;
}

// The stock suspension (k-c) and 7 variants within the study's bounds (inerter ≤ 1000 kg, spring ≤ 1e6 N/m,
// damper ≤ 1e5 N·s/m), each of at most four elements.
std::vector<network::Network> eight_designs(const optim::Study& s) {
  using P = network::Params;
  return {optim::default_suspension(s),
          network::resolve("k-c", P{{"k", 0.7 * 141e3}, {"c", 1.3 * 10.44e3}}),
          network::resolve("k-c", P{{"k", 1.3 * 141e3}, {"c", 0.7 * 10.44e3}}),
          network::resolve("k-(b|c)", P{{"k", 141e3}, {"b", 5}, {"c", 10.44e3}}),
          network::resolve("k-(b|c)", P{{"k", 8e4}, {"b", 20}, {"c", 5e3}}),
          network::resolve("b|c", P{{"b", 10}, {"c", 3e3}}),
          network::resolve("(k-c)|b", P{{"k", 1e5}, {"c", 8e3}, {"b", 2}}),
          network::resolve("c|k", P{{"c", 6e3}, {"k", 2e3}})};
}
}  // namespace

static void BM_RealLineEvaluation(benchmark::State& state) {
  const optim::Study& s = real_line_study();
  const network::Network stock = optim::default_suspension(s);
  for (auto _ : state) {
    const optim::StudyCost c = optim::evaluate(s, stock);
    benchmark::DoNotOptimize(c.J);
    state.counters["J"] = c.J;
  }
}
BENCHMARK(BM_RealLineEvaluation)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

static void BM_Lockstep(benchmark::State& state) {
  const optim::Study& s = real_line_study();
  const std::vector<network::Network> designs = eight_designs(s);
  using clock = std::chrono::steady_clock;
  for (auto _ : state) {
    const auto t0 = clock::now();
    const std::vector<optim::BatchEvaluation> batch = optim::evaluate_batch(s, designs);
    const auto t1 = clock::now();
    std::vector<optim::StudyCost> alone;
    for (const network::Network& d : designs) alone.push_back(optim::evaluate(s, d));
    const auto t2 = clock::now();
    for (std::size_t k = 0; k < designs.size(); ++k)
      if (batch[k].error || batch[k].cost.J != alone[k].J) {
        state.SkipWithError("a design's cost in the batch differs from its own evaluation");
        return;
      }
    const double lockstep = std::chrono::duration<double>(t1 - t0).count(), one = std::chrono::duration<double>(t2 - t1).count();
    state.counters["lockstep_s"] = lockstep;
    state.counters["one_at_a_time_s"] = one;
    state.counters["throughput_ratio"] = one / lockstep;
  }
}
BENCHMARK(BM_Lockstep)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// A re-check with the early stops (issue 50 item 4): the incumbent evaluated in full first, the other seven
// in lanes with its J as their bound (optim::StudyOptions::early_stops: the fastest speed first, a design
// stopped once it cannot rank ahead), against the eight one at a time. Two incumbents: the best of the eight
// (a fast path that ranked right) and the stock suspension (arg 0). The winner and every design not stopped
// are checked against the one-at-a-time costs.
static void BM_LockstepRecheck(benchmark::State& state) {
  const optim::Study& s = real_line_study();
  const std::vector<network::Network> designs = eight_designs(s);
  using clock = std::chrono::steady_clock;
  for (auto _ : state) {
    const auto t0 = clock::now();
    std::vector<optim::StudyCost> alone;
    for (const network::Network& d : designs) alone.push_back(optim::evaluate(s, d));
    const auto t1 = clock::now();
    std::vector<double> pen;
    for (const auto& c : alone) pen.push_back(c.penalised());
    const std::size_t best = optim::best_design(pen);
    const std::size_t lead = state.range(0) == 0 ? 0 : best;
    const auto t2 = clock::now();
    const optim::StudyCost incumbent = optim::evaluate_batch(s, {designs[lead]}).at(0).get();
    std::vector<network::Network> rest;
    std::vector<std::size_t> at;
    for (std::size_t k = 0; k < designs.size(); ++k)
      if (k != lead) rest.push_back(designs[k]), at.push_back(k);
    const optim::EarlyStop stop = optim::EarlyStop::behind(incumbent);
    const double bound = stop.above;
    const std::vector<optim::BatchEvaluation> got = optim::evaluate_time_batch(s, rest, std::vector<optim::EarlyStop>(rest.size(), stop));
    const auto t3 = clock::now();
    int stopped = 0;
    std::vector<double> ranked(designs.size(), INFINITY);
    ranked[lead] = incumbent.penalised();
    for (std::size_t j = 0; j < rest.size(); ++j) {
      const std::size_t k = at[j];
      if (got[j].error) {
        state.SkipWithError("a design failed");
        return;
      }
      if (got[j].stopped) {
        ++stopped;
        if (!(alone[k].penalised() > bound)) {
          state.SkipWithError("a stopped design could have won");
          return;
        }
        continue;
      }
      if (got[j].cost.J != alone[k].J) {
        state.SkipWithError("a design's cost differs from its own evaluation");
        return;
      }
      ranked[k] = got[j].cost.penalised();
    }
    if (optim::best_design(ranked) != best) {
      state.SkipWithError("the early stops changed the winner");
      return;
    }
    const double one = std::chrono::duration<double>(t1 - t0).count(), recheck = std::chrono::duration<double>(t3 - t2).count();
    state.counters["one_at_a_time_s"] = one;
    state.counters["recheck_s"] = recheck;
    state.counters["stopped"] = stopped;
    state.counters["throughput_ratio"] = one / recheck;
  }
}
BENCHMARK(BM_LockstepRecheck)->Arg(1)->Arg(0)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
