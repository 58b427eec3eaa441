#pragma once
// A network drawn as a mechanical schematic (issue 53): springs, dampers and inerters between two
// terminals, series left to right, parallel branches stacked between two bars, each element with
// its name, value and unit. SVG text, from the network itself (no plotting package).
#include <string>

#include "inerta/network/network.hpp"

namespace inerta::network {

struct SchematicOptions {
  bool values = true;  ///< "k1 = 528 kN/m" under each element (its name only while its value is 0: not assigned)
  std::string title;   ///< drawn above the schematic and as the SVG <title> (default: the expression)
};

/// A standalone SVG document of `net` (terminals left and right). Open branches are drawn as a gap
/// marked "open", rigid ones as a line, an Admittance leaf as a box "Y(s)".
std::string schematic_svg(const Network& net, const SchematicOptions& options = {});

}  // namespace inerta::network
