#pragma once
// The default line of models/catenary-fe.yaml (issue 12 item 7) as data, `spans` spans: the
// finite-element tests build their lines from it.
#include "inerta/catenary/fe_catenary.hpp"

namespace inerta::testing {

inline catenary::FeCatenaryData fe_benchmark_line(int spans = 10) {
  catenary::FeCatenaryData d;
  d.span = 55;
  d.spans = spans;
  d.encumbrance = 1.2;
  d.dropper_x = {4.5, 10.25, 16.0, 21.75, 27.5, 33.25, 39.0, 44.75, 50.5};
  d.presag = {0, 0.024, 0.041, 0.052, 0.055, 0.052, 0.041, 0.024, 0};
  d.nominal_dropper_length = {1.017, 0.896, 0.810, 0.758, 0.741, 0.758, 0.810, 0.896, 1.017};
  d.messenger = {16e3, 1.08, 131.7};
  d.contact_wire = {22e3, 1.35, 195};
  return d;
}

}  // namespace inerta::testing
