#pragma once
// Line plots as inline SVG for reports (no plotting package): curves, shaded bands between two
// curves, vertical marks (masts, droppers, stitch wires) and shaded x ranges (overlaps).
#include <string>
#include <utility>
#include <vector>

namespace inerta::report {

struct PlotSeries {
  explicit PlotSeries(std::string name_ = {}, std::string color_ = "#1f5fa8", bool dashed_ = false, bool points_ = false)
      : name(std::move(name_)), color(std::move(color_)), dashed(dashed_), points(points_) {}
  std::string name;
  std::vector<double> x, y;  ///< NaN y: a gap
  std::string color = "#1f5fa8";
  bool dashed = false;
  bool points = false;  ///< a dot at each point (a sweep's speeds)
};
struct PlotBand {  ///< shaded between lower(x) and upper(x)
  std::string name;
  std::vector<double> x, lower, upper;
  std::string color = "#3a9a4a";
};
struct PlotMark {  ///< a vertical line at x; `kind` picks its style: mast, dropper, stitch_dropper
  double x = 0;
  std::string kind;
};
struct PlotRange {  ///< a shaded x range with a label: stitch wire, overlap
  double from = 0, to = 0;
  std::string kind, label;
};
struct Plot {
  explicit Plot(std::string title_ = {}, std::string xlabel_ = {}, std::string ylabel_ = {})
      : title(std::move(title_)), xlabel(std::move(xlabel_)), ylabel(std::move(ylabel_)) {}
  std::string title, xlabel, ylabel;
  std::vector<PlotSeries> series;
  std::vector<PlotBand> bands;
  std::vector<PlotMark> marks;
  std::vector<PlotRange> ranges;
  int width = 820, height = 300;
};

/// The plot as an <svg> element (no XML prolog: to be inlined in HTML). Axes span the data (bands and
/// series) with rounded ticks; an empty plot says "no data".
std::string svg_plot(const Plot& plot);

/// Rounded tick positions covering [lo, hi] (about `n` of them).
std::vector<double> nice_ticks(double lo, double hi, int n = 6);

}  // namespace inerta::report
