#pragma once
// The stitch wire of a finite-element line (docs/catenary-fe.md "Stitch wire").
#include <vector>

#include "inerta/catenary/fe_wire.hpp"

namespace inerta::catenary {

/// A stitch wire at a mast (docs/catenary-fe.md "Stitch wire"): a short tensioned wire of `length`
/// centred on the mast, its ends clamped to the messenger (the same vertical displacement, slopes
/// free), not supported at the mast, from which the droppers near the mast hang (`dropper_x`: signed
/// positions from the mast, negative in the span before it). Every interior mast carries one; the
/// line's two end masts (anchors) carry none, and the stitch droppers on the line's side of an end
/// mast hang from the messenger there. `enabled = false`: the same line without the stitch wire,
/// every stitch dropper hanging from the messenger at its position.
struct FeStitch {
  bool present = false;          ///< the file has a `stitch:` section
  bool enabled = true;
  double length = 0;             ///< m, between its two clamps on the messenger
  FeWire wire;                   ///< tension (N), mass per length (kg/m), EI (N·m²)
  double clamp_mass = 0;         ///< kg, at each of its two clamps on the messenger
  std::vector<double> dropper_x;       ///< m from the mast, signed, |x| < length / 2
  std::vector<double> dropper_presag;  ///< m, contact-wire pre-sag at each (positive down); empty: 0
  double dropper_EA = 200e3;               ///< N
  double dropper_mass_per_length = 0;      ///< kg/m
  double clamp_mass_stitch = 0;            ///< kg, at each stitch dropper's upper end
  double clamp_mass_contact = 0;           ///< kg, at each stitch dropper's contact-wire end
};

}  // namespace inerta::catenary
