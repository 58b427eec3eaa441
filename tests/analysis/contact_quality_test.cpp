// EN 50317 contact-quality outputs (analysis/contact_quality.hpp) on synthetic histories.
#include "inerta/analysis/contact_quality.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "inerta/error.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_analysis_contact_quality {

using namespace inerta;
using std::numbers::pi;

namespace {
/// A pantograph moving at v from x0, sampled at fs: exact binary grids when fs and v are powers of 2.
struct History {
  std::vector<double> t, x, F;
};
History history(std::size_t n, double fs, double v, double x0, double (*force)(double t)) {
  History r;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs;
    r.t.push_back(t), r.x.push_back(x0 + v * t), r.F.push_back(force(t));
  }
  return r;
}
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }
std::string message(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "no InvalidArgument";
}
}  // namespace

TEST(ContactQuality, KnownMeanAndSigmaRawAndFiltered) {
  // F = 100 + 20 sin(2π·2t) + 5 sin(2π·60t): σ_raw² = 20²/2 + 5²/2; the 20 Hz filter keeps the 2 Hz
  // part (|H(2)|² ≈ 1 − 1e-8) and removes the 60 Hz one (|H(60)|² ≈ 1/(1 + 3⁸)).
  const History r = history(8000, 1000, 50, -100, [](double t) {
    return 100 + 20 * std::sin(2 * pi * 2 * t) + 5 * std::sin(2 * pi * 60 * t);
  });
  // x = −100 + 0.05 i: the section [0, 99.99] holds samples 2000..3999, four whole 2 Hz periods.
  const auto q = analysis::contact_quality(r.t, r.x, r.F, -1e-9, 99.99);
  EXPECT_EQ(q.raw.samples, 2000);
  EXPECT_EQ(q.first, 2000u);
  EXPECT_NEAR(q.sample_rate, 1000, 1e-6);
  EXPECT_NEAR(q.raw.mean, 100, 1e-9);
  EXPECT_NEAR(q.raw.std, std::sqrt(200 + 12.5), 1e-9);
  EXPECT_NEAR(q.raw.stat_max, 100 + 3 * std::sqrt(212.5), 1e-9);
  EXPECT_NEAR(q.raw.stat_min, 100 - 3 * std::sqrt(212.5), 1e-9);
  EXPECT_EQ(q.loss_pct, 0.0);
  const numerics::SosFilter h = numerics::butterworth_lowpass(20, 1000, 4);
  const double g2 = std::pow(h.magnitude(2), 2), g60 = std::pow(h.magnitude(60), 2);
  EXPECT_NEAR(q.filtered.mean, 100, 1e-6);
  EXPECT_NEAR(q.filtered.std, std::sqrt(std::pow(20 * g2, 2) / 2 + std::pow(5 * g60, 2) / 2), 1e-4);
  EXPECT_NEAR(q.filtered.std, 20 / std::sqrt(2.0), 1e-3);
  EXPECT_NEAR(q.filtered.stat_max, q.filtered.mean + 3 * q.filtered.std, 1e-12);
  EXPECT_NEAR(q.filtered.max, 120, 0.01);
  EXPECT_NEAR(q.filtered.min, 80, 0.01);
  EXPECT_NEAR(q.raw.max, 100 + 20 + 5, 0.5);
  EXPECT_EQ(q.cutoff, 20.0);
  EXPECT_EQ(q.order, 4);
}

TEST(ContactQuality, TheSectionIsExactlyTheSamplesWithXInside) {
  // x_i = i/16 m, t_i = i/1024 s (exact); F_i = i. [10, 20] m: samples 160..320, both ends included.
  History r;
  for (int i = 0; i < 1000; ++i) r.t.push_back(i / 1024.0), r.x.push_back(i / 16.0), r.F.push_back(i);
  const auto q = analysis::contact_quality(r.t, r.x, r.F, 10, 20);
  EXPECT_EQ(q.raw.samples, 161);
  EXPECT_EQ(q.first, 160u);
  EXPECT_EQ(q.t_from, 160 / 1024.0);
  EXPECT_EQ(q.t_to, 320 / 1024.0);
  EXPECT_EQ(q.raw.min, 160);
  EXPECT_EQ(q.raw.max, 320);
  EXPECT_DOUBLE_EQ(q.raw.mean, 240);
  EXPECT_EQ(q.filtered.samples, 161);
  // The filter runs over the whole history, then the section is cut.
  const auto whole = numerics::filtfilt(numerics::butterworth_lowpass(20, 1024, 4), r.F);
  const auto cut = analysis::statistics(std::vector<double>(whole.begin() + 160, whole.begin() + 321));
  EXPECT_EQ(q.filtered.mean, cut.mean);
  EXPECT_EQ(q.filtered.std, cut.std);
  EXPECT_EQ(q.filtered.max, cut.max);
  // The catenary-section overload is the same.
  const auto q2 = analysis::contact_quality(r.t, r.x, r.F, catenary::Section{10, 20});
  EXPECT_EQ(q2.raw.samples, 161);
  EXPECT_EQ(q2.filtered.std, q.filtered.std);
}

TEST(ContactQuality, LossIsTheShareOfRawSectionSamplesAtOrBelowZero) {
  History r;
  for (int i = 0; i < 2000; ++i) r.t.push_back(i / 1024.0), r.x.push_back(i / 16.0), r.F.push_back(80);
  // Section [20, 80] m: samples 320..1280 (961). Every 10th of them ≤ 0 (97 samples: i = 320, 330, …, 1280).
  int lost = 0;
  for (int i = 320; i <= 1280; i += 10) r.F[static_cast<std::size_t>(i)] = (i % 20 == 0) ? 0.0 : -3.0, ++lost;
  // Outside the section: not counted.
  for (int i = 0; i < 300; i += 7) r.F[static_cast<std::size_t>(i)] = -10;
  const auto q = analysis::contact_quality(r.t, r.x, r.F, 20, 80);
  EXPECT_EQ(lost, 97);
  EXPECT_EQ(q.raw.samples, 961);
  EXPECT_NEAR(q.loss_pct, 100.0 * 97 / 961, 1e-12);
  EXPECT_EQ(q.raw.loss_pct, q.loss_pct);
  EXPECT_EQ(q.raw.min, -3);
  // Single-sample dips are short: the 20 Hz filter smooths them away (and filtered loss is 0).
  EXPECT_EQ(q.filtered.loss_pct, 0.0);
  EXPECT_GT(q.filtered.min, 0);
}

TEST(ContactQuality, PsdOfTheSectionForce) {
  const History r = history(20000, 1024, 64, 0, [](double t) { return 120 + 10 * std::sin(2 * pi * 7 * t); });
  const auto q = analysis::contact_quality(r.t, r.x, r.F, 100, 1100);  // 16 000 samples
  const auto& s = q.psd;
  ASSERT_FALSE(s.S.empty());
  EXPECT_EQ(s.resolution, 1024.0 / 2048);  // automatic: largest power of two ≤ 16000/4
  std::size_t peak = 0;
  for (std::size_t k = 1; k < s.S.size(); ++k)
    if (s.S[k] > s.S[peak]) peak = k;
  EXPECT_NEAR(s.f[peak], 7, s.resolution / 2);
  EXPECT_NEAR(s.integral(5, 9) / 50, 1, 1e-3);  // A²/2 in N²
  EXPECT_NEAR(s.integral() / (q.raw.std * q.raw.std), 1, 3e-3);
  const auto q512 = analysis::contact_quality(r.t, r.x, r.F, 100, 1100, {.psd_segment = 512});
  EXPECT_EQ(q512.psd.resolution, 2.0);
}

TEST(ContactQuality, Errors) {
  const History r = history(1000, 1000, 50, 0, [](double) { return 100.0; });  // x from 0 to 49.95 m
  auto e = message([&] { analysis::contact_quality(r.t, r.x, r.F, 60, 80); });
  EXPECT_TRUE(contains(e, "section [60, 80] m contains no samples")) << e;
  EXPECT_TRUE(contains(e, "covered x_contact from 0 to 49.95 m")) << e;
  // A short history: 12 samples, the order-4 filter needs more than 15.
  const History s = history(12, 1000, 50, 0, [](double) { return 100.0; });
  e = message([&] { analysis::contact_quality(s.t, s.x, s.F, 0, 1); });
  EXPECT_TRUE(contains(e, "too few samples for the 20 Hz low-pass of order 4")) << e;
  EXPECT_TRUE(contains(e, "more than 15 samples")) << e;
  // Sampled at 20 Hz: a 20 Hz cutoff is above Nyquist.
  const History c = history(1000, 20, 5, 0, [](double) { return 100.0; });
  e = message([&] { analysis::contact_quality(c.t, c.x, c.F, 0, 100); });
  EXPECT_TRUE(contains(e, "Nyquist")) << e;
  EXPECT_NO_THROW(analysis::contact_quality(c.t, c.x, c.F, 0, 100, {.cutoff = 5}));
  // Non-uniform sampling.
  History g = r;
  g.t.erase(g.t.begin() + 500), g.x.erase(g.x.begin() + 500), g.F.erase(g.F.begin() + 500);
  e = message([&] { analysis::contact_quality(g.t, g.x, g.F, 0, 40); });
  EXPECT_TRUE(contains(e, "not uniform")) << e;
  // Sizes, reversed section, too few section samples, a non-finite force.
  EXPECT_THROW(analysis::contact_quality(r.t, r.x, std::vector<double>(999, 1.0), 0, 10), InvalidArgument);
  EXPECT_THROW(analysis::contact_quality(r.t, r.x, r.F, 10, 0), InvalidArgument);
  e = message([&] { analysis::contact_quality(r.t, r.x, r.F, 10, 10.2); });
  EXPECT_TRUE(contains(e, "too few for its power spectral density")) << e;
  History n = r;
  n.F[300] = NAN;
  EXPECT_THROW(analysis::contact_quality(n.t, n.x, n.F, 0, 40), InvalidArgument);
  // A section entered twice (x not monotonic).
  History b = r;
  for (std::size_t i = 500; i < b.x.size(); ++i) b.x[i] = 49.95 - b.x[i];
  e = message([&] { analysis::contact_quality(b.t, b.x, b.F, 10, 20); });
  EXPECT_TRUE(contains(e, "not consecutive")) << e;
}

TEST(SupportUplift, MaximumAndTimeAtEachSupportInTheSection) {
  // Four supports at 0, 55, 110, 165 m; the pantograph passes support k at t = x_k/v (v = 55 m/s);
  // the uplift is a pulse 0.05·(1 + 0.1k)·exp(−((t − t_k)/0.1)²) plus a small negative wake.
  const std::vector<double> xs = {0, 55, 110, 165};
  std::vector<double> t;
  std::vector<std::vector<double>> u;
  for (int i = 0; i <= 4000; ++i) {
    const double ti = i / 1000.0;
    t.push_back(ti);
    std::vector<double> row;
    for (std::size_t k = 0; k < xs.size(); ++k) {
      const double tk = xs[k] / 55, a = 0.05 * (1 + 0.1 * static_cast<double>(k));
      row.push_back(a * std::exp(-std::pow((ti - tk) / 0.1, 2)) - 0.01 * std::exp(-std::pow((ti - tk - 0.5) / 0.1, 2)));
    }
    u.push_back(row);
  }
  const auto s = analysis::support_uplift(t, xs, u, 50, 120);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].support, 1u);
  EXPECT_EQ(s[0].x, 55);
  EXPECT_NEAR(s[0].max_uplift, 0.055, 1e-12);
  EXPECT_NEAR(s[0].t_max, 1.0, 1e-12);
  EXPECT_EQ(s[1].support, 2u);
  EXPECT_NEAR(s[1].max_uplift, 0.06, 1e-12);
  EXPECT_NEAR(s[1].t_max, 2.0, 1e-12);
  EXPECT_EQ(analysis::support_uplift(t, xs, u, 0, 200).size(), 4u);
  EXPECT_TRUE(analysis::support_uplift(t, xs, u, 56, 100).empty());
  // Shapes checked.
  auto bad = u;
  bad[7].pop_back();
  EXPECT_THROW(analysis::support_uplift(t, xs, bad, 0, 200), InvalidArgument);
  EXPECT_THROW(analysis::support_uplift(std::vector<double>(t.begin(), t.end() - 1), xs, u, 0, 200), InvalidArgument);
  EXPECT_THROW(analysis::support_uplift(t, xs, u, 200, 0), InvalidArgument);
}
}  // namespace test_analysis_contact_quality
