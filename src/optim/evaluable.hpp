#pragma once
// A design a study can evaluate accurately (internal): the realisation of a network (F = d2 l̈ +
// d1 l̇ + d0 u + C x, network/realisation.hpp) splits off direct terms by polynomial division; a
// corner frequency far above the dynamics (a damper of 5e8 N·s/m in series with a 1.6 kg inerter:
// a pole at 3e8 rad/s) makes those terms huge and cancelling (d0 = −c²/b), and the periodic path
// and the linearisation then return numbers dominated by rounding (study 2 measured J2 = 6.4 N for
// c = 4.9e8 N·s/m where the limit c → ∞ is 9.38 N). Such a design is refused as NumericalError
// ("no design" for the search), which then reaches the element's rigid or open limit instead.
#include <fmt/format.h>

#include <Eigen/Eigenvalues>

#include "inerta/error.hpp"
#include "inerta/network/realisation.hpp"

namespace inerta::optim {

/// Fastest internal pole a design's network may have, rad/s (c = 1e6 N·s/m in series with 1.6 kg:
/// 6e5 rad/s still changes J2 of study 2 by 2e-6 relative only; 6e6 rad/s by 2e-4).
constexpr double max_network_pole = 1e6;

inline void require_evaluable(const network::Network& bound) {
  const network::Network s = network::simplify(bound);
  if (s.kind == network::Network::Kind::Open || s.kind == network::Network::Kind::Rigid) return;
  const network::Realisation r = network::realise(s);
  if (r.n_states() == 0) return;
  const Eigen::VectorXcd ev = r.A.eigenvalues();
  for (Eigen::Index i = 0; i < ev.size(); ++i)
    if (!(std::abs(ev(i)) <= max_network_pole))
      throw NumericalError(fmt::format("network {} has a pole at {:.3g} rad/s, beyond {:g} rad/s: its realisation is too "
                                       "ill-conditioned to evaluate (an element is effectively rigid or open)",
                                       network::to_string(s, true), std::abs(ev(i)), max_network_pole));
}

}  // namespace inerta::optim
