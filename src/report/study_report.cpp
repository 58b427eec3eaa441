// The HTML report of a study (report/study_report.hpp).
#include "inerta/report/study_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <filesystem>
#include <map>

#include "inerta/io/files.hpp"
#include "inerta/network/schematic.hpp"
#include "inerta/report/html.hpp"
#include "inerta/report/svg_plot.hpp"

namespace inerta::report {

namespace {

std::string values_text(const network::Params& p) {
  std::vector<std::string> v;
  for (const auto& [k, x] : p) v.push_back(fmt::format("{}={:.4g}", k, x));
  return fmt::format("{}", fmt::join(v, "; "));
}

std::string pct(double J, double ref) {
  return std::isfinite(J) && ref > 0 ? fmt::format("{:+.2f}", 100 * (J - ref) / ref) : "-";
}

// The schematic of a design as built: bound to its values and simplified (an element at 0 is open and
// left out, one at ∞ is rigid); a note if it cannot be drawn.
std::string drawing(const network::Network& bound, const std::string& title) {
  try {
    const network::Network n = network::simplify(bound);
    return network::schematic_svg(n, {.values = true, .title = title});
  } catch (const std::exception& e) {
    return fmt::format("<p>(no drawing of {}: {})</p>", escape(network::to_string(bound)), escape(e.what()));
  }
}
std::string drawing(const std::string& expression, const network::Params& values, const std::string& title) {
  try {
    return drawing(network::assign(network::parse(expression), values), title);
  } catch (const std::exception& e) {
    return fmt::format("<p>(no drawing of {}: {})</p>", escape(expression), escape(e.what()));
  }
}

const char* kColors[] = {"#1f5fa8", "#c0392b", "#2e8b3e", "#8e44ad", "#d35400", "#16a085"};

void j2_study(Document& doc, Record& rec, const optim::StudyOutcome& o) {
  const optim::Study& s = *o.study;
  const double ref = o.default_cost.J;
  const auto& best = o.best;
  const bool time = s.method == optim::Study::Method::Time;
  std::vector<std::string> lines;
  lines.push_back(fmt::format("Recommendation: {}{} ({}), J2 = {:.3f} N{} against the default suspension's {:.3f} N ({} %).",
                              o.stock_best ? "the stock suspension " : "", best.layout, best.expression, best.J,
                              best.verified ? " (verified in the time domain)" : "", ref, pct(best.J, ref)));
  if (!best.feasible) lines.push_back("No design keeps the study's limits: the recommendation is the least infeasible.");
  std::string status = best.feasible ? "RECOMMENDATION" : "NO FEASIBLE DESIGN";
  if (o.report && !o.report->margins.empty()) {
    // the verdict of the best design over the acceptance margins (every variant, speed and pantograph)
    bool any = false, fail = false;
    std::vector<std::string> failed, not_assessed;
    for (const auto& m : o.report->margins) {
      if (m.design != o.report->best.label) continue;
      if (!m.result.assessed) {
        if (std::find(not_assessed.begin(), not_assessed.end(), m.result.criterion) == not_assessed.end())
          not_assessed.push_back(m.result.criterion);
        continue;
      }
      any = true;
      if (!m.result.passed) {
        fail = true;
        if (std::find(failed.begin(), failed.end(), m.result.criterion) == failed.end()) failed.push_back(m.result.criterion);
      }
    }
    status = !any ? "NOT ASSESSED" : fail ? "FAIL" : "PASS";
    rec.verdict = status;
    lines.push_back(fmt::format("Acceptance ({}) of the recommended design over every line variant and speed: {}{}{}.",
                                o.report->acceptance, status, failed.empty() ? "" : fmt::format(" ({})", fmt::join(failed, ", ")),
                                not_assessed.empty() ? "" : fmt::format("; not assessed: {}", fmt::join(not_assessed, ", "))));
  }
  doc.verdict(status, lines);
  rec.add("default/J", ref);
  rec.add("best/J", best.J);
  doc.heading("Study");
  doc.paragraph(fmt::format("{}: {} catenary variant(s), {} speeds{}, {}.", s.name, s.catenaries.size(), s.speeds.size(),
                            s.speeds.empty() ? "" : fmt::format(" ({:.0f}–{:.0f} km/h)", 3.6 * s.speeds.front(), 3.6 * s.speeds.back()),
                            time ? "time domain" : "periodic fast path (harmonic balance)"));
  // the ranking: each design with its J, against the default, its binding criterion
  doc.heading("Ranking");
  Table t;
  t.id = "ranking";
  t.header = {"rank", "design", "network", "J2, N", "vs default, %", "feasible", "binding criterion", "its margin, %", "values"};
  std::vector<std::size_t> idx(o.results.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    const auto &x = o.results[a].cost, &y = o.results[b].cost;
    if (x.feasible != y.feasible) return x.feasible;
    return x.J < y.J;
  });
  int rank = 0;
  for (std::size_t i : idx) {
    const auto& r = o.results[i];
    ++rank;
    t.rows.push_back({std::to_string(rank), r.stock ? r.layout + " (stock)" : r.layout, r.expression, fmt::format("{:.4f}", r.cost.J),
                      pct(r.cost.J, ref), r.cost.feasible ? "yes" : "no: " + r.cost.violation,
                      r.cost.binding.empty() ? "-" : r.cost.binding,
                      std::isnan(r.cost.binding_margin) ? "-" : fmt::format("{:.1f}", 100 * r.cost.binding_margin), values_text(r.values)});
    t.row_class.push_back(r.cost.feasible ? "" : "fail");
    rec.add(fmt::format("rank {}/{}/J", rank, r.expression), r.cost.J);
    if (!std::isnan(r.cost.binding_margin)) rec.add(fmt::format("rank {}/{}/binding_margin", rank, r.expression), r.cost.binding_margin);
  }
  doc.table(t);
  // the networks drawn: the default and the ranked designs (at most 12)
  doc.heading("The networks, drawn with their values");
  doc.figure(drawing(o.report ? o.report->baseline.net : o.baseline, "default suspension: " + network::to_string(o.baseline)),
             "The pantograph's own suspension (the default).");
  rank = 0;
  for (std::size_t i : idx) {
    if (++rank > 12) {
      doc.paragraph(fmt::format("… and {} more designs (structure.csv).", idx.size() - 12));
      break;
    }
    const auto& r = o.results[i];
    doc.figure(drawing(r.expression, r.values, fmt::format("rank {}: {}", rank, r.layout)),
               fmt::format("Rank {}: {} — J2 = {:.3f} N ({} % against the default); drawn as built: an element at 0 is open "
                           "and left out, one at ∞ is rigid.", rank, r.expression, r.cost.J, pct(r.cost.J, ref)));
  }
  if (!o.report) return;
  const optim::Report& r = *o.report;
  // σ(v) of the default and the best, per variant
  Plot p("σ(v): the default and the best design", "speed, km/h", "σ, N");
  int c = 0;
  auto curves = [&](const std::vector<optim::SpeedCurve>& cs, const std::string& who, bool dashed) {
    for (const auto& sc : cs) {
      PlotSeries ser(who + " " + sc.catenary, kColors[c++ % 6], dashed, false);
      for (std::size_t i = 0; i < sc.speed.size(); ++i) ser.x.push_back(3.6 * sc.speed[i]), ser.y.push_back(sc.sigma[i]);
      p.series.push_back(ser);
    }
  };
  curves(r.sigma_default, "default", true);
  c = 0;
  curves(r.sigma_best, "best", false);
  p.height = 340;
  doc.heading("Standard deviation over speed");
  doc.figure(svg_plot(p), "σ of the contact force of the default (dashed) and the best design (solid), one colour per line variant.");
  if (!r.margins.empty()) {
    doc.heading(fmt::format("Acceptance margins ({})", r.acceptance));
    Table m;
    m.id = "margins";
    m.header = {"design", "variant", "v km/h", "pantograph", "criterion", "value", "limit", "margin", "margin %", "status"};
    for (const auto& x : r.margins) {
      const auto& q = x.result;
      m.rows.push_back({x.design, x.catenary, fmt::format("{:.6g}", 3.6 * x.speed), std::to_string(x.contact + 1),
                        q.criterion + (q.assumed ? " [assumed]" : ""), fmt::format("{:.6g}", q.value), fmt::format("{:.6g}", q.limit),
                        fmt::format("{:.6g}", q.margin), std::isnan(x.relative) ? "-" : fmt::format("{:.1f}", 100 * x.relative),
                        !q.assessed ? "not assessed" : q.passed ? "PASS" : "FAIL"});
      m.row_class.push_back(!q.assessed ? "na" : q.passed ? "" : "fail");
      rec.add(fmt::format("margin/{}/{}/v={:.6g} km/h/panto {}/{}", x.design, x.catenary, 3.6 * x.speed, x.contact + 1, q.criterion), q.margin);
    }
    doc.table(m);
  }
}

void model_study(Document& doc, Record& rec, const optim::StudyOutcome& o) {
  const optim::ModelStudyResult& m = *o.model;
  const double ref = m.baseline_cost.J;
  const auto& best = m.results.at(m.best);
  doc.verdict("RECOMMENDATION", {fmt::format("Recommendation: {} ({}), J = {:.6g} against the default's {:.6g} ({} %).", best.layout,
                                             best.expression, best.cost.J, ref, pct(best.cost.J, ref))});
  rec.add("default/J", ref);
  doc.heading("Ranking");
  Table t;
  t.id = "ranking";
  t.header = {"design", "network", "J", "vs default, %", "values"};
  for (const auto& r : m.results) {
    t.rows.push_back({r.layout, r.expression, fmt::format("{:.6g}", r.cost.J), pct(r.cost.J, ref), values_text(r.values)});
    rec.add(fmt::format("{}/J", r.expression), r.cost.J);
  }
  doc.table(t);
  doc.heading("The networks, drawn with their values");
  int n = 0;
  for (const auto& r : m.results) {
    if (++n > 12) break;
    doc.figure(drawing(r.expression, r.values, r.layout), fmt::format("{}: J = {:.6g}", r.expression, r.cost.J));
  }
}

}  // namespace

std::string study_report(const Provenance& provenance, const optim::StudyOutcome& o, Record& rec) {
  rec.command = "optimise";
  rec.provenance = provenance;
  Document doc(o.study ? "Inerta study: " + o.study->name : "Inerta model study");
  if (o.study)
    j2_study(doc, rec, o);
  else if (o.model)
    model_study(doc, rec, o);
  doc.provenance(provenance);
  return doc.html(rec);
}

std::string write_study_report(const std::string& dir, const Provenance& provenance, const optim::StudyOutcome& outcome) {
  Record rec;
  const std::string html = study_report(provenance, outcome, rec);
  const std::string path = (std::filesystem::path(dir) / "report.html").string();
  io::write_text_file(path, html);
  return path;
}

}  // namespace inerta::report
