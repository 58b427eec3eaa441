// The HTML reports of sweep and simulate (report/run_reports.hpp).
#include "inerta/report/run_reports.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "inerta/report/html.hpp"
#include "inerta/network/schematic.hpp"
#include "inerta/report/svg_plot.hpp"

namespace inerta::report {

namespace {

std::string g6(double v) { return std::isnan(v) ? "-" : fmt::format("{:.6g}", v); }

// A value in the unit a reader expects (as the CLI's verdict table): uplift in mm, forces in N, loss in %.
std::string shown(const analysis::CriterionResult& r, double x) {
  if (std::isnan(x)) return "-";
  if (r.unit == "m") return fmt::format("{:.1f} mm", 1e3 * x);
  if (r.unit == "%") return fmt::format("{:.3f} %", x);
  return fmt::format("{:.2f} N", x);
}

std::string speed_key(double v_ms, bool kmh) { return kmh ? fmt::format("v={:.6g} km/h", 3.6 * v_ms) : fmt::format("v={:.6g} m/s", v_ms); }

// The banner and the verdict table; the rows' numbers into the record.
void verdict_section(Document& doc, Record& record, const RunContext& c) {
  if (!c.criteria) {
    doc.verdict("NO CRITERIA", {"No acceptance criteria were given (--acceptance PRESET|FILE): the results below are not judged."});
    return;
  }
  const analysis::Verdict v = analysis::judge(c.verdict);
  record.verdict = v.text();
  std::vector<std::string> lines{fmt::format("Criteria: {} ({})", c.criteria->name, c.criteria->source)};
  if (!v.failed.empty()) lines.push_back(fmt::format("Failed: {}", fmt::join(v.failed, ", ")));
  if (!v.not_assessed.empty()) lines.push_back(fmt::format("Not assessed: {}", fmt::join(v.not_assessed, ", ")));
  bool assumed = false;
  for (const auto& x : c.verdict) assumed = assumed || (x.result.assessed && x.result.assumed);
  if (assumed)
    lines.push_back("Criteria marked [assumed] are not verified against a public source: check them against the standard "
                    "before an approval.");
  if (const std::string arcing = analysis::arcing_text(*c.criteria); !arcing.empty()) lines.push_back(arcing);
  doc.verdict(v.text(), lines);
  doc.heading("Verdict per speed and criterion");
  Table t;
  t.id = "verdict";
  t.header = {c.kmh ? "v km/h" : "v m/s", "pantograph", "criterion", "value", "limit", "margin", "margin %", "status", "note"};
  Table src;  // each criterion once: what it reads and where its number comes from
  src.id = "criteria";
  src.header = {"criterion", "statistic", "source", "verified"};
  for (const auto& x : c.verdict) {
    const auto& r = x.result;
    const double rel = r.assessed ? 100 * analysis::relative_margin(r) : NAN;
    t.rows.push_back({fmt::format("{:.6g}", c.kmh ? 3.6 * x.speed : x.speed), std::to_string(x.pantograph),
                      r.criterion + (r.assumed ? " [assumed]" : ""), shown(r, r.value), shown(r, r.limit),
                      shown(r, r.margin), std::isnan(rel) ? "-" : fmt::format("{:.1f}", rel),
                      !r.assessed ? "not assessed" : r.passed ? "PASS" : "FAIL", r.note});
    const std::vector<std::string> entry{r.criterion, r.statistic, r.source.empty() ? "-" : r.source,
                                         r.assumed ? "no: [assumed]" : "yes"};
    if (std::find(src.rows.begin(), src.rows.end(), entry) == src.rows.end()) src.rows.push_back(entry);
    t.row_class.push_back(!r.assessed ? "na" : r.passed ? "" : "fail");
    const std::string key = fmt::format("verdict/{}/panto {}/{}", speed_key(x.speed, c.kmh), x.pantograph, r.criterion);
    record.add(key + "/value", r.value);
    record.add(key + "/limit", r.limit);
    record.add(key + "/margin", r.margin);
  }
  doc.table(t);
  doc.heading("Criteria: what each reads and where its number comes from");
  doc.table(src);
}

void add_stats(Record& record, const std::string& key, const analysis::ContactStatistics& s) {
  record.add(key + "/mean", s.mean);
  record.add(key + "/std", s.std);
  record.add(key + "/max", s.max);
  record.add(key + "/min", s.min);
  record.add(key + "/stat_max", s.stat_max);
  record.add(key + "/stat_min", s.stat_min);
  record.add(key + "/loss_pct", s.loss_pct);
}

std::vector<std::string> stats_cells(const analysis::ContactStatistics& s) {
  return {g6(s.mean), g6(s.std), g6(s.max), g6(s.min), g6(s.stat_max), g6(s.stat_min), fmt::format("{:.4g}", s.loss_pct)};
}

// The band of the criteria's mean force over speeds v (km/h) where an entry covers it.
void mean_band(const analysis::AcceptanceCriteria& c, const std::vector<double>& v_kmh, Plot& p) {
  for (const auto& m : c.mean) {
    PlotBand b;
    b.name = "F_m band of " + c.name;
    for (double v : v_kmh)
      if (m.speeds.contains(v)) b.x.push_back(v), b.lower.push_back(m.lower.at(v)), b.upper.push_back(m.upper.at(v));
    if (b.x.size() == 1) {  // one speed: a short stretch, so that the band shows
      b.x = {b.x[0] - 2, b.x[0] + 2}, b.lower = {b.lower[0], b.lower[0]}, b.upper = {b.upper[0], b.upper[0]};
    }
    if (!b.x.empty()) p.bands.push_back(b);
  }
  if (c.has_target) {
    PlotSeries s("F_m target", "#2e8b3e", true, false);
    for (double v : v_kmh) s.x.push_back(v), s.y.push_back(c.target.at(v));
    p.series.push_back(s);
  }
}

void feature_marks(const std::vector<catenary::LineFeature>& features, double from, double to, Plot& p) {
  using K = catenary::LineFeature::Kind;
  for (const auto& f : features) {
    if (f.to < from || f.from > to) continue;
    switch (f.kind) {
      case K::Mast: p.marks.push_back({f.from, "mast"}); break;
      case K::Dropper: p.marks.push_back({f.from, "dropper"}); break;
      case K::StitchDropper: p.marks.push_back({f.from, "stitch_dropper"}); break;
      case K::StitchWire: p.ranges.push_back({f.from, f.to, "stitch", fmt::format("stitch wire {:g}–{:g} m", f.from, f.to)}); break;
      case K::Overlap: p.ranges.push_back({f.from, f.to, "overlap", fmt::format("overlap {:g}–{:g} m", f.from, f.to)}); break;
    }
  }
}

// The run's pantograph and line, and its suspension drawn when it replaces the model's.
void run_section(Document& doc, const RunContext& c) {
  doc.heading("Run");
  doc.paragraph("Pantograph: " + c.model);
  if (c.suspension)
    doc.figure(network::schematic_svg(network::simplify(*c.suspension), {.values = true, .title = "suspension: " + network::to_string(*c.suspension, true)}),
               "The suspension network of this run (--suspension), in place of the model's own.");
  doc.paragraph("Line: " + c.line);
}

}  // namespace

std::string sweep_report(const RunContext& c, const std::vector<analysis::SpeedResult>& results, Record& record) {
  record.command = "sweep";
  record.provenance = c.provenance;
  Document doc("Inerta sweep: contact force over speeds");
  verdict_section(doc, record, c);
  run_section(doc, c);
  const bool line = !results.empty() && !results.front().filtered.empty();
  std::vector<double> v_shown, v_kmh;
  for (const auto& r : results) v_shown.push_back(c.kmh ? 3.6 * r.speed : r.speed), v_kmh.push_back(3.6 * r.speed);
  // EN 50317 statistics, as the CSV writes them (6 significant digits)
  doc.heading(line ? "Statistics over the analysis section (EN 50317), leading pantograph" : "Statistics, leading pantograph");
  // two tables (raw; 20 Hz filtered and uplift) with the CSV's column names, so that each fits the page
  Table t, tf;
  t.id = "statistics";
  t.header = {"v_kmh", "mean", "std", "max", "min", "stat_max", "stat_min", "loss_pct"};
  tf.id = "statistics_filtered";
  tf.header = {"v_kmh", "f_mean", "f_std", "f_max", "f_min", "f_stat_max", "f_stat_min", "uplift_max_m"};
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    std::vector<std::string> row{fmt::format("{:.6g}", v_kmh[i])};
    const auto cells = stats_cells(r.stats);
    row.insert(row.end(), cells.begin(), cells.end());
    const std::string key = speed_key(r.speed, c.kmh);
    add_stats(record, key + "/raw", r.stats);
    t.rows.push_back(row);
    if (line) {
      const auto& f = r.filtered.front();
      std::vector<std::string> frow{row.front()};
      for (double x : {f.mean, f.std, f.max, f.min, f.stat_max, f.stat_min}) frow.push_back(g6(x));
      add_stats(record, key + "/filtered", f);
      const double up = r.support_uplift.empty() ? 0.0 : *std::max_element(r.support_uplift.begin(), r.support_uplift.end());
      frow.push_back(g6(up));
      record.add(key + "/uplift_max", up);
      tf.rows.push_back(frow);
    }
  }
  doc.table(t);
  if (line) {
    doc.paragraph("After the 20 Hz low-pass (EN 50317), and the largest support uplift over the run (m):");
    doc.table(tf);
  }
  // σ(v) and F_m(v) against the band
  Plot fm("Mean contact force F_m(v)", "speed, km/h", "F_m, N");
  PlotSeries m(line ? "F_m (20 Hz filtered)" : "F_m", "#1f5fa8", false, true);
  PlotSeries sd(line ? "σ (20 Hz filtered)" : "σ", "#c0392b", false, true);
  PlotSeries sdl("σ limit", "#c0392b", true, false);
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& s = line ? results[i].filtered.front() : results[i].stats;
    m.x.push_back(v_kmh[i]), m.y.push_back(s.mean);
    sd.x.push_back(v_kmh[i]), sd.y.push_back(s.std);
    if (c.criteria)
      for (const auto& e : c.criteria->sigma)
        if (e.speeds.contains(v_kmh[i])) sdl.x.push_back(v_kmh[i]), sdl.y.push_back(e.ratio * s.mean);
  }
  fm.series.push_back(m);
  if (c.criteria) mean_band(*c.criteria, v_kmh, fm);
  doc.heading("Mean force and standard deviation over speed");
  doc.figure(svg_plot(fm), c.criteria ? "F_m of the leading pantograph against the criteria's band (shaded) and target (dashed)."
                                      : "F_m of the leading pantograph.");
  Plot sp("Standard deviation σ(v)", "speed, km/h", "σ, N");
  sp.series.push_back(sd);
  if (!sdl.x.empty()) sp.series.push_back(sdl);
  doc.figure(svg_plot(sp), "σ of the leading pantograph's contact force; dashed: the criteria's σ limit (ratio × F_m).");
  // supports' uplift
  if (line) {
    Plot up("Largest support uplift", "speed, km/h", "uplift, mm");
    PlotSeries u("largest uplift at a support", "#1f5fa8", false, true);
    for (std::size_t i = 0; i < results.size(); ++i) {
      const auto& s = results[i].support_uplift;
      u.x.push_back(v_kmh[i]), u.y.push_back(s.empty() ? NAN : 1e3 * *std::max_element(s.begin(), s.end()));
    }
    up.series.push_back(u);
    const double limit = results.front().uplift_limit;
    if (std::isfinite(limit) && c.criteria && !c.criteria->support_uplift.empty()) {
      PlotSeries l("limit / clearance factor", "#c0392b", true, false);
      for (std::size_t i = 0; i < results.size(); ++i)
        for (const auto& e : c.criteria->support_uplift)
          if (e.speeds.contains(v_kmh[i])) l.x.push_back(v_kmh[i]), l.y.push_back(1e3 * limit / e.factor(results[i].uplift_limited));
      up.series.push_back(l);
    }
    doc.figure(svg_plot(up), "The contact wire's largest uplift at a support (registration) over the run; dashed: the "
                             "line's uplift limit divided by the criterion's clearance factor.");
  }
  doc.provenance(c.provenance);
  return doc.html(record);
}

std::string simulate_report(const RunContext& c, const analysis::CoupledSimulation& sim,
                            const std::vector<catenary::LineFeature>& features, Record& record) {
  record.command = "simulate";
  record.provenance = c.provenance;
  Document doc(fmt::format("Inerta simulate: {:.4g} km/h", 3.6 * sim.speed));
  verdict_section(doc, record, c);
  run_section(doc, c);
  doc.paragraph(fmt::format("Speed {:.4g} km/h ({:.4g} m/s); analysis section {:g}–{:g} m.", 3.6 * sim.speed, sim.speed,
                            sim.section.from, sim.section.to));
  const bool line = !sim.quality.empty();
  doc.heading(line ? "Statistics over the analysis section (EN 50317)" : "Statistics");
  Table t;
  t.id = "statistics";
  t.header = {"pantograph", "statistics", "mean", "std", "max", "min", "stat_max", "stat_min", "loss_pct"};
  for (std::size_t k = 0; k < sim.contacts.size(); ++k) {
    const std::string key = fmt::format("panto {}", k + 1);
    auto add = [&](const char* which, const analysis::ContactStatistics& s) {
      std::vector<std::string> row{std::to_string(k + 1), which};
      const auto cells = stats_cells(s);
      row.insert(row.end(), cells.begin(), cells.end());
      t.rows.push_back(row);
      add_stats(record, key + "/" + which, s);
    };
    if (line) {
      add("raw", sim.quality[k].raw);
      add("filtered", sim.quality[k].filtered);
    } else {
      add("raw", sim.contacts[k].stats);
    }
  }
  doc.table(t);
  // the contact force along the section
  if (line)
    for (std::size_t k = 0; k < sim.histories.size(); ++k) {
      const auto& h = sim.histories[k];
      const auto col = [&](const std::string& name) -> const std::vector<double>* {
        for (std::size_t j = 0; j < h.names.size(); ++j)
          if (h.names[j] == name) return &h.columns[j];
        return nullptr;
      };
      const auto* x = col("x_contact");
      const auto* F = col("F_contact");
      if (!x || !F) continue;
      Plot p(fmt::format("Contact force along the analysis section, pantograph {}", k + 1), "position along the line, m", "contact force, N");
      PlotSeries s("raw contact force", "#1f5fa8", false, false);
      for (std::size_t i = 0; i < x->size(); ++i)
        if ((*x)[i] >= sim.section.from && (*x)[i] <= sim.section.to) s.x.push_back((*x)[i]), s.y.push_back((*F)[i]);
      p.series.push_back(s);
      feature_marks(features, sim.section.from, sim.section.to, p);
      p.height = 340;
      doc.figure(svg_plot(p), "Masts: dashed lines; droppers: ticks at the bottom (stitch droppers purple); stitch wires: "
                              "purple bars; overlaps (two contact wires): shaded yellow.");
    }
  if (!sim.uplift.empty()) {
    doc.heading("Support uplift");
    Table u;
    u.id = "uplift";
    u.header = {"support x, m", "largest uplift, mm", "at t, s"};
    for (const auto& s : sim.uplift) {
      u.rows.push_back({fmt::format("{:g}", s.x), fmt::format("{:.2f}", 1e3 * s.max_uplift), fmt::format("{:.3f}", s.t_max)});
      record.add(fmt::format("uplift/x={:g}", s.x), s.max_uplift);
    }
    doc.table(u);
    if (std::isfinite(sim.uplift_limit))
      doc.paragraph(fmt::format("The line's registration uplift limit: {:.1f} mm{}.", 1e3 * sim.uplift_limit,
                                sim.uplift_limited ? " (physically limited by a stop)" : ""));
  }
  doc.provenance(c.provenance);
  return doc.html(record);
}

std::string reduction_report(const RunContext& c, const std::vector<analysis::RunComparison>& rows,
                             const std::vector<analysis::VerdictRow>& modal_verdict, double tolerance_pct, Record& record) {
  record.command = "check-reduction";
  record.provenance = c.provenance;
  Document doc("Inerta check-reduction: the modal solve against the direct one");
  auto pct = [](double a, double b) { return a != 0 ? 100 * (b - a) / std::abs(a) : 0.0; };
  double worst = 0;
  for (const auto& r : rows)
    worst = std::max({worst, std::abs(pct(r.reference.stats.std, r.candidate.stats.std)),
                      std::abs(pct(r.reference.filtered[0].std, r.candidate.filtered[0].std))});
  std::vector<std::string> lines{fmt::format("Largest difference of σ (raw or 20 Hz): {:.3f} % (tolerance {:g} %).", worst, tolerance_pct)};
  if (c.criteria) {
    const auto vd = analysis::judge(c.verdict), vm = analysis::judge(modal_verdict);
    lines.push_back(fmt::format("Acceptance {}: direct {}, modal {}.", c.criteria->name, vd.text(), vm.text()));
    record.verdict = fmt::format("direct {}, modal {}", vd.text(), vm.text());
  }
  doc.verdict(worst <= tolerance_pct ? "AGREE" : "DIFFER", lines);
  doc.heading("Run");
  doc.paragraph("Pantograph: " + c.model);
  doc.paragraph("Line: " + c.line);
  doc.heading("Both solves side by side (analysis section, EN 50317)");
  Table t;
  t.id = "comparison";
  t.header = {c.kmh ? "v km/h" : "v m/s", "quantity", "direct", "modal", "difference"};
  for (const auto& r : rows) {
    const auto &d = r.reference, &m = r.candidate;
    const std::string v = fmt::format("{:.6g}", c.kmh ? 3.6 * r.speed : r.speed), key = speed_key(r.speed, c.kmh);
    const double up_d = d.support_uplift.empty() ? 0 : *std::max_element(d.support_uplift.begin(), d.support_uplift.end());
    const double up_m = m.support_uplift.empty() ? 0 : *std::max_element(m.support_uplift.begin(), m.support_uplift.end());
    auto row = [&](const std::string& q, double x, double y, bool relative) {
      t.rows.push_back({v, q, fmt::format("{:.4f}", x), fmt::format("{:.4f}", y),
                        relative ? fmt::format("{:+.3f} %", pct(x, y)) : fmt::format("{:+.4f}", y - x)});
      t.row_class.push_back("");
      record.add(key + "/direct/" + q, x);
      record.add(key + "/modal/" + q, y);
    };
    row("mean, N", d.stats.mean, m.stats.mean, true);
    row("σ, N", d.stats.std, m.stats.std, true);
    row("σ 20 Hz, N", d.filtered[0].std, m.filtered[0].std, true);
    row("max, N", d.stats.max, m.stats.max, true);
    row("min, N", d.stats.min, m.stats.min, false);
    row("min 20 Hz, N", d.filtered[0].min, m.filtered[0].min, false);
    row("loss, %", d.stats.loss_pct, m.stats.loss_pct, false);
    row("uplift max, mm", 1e3 * up_d, 1e3 * up_m, true);
    t.rows.push_back({v, "wall, s", fmt::format("{:.2f}", r.reference_s), fmt::format("{:.2f}", r.candidate_s), ""});
    t.row_class.push_back("na");
  }
  doc.table(t);
  Plot p("σ(v) of both solves", "speed, km/h", "σ, N");
  PlotSeries sd("direct, raw", "#1f5fa8", false, true), sm("modal, raw", "#c0392b", true, true);
  PlotSeries fd("direct, 20 Hz", "#2e8b3e", false, true), fm("modal, 20 Hz", "#8e44ad", true, true);
  for (const auto& r : rows) {
    const double v = 3.6 * r.speed;
    sd.x.push_back(v), sd.y.push_back(r.reference.stats.std), sm.x.push_back(v), sm.y.push_back(r.candidate.stats.std);
    fd.x.push_back(v), fd.y.push_back(r.reference.filtered[0].std), fm.x.push_back(v), fm.y.push_back(r.candidate.filtered[0].std);
  }
  p.series = {sd, sm, fd, fm};
  doc.figure(svg_plot(p), "σ of the leading pantograph's contact force by the direct (solid) and the modal solve (dashed).");
  if (c.criteria) {
    doc.heading("Verdict of each solve");
    Table v;
    v.id = "verdicts";
    v.header = {c.kmh ? "v km/h" : "v m/s", "criterion", "direct value", "direct", "modal value", "modal", "same"};
    for (std::size_t i = 0; i < c.verdict.size() && i < modal_verdict.size(); ++i) {
      const auto &a = c.verdict[i].result, &b = modal_verdict[i].result;
      auto st = [](const analysis::CriterionResult& r) { return !r.assessed ? "not assessed" : r.passed ? "PASS" : "FAIL"; };
      const bool same = std::string(st(a)) == st(b);
      v.rows.push_back({fmt::format("{:.6g}", c.kmh ? 3.6 * c.verdict[i].speed : c.verdict[i].speed), a.criterion + (a.assumed ? " [assumed]" : ""),
                        shown(a, a.value), st(a), shown(b, b.value), st(b), same ? "yes" : "NO"});
      v.row_class.push_back(same ? "" : "fail");
      record.add(fmt::format("verdict/{}/{}/direct", speed_key(c.verdict[i].speed, c.kmh), a.criterion), a.value);
      record.add(fmt::format("verdict/{}/{}/modal", speed_key(c.verdict[i].speed, c.kmh), b.criterion), b.value);
    }
    doc.table(v);
  }
  doc.provenance(c.provenance);
  return doc.html(record);
}

}  // namespace inerta::report
