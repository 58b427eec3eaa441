#pragma once
// Every series–parallel network of springs, dampers and inerters up to N elements, each once
// (docs/networks.md). A network is counted in its canonical form: nested series (parallel) groups
// flattened, same-type elements directly in series or in parallel merged into one (two springs in
// parallel are one spring), the members of a group in a fixed order (so reorderings coincide).
// Networks that differ in form but share an admittance family (k1-(k2|c) and k1|(k2-c)) are
// different networks here: the enumeration is structural, not by admittance.
#include <string>
#include <vector>

#include "inerta/network/network.hpp"

namespace inerta::network {

struct ElementCounts {
  int elements = 0, springs = 0, dampers = 0, inerters = 0;
};
/// Elements of each type in the network (after simplify if it has 0/∞ values).
ElementCounts count_elements(const Network& net);

/// True if springs alone connect the terminals (the network carries a static load): a spring does,
/// a series group if all its members do, a parallel group if one of them does.
bool static_path(const Network& net);

/// The canonical form of a network without 0/∞ values (simplify first): groups flattened, same-type
/// elements directly in one group merged (values combined: parallel springs, dampers and inerters
/// add, series ones add reciprocally), members ordered by structure(). Keeps the first merged
/// member's name.
Network canonical(const Network& net);

/// The canonical structure as an expression of bare type letters, e.g. "k-(c|b)": two networks have
/// the same structure() exactly when they are the same network up to merging and reordering.
std::string structure(const Network& net);

/// The network with its elements renamed by type in order of appearance: "k" if it has one spring,
/// else "k1", "k2", …; the same for c and b. Values are kept.
Network renamed(const Network& net);

enum class StaticLoad { Any, Required, Excluded };

struct EnumerationOptions {
  int max_elements = 4;  ///< 1 … max_enumerated_elements
  bool springs = true, dampers = true, inerters = true;  ///< which element types may appear
  int max_springs = -1, max_dampers = -1, max_inerters = -1;  ///< -1: no limit
  StaticLoad static_load = StaticLoad::Any;  ///< Required: a spring path between the terminals
};
/// The largest max_elements accepted (at most 7 elements: 14 453 networks of all three types).
constexpr int max_enumerated_elements = 7;

/// The networks allowed by the options, as expressions in canonical form with renamed() element
/// names, by number of elements, then by structure. Throws NetworkError for options out of range.
std::vector<std::string> enumerate(const EnumerationOptions& options);

}  // namespace inerta::network
