#pragma once
// Modes about a static equilibrium as a library call (`inerta modes`, spec/02 §2.5, spec/06 §6.3):
// of any model, of a pantograph under the mean of a catenary, or of a pantograph whose head is
// released from the rig and loaded by its static contact force.
#include <string>
#include <vector>

#include "inerta/catenary/catenary.hpp"
#include "inerta/mbs/linearisation.hpp"

namespace inerta::analysis {

struct ModalAnalysis {
  std::string setting;           ///< what the modes are of, in words ("" for a plain model)
  mbs::Model model;              ///< the model that was linearised
  mbs::State equilibrium;        ///< its static equilibrium
  mbs::LinearModel linear;
  std::vector<mbs::Mode> modes;  ///< sorted by frequency
};

/// The model about its static equilibrium at t = 0.
ModalAnalysis modal_analysis(const mbs::Model& model);

/// The pantograph coupled to the catenary's mean (Catenary::mean: the time-invariant part).
ModalAnalysis modal_analysis(const pantograph::Pantograph& p, const catenary::Catenary& catenary,
                             const catenary::Contact& contact);

/// The free pantograph: its head released from the rig joint and loaded by the static contact
/// force instead (pantograph::release_head). ModelError without a rig joint.
ModalAnalysis modal_analysis_free_head(const pantograph::Pantograph& p);

}  // namespace inerta::analysis
