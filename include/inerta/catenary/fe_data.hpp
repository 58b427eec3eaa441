#pragma once
// What a finite-element line is made from: the data of a catenary file (docs/model-format.md), its
// tension sections and overlaps; checked by validate() (src/catenary/fe_data.cpp).
#include <cmath>
#include <string>
#include <vector>

#include "inerta/catenary/fe_irregularity.hpp"
#include "inerta/catenary/fe_stitch.hpp"
#include "inerta/catenary/fe_wear.hpp"
#include "inerta/catenary/fe_wire.hpp"

namespace inerta::catenary {

/// Everything a catenary file gives (docs/model-format.md#finite-element-catenary).
struct FeCatenaryData {
  double span = 55;          ///< m, distance between masts
  int spans = 10;            ///< number of spans; masts at x = 0, span, …, spans·span
  double encumbrance = 1.2;  ///< m, messenger height above the contact wire at the masts
  std::vector<double> dropper_x;  ///< m from the span's first mast, strictly inside (0, span), increasing
  std::vector<double> presag;     ///< m, contact-wire pre-sag at each dropper (positive down)
  std::vector<double> nominal_dropper_length;  ///< m, optional (for comparison with the form-finding)
  FeWire messenger, contact_wire;
  double dropper_EA = 200e3;                 ///< N
  double dropper_mass_per_length = 0.117;    ///< kg/m
  double clamp_mass_messenger = 0.195;       ///< kg, at each dropper's messenger end
  double clamp_mass_contact = 0.165;         ///< kg, at each dropper's contact-wire end
  double support_stiffness = 500e3;          ///< N/m, messenger support at each mast
  double support_mass = 0;                   ///< kg, at each messenger support
  double registration_stiffness = 2673.58;   ///< N/m, contact-wire registration (steady arm) at each mast
  double registration_mass = 0;              ///< kg, at each registration
  /// m, the design limit of the contact wire's uplift at a registration (steady arm); NaN: not given
  /// (the acceptance criterion support_uplift is then not assessed). Not part of the dynamics.
  double registration_uplift_limit = NAN;
  /// A stop limits the registration's uplift physically (registration.uplift_limited: true): the acceptance
  /// criterion support_uplift takes its limited_clearance_factor (1.5 S₀) in place of 2 S₀. Not part of the dynamics.
  bool registration_uplift_limited = false;
  double element_length = 0.25;              ///< m, largest element; nodes at every dropper and mast
  double rayleigh_mass = 0.0125;             ///< a, 1/s
  double rayleigh_stiffness = 1e-4;          ///< b, s
  double gravity = 9.81;                     ///< m/s²
  double time_step = 1e-3;                   ///< s, structural (and coupling) step
  double hht_alpha = 0.0;                    ///< α of HHT-α, in [−1/3, 0]
  /// Structural solver of a run: the modal solve of a window of spans around the pantographs
  /// (fe_modal.hpp; `solver: modal` in models/catenary-fe.yaml) or the direct solve of the whole
  /// line (the reference; the default of a file without `solver`, so that older files keep their results).
  enum class Solver { Modal, Direct } solver = Solver::Direct;
  double modal_cutoff = 100; ///< Hz, highest natural frequency kept (droppers taut)
  int window_behind = 2;     ///< spans of the window behind the rearmost pantograph's span; −1: the whole line
  int window_ahead = 3;      ///< spans ahead of the leading pantograph's span; −1: the whole line
  int section_first = -1, section_last = -1;  ///< analysis section: spans first..last (1-based); −1: default
  FeStitch stitch;            ///< none unless stitch.present
  FeIrregularity irregularity;
  FeWear wear;               ///< contact-wire wear (none: 100 %)
  bool has_stitch() const { return stitch.present && stitch.enabled; }

  // A tension section of a longer line (docs/catenary-fe.md "Tension sections and overlaps").
  /// m: the contact wire's height at each mast (spans + 1 values, the end masts its anchors; empty:
  /// 0 at every mast). The messenger is `encumbrance` above it at every mast, the droppers' targets
  /// are the heights interpolated linearly between the masts, less the pre-sag.
  std::vector<double> mast_height;
  /// m: the contact wire's height profile, piecewise linear through the points (height_x from the
  /// section's first mast, strictly increasing from 0 to its length; height_z up): the droppers'
  /// targets between masts, e.g. an overlap's middle span with both wires at the running height over
  /// part of it. Empty: mast_height, linear between the masts. A linked section's are set from the
  /// overlaps (link_sections); a file's sections do not give them.
  std::vector<double> height_x, height_z;
  /// The height at x (m from the section's first mast): height_x/z, else mast_height, else 0.
  double height_at(double x) const;
  /// The anchors at the section's two ends: pinned (w = 0), or a tensioning device's vertical
  /// stiffness (N/m) and mass (kg) on both wires' ends.
  struct Anchor {
    bool pinned = true;
    double stiffness = 0, mass = 0;
  } anchor;
  /// The line's tension sections as written, each a whole section (the line's keys with its own over
  /// them); link_sections places them along the line. Consecutive ones
  /// overlap over `overlap_spans` spans (they share overlap_spans + 1 masts). Empty: the line is one
  /// section, pinned at height 0 at both ends (every file before issue 35).
  std::vector<FeCatenaryData> tension_sections;
  int overlap_spans = 0;
  /// m: the contact wire's heights over an overlap, in line order: the section that ends there
  /// (outgoing; its last value is at its anchor) and the one that starts (incoming; its first value
  /// at its anchor). Without overlap_*_x, one height per overlap support (overlap_spans + 1 values);
  /// with them, a piecewise-linear profile through (x, height), x in m from the overlap's first
  /// support, strictly increasing from 0 to overlap_spans spans.
  std::vector<double> overlap_outgoing, overlap_incoming;
  std::vector<double> overlap_outgoing_x, overlap_incoming_x;
  bool sectioned() const { return !tension_sections.empty(); }
  /// The whole line's spans (the sections' less the overlaps), for a sectioned line.
  int line_spans() const;
  /// A line of tension sections: checks that its sections form a line (link_sections) and sets the
  /// whole line's `spans` (line_spans) and `span` (the first section's) from them; FeKeyError naming
  /// the key (tension_sections[k].…, overlap.…) when they cannot. The sections themselves are left as
  /// written. Nothing for a single-section line.
  void join_sections();
  /// InvalidArgument naming the offending value.
  void validate() const;
};

/// A tension section placed along its line (the sections pass, src/catenary/fe_sections.cpp): its
/// data with its heights set from the overlaps (a line of its own for FeLine), where it starts and which
/// contact wire it is.
struct FeLinkedSection {
  FeCatenaryData line;     ///< the section as a line: its keys, its mast_height and height profile
  double line_start = 0;   ///< m: x of its first mast along the whole line
  int first_span = 0;      ///< its first span among the line's (0-based)
  int wire_label = 1;      ///< which contact wire it is along the line: 1 (odd sections) or 2 (even)
};
/// The sections of a line of tension sections placed along it (empty for a single-section line);
/// FeKeyError (tension_sections[k].…, overlap.…) when they cannot form a line. `line` is unchanged.
std::vector<FeLinkedSection> link_sections(const FeCatenaryData& line);

}  // namespace inerta::catenary
