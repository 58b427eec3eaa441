#include "inerta/analysis/catenary_response.hpp"
#include "inerta/analysis/frf.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "inerta/catenary/lumped.hpp"
#include "inerta/mbs/applied_forces.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/solve/integrator.hpp"

namespace inerta::analysis {

std::vector<CatenaryResponse> catenary_response(const catenary::LumpedCatenary& cat, double force,
                                                const std::vector<double>& fp, double settle, int periods) {
  require(force_rule, force, "force");
  require(settle_rule, settle, "settle");
  require(periods_rule, periods, "periods");
  for (double f : fp) require(frequency_rule, f, "fp");
  std::vector<CatenaryResponse> out(fp.size());
  tbb::parallel_for(std::size_t{0}, fp.size(), [&](std::size_t k) {
    CatenaryResponse& r = out[k];
    r.fp = fp[k];
    r.speed = fp[k] * cat.span;
    mbs::Model m;
    m.name = "catenary";
    m.options.gravity = false;
    const int b = catenary::add_catenary(m, cat, r.speed, 0.0, 0.0);
    m.forces.push_back(std::make_shared<mbs::PointForce>("F", b, mbs::Vec2::Zero(), mbs::Vec2(0, 1),
                                                         mbs::TimeFunction::constant(force)));
    m.finalize();
    mbs::State x = mbs::assemble(m, 0.0);
    mbs::static_equilibrium(m, 0.0, x);
    const double T = 1.0 / fp[k], t0 = std::ceil(settle / T) * T;
    solve::IntegratorOptions opt;
    opt.rtol = 1e-8;
    opt.atol = 1e-11;
    double amin = INFINITY, amax = -INFINITY, ymin = INFINITY, ymax = -INFINITY, ysum = 0;
    double half[2][2] = {{INFINITY, -INFINITY}, {INFINITY, -INFINITY}};  // y range per half
    long n = 0;
    solve::integrate(
        m, x, 0.0, t0 + periods * T, T / 200, opt,
        [&](double t, const mbs::State& s, const mbs::Workspace& ws) {
          if (t < t0 - 1e-9) return;
          const double a = ws.qdd[3 * b + 1], y = s.q[3 * b + 1];
          amin = std::min(amin, a), amax = std::max(amax, a), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
          ysum += y, ++n;
          const int h = t < t0 + 0.5 * periods * T ? 0 : 1;
          half[h][0] = std::min(half[h][0], y), half[h][1] = std::max(half[h][1], y);
        },
        true);
    r.acc_amplitude = 0.5 * (amax - amin);
    r.disp_amplitude = 0.5 * (ymax - ymin);
    r.mean_uplift = ysum / static_cast<double>(n);
    const double first = half[0][1] - half[0][0], second = half[1][1] - half[1][0];
    r.growth = first > 0 ? second / first : 1.0;
  });
  return out;
}

}  // namespace inerta::analysis
