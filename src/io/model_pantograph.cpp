// Model files: the `pantograph:` section (docs/model-format.md#pantograph).
#include <fmt/format.h>

#include "model_loader.hpp"

namespace inerta::io::detail {

std::pair<int, int> Loader::pantograph(const YAML::Node& p) {
  int contact = -1, rig_joint = -1;
  if (!p.IsDefined()) return {contact, rig_joint};
  if (model.spatial()) rd.fail(p, "pantograph", "the pantograph-catenary analyses are planar (dimension: 2)");
  rd.keys(p, "pantograph", {"contact", "rig_joint"});
  contact = marker(rd.need(p, "contact", "pantograph"), "contact");
  if (p["rig_joint"].IsDefined()) {
    const std::string rig = rd.text(p["rig_joint"], "rig_joint");
    rig_joint = model.find_joint(rig);
    if (rig_joint < 0) rd.fail(p["rig_joint"], "rig_joint", fmt::format("unknown joint '{}'", rig));
  }
  return {contact, rig_joint};
}

}  // namespace inerta::io::detail
