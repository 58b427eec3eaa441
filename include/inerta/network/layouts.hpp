#pragma once
// The thesis's candidate layouts (spec/03 §3.2), by name, with their fixed values.
#include <optional>
#include <string>
#include <vector>

#include "inerta/network/network.hpp"

namespace inerta::network {

struct Layout {
  std::string name;        ///< "S2-default"
  std::string expression;  ///< "k-c"
  Params fixed;            ///< values that the layout fixes (e.g. c = 10.44 kN·s/m for S2-1*)
  std::string note;
};

const std::vector<Layout>& layouts();
/// The named layout, or nullopt.
std::optional<Layout> find_layout(const std::string& name);

/// A layout name or an expression, with parameters: the layout's fixed values, then `params`
/// (a fixed value cannot be overridden: NetworkError). Returns the bound, unsimplified network.
Network resolve(const std::string& layout_or_expression, const Params& params);

}  // namespace inerta::network
