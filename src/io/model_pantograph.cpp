// Model files: the `pantograph:` section (docs/model-format.md#pantograph).
#include <fmt/format.h>

#include "model_loader.hpp"

namespace inerta::io::detail {

pantograph::Pantograph Loader::pantograph(const YAML::Node& p) {
  pantograph::Pantograph out;  // the model is moved in by the caller
  if (!p.IsDefined()) return out;
  if (model.spatial()) rd.fail(p, "pantograph", "the pantograph-catenary analyses are planar (dimension: 2)");
  rd.keys(p, "pantograph", {"contact", "rig_joint", "aerodynamic"});
  out.contact_marker = marker(rd.need(p, "contact", "pantograph"), "contact");
  if (p["rig_joint"].IsDefined()) {
    const std::string rig = rd.text(p["rig_joint"], "rig_joint");
    out.rig_joint = model.find_joint(rig);
    if (out.rig_joint < 0) rd.fail(p["rig_joint"], "rig_joint", fmt::format("unknown joint '{}'", rig));
  }
  // Aerodynamic uplift a v² + b v + c (N, up, v in m/s) on the body carrying the contact point, as a
  // lumped pantograph's (pantograph::at_speed adds it at each running speed).
  if (const YAML::Node a = p["aerodynamic"]; a.IsDefined()) {
    rd.keys(a, "aerodynamic", {"a", "b", "c"});
    out.aero.body = model.markers[static_cast<std::size_t>(out.contact_marker)].body;
    if (out.aero.body < 0) rd.fail(a, "aerodynamic", "the contact marker is on the ground; the uplift needs a body");
    out.aero.a = a["a"].IsDefined() ? rd.number(a["a"], "aerodynamic.a") : 0.0;
    out.aero.b = a["b"].IsDefined() ? rd.number(a["b"], "aerodynamic.b") : 0.0;
    out.aero.c = a["c"].IsDefined() ? rd.number(a["c"], "aerodynamic.c") : 0.0;
  }
  return out;
}

}  // namespace inerta::io::detail
