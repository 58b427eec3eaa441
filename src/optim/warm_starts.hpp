#pragma once
// Warm starts of a layout's pattern search from other designs' element values (internal).
#include <cmath>
#include <vector>

#include "inerta/network/network.hpp"
#include "inerta/numerics/pattern_search.hpp"

namespace inerta::optim {

/// Appends to `search.initial_values` one start per design in `warm`: its values for the names it
/// shares with `vars`, each other element open (0) or rigid (∞), every combination of those up to
/// four; designs that share no name are skipped.
inline void add_warm_starts(const std::vector<numerics::Variable>& vars, const std::vector<network::Params>& warm,
                            numerics::Options& search) {
  for (const network::Params& w : warm) {
    std::vector<std::size_t> missing;
    std::vector<double> v(vars.size());
    for (std::size_t i = 0; i < vars.size(); ++i) {
      const auto it = w.find(vars[i].name);
      if (it == w.end()) missing.push_back(i); else v[i] = it->second;
    }
    if (missing.size() == vars.size() || missing.size() > 4) continue;  // nothing shared, or too many combinations
    for (unsigned mask = 0; mask < (1u << missing.size()); ++mask) {
      for (std::size_t j = 0; j < missing.size(); ++j) v[missing[j]] = (mask >> j) & 1u ? INFINITY : 0.0;
      search.initial_values.push_back(v);
    }
  }
}

}  // namespace inerta::optim
