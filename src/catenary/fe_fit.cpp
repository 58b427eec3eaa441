// The lumped catenary of eq. 7.1 fitted to a finite-element line (catenary/fe_catenary.hpp).
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/error.hpp"

namespace inerta::catenary {

LumpedFit fit_lumped(const FeLine& line, int span, int points) {
  const FeCatenaryData& d = line.data();
  if (span == 0) span = (d.spans + 1) / 2;
  if (span < 1 || span > d.spans)
    throw InvalidArgument(fmt::format("lumped fit: span {} does not exist (the line has {} spans)", span, d.spans));
  if (points < 16) throw InvalidArgument(fmt::format("lumped fit: needs at least 16 points a span, got {}", points));
  // An overlap span carries two contact wires: a point model of one wire has no meaning there (issue 52).
  const std::vector<FeLinkedSection> sections = link_sections(d);
  for (std::size_t k = 1; k < sections.size(); ++k) {
    const int from = sections[k].first_span + 1, to = from + d.overlap_spans - 1;  // 1-based
    if (span >= from && span <= to)
      throw InvalidArgument(fmt::format("lumped fit: span {} is in the overlap of sections {} and {} (spans {} … {}: two "
                                        "contact wires); fit a span of one wire (--span)",
                                        span, k, k + 1, from, to));
  }
  LumpedFit fit;
  fit.span = span;
  const double L = d.span, x_start = (span - 1) * L;
  BandLlt llt(line.K());
  std::vector<double> k(static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i) {
    const double x = L * (i + 0.5) / points;  // midpoints: an exact quadrature of the cosines
    const Eigen::VectorXd f = line.load_vector(x_start + x, 1.0);
    const Eigen::VectorXd g = llt.solve(f);
    const double e = f.dot(g);
    fit.x.push_back(x);
    fit.elasticity.push_back(e);
    fit.mass.push_back(g.dot(line.M() * g) / (e * e));
    fit.damping.push_back(g.dot(line.C() * g) / (e * e));
    k[static_cast<std::size_t>(i)] = 1 / e;
  }
  auto cosines = [&](const std::vector<double>& y) {
    std::array<double, 4> c{};
    for (int h = 0; h < 4; ++h) {
      double s = 0;
      for (int i = 0; i < points; ++i)
        s += y[static_cast<std::size_t>(i)] * std::cos(2 * std::numbers::pi * h * fit.x[static_cast<std::size_t>(i)] / L);
      c[static_cast<std::size_t>(h)] = (h == 0 ? 1.0 : 2.0) * s / points;
    }
    return c;
  };
  fit.lumped.span = L;
  fit.lumped.k = cosines(k);
  fit.lumped.m = cosines(fit.mass);
  fit.lumped.c = cosines(fit.damping);
  for (int i = 0; i < points; ++i) {
    double kf = 0;
    for (int h = 0; h < 4; ++h)
      kf += fit.lumped.k[static_cast<std::size_t>(h)] *
            std::cos(2 * std::numbers::pi * h * fit.x[static_cast<std::size_t>(i)] / L);
    fit.fitted_elasticity.push_back(1 / kf);
    const double err = std::abs(1 / kf - fit.elasticity[static_cast<std::size_t>(i)]) /
                       fit.elasticity[static_cast<std::size_t>(i)];
    fit.max_elasticity_error = std::max(fit.max_elasticity_error, err);
    fit.rms_error += err * err / points;
  }
  // Moving average of the FE elasticity over one dropper spacing (periodic over the span).
  const std::size_t per_span = d.dropper_x.size() + (d.stitch.present ? d.stitch.dropper_x.size() : 0);
  const double spacing = L / static_cast<double>(per_span + 1);
  const int half = std::max(0, static_cast<int>(std::lround(0.5 * spacing / (L / points))));
  for (int i = 0; i < points; ++i) {
    double s = 0;
    for (int j = -half; j <= half; ++j) s += fit.elasticity[static_cast<std::size_t>((i + j + points) % points)];
    s /= 2 * half + 1;
    const double err = std::abs(fit.fitted_elasticity[static_cast<std::size_t>(i)] - s) / s;
    fit.max_smoothed_error = std::max(fit.max_smoothed_error, err);
    fit.rms_smoothed_error += err * err / points;
  }
  fit.rms_error = std::sqrt(fit.rms_error);
  fit.rms_smoothed_error = std::sqrt(fit.rms_smoothed_error);
  return fit;
}

}  // namespace inerta::catenary
