// Acceptance-criteria files: the YAML form of analysis::AcceptanceCriteria (docs/contact-quality.md
// "Acceptance"). Every field of a criterion given is required: a set says what it checks.
#include "inerta/io/data_dir.hpp"
#include "inerta/io/acceptance_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "inerta/error.hpp"
#include "inerta/io/yaml_errors.hpp"

namespace inerta::io {

namespace {

using analysis::AcceptanceCriteria;
using analysis::SpeedCurve;
using analysis::SpeedRange;
using analysis::Statistics;

// Band edges are checked up to this speed when a range is open above (km/h).
constexpr double kBandCheckTo = 1000;

std::string preset_dir() { return (data_dir() / "criteria").string(); }

bool is_preset_name(const std::string& s) {
  if (s.empty() || s.ends_with(".yaml") || s.ends_with(".yml") || s.front() == '.') return false;
  // Letters, digits, '-', '_' and '.' (en50367-dc1.5), not first.
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.'; });
}

void keys(const std::string& f, const YAML::Node& n, const std::string& section, const std::set<std::string>& allowed) {
  if (!n.IsMap()) yaml_fail(f, n, section, fmt::format("expected a map of {}", fmt::join(allowed, ", ")));
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string k = it->first.Scalar();
    if (!allowed.count(k)) yaml_fail(f, it->first, section + "." + k, fmt::format("unknown key; expected {}", fmt::join(allowed, ", ")));
  }
}

double number(const std::string& f, const YAML::Node& sec, const std::string& section, const std::string& key) {
  const YAML::Node v = sec[key];
  if (!v.IsDefined()) yaml_fail(f, sec, section + "." + key, "missing; expected a number");
  return yaml_number(f, v, section + "." + key);
}

double number_in(const std::string& f, const YAML::Node& sec, const std::string& section, const std::string& key, double lo,
                 double hi, const std::string& range) {
  const double v = number(f, sec, section, key);
  if (!(v >= lo && v <= hi)) yaml_fail(f, sec[key], section + "." + key, fmt::format("{}; expected {}", sec[key].Scalar(), range));
  return v;
}

// A force curve of speed: |F(v)| ≤ 1e6 N from 0 to kBandCheckTo km/h (its ends and vertex decide), so
// that no absurd coefficient (1e300) passes as a limit.
SpeedCurve curve(const std::string& f, const YAML::Node& sec, const std::string& section,
                 std::set<std::string> allowed = {"v2", "v1", "v0"}) {
  keys(f, sec, section, allowed);
  const SpeedCurve c{number(f, sec, section, "v2"), number(f, sec, section, "v1"), number(f, sec, section, "v0")};
  std::vector<double> vs{0, kBandCheckTo};
  if (c.v2 != 0 && -c.v1 / (2 * c.v2) > 0 && -c.v1 / (2 * c.v2) < kBandCheckTo) vs.push_back(-c.v1 / (2 * c.v2));
  for (double v : vs)
    if (!(std::abs(c.at(v)) <= 1e6))
      yaml_fail(f, sec, section,
                fmt::format("{:.4g} N at {:g} km/h; expected a force within ±1e6 N from 0 to {:g} km/h", c.at(v), v, kBandCheckTo));
  return c;
}

Statistics statistics(const std::string& f, const YAML::Node& sec, const std::string& section) {
  const YAML::Node v = sec["statistics"];
  const std::string key = section + ".statistics";
  if (!v.IsDefined()) yaml_fail(f, sec, key, "missing; expected raw or filtered (the 20 Hz low-pass)");
  if (v.IsScalar() && v.Scalar() == "raw") return Statistics::Raw;
  if (v.IsScalar() && v.Scalar() == "filtered") return Statistics::Filtered;
  yaml_fail(f, v, key, fmt::format("'{}'; expected raw or filtered (the 20 Hz low-pass)", v.IsScalar() ? v.Scalar() : "a list or map"));
}

SpeedRange speeds(const std::string& f, const YAML::Node& sec, const std::string& section) {
  SpeedRange r;
  const YAML::Node v = sec["speeds"];
  if (!v.IsDefined()) return r;
  const std::string key = section + ".speeds";
  if (!v.IsSequence() || v.size() != 2) yaml_fail(f, v, key, "expected [from, to] in km/h, from <= v < to (to may be .inf)");
  r.from = yaml_number(f, v[0], key);
  const bool inf = v[1].IsScalar() && (v[1].Scalar() == ".inf" || v[1].Scalar() == "inf");
  r.to = inf ? INFINITY : yaml_number(f, v[1], key);
  if (!(r.from >= 0) || !(r.to > r.from)) yaml_fail(f, v, key, "expected 0 <= from < to (km/h)");
  return r;
}

// Where an entry's number comes from (issue 53): `source:` (text: the document and the public address it was
// read at) and `assumed:` (true: not verified against a public source; the default, so a file claims a
// verified number only by saying assumed: false).
template <class Entry>
void sourced(const std::string& f, const YAML::Node& sec, const std::string& section, Entry& e) {
  if (const YAML::Node s = sec["source"]; s.IsDefined()) {
    if (!s.IsScalar() || s.Scalar().empty())
      yaml_fail(f, s, section + ".source", "expected a text: the document and the public address the number was read at");
    e.source = s.Scalar();
  }
  if (const YAML::Node a = sec["assumed"]; a.IsDefined()) {
    if (!a.IsScalar() || (a.Scalar() != "true" && a.Scalar() != "false"))
      yaml_fail(f, a, section + ".assumed", fmt::format("'{}'; expected true (not verified against a public source) or false",
                                                        a.IsScalar() ? a.Scalar() : "a list or map"));
    e.assumed = a.Scalar() == "true";
  }
}

// The speeds where two ranges both hold (the top end closed, as the verdict takes it); empty: from > to.
SpeedRange common(const SpeedRange& a, const SpeedRange& b) {
  SpeedRange r;
  r.from = std::max(a.from, b.from), r.to = std::min(a.to, b.to);
  return r;
}

// a(v) ≤ b(v) over [lo, hi]: the difference is a quadratic, so its ends and its vertex decide. The first speed
// where it fails, or NaN.
double first_above(const SpeedCurve& a, const SpeedCurve& b, double lo, double hi) {
  const double d2 = b.v2 - a.v2, d1 = b.v1 - a.v1;
  std::vector<double> vs{lo, hi};
  if (d2 != 0) {
    const double vertex = -d1 / (2 * d2);
    if (vertex > lo && vertex < hi) vs.push_back(vertex);
  }
  for (double v : vs)
    if (a.at(v) > b.at(v) + 1e-9 * std::max(1.0, std::abs(b.at(v)))) return v;
  return NAN;
}

// lower(v) ≤ upper(v) over the range: the difference is a quadratic, so its ends and its vertex decide.
void check_band(const std::string& f, const YAML::Node& sec, const std::string& key, const AcceptanceCriteria::MeanBand& b) {
  const double a = b.upper.v2 - b.lower.v2, c1 = b.upper.v1 - b.lower.v1;
  const double lo = b.speeds.from, hi = std::isinf(b.speeds.to) ? std::max(kBandCheckTo, lo) : b.speeds.to;
  std::vector<double> vs{lo, hi};
  if (a != 0) {
    const double vertex = -c1 / (2 * a);
    if (vertex > lo && vertex < hi) vs.push_back(vertex);
  }
  for (double v : vs)
    if (b.lower.at(v) > b.upper.at(v))
      yaml_fail(f, sec, key,
                fmt::format("the lower edge {:.4g} N exceeds the upper edge {:.4g} N at {:.4g} km/h; expected lower <= upper "
                            "over the band's speeds",
                            b.lower.at(v), b.upper.at(v), v));
}

// A criterion's section: one map, or a list of maps with disjoint speed ranges; `one` reads an entry.
template <class Entry, class Read>
std::vector<Entry> entries(const std::string& f, const YAML::Node& root, const std::string& name, Read one) {
  std::vector<Entry> list;
  const YAML::Node s = root[name];
  if (!s.IsDefined()) return list;
  if (s.IsSequence()) {
    if (s.size() == 0) yaml_fail(f, s, name, "an empty list; expected a map or a list of maps with disjoint speeds");
    for (std::size_t i = 0; i < s.size(); ++i) list.push_back(one(s[i], fmt::format("{}[{}]", name, i)));
  } else {
    list.push_back(one(s, name));
  }
  for (std::size_t i = 0; i < list.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (list[i].speeds.from < list[j].speeds.to && list[j].speeds.from < list[i].speeds.to)
        yaml_fail(f, s, name,
                  fmt::format("entries {} and {} overlap in speed ([{:g}, {:g}] and [{:g}, {:g}] km/h); expected disjoint "
                              "speeds",
                              j, i, list[j].speeds.from, list[j].speeds.to, list[i].speeds.from, list[i].speeds.to));
  return list;
}

AcceptanceCriteria read(const std::string& f) {
  const YAML::Node root = yaml_load_file(f, "acceptance criteria file");
  if (!root.IsMap()) yaml_fail(f, root, "criteria", "expected a map with name, filter and criteria");
  keys(f, root, "criteria",
       {"name", "filter", "mean_force", "sigma", "statistical_min", "max_force", "contact_loss", "support_uplift", "target",
        "static_contact_force"});
  // Keys every criterion's entry may give besides its own (issue 53).
  auto with_common = [](std::set<std::string> k) {
    k.insert({"speeds", "source", "assumed"});
    return k;
  };
  AcceptanceCriteria c;
  c.source = f;
  if (!root["name"].IsDefined() || !root["name"].IsScalar()) yaml_fail(f, root, "name", "missing; expected the set's name");
  c.name = root["name"].Scalar();
  const YAML::Node filter = root["filter"];
  if (!filter.IsDefined()) yaml_fail(f, root, "filter", "missing; expected {cutoff: Hz, order: n} (EN 50317: 20 Hz)");
  keys(f, filter, "filter", {"cutoff", "order"});
  c.filter_cutoff = number_in(f, filter, "filter", "cutoff", 0.1, 1000, "a cutoff from 0.1 to 1000 Hz");
  if (!filter["order"].IsDefined()) yaml_fail(f, filter, "filter.order", "missing; expected a whole number from 1 to 8");
  c.filter_order = yaml_whole(f, filter["order"], "filter.order", 1, 8);
  using C = AcceptanceCriteria;
  c.mean = entries<C::MeanBand>(f, root, "mean_force", [&](const YAML::Node& s, const std::string& k) {
    keys(f, s, k, with_common({"lower", "upper", "statistics"}));
    for (const char* e : {"lower", "upper"})
      if (!s[e].IsDefined()) yaml_fail(f, s, fmt::format("{}.{}", k, e), "missing; expected {v2, v1, v0} (N, v in km/h)");
    C::MeanBand b;
    b.lower = curve(f, s["lower"], k + ".lower"), b.upper = curve(f, s["upper"], k + ".upper");
    b.statistics = statistics(f, s, k), b.speeds = speeds(f, s, k);
    sourced(f, s, k, b);
    check_band(f, s, k, b);
    return b;
  });
  c.sigma = entries<C::SigmaRatio>(f, root, "sigma", [&](const YAML::Node& s, const std::string& k) {
    keys(f, s, k, with_common({"max_ratio", "statistics"}));
    C::SigmaRatio e;
    e.ratio = number_in(f, s, k, "max_ratio", 1e-6, 10, "> 0 (σ / F_m)"), e.statistics = statistics(f, s, k), e.speeds = speeds(f, s, k);
    sourced(f, s, k, e);
    return e;
  });
  c.statistical_min = entries<C::StatisticalMin>(f, root, "statistical_min", [&](const YAML::Node& s, const std::string& k) {
    keys(f, s, k, with_common({"min", "statistics"}));
    C::StatisticalMin e;
    e.min = number(f, s, k, "min"), e.statistics = statistics(f, s, k), e.speeds = speeds(f, s, k);
    sourced(f, s, k, e);
    return e;
  });
  c.max_force = entries<C::MaxForce>(f, root, "max_force", [&](const YAML::Node& s, const std::string& k) {
    keys(f, s, k, with_common({"max", "statistics", "measure"}));
    C::MaxForce e;
    e.max = number_in(f, s, k, "max", 1e-6, 1e6, "> 0 (N)"), e.statistics = statistics(f, s, k), e.speeds = speeds(f, s, k);
    sourced(f, s, k, e);
    if (const YAML::Node m = s["measure"]; m.IsDefined()) {  // the largest sample (the default) or F_m + 3σ
      if (m.IsScalar() && m.Scalar() == "statistical_max")
        e.measure = analysis::ForceMeasure::StatisticalMax;
      else if (!m.IsScalar() || m.Scalar() != "largest")
        yaml_fail(f, m, k + ".measure",
                  fmt::format("'{}'; expected largest (the largest sample) or statistical_max (F_m + 3σ)",
                              m.IsScalar() ? m.Scalar() : "a list or map"));
    }
    return e;
  });
  c.contact_loss = entries<C::ContactLoss>(f, root, "contact_loss", [&](const YAML::Node& s, const std::string& k) {
    keys(f, s, k, with_common({"max_pct", "min_duration"}));
    C::ContactLoss e;
    e.max_pct = number_in(f, s, k, "max_pct", 0, 100, "a percentage from 0 to 100");
    e.min_duration = number_in(f, s, k, "min_duration", 0, 10, "0 to 10 s"), e.speeds = speeds(f, s, k);
    sourced(f, s, k, e);
    return e;
  });
  c.support_uplift = entries<C::SupportUplift>(f, root, "support_uplift", [&](const YAML::Node& s, const std::string& k) {
    keys(f, s, k, with_common({"clearance_factor", "limited_clearance_factor"}));
    C::SupportUplift e;
    e.clearance_factor = number_in(f, s, k, "clearance_factor", 1, 10, "1 to 10"), e.speeds = speeds(f, s, k);
    sourced(f, s, k, e);
    if (s["limited_clearance_factor"].IsDefined()) {  // a line whose uplift a stop limits (registration.uplift_limited)
      e.limited_clearance_factor = number_in(f, s, k, "limited_clearance_factor", 1, 10, "1 to 10");
      if (e.limited_clearance_factor > e.clearance_factor)
        yaml_fail(f, s["limited_clearance_factor"], k + ".limited_clearance_factor",
                  fmt::format("{:g} is above clearance_factor ({:g}); expected at most it (a stop limits the uplift)",
                              e.limited_clearance_factor, e.clearance_factor));
    }
    return e;
  });
  if (const YAML::Node s = root["target"]; s.IsDefined()) {  // {v2, v1, v0, speeds, source, assumed}
    c.has_target = true;
    static_cast<SpeedCurve&>(c.target) = curve(f, s, "target", with_common({"v2", "v1", "v0"}));
    c.target.speeds = speeds(f, s, "target");
    sourced(f, s, "target", c.target);
    // Inside every mean-force band where both hold: lower ≤ target ≤ upper (issue 53).
    for (std::size_t i = 0; i < c.mean.size(); ++i) {
      const auto& b = c.mean[i];
      const SpeedRange r = common(b.speeds, c.target.speeds);
      if (!(r.from <= r.to)) continue;
      const double hi = std::isinf(r.to) ? std::max(kBandCheckTo, r.from) : r.to;
      const std::string band = c.mean.size() > 1 ? fmt::format("mean_force[{}]", i) : std::string("mean_force");
      if (const double v = first_above(b.lower, c.target, r.from, hi); !std::isnan(v))
        yaml_fail(f, s, "target",
                  fmt::format("{:.4g} N at {:.4g} km/h is below {}'s lower edge {:.4g} N; expected lower <= target <= upper "
                              "where both hold (bound the target's speeds)",
                              c.target.SpeedCurve::at(v), v, band, b.lower.at(v)));
      if (const double v = first_above(c.target, b.upper, r.from, hi); !std::isnan(v))
        yaml_fail(f, s, "target",
                  fmt::format("{:.4g} N at {:.4g} km/h is above {}'s upper edge {:.4g} N; expected lower <= target <= upper "
                              "where both hold (bound the target's speeds)",
                              c.target.SpeedCurve::at(v), v, band, b.upper.at(v)));
    }
  }
  if (const YAML::Node s = root["static_contact_force"]; s.IsDefined()) {  // {lower, upper, tolerance_pct} (issue 49)
    const std::string k = "static_contact_force";
    if (!s.IsMap()) yaml_fail(f, s, k, "expected {lower: N, upper: N, tolerance_pct: %} (at least one)");
    keys(f, s, k, {"lower", "upper", "tolerance_pct", "source", "assumed"});
    c.has_static_force = true;
    sourced(f, s, k, c.static_force);
    if (s["lower"].IsDefined()) c.static_force.lower = number_in(f, s, k, "lower", 0, 1e4, "a force from 0 to 1e4 N");
    if (s["upper"].IsDefined()) c.static_force.upper = number_in(f, s, k, "upper", 0, 1e4, "a force from 0 to 1e4 N");
    if (s["tolerance_pct"].IsDefined())
      c.static_force.tolerance_pct = number_in(f, s, k, "tolerance_pct", 0, 100, "a percentage from 0 to 100");
    if (std::isnan(c.static_force.lower) && std::isnan(c.static_force.upper) && std::isnan(c.static_force.tolerance_pct))
      yaml_fail(f, s, k, "expected at least one of lower, upper, tolerance_pct");
    if (c.static_force.lower > c.static_force.upper)
      yaml_fail(f, s["upper"], k + ".upper", fmt::format("{} N is below lower ({} N)", c.static_force.upper, c.static_force.lower));
  }
  if (c.mean.empty() && c.sigma.empty() && c.statistical_min.empty() && c.max_force.empty() && c.contact_loss.empty() &&
      c.support_uplift.empty() && !c.has_static_force)
    yaml_fail(f, root, "criteria",
              "no criterion; expected at least one of mean_force, sigma, statistical_min, max_force, contact_loss, support_uplift");
  return c;
}

}  // namespace

std::vector<std::string> acceptance_presets() {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(preset_dir(), ec))
    if (e.path().extension() == ".yaml") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

analysis::AcceptanceCriteria load_acceptance(const std::string& s) {
  if (!is_preset_name(s)) return read(s);
  const std::vector<std::string> presets = acceptance_presets();
  if (std::find(presets.begin(), presets.end(), s) == presets.end())
  {
    const char* env = std::getenv("INERTA_DATA_DIR");  // the folder data_dir() took it from, if the user set it
    throw ModelError(fmt::format("acceptance: unknown preset '{}'; expected one of {} (in {}{}) or a criteria file "
                                 "(a path with '/' or ending in .yaml)",
                                 s, presets.empty() ? std::string("(none found)") : fmt::format("{}", fmt::join(presets, ", ")),
                                 preset_dir(), env && *env ? ", from $INERTA_DATA_DIR: a folder with criteria/, models/, scripts/" : ""));
  }
  return read(preset_dir() + "/" + s + ".yaml");
}

const char* status_text(const analysis::CriterionResult& r) {
  return !r.assessed ? "not assessed" : r.passed ? "PASS" : "FAIL";
}

std::string acceptance_csv(const std::vector<analysis::VerdictRow>& rows) {
  std::string out = "v_kmh,v_ms,pantograph,criterion,unit,value,limit,margin,status,note,statistic,assumed,source\n";
  for (const analysis::VerdictRow& x : rows) {
    const analysis::CriterionResult& r = x.result;
    out += fmt::format("{:.6g},{:.6g},{},{},{},{:.6g},{:.6g},{:.6g},{},{},{},{},{}\n", x.speed * 3.6, x.speed, x.pantograph,
                       r.criterion, r.unit, r.value, r.limit, r.margin, status_text(r), csv_field(r.note),
                       csv_field(r.statistic), r.statistic.empty() ? "" : r.assumed ? "true" : "false", csv_field(r.source));
  }
  return out;
}

void write_acceptance_csv(const std::string& path, const std::vector<analysis::VerdictRow>& rows) {
  write_text_file(path, acceptance_csv(rows));
}

}  // namespace inerta::io
