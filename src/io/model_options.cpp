// Model files: the `options:` section (docs/model-format.md#options).
#include <cmath>

#include "inerta/mbs/applied_forces.hpp"
#include "model_loader.hpp"

namespace inerta::io::detail {

void Loader::options(const YAML::Node& n) {
  if (!n.IsDefined()) return;
  rd.keys(n, "options", {"gravity", "baumgarte", "centripetal", "t_end", "sample", "max_violation"});
  if (YAML::Node g = n["gravity"]; g.IsDefined()) {
    if (g.IsSequence() && model.spatial())
      model.options.g3 = rd.vec3(g, "gravity");
    else if (g.IsSequence())
      model.options.g = rd.vec2(g, "gravity");
    else
      model.options.gravity = rd.boolean(g, "gravity");
    if (g.IsSequence())  // the element's constructor checks the vector (eq. 6.39)
      rd.guard_value(g, "gravity", [&] {
        if (model.spatial())
          (void)mbs::Gravity(model.options.g3);
        else
          (void)mbs::Gravity(model.options.g);
      });
  }
  if (YAML::Node b = n["baumgarte"]; b.IsDefined()) {
    rd.keys(b, "baumgarte", {"alpha", "beta"});
    model.options.alpha = rd.number_or(b, "alpha", 5.0);
    model.options.beta = rd.number_or(b, "beta", 5.0);
    const auto ok = [](double v) { return std::isfinite(v) && v >= 0; };
    if (!ok(model.options.alpha) || !ok(model.options.beta))
      rd.fail(b, "baumgarte", "alpha and beta must be >= 0 (1/s) and finite");
  }
  if (n["centripetal"].IsDefined()) model.options.centripetal = rd.boolean(n["centripetal"], "centripetal");
  model.options.t_end = rd.number_or(n, "t_end", model.options.t_end);
  model.options.sample = rd.number_or(n, "sample", model.options.sample);
  if (!(model.options.t_end > 0)) rd.fail(n["t_end"], "t_end", "must be > 0 (s)");
  if (!(model.options.sample > 0)) rd.fail(n["sample"], "sample", "must be > 0 (s)");
  if (const YAML::Node mv = n["max_violation"]; mv.IsDefined() && mv.IsScalar() && (mv.Scalar() == ".inf" || mv.Scalar() == "inf"))
    model.options.max_violation = INFINITY;  // the check off
  else
    model.options.max_violation = rd.number_or(n, "max_violation", model.options.max_violation);
  if (!(model.options.max_violation > 0))
    rd.fail(n["max_violation"], "max_violation",
            "must be > 0 (m or rad; .inf switches the check off): the largest constraint violation |C| a run may reach");
}

}  // namespace inerta::io::detail
