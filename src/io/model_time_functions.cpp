// Model files: time functions of point forces and driving joints (docs/model-format.md#time-functions).
// Each type accepts its own keys only; the values are checked by mbs::TimeFunction's factories,
// whose complaints come back at the line of the key they name.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "inerta/io/csv_table.hpp"
#include "model_reader.hpp"

namespace inerta::io::detail {

namespace {

using TF = mbs::TimeFunction;

std::vector<double> number_list(const Reader& rd, const YAML::Node& map, const char* key, const std::string& what) {
  const YAML::Node n = rd.need(map, key, what);
  if (!n.IsSequence()) rd.fail(n, key, "expected a list of numbers [a, b, ...]");
  std::vector<double> out;
  for (const auto& x : n) out.push_back(rd.number(x, key));
  return out;
}

// `columns: [t, y]` of a CSV table: names, or 0-based positions.
std::string csv_column(const Reader& rd, const YAML::Node& c, const CsvTable& csv) {
  const std::string s = rd.text(c, "columns");
  if (csv.has(s)) return s;
  std::size_t pos = 0;
  bool index = !s.empty();
  for (char ch : s) index = index && ch >= '0' && ch <= '9';
  if (index) pos = std::stoul(s);
  if (!index || pos >= csv.names().size()) {
    std::string names;
    for (std::size_t k = 0; k < csv.names().size(); ++k) names += fmt::format("{}{} ({})", k ? ", " : "", csv.names()[k], k);
    rd.fail(c, "columns", fmt::format("{} has no column '{}'; its columns (0-based positions): {}", csv.source(), s, names));
  }
  return csv.names()[pos];
}

TF table(const Reader& rd, const YAML::Node& n, const std::string& key, const std::string& what) {
  rd.keys(n, what, {"type", "points", "file", "columns", "interpolation", "accept_linear"});
  TF::Interpolation interp = TF::Interpolation::Spline;
  if (const YAML::Node i = n["interpolation"]; i.IsDefined()) {
    const std::string s = rd.text(i, "interpolation");
    if (s == "linear")
      interp = TF::Interpolation::Linear;
    else if (s != "spline")
      rd.fail(i, "interpolation", fmt::format("expected spline (the default, C²) or linear, got '{}'", s));
  }
  std::vector<double> t, v;
  if (n["file"].IsDefined() == n["points"].IsDefined())
    rd.fail(n, key, "give either points: [[t, value], ...] or file: TABLE.csv (with columns: [t, value]), not both");
  if (n["points"].IsDefined()) {
    if (n["columns"].IsDefined()) rd.fail(n["columns"], "columns", "belongs to a table read from a file (file: TABLE.csv)");
    YAML::Node pts = n["points"];
    if (!pts.IsSequence()) rd.fail(pts, "points", "expected a list of [t, value] pairs");
    for (const auto& p : pts) {
      const mbs::Vec2 tv = rd.vec2(p, "points");
      t.push_back(tv.x());
      v.push_back(tv.y());
    }
    return rd.guard(n, what, [&] { return TF::table(std::move(t), std::move(v), interp); });
  }
  const std::string path = rd.relative_path(rd.text(n["file"], "file"));
  const YAML::Node cols = rd.need(n, "columns", key + " (table from a file)");
  if (!cols.IsSequence() || cols.size() != 2)
    rd.fail(cols, "columns", "expected two columns [time, value], by name or 0-based position");
  CsvTable csv = [&] {
    try {
      return CsvTable::read(path);
    } catch (const ModelError& e) {
      rd.fail(n["file"], "file", e.what());
    }
  }();
  csv.require_rows(1, "a table");
  const std::string ct = csv_column(rd, cols[0], csv), cv = csv_column(rd, cols[1], csv);
  t = csv.column(ct);
  v = csv.column(cv);
  for (std::size_t r = 1; r < t.size(); ++r)
    if (!(t[r] > t[r - 1]))
      throw ModelError(fmt::format("{}:{}: column '{}': times must be strictly increasing (t = {} after t = {}); "
                                   "table of {}",
                                   csv.source(), csv.line(r), ct, t[r], t[r - 1], rd.file()));
  return rd.guard(n, what, [&] { return TF::table(std::move(t), std::move(v), interp); });
}

TF road(const Reader& rd, const YAML::Node& n, const std::string& key, const std::string& what) {
  rd.keys(n, what, {"type", "class", "speed", "seed", "n_min", "n_max", "length", "duration", "delay", "offset"});
  mbs::RoadProfile r;
  const YAML::Node c = rd.need(n, "class", key);
  const std::string cls = rd.text(c, "class");
  if (cls.size() != 1) rd.fail(c, "class", fmt::format("expected an ISO 8608 class A to H, got '{}'", cls));
  r.road_class = cls[0];
  r.speed = rd.number(n, "speed", key);
  if (const YAML::Node s = n["seed"]; s.IsDefined()) {
    const double seed = rd.number(s, "seed");
    if (!(seed >= 0) || seed != std::floor(seed) || seed > 9.007e15)
      rd.fail(s, "seed", fmt::format("expected a whole number >= 0, got '{}'", s.Scalar()));
    r.seed = static_cast<std::uint64_t>(seed);
  }
  r.n_min = rd.number_or(n, "n_min", r.n_min);
  r.n_max = rd.number_or(n, "n_max", r.n_max);
  if (n["length"].IsDefined() == n["duration"].IsDefined())
    rd.fail(n, key, "give either length (m) or duration (s, length = speed · duration) of the road profile, not both");
  if (n["length"].IsDefined()) {
    r.length = rd.number(n["length"], "length");
  } else {
    const double d = rd.number(n["duration"], "duration");
    if (!(d > 0) || !std::isfinite(d)) rd.fail(n["duration"], "duration", fmt::format("must be > 0 (s), got {}", d));
    r.length = d * r.speed;
  }
  r.delay = rd.number_or(n, "delay", 0.0);
  const double offset = rd.number_or(n, "offset", 0.0);
  return rd.guard(n, what, [&] { return TF::road(r, offset); });
}

// The reason a function with corners is refused for a driving joint, at the key that makes it so.
void refuse_corners(const Reader& rd, const YAML::Node& n, const TF& f) {
  if (const YAML::Node a = n["accept_linear"]; a.IsDefined() && rd.boolean(a, "accept_linear")) return;
  if (f.kind == TF::Kind::Table)
    rd.fail(n["interpolation"], "interpolation",
            "a linear table drives a coordinate with f'' = 0 and jumps of f' at its points, so the coordinate "
            "follows it only through the Baumgarte terms (spec/02 §2.2, eq. 4.11); use the default spline "
            "interpolation (C²), or add accept_linear: true to accept that");
  const bool late_start = f.start > 0;
  rd.fail(late_start ? n["start"] : n["end"], late_start ? "start" : "end",
          fmt::format("a ramp driving a coordinate has a corner at t = {:g} s, where the velocity jumps and f'' (a "
                      "Dirac) is missing, so the coordinate follows it only through the Baumgarte terms (spec/02 §2.2, "
                      "eq. 4.11); use a step (smooth), start the ramp at t <= 0 without an end, or add "
                      "accept_linear: true to accept that",
                      late_start ? f.start : f.end));
}

}  // namespace

mbs::TimeFunction time_function(const Reader& rd, const YAML::Node& n, const std::string& key, bool driving) {
  if (n.IsScalar()) {
    const double value = rd.number(n, key);
    return rd.guard_value(n, key, [&] { return TF::constant(value); });
  }
  const char* kinds = "constant, sine, table, ramp, step, chirp, sum_of_sines, polynomial or road";
  if (!n.IsMap()) rd.fail(n, key, fmt::format("expected a number or a function {{type: ..., ...}} ({})", kinds));
  const std::string type = rd.text(n, "type", key);
  const std::string what = key + " (" + type + ")";
  TF f;
  if (type == "constant") {
    rd.keys(n, what, {"type", "value"});
    const double value = rd.number(n, "value", key);
    f = rd.guard(n, what, [&] { return TF::constant(value); });
  } else if (type == "sine") {
    rd.keys(n, what, {"type", "amplitude", "frequency", "phase", "phase_deg", "offset"});
    const double fr = rd.number(n, "frequency", key), amplitude = rd.number(n, "amplitude", key);
    const double phase = rd.angle(n, "phase", 0.0), offset = rd.number_or(n, "offset", 0.0);
    f = rd.guard(n, what, [&] { return TF::sine(amplitude, fr, phase, offset); });
  } else if (type == "table") {
    f = table(rd, n, key, what);
  } else if (type == "ramp") {
    rd.keys(n, what, {"type", "slope", "start", "end", "offset", "accept_linear"});
    const double slope = rd.number(n, "slope", key), start = rd.number_or(n, "start", 0.0);
    const double end = rd.number_or(n, "end", std::numeric_limits<double>::infinity());
    const double offset = rd.number_or(n, "offset", 0.0);
    f = rd.guard(n, what, [&] { return TF::ramp(slope, start, offset, end); });
  } else if (type == "step") {
    rd.keys(n, what, {"type", "height", "rise", "start", "offset"});
    const double height = rd.number(n, "height", key), rise = rd.number(n, "rise", key);
    const double start = rd.number_or(n, "start", 0.0), offset = rd.number_or(n, "offset", 0.0);
    f = rd.guard(n, what, [&] { return TF::step(height, rise, start, offset); });
  } else if (type == "chirp") {
    rd.keys(n, what, {"type", "amplitude", "f0", "f1", "duration", "sweep", "offset"});
    const double amplitude = rd.number(n, "amplitude", key), f0 = rd.number(n, "f0", key);
    const double f1 = rd.number(n, "f1", key), duration = rd.number(n, "duration", key);
    const double offset = rd.number_or(n, "offset", 0.0);
    TF::Sweep sweep = TF::Sweep::Linear;
    if (const YAML::Node s = n["sweep"]; s.IsDefined()) {
      const std::string v = rd.text(s, "sweep");
      if (v == "logarithmic")
        sweep = TF::Sweep::Logarithmic;
      else if (v != "linear")
        rd.fail(s, "sweep", fmt::format("expected linear (the default) or logarithmic, got '{}'", v));
    }
    f = rd.guard(n, what, [&] { return TF::chirp(amplitude, f0, f1, duration, sweep, offset); });
  } else if (type == "sum_of_sines") {
    rd.keys(n, what, {"type", "amplitudes", "frequencies", "phases", "phases_deg", "offset"});
    std::vector<double> a = number_list(rd, n, "amplitudes", key), fr = number_list(rd, n, "frequencies", key), p;
    if (n["phases"].IsDefined() && n["phases_deg"].IsDefined())
      rd.fail(n["phases_deg"], "phases_deg", "give either phases (rad) or phases_deg, not both");
    if (n["phases"].IsDefined()) p = number_list(rd, n, "phases", key);
    if (n["phases_deg"].IsDefined()) {
      p = number_list(rd, n, "phases_deg", key);
      for (double& x : p) x *= std::numbers::pi / 180;
    }
    const double offset = rd.number_or(n, "offset", 0.0);
    f = rd.guard(n, what, [&] { return TF::sum_of_sines(std::move(a), std::move(fr), std::move(p), offset); });
  } else if (type == "polynomial") {
    rd.keys(n, what, {"type", "coefficients", "t0"});
    std::vector<double> c = number_list(rd, n, "coefficients", key);
    const double t0 = rd.number_or(n, "t0", 0.0);
    f = rd.guard(n, what, [&] { return TF::polynomial(std::move(c), t0); });
  } else if (type == "road") {
    f = road(rd, n, key, what);
  } else {
    rd.fail(n["type"], "type", fmt::format("unknown function type '{}'; expected {}", type, kinds));
  }
  if (driving && !f.smooth()) refuse_corners(rd, n, f);
  return f;
}

}  // namespace inerta::io::detail
