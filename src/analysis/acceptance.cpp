#include "inerta/analysis/acceptance.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "inerta/analysis/commission.hpp"
#include "inerta/analysis/simulate.hpp"
#include "inerta/error.hpp"

namespace inerta::analysis {

std::vector<long> loss_runs(const std::vector<double>& F) {
  std::vector<long> runs;
  long n = 0;
  for (double f : F) {
    if (f <= 0) {
      ++n;
    } else if (n > 0) {
      runs.push_back(n), n = 0;
    }
  }
  if (n > 0) runs.push_back(n);
  return runs;
}

double counted_loss_pct(const std::vector<long>& runs, long samples, double dt, double min_duration) {
  if (samples <= 0) return 0;
  long counted = 0;
  // A run of n samples lasts n·dt; 1e-9 of a step forgives the rounding of n·dt against a duration
  // given as a multiple of the step.
  for (long n : runs)
    if (static_cast<double>(n) * dt >= min_duration - 1e-9 * dt) counted += n;
  return 100.0 * static_cast<double>(counted) / static_cast<double>(samples);
}

std::string range_text(const SpeedRange& r) {
  if (r.from <= 0 && std::isinf(r.to)) return "at every speed";
  return std::isinf(r.to) ? fmt::format("from {:g} km/h", r.from) : fmt::format("from {:g} to {:g} km/h", r.from, r.to);
}

double TargetCurve::at(double v_kmh) const {
  if (!covers(v_kmh))
    throw InvalidArgument(fmt::format("acceptance: the mean-force target curve at {:.4g} km/h: its source gives it {} only; "
                                      "the target is not assessed outside that range (give a speed inside it, or a target of "
                                      "your own)",
                                      v_kmh, range_text(speeds)));
  return SpeedCurve::at(v_kmh);
}

std::string arcing_text(const AcceptanceCriteria& c) {
  if (c.contact_loss.empty()) return "";
  std::string durations;
  for (const auto& e : c.contact_loss) {
    const std::string d = fmt::format("{:g} ms", 1e3 * e.min_duration);
    if (durations.find(d) == std::string::npos) durations += (durations.empty() ? "" : " / ") + d;
  }
  return fmt::format("contact_loss: contact loss of the simulation (raw force <= 0 N for at least {}) stands in for the "
                     "measured percentage of arcing of EN 50367 / EN 50317; arcing itself is not modelled",
                     durations);
}

namespace {

const ContactStatistics& pick(const VerdictInput& in, Statistics s) { return s == Statistics::Raw ? in.raw : in.filtered; }

const char* stats_text(Statistics s) { return s == Statistics::Raw ? "raw" : "filtered"; }

// The row's source and its statistic, from the entry that judged it.
template <class Entry>
CriterionResult& sourced(CriterionResult& r, const Entry& e, std::string statistic) {
  r.source = e.source, r.assumed = e.assumed, r.statistic = std::move(statistic);
  return r;
}

CriterionResult row(const char* name, const char* unit, double value, double limit, bool upper) {
  CriterionResult r;
  r.criterion = name, r.unit = unit;
  r.value = value, r.limit = limit, r.upper = upper;
  r.margin = upper ? limit - value : value - limit;
  r.assessed = true;
  r.passed = r.margin >= 0;
  return r;
}

CriterionResult not_assessed(const char* name, const char* unit, double value, std::string why) {
  CriterionResult r;
  r.criterion = name, r.unit = unit, r.value = value;
  r.note = std::move(why);
  return r;
}

// The entry of a criterion whose speed range holds v (km/h), or nullptr; `why` then says which ranges it has.
// A speed at a band's upper end belongs to it when no band starts there (the top band is closed: a source's
// "up to 320 km/h" holds at 320 km/h).
template <class Entry>
const Entry* entry_at(const std::vector<Entry>& list, double v, std::string& why) {
  std::string ranges;
  for (const Entry& e : list) {
    if (e.speeds.contains(v)) return &e;
    ranges += (ranges.empty() ? "" : ", ") + range_text(e.speeds);
  }
  for (const Entry& e : list)
    if (v == e.speeds.to) return &e;
  why = fmt::format("applies {} only", ranges);
  return nullptr;
}

}  // namespace

std::vector<CriterionResult> assess(const AcceptanceCriteria& c, const VerdictInput& in) {
  if (!(in.speed >= 0) || !std::isfinite(in.speed))
    throw InvalidArgument(fmt::format("acceptance: speed {} m/s: expected a finite speed >= 0", in.speed));
  if (in.has_loss_runs && !(in.sample_dt > 0))
    throw InvalidArgument(fmt::format("acceptance: sample step {} s: expected > 0 with loss events given", in.sample_dt));
  const double v = in.speed * 3.6;
  std::vector<CriterionResult> rows;
  std::string why;
  // The entry for this speed, if any, and the statistics it reads (the 20 Hz ones need a finite line).
  auto usable = [&](const auto& list, const char* name, const char* unit) {
    using Entry = typename std::decay_t<decltype(list)>::value_type;
    const Entry* e = entry_at(list, v, why);
    if (!e) return rows.push_back(not_assessed(name, unit, NAN, why)), e;
    if constexpr (requires { e->statistics; })
      if (e->statistics == Statistics::Filtered && !in.has_filtered) {
        rows.push_back(not_assessed(name, unit, NAN, "needs the 20 Hz statistics of a finite line"));
        sourced(rows.back(), *e, stats_text(e->statistics));
        return (const Entry*)nullptr;
      }
    return e;
  };
  if (!c.mean.empty()) {
    std::string w;
    if (const auto* e = entry_at(c.mean, v, w); !e) {
      rows.push_back(not_assessed("mean_lower", "N", NAN, w)), rows.push_back(not_assessed("mean_upper", "N", NAN, w));
    } else if (e->statistics == Statistics::Filtered && !in.has_filtered) {
      for (const char* n : {"mean_lower", "mean_upper"}) {
        rows.push_back(not_assessed(n, "N", NAN, "needs the 20 Hz statistics of a finite line"));
        sourced(rows.back(), *e, fmt::format("{}, F_m", stats_text(e->statistics)));
      }
    } else {
      const double m = pick(in, e->statistics).mean;
      const std::string what = fmt::format("{}, F_m", stats_text(e->statistics));
      rows.push_back(row("mean_lower", "N", m, e->lower.at(v), false)), sourced(rows.back(), *e, what);
      rows.push_back(row("mean_upper", "N", m, e->upper.at(v), true)), sourced(rows.back(), *e, what);
    }
  }
  if (!c.sigma.empty())  // σ ≤ ratio · F_m, both of the chosen statistics
    if (const auto* e = usable(c.sigma, "sigma", "N")) {
      const ContactStatistics& s = pick(in, e->statistics);
      rows.push_back(row("sigma", "N", s.std, e->ratio * s.mean, true));
      sourced(rows.back(), *e, fmt::format("{}, σ against {:g} F_m", stats_text(e->statistics), e->ratio));
    }
  if (!c.statistical_min.empty())
    if (const auto* e = usable(c.statistical_min, "statistical_min", "N")) {
      rows.push_back(row("statistical_min", "N", pick(in, e->statistics).stat_min, e->min, false));
      sourced(rows.back(), *e, fmt::format("{}, F_m − 3σ", stats_text(e->statistics)));
    }
  if (!c.max_force.empty())
    if (const auto* e = usable(c.max_force, "max_force", "N")) {
      const ContactStatistics& s = pick(in, e->statistics);
      const bool stat = e->measure == ForceMeasure::StatisticalMax;
      // F_m + 3σ (ContactStatistics::stat_max), or the largest sample of the section.
      rows.push_back(row("max_force", "N", stat ? s.mean + 3 * s.std : s.max, e->max, true));
      sourced(rows.back(), *e, fmt::format("{}, {}", stats_text(e->statistics), stat ? "F_m + 3σ" : "largest sample"));
    }
  if (!c.contact_loss.empty())
    if (const auto* e = usable(c.contact_loss, "contact_loss", "%")) {
      const std::string what = e->min_duration > 0 ? fmt::format("raw, F <= 0 for >= {:g} ms (stands in for arcing)", 1e3 * e->min_duration)
                                                   : std::string("raw, F <= 0 (stands in for arcing)");
      if (!in.has_loss_runs && e->min_duration > 0) {
        rows.push_back(not_assessed("contact_loss", "%", in.raw.loss_pct,
                                    "a minimum event duration needs the loss events of a finite line"));
      } else {
        const double loss = in.has_loss_runs ? counted_loss_pct(in.loss_runs, in.raw.samples, in.sample_dt, e->min_duration)
                                             : in.raw.loss_pct;
        rows.push_back(row("contact_loss", "%", loss, e->max_pct, true));
      }
      sourced(rows.back(), *e, what);
    }
  if (!c.support_uplift.empty()) {  // EN 50119 practice: factor · uplift within the line's design limit
    std::string w;
    const auto* e = entry_at(c.support_uplift, v, w);
    if (std::isnan(in.uplift_max))
      rows.push_back(not_assessed("support_uplift", "m", NAN, "needs a finite line"));
    else if (std::isnan(in.uplift_limit))
      rows.push_back(not_assessed("support_uplift", "m", in.uplift_max, "the line has no registration.uplift_limit"));
    else if (!e)
      rows.push_back(not_assessed("support_uplift", "m", in.uplift_max, w));
    else
      rows.push_back(row("support_uplift", "m", in.uplift_max, in.uplift_limit / e->factor(in.uplift_limited), true));
    if (e)
      sourced(rows.back(), *e,
              fmt::format("largest registration uplift × {:g}{}", e->factor(in.uplift_limited),
                          in.uplift_limited && !std::isnan(e->limited_clearance_factor) ? " (uplift limited by a stop)" : ""));
  }
  return rows;
}

bool passed(const std::vector<CriterionResult>& rows) {
  return std::all_of(rows.begin(), rows.end(), [](const CriterionResult& r) { return !r.assessed || r.passed; });
}

std::vector<CriterionResult> assess_static(const AcceptanceCriteria& criteria, const Commissioning& c) {
  std::vector<CriterionResult> rows;
  if (!criteria.has_static_force) return rows;
  const AcceptanceCriteria::StaticForce& s = criteria.static_force;
  const double f0 = c.static_force, tol = s.tolerance_pct / 100;
  double lo = s.lower, hi = s.upper;
  if (!std::isnan(tol) && std::isfinite(f0)) {
    lo = std::isnan(lo) ? f0 * (1 - tol) : std::max(lo, f0 * (1 - tol));
    hi = std::isnan(hi) ? f0 * (1 + tol) : std::min(hi, f0 * (1 + tol));
  }
  const bool have = !c.range_force.empty();
  for (const bool upper : {false, true}) {
    CriterionResult r;
    r.criterion = upper ? "static_force_upper" : "static_force_lower";
    r.unit = "N";
    r.statistic = "static force over the working range";
    r.source = s.source, r.assumed = s.assumed;
    r.upper = upper;
    r.limit = upper ? hi : lo;
    r.value = upper ? c.range_max() : c.range_min();
    if (std::isnan(r.limit)) continue;
    if (!have) {
      r.note = "no static force over the working range (a pantograph without a rig joint, or not commissioned)";
    } else {
      r.assessed = true;
      r.margin = upper ? r.limit - r.value : r.value - r.limit;
      r.passed = r.margin >= 0;
    }
    rows.push_back(r);
  }
  return rows;
}

double relative_margin(const CriterionResult& r) {
  return r.margin / (std::abs(r.limit) > 0 ? std::abs(r.limit) : std::max(std::abs(r.value), 1.0));
}

std::size_t binding(const std::vector<CriterionResult>& rows) {
  std::size_t best = rows.size();
  double least = INFINITY;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const CriterionResult& r = rows[i];
    if (!r.assessed) continue;
    if (const double rel = relative_margin(r); rel < least) least = rel, best = i;
  }
  return best;
}

std::vector<VerdictInput> verdict_inputs(const SpeedResult& r) {
  const std::vector<ContactStatistics> one{r.stats};
  const auto& contacts = r.contacts.empty() ? one : r.contacts;
  std::vector<VerdictInput> in(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    VerdictInput& x = in[k];
    x.speed = r.speed;
    x.raw = contacts[k];
    x.has_filtered = k < r.filtered.size();
    if (x.has_filtered) x.filtered = r.filtered[k];
    x.has_loss_runs = k < r.loss_runs.size();
    if (x.has_loss_runs) x.loss_runs = r.loss_runs[k];
    x.sample_dt = r.sample_dt;
    if (x.has_filtered)  // a finite line: its registrations in the section (0 if none is there)
      x.uplift_max = r.support_uplift.empty() ? 0.0 : *std::max_element(r.support_uplift.begin(), r.support_uplift.end());
    x.uplift_limit = r.uplift_limit;
    x.uplift_limited = r.uplift_limited;
  }
  return in;
}

std::vector<VerdictInput> verdict_inputs(const CoupledSimulation& r) {
  std::vector<VerdictInput> in(r.contacts.size());
  double uplift = NAN;
  if (!r.quality.empty()) {
    uplift = 0;
    for (const SupportUplift& u : r.uplift) uplift = std::max(uplift, u.max_uplift);
  }
  for (std::size_t k = 0; k < in.size(); ++k) {
    VerdictInput& x = in[k];
    x.speed = r.speed;
    x.uplift_limit = r.uplift_limit;
    x.uplift_limited = r.uplift_limited;
    x.uplift_max = uplift;
    if (k < r.quality.size()) {
      const ContactQuality& q = r.quality[k];
      x.raw = q.raw, x.filtered = q.filtered, x.has_filtered = true;
      x.loss_runs = q.loss_runs, x.has_loss_runs = true;
      x.sample_dt = 1 / q.sample_rate;
    } else {
      x.raw = r.contacts[k].stats;
    }
  }
  return in;
}

namespace {
std::vector<VerdictRow> rows_of(const AcceptanceCriteria& c, const std::vector<VerdictInput>& in) {
  std::vector<VerdictRow> rows;
  for (std::size_t k = 0; k < in.size(); ++k)
    for (CriterionResult& r : assess(c, in[k])) rows.push_back({in[k].speed, static_cast<int>(k) + 1, std::move(r)});
  return rows;
}
}  // namespace

std::vector<VerdictRow> verdict(const AcceptanceCriteria& c, const std::vector<SpeedResult>& sweep) {
  std::vector<VerdictRow> rows;
  for (const SpeedResult& r : sweep) {
    if (!r.stable()) continue;  // no steady state, NaN statistics: a sweep reports it separately
    for (VerdictRow& x : rows_of(c, verdict_inputs(r))) rows.push_back(std::move(x));
  }
  return rows;
}

std::vector<VerdictRow> verdict(const AcceptanceCriteria& c, const CoupledSimulation& s) { return rows_of(c, verdict_inputs(s)); }

bool passed(const std::vector<VerdictRow>& rows) {
  return std::all_of(rows.begin(), rows.end(), [](const VerdictRow& r) { return !r.result.assessed || r.result.passed; });
}

const char* Verdict::text() const {
  switch (status) {
    case Status::kPass: return "PASS";
    case Status::kFail: return "FAIL";
    case Status::kNotAssessed: break;
  }
  return "NOT ASSESSED";
}

Verdict judge(const std::vector<VerdictRow>& rows) {
  Verdict v;
  bool any = false;
  auto add = [](std::vector<std::string>& list, const std::string& c) {
    if (std::find(list.begin(), list.end(), c) == list.end()) list.push_back(c);
  };
  for (const VerdictRow& r : rows) {
    if (!r.result.assessed) {
      add(v.not_assessed, r.result.criterion);
      continue;
    }
    any = true;
    if (!r.result.passed) add(v.failed, r.result.criterion);
  }
  v.status = !v.failed.empty() ? Verdict::Status::kFail : any ? Verdict::Status::kPass : Verdict::Status::kNotAssessed;
  return v;
}

}  // namespace inerta::analysis
