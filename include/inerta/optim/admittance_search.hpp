#pragma once
// The immittance route (docs/networks.md#the-admittance-bound): instead of a network, optimise the
// coefficients of a positive-real admittance Y(s) = num(s)/den(s) of a given degree (2:
// biquadratic, 3: bicubic) against a study's objective, positive-realness enforced exactly
// (network::positive_real, a certificate, not a frequency grid), then realise the optimum as a
// network (network::synthesise). Any passive network whose admittance has at most that degree —
// every network with at most that many springs and inerters, with any number of dampers — is one
// such Y, so the optimum bounds what such networks can reach.
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "inerta/network/positive_real.hpp"
#include "inerta/network/synthesis.hpp"
#include "inerta/numerics/pattern_search.hpp"
#include "inerta/optim/model_study.hpp"
#include "inerta/optim/study.hpp"

namespace inerta::optim {

struct AdmittanceResult {
  int degree = 0;
  network::Rational y;  ///< the optimum, SI (force per relative velocity)
  double J = std::numeric_limits<double>::infinity();     ///< its objective
  double cost = std::numeric_limits<double>::infinity();  ///< what the search minimised (limits as penalties)
  int evaluations = 0;
  network::PrTest pr;  ///< the certificate at the optimum
  std::optional<network::Synthesis> synthesis;  ///< the optimum realised as a network, if that succeeded
  std::string synthesis_error;                  ///< why not, else ""
  double J_realised = std::numeric_limits<double>::quiet_NaN();  ///< the objective of the realised network
  std::string warm_from;  ///< the network whose admittance was the search's warm start
};

/// The objective of a study for a network (penalised by the study's limits), +∞ where it cannot be
/// evaluated.
using NetworkCost = std::function<double(const network::Network&)>;

/// Minimises cost over positive-real Y of degree ≤ `degree` (1 … 4): the coefficients of num and den,
/// scaled by a frequency and a magnitude taken from `warm` (a bound network, or an Admittance leaf)
/// and searched in decades (0 reachable), with `warm`'s own admittance as a further start, so the
/// result is never worse than `warm` if its degree is ≤ `degree`. `objective(net)` gives J for the
/// report (= cost without limits).
AdmittanceResult optimise_admittance(int degree, const NetworkCost& cost, const NetworkCost& objective,
                                     const network::Network& warm, const numerics::Options& search,
                                     const numerics::Progress& progress = {});

/// The same with a study's objective (J2 by the periodic fast path; a model study's J).
AdmittanceResult admittance_bound(const Study& study, int degree, const network::Network& warm,
                                  const numerics::Progress& progress = {});
AdmittanceResult admittance_bound(const ModelStudy& study, int degree, const network::Network& warm,
                                  const numerics::Progress& progress = {});

/// A design of a study: a warm start of the admittance bounds, and the network each bound is compared with.
struct BoundCandidate {
  std::string label;
  network::Network net;  ///< bound
  double cost = 0, J = 0;  ///< what the search minimised; the objective
};
/// One degree's bound, with the best candidate of at most that many springs and inerters.
struct AdmittanceBound {
  AdmittanceResult result;
  std::optional<BoundCandidate> best;  ///< none if no candidate has so few springs and inerters
  double seconds = 0;                  ///< wall time of the bound's search
  bool feasible() const { return result.cost <= result.J * (1 + 1e-12); }  ///< cost = J unless a limit is exceeded
  double gap_pct() const;  ///< 100 (best.J − J)/J: how far the best network is above the bound; NaN without one
};
/// The bounds of `degrees`, lowest first: each starts from the best of the candidates and the lower
/// degrees' bounds with at most that many springs and inerters (a lower degree's bound is a start of
/// the next, so never worse), and is compared with the best candidate. done(bound) after each.
std::vector<AdmittanceBound> admittance_bounds(std::vector<int> degrees, const std::vector<BoundCandidate>& candidates,
                                               const std::function<AdmittanceResult(int, const network::Network&)>& bound,
                                               const std::function<void(const AdmittanceBound&)>& done = {});

/// Springs + inerters of the simplified network in canonical form (same-type neighbours merged): an
/// upper bound of the McMillan degree of its admittance, the degree of an Admittance leaf itself.
int reactive_elements(const network::Network& bound);

}  // namespace inerta::optim
