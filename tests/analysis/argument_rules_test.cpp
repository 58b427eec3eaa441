// The rules the CLI options and the Python arguments share (inerta::NumberRule, CountRule): the
// library applies them itself to its options, so a caller that skips the CLI is refused alike.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "inerta/analysis/catenary_response.hpp"
#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/frf.hpp"
#include "inerta/analysis/simulate.hpp"
#include "inerta/error.hpp"

namespace test_analysis_argument_rules {

using namespace inerta;

std::string refusal(const auto& f) {
  try {
    f();
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

TEST(ArgumentRules, ACountIsAWholeNumberInItsRangeAndNeverCastBeforeTheCheck) {
  const CountRule r{1, 100};
  EXPECT_EQ(r.check(1, "1"), "");
  EXPECT_EQ(r.check(100, "100"), "");
  EXPECT_EQ(r.check(0, "0"), "0 is out of range; expected 1 … 100");
  EXPECT_EQ(r.check(101, "101"), "101 is out of range; expected 1 … 100");
  EXPECT_EQ(r.check(2.5, "2.5"), "expected a whole number, got '2.5'");
  EXPECT_EQ(r.check(std::nan(""), "nan"), "expected a whole number, got 'nan'");
  EXPECT_EQ(r.check(1e300, "1e300"), "1e300 is out of range; expected 1 … 100");  // no overflowing cast
  EXPECT_EQ(r.check(-std::numeric_limits<double>::infinity(), "-inf"), "expected a whole number, got '-inf'");
}

TEST(ArgumentRules, RequireNamesTheFieldAndWritesTheValue) {
  EXPECT_EQ(refusal([] { require(analysis::vc_rule, -0.25, "vc"); }), "vc: -0.25 is out of range; expected > 0 m/s");
  EXPECT_EQ(refusal([] { require(analysis::vc_rule, 0.06, "vc"); }), "");
  EXPECT_EQ(refusal([] { require(analysis::cycles_rule, 1e12, "cycles"); }),
            "cycles: 1000000000000 is out of range; expected 1 … 100000");
}

TEST(ArgumentRules, SteppedSineOptionsAreCheckedByTheLibrary) {
  analysis::SteppedSine o;
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "");
  o.vc = 0;
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "vc: 0 is out of range; expected > 0 m/s");
  o = {};
  o.cycles = 10, o.analysed = 11;
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "analysed: 11 is more than cycles (10); expected 1 … cycles");
  o = {};
  o.samples_per_cycle = 3;
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "samples_per_cycle: 3 is out of range; expected 4 … 100000");
}

TEST(ArgumentRules, CoupledOptionsRefuseNaNAsUnsetAndZeroSpans) {
  analysis::CoupledOptions o;
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "");  // t_end, sample unset (−1)
  o.t_end = std::nan("");
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "t_end: expected a finite number, got 'nan'");
  o = {};
  o.sample = 1e-3, o.t_end = 2e7;
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "t_end: 20000000 is out of range; expected > 0 s, at most 1e7 s");
  o = {};
  o.spans = 0;
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "spans: 0 is out of range; expected 1 … 10000");
  o = {};
  o.window_spans = 0;
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "window_spans: 0 is out of range; expected 1 … 10000");
}

TEST(ArgumentRules, TheCatenaryResponseChecksItsArgumentsBeforeRunning) {
  const catenary::LumpedCatenary cat;  // never run: the arguments are refused first
  EXPECT_EQ(refusal([&] { analysis::catenary_response(cat, std::nan(""), {0.5}); }), "force: expected a finite number, got 'nan'");
  EXPECT_EQ(refusal([&] { analysis::catenary_response(cat, 70, {0.5}, -1); }), "settle: -1 is out of range; expected >= 0 s");
  EXPECT_EQ(refusal([&] { analysis::catenary_response(cat, 70, {0.5}, 1, 0); }), "periods: 0 is out of range; expected 1 … 100000");
  EXPECT_EQ(refusal([&] { analysis::catenary_response(cat, 70, {0.5, 0.0}); }), "fp: 0 is out of range; expected > 0 Hz, at most 1e6 Hz");
}

TEST(ArgumentRules, RunOptionsAreCheckedBeforeAnyRun) {
  analysis::RunOptions o;
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "");
  o.max_spans = 0;  // once a division by zero (a crash) in the window's statistics
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "max_spans: 0 is out of range; expected 1 … 10000");
  o = {};
  o.min_spans = 8, o.max_spans = 7;
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "max_spans: 7 is less than min_spans (8)");
  o = {};
  o.tolerance = std::nan("");
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "tolerance: expected a finite number, got 'nan'");
  o = {};
  o.samples_per_span = 5;
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "samples_per_span: 5 is out of range; expected 10 … 1000000");
  o = {};
  o.settled_spans = 0;
  EXPECT_EQ(refusal([&] { analysis::check(o); }), "settled_spans: 0 is out of range; expected 1 … 1000");
}

}  // namespace test_analysis_argument_rules
