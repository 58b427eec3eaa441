#pragma once
// The finite-element catenary as a catenary type; its parts by concept: fe_wire.hpp, fe_stitch.hpp,
// fe_irregularity.hpp, fe_data.hpp (what a file gives), fe_line.hpp (the compiled line), fe_solver.hpp,
// fe_fit.hpp, fe_cost.hpp.
#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "inerta/catenary/catenary.hpp"
#include "inerta/catenary/fe_cost.hpp"
#include "inerta/catenary/fe_data.hpp"
#include "inerta/catenary/fe_fit.hpp"
#include "inerta/catenary/fe_irregularity.hpp"
#include "inerta/catenary/fe_line.hpp"
#include "inerta/catenary/fe_solver.hpp"
#include "inerta/catenary/fe_stitch.hpp"
#include "inerta/catenary/fe_wire.hpp"

namespace inerta::catenary {

/// One tension section as a run sees it: its line (x local, from its first mast), its modes (null:
/// the direct solve), where it lies along the whole line and which contact wire it is.
struct FeSectionLine {
  std::shared_ptr<const FeLine> line;
  std::shared_ptr<const class FeModalLine> modal;
  double start = 0, end = 0;  ///< m along the whole line: its first and last mast (its anchors)
  int wire = 1;               ///< 1 or 2 (FeLinkedSection::wire_label)
};

/// The finite-element catenary as a catenary type (co-simulated: the line is stepped by
/// FeIntegrator, each pantograph's multibody model by the multibody integrator; see fe_coupled).
/// The line (mesh, form-finding, factorisation) is built when first needed, not by the constructor,
/// so that a run's cost can be estimated — and refused — before any of that work (the cost guard).
class FeCatenary final : public Catenary {
 public:
  /// Checks the data (FeCatenaryData::validate); builds nothing.
  explicit FeCatenary(FeCatenaryData data);
  const FeCatenaryData& data() const { return data_; }
  const FeLine& line() const;  ///< built on first use (thread-safe)
  std::string describe() const override;
  double span() const override { return data_.span; }
  int max_pantographs() const override { return 64; }
  double line_length() const override;
  /// The overlaps of a line of tension sections: from the incoming section's anchor to the outgoing one's.
  std::vector<Section> overlaps() const;
  double wave_speed() const override { return data_.contact_wire.wave_speed(); }
  std::vector<LineFeature> features() const override;
  Section section() const override;
  double uplift_limit() const override { return data_.registration_uplift_limit; }  // the file's: no build needed
  bool uplift_limited() const override { return data_.registration_uplift_limited; }
  std::shared_ptr<const Catenary> mean() const override;
  /// The modes of the line's windows (computed when first needed, kept for every later run: a sweep
  /// or a study decomposes a window once); nullptr with solver: direct.
  std::shared_ptr<const class FeModalLine> modal() const;
  /// The line's tension sections (one for a file without tension_sections: line() and modal()).
  const std::vector<FeSectionLine>& sections() const;
  void prepare(const std::vector<PantographOnLine>& pantographs) const override;
  double estimated_seconds(const std::vector<PantographOnLine>& pantographs, double speed, double t_end) const override;
  double estimated_setup_seconds(const std::vector<PantographOnLine>& pantographs) const override;
  double estimated_bytes(const std::vector<PantographOnLine>& pantographs, double speed, double t_end) const override;

 protected:
  std::unique_ptr<Coupled> make_coupled(const std::vector<PantographOnLine>& pantographs, double speed) const override;
  /// Lanes stepped together: one solver group per section (fe_modal.hpp make_modal_lanes).
  std::unique_ptr<CoupledLanes> make_lanes(const std::vector<std::vector<PantographOnLine>>& trains,
                                           double speed) const override;

 private:
  void build() const;
  FeCostEstimate estimate(const std::vector<PantographOnLine>& pantographs, double speed, double t_end) const;
  FeCatenaryData data_;
  mutable std::once_flag built_;
  mutable std::atomic<bool> line_ready_{false};
  mutable std::shared_ptr<const FeLine> line_;
  mutable std::shared_ptr<const class FeModalLine> modal_;
  mutable std::vector<FeSectionLine> sections_;
};

}  // namespace inerta::catenary
