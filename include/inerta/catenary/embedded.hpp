#pragma once
// A coupled system in which each pantograph's multibody model holds everything it interacts with:
// an embedded catenary's bodies and forces (lumped.hpp) or a rigid wire profile (wire_profile.hpp).
// The parts share no coordinates, so each is integrated on its own over every `advance`.
#include <vector>

#include "inerta/catenary/catenary.hpp"
#include "inerta/mbs/output.hpp"

namespace inerta::catenary {

class EmbeddedCoupled final : public Coupled {
 public:
  struct Part {
    mbs::Model model;         ///< the pantograph with what the catenary adds (finalized)
    mbs::Output force;        ///< contact-force channel of the model (compression positive)
    bool bilateral = false;   ///< the force must stay >= 0
    double x0 = 0;            ///< position of the contact point along the line at t = 0, m
  };
  /// The parts start assembled at t = 0 (call equilibrate for the static equilibrium).
  EmbeddedCoupled(std::vector<Part> parts, double speed, double span);

  int n_contacts() const override { return static_cast<int>(parts_.size()); }
  double speed() const override { return speed_; }
  double span() const override { return span_; }
  const mbs::Model& model(ContactId c) const override { return part(c).model; }
  const mbs::State& state(ContactId c) const override;
  double time() const override { return t_; }
  void equilibrate() override;
  solve::RunStats advance(double t_end, double dt, const solve::IntegratorOptions& options,
                          const SampleObserver& observer, bool accelerations = false) override;

 private:
  const Part& part(ContactId c) const;
  std::vector<Part> parts_;
  std::vector<mbs::State> x_;
  double speed_, span_, t_ = 0;
  bool sampled_start_ = false;  ///< the sample at time() was already delivered
};

}  // namespace inerta::catenary
