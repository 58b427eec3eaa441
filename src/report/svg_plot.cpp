// SVG line plots (report/svg_plot.hpp).
#include "inerta/report/svg_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "inerta/report/html.hpp"

namespace inerta::report {

std::vector<double> nice_ticks(double lo, double hi, int n) {
  if (!(hi > lo)) return {lo};
  const double raw = (hi - lo) / std::max(n - 1, 1);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  std::vector<double> t;
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step) t.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  return t;
}

namespace {
struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  bool empty() const { return !(hi >= lo); }
};

std::string tick_text(double v) { return fmt::format("{:g}", v); }
}  // namespace

std::string svg_plot(const Plot& p) {
  const double W = p.width, H = p.height, left = 64, right = 16, top = p.title.empty() ? 14 : 30, bottom = 44;
  Range xr, yr;
  for (const auto& s : p.series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (std::isfinite(s.y[i])) xr.add(s.x[i]), yr.add(s.y[i]);
  for (const auto& b : p.bands)
    for (std::size_t i = 0; i < b.x.size(); ++i) xr.add(b.x[i]), yr.add(b.lower[i]), yr.add(b.upper[i]);
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\" font-size=\"11\">\n",
      p.width, p.height);
  if (!p.title.empty())
    svg += fmt::format("<text x=\"{}\" y=\"18\" font-size=\"13\" font-weight=\"bold\">{}</text>\n", left, escape(p.title));
  if (xr.empty() || yr.empty()) {
    svg += fmt::format("<text x=\"{}\" y=\"{}\">no data</text>\n</svg>\n", W / 2 - 20, H / 2);
    return svg;
  }
  if (xr.hi == xr.lo) xr.lo -= 1, xr.hi += 1;
  const double pad = yr.hi > yr.lo ? 0.06 * (yr.hi - yr.lo) : std::max(1.0, 0.1 * std::abs(yr.hi));
  yr.lo -= pad, yr.hi += pad;
  const auto xt = nice_ticks(xr.lo, xr.hi), yt = nice_ticks(yr.lo, yr.hi);
  const double pw = W - left - right, ph = H - top - bottom;
  auto X = [&](double x) { return left + (x - xr.lo) / (xr.hi - xr.lo) * pw; };
  auto Y = [&](double y) { return top + (yr.hi - y) / (yr.hi - yr.lo) * ph; };
  svg += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"#fff\" stroke=\"#888\"/>\n", left,
                     top, pw, ph);
  // x ranges (overlaps, stitch wires) under everything
  for (const auto& r : p.ranges) {
    const double a = std::clamp(X(r.from), left, left + pw), b = std::clamp(X(r.to), left, left + pw);
    if (b <= a) continue;
    const bool overlap = r.kind == "overlap";
    svg += fmt::format("<rect class=\"range {}\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"{}\" "
                       "opacity=\"{}\"><title>{}</title></rect>\n",
                       escape(r.kind), a, overlap ? top : top + ph - 8, b - a, overlap ? ph : 8.0,
                       overlap ? "#f2c14e" : "#9b59b6", overlap ? 0.25 : 0.6, escape(r.label));
  }
  for (const auto& m : p.marks) {
    const double x = X(m.x);
    if (x < left - 0.5 || x > left + pw + 0.5) continue;
    const bool mast = m.kind == "mast";
    svg += fmt::format("<line class=\"mark {}\" x1=\"{:.1f}\" x2=\"{:.1f}\" y1=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" "
                       "stroke-width=\"{}\"{}/>\n",
                       escape(m.kind), x, x, mast ? top : top + ph - 5, top + ph, mast ? "#555" : m.kind == "stitch_dropper" ? "#9b59b6" : "#999",
                       mast ? 1.0 : 0.8, mast ? " stroke-dasharray=\"3 3\"" : "");
  }
  for (double t : xt) {
    const double x = X(t);
    svg += fmt::format("<line x1=\"{0:.1f}\" x2=\"{0:.1f}\" y1=\"{1:.1f}\" y2=\"{2:.1f}\" stroke=\"#888\"/>"
                       "<text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\">{4}</text>\n",
                       x, top + ph, top + ph + 4, top + ph + 16, tick_text(t));
  }
  for (double t : yt) {
    const double y = Y(t);
    svg += fmt::format("<line x1=\"{0:.1f}\" x2=\"{1:.1f}\" y1=\"{2:.1f}\" y2=\"{2:.1f}\" stroke=\"#eee\"/>"
                       "<text x=\"{3:.1f}\" y=\"{4:.1f}\" text-anchor=\"end\">{5}</text>\n",
                       left, left + pw, y, left - 6, y + 4, tick_text(t));
  }
  svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n", left + pw / 2, H - 8, escape(p.xlabel));
  svg += fmt::format("<text transform=\"translate(14 {:.1f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n", top + ph / 2,
                     escape(p.ylabel));
  for (const auto& b : p.bands) {
    std::string pts;
    for (std::size_t i = 0; i < b.x.size(); ++i) pts += fmt::format("{:.1f},{:.1f} ", X(b.x[i]), Y(b.upper[i]));
    for (std::size_t i = b.x.size(); i-- > 0;) pts += fmt::format("{:.1f},{:.1f} ", X(b.x[i]), Y(b.lower[i]));
    svg += fmt::format("<polygon class=\"band\" points=\"{}\" fill=\"{}\" opacity=\"0.18\" stroke=\"{}\"><title>{}</title></polygon>\n",
                       pts, b.color, b.color, escape(b.name));
  }
  // curves, split at NaN; the legend on a white box over the top right corner
  int legend = 0;
  const std::size_t entries = p.series.size() + p.bands.size();
  std::string legend_box = entries == 0 ? std::string()
                                        : fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"172\" height=\"{:.1f}\" fill=\"#fff\" "
                                                      "opacity=\"0.85\" stroke=\"#ccc\"/>\n",
                                                      left + pw - 176, top + 3, 14.0 * static_cast<double>(entries) + 6);
  std::string legend_items;
  for (const auto& s : p.series) {
    std::string path;
    bool pen = false;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.y[i])) {
        pen = false;
        continue;
      }
      path += fmt::format("{}{:.1f},{:.1f} ", pen ? "L" : "M", X(s.x[i]), Y(std::clamp(s.y[i], yr.lo, yr.hi)));
      pen = true;
    }
    svg += fmt::format("<path class=\"series\" data-name=\"{}\" d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.4\"{}/>\n",
                       escape(s.name), path, s.color, s.dashed ? " stroke-dasharray=\"6 4\"" : "");
    if (s.points)
      for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
        if (std::isfinite(s.y[i]))
          svg += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" fill=\"{}\"><title>{}: {:g}, {:.4g}</title></circle>\n",
                             X(s.x[i]), Y(s.y[i]), s.color, escape(s.name), s.x[i], s.y[i]);
    const double ly = top + 12 + 14 * legend++;
    legend_items += fmt::format("<line x1=\"{0:.1f}\" x2=\"{1:.1f}\" y1=\"{2:.1f}\" y2=\"{2:.1f}\" stroke=\"{3}\" stroke-width=\"2\"{4}/>"
                       "<text x=\"{5:.1f}\" y=\"{6:.1f}\">{7}</text>\n",
                       left + pw - 170, left + pw - 150, ly, s.color, s.dashed ? " stroke-dasharray=\"6 4\"" : "", left + pw - 146,
                       ly + 4, escape(s.name));
  }
  for (const auto& b : p.bands) {
    const double ly = top + 12 + 14 * legend++;
    legend_items += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"20\" height=\"8\" fill=\"{}\" opacity=\"0.3\"/>"
                       "<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n",
                       left + pw - 170, ly - 4, b.color, left + pw - 146, ly + 4, escape(b.name));
  }
  svg += legend_box + legend_items + "</svg>\n";
  return svg;
}

}  // namespace inerta::report
