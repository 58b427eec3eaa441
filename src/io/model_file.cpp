// Model files (docs/model-format.md): the entry points. The sections are read in the order the
// format documents (options, ground, bodies, joints, assembly; then the model is assembled once;
// then forces, outputs, pantograph), each by its own file in src/io:
//   model_reader.{hpp,cpp}   Reader (file:line:key errors, numbers, angles), time functions
//   model_loader.hpp         Loader: the model being built and the lookups the sections share
//   element_registry.hpp     type name → {accepted keys, builder}, for forces, joints and outputs
//   model_options.cpp, model_bodies.cpp, model_joints.cpp, model_forces.cpp, model_outputs.cpp,
//   model_pantograph.cpp, model_overrides.cpp
// A file whose top level has `lumped_pantograph:` is a lumped n-mass pantograph instead
// (lumped_pantograph_file.{hpp,cpp}).
#include "inerta/io/model_file.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "inerta/error.hpp"
#include "inerta/io/files.hpp"
#include "inerta/mbs/assembly.hpp"
#include "lumped_pantograph_file.hpp"
#include "inerta/io/yaml_errors.hpp"
#include "inerta/numerics/phase_times.hpp"
#include "model_loader.hpp"

namespace inerta::io {

namespace {

// Global positions of body b's centre and markers in q.
std::vector<Eigen::Vector3d> body_points(const mbs::Model& m, const Eigen::VectorXd& q, int b) {
  const mbs::State x{q, Eigen::VectorXd::Zero(q.size()), Eigen::VectorXd::Zero(m.n_states())};
  std::vector<Eigen::Vector3d> pts;
  auto at = [&](const mbs::Vec2& u, const mbs::Vec3& u3) -> Eigen::Vector3d {
    if (m.spatial()) {
      const mbs::SpatialFrame f = m.sframe(x, b);
      return f.R + f.A * u3;
    }
    const mbs::BodyFrame f = m.frame(x, b);
    const mbs::Vec2 r = f.q.head<2>() + f.rotate(u);
    return {r.x(), r.y(), 0.0};
  };
  pts.push_back(at(mbs::Vec2::Zero(), mbs::Vec3::Zero()));
  for (const mbs::Marker& mk : m.markers)
    if (mk.body == b) pts.push_back(at(mk.u, mk.u3));
  return pts;
}

// A warning when assembly moves a body's point by more than kLargeCorrection of the model's size
// (the largest distance between two tabulated points): the tabulated pose was probably not meant
// (degrees written as radians, a wrong sign). docs/assumptions.md#assembly-warnings.
constexpr double kLargeCorrection = 0.1;
void warn_large_correction(const detail::Loader& ld, const YAML::Node& bodies, const Eigen::VectorXd& q) {
  const mbs::Model& m = ld.model;
  const Eigen::VectorXd q0 = m.q0();
  std::vector<Eigen::Vector3d> all;
  for (const mbs::Marker& mk : m.markers)
    if (mk.body < 0) all.push_back(m.spatial() ? Eigen::Vector3d(mk.u3) : Eigen::Vector3d(mk.u.x(), mk.u.y(), 0.0));
  for (int b = 0; b < static_cast<int>(m.bodies.size()); ++b)
    for (const auto& p : body_points(m, q0, b)) all.push_back(p);
  double size = 0;
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) size = std::max(size, (all[i] - all[j]).norm());
  for (int b = 0; b < static_cast<int>(m.bodies.size()); ++b) {
    const auto before = body_points(m, q0, b), after = body_points(m, q, b);
    double move = 0;
    for (std::size_t k = 0; k < before.size(); ++k) move = std::max(move, (after[k] - before[k]).norm());
    if (size > 0 && move > kLargeCorrection * size) {
      const YAML::Node at = bodies.IsSequence() && static_cast<std::size_t>(b) < bodies.size()
                                ? bodies[static_cast<std::size_t>(b)]
                                : bodies;
      ld.rd.warning(at, "",
                    fmt::format("assembly moved body '{}' by {:.4g} m (largest displacement of its points), more than "
                                "{:g} % of the model's size {:.4g} m; check its tabulated position and angle against "
                                "the joints (angle is in rad, angle_deg in degrees)",
                                m.bodies[static_cast<std::size_t>(b)].name, move, 100 * kLargeCorrection, size));
    }
  }
}

// The whole file: the model and, if the file has a `pantograph:` section, its contact point and rig joint.
pantograph::Pantograph parse_file(const std::string& text, const std::string& source,
                                  const std::vector<std::string>& overrides) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    yaml_syntax_error(source, e);
  }
  if (detail::is_lumped_pantograph(root)) {  // a lumped n-mass pantograph (lumped_pantograph_file.cpp)
    try {
      if (!overrides.empty()) detail::apply_lumped_overrides(root, overrides, source);
      return detail::read_lumped_pantograph(root, source);
    } catch (const YAML::Exception& e) {
      throw ModelError(fmt::format("{}:{}: {}", source, e.mark.line + 1, e.msg));
    }
  }
  if (!overrides.empty()) detail::apply_overrides(root, overrides, source);
  detail::Loader ld{detail::Reader(source), {}};
  ld.rd.set_notes(&ld.model.notes);
  pantograph::Pantograph panto;
  const detail::Reader& rd = ld.rd;
  try {
    if (!root.IsMap()) rd.fail(root, "", "expected a model (a mapping with bodies, joints, forces, outputs)");
    rd.keys(
        root, "the model",
        {"name", "options", "ground", "bodies", "joints", "forces", "outputs", "assembly", "pantograph", "dimension"});
    ld.model.source = source;
    if (YAML::Node d = root["dimension"]; d.IsDefined()) {
      double dim = rd.number(d, "dimension");
      if (dim != 2 && dim != 3) rd.fail(d, "dimension", "expected 2 (planar) or 3 (spatial)");
      ld.model.dimension = static_cast<int>(dim);
    }
    ld.model.name = root["name"].IsDefined() ? rd.text(root["name"], "name") : source;
    ld.options(root["options"]);
    ld.ground(root["ground"]);
    ld.bodies(rd.need(root, "bodies", "the model"));
    ld.joints(root["joints"]);
    ld.assembly(root["assembly"]);
    ld.model.finalize();
    try {
      mbs::State x = mbs::assemble(ld.model, 0.0);
      warn_large_correction(ld, root["bodies"], x.q);
      ld.forces(root["forces"], x.q);
      ld.model.finalize();  // internal states, and distance joints of rigid networks
    } catch (const NumericalError& e) {
      throw ModelError(fmt::format("{}: {}", source, e.what()));
    }
    ld.outputs(root["outputs"]);
    panto = ld.pantograph(root["pantograph"]);
  } catch (const YAML::Exception& e) {  // safety net: no yaml-cpp exception leaves without file:line
    throw ModelError(fmt::format("{}:{}: {}", source, e.mark.line + 1, e.msg));
  }
  panto.model = std::move(ld.model);
  return panto;
}

std::string read_text(const std::string& path) { return read_input_text(path, "model file"); }

}  // namespace

mbs::Model parse_model(const std::string& text, const std::string& source, const std::vector<std::string>& overrides) {
  return parse_file(text, source, overrides).model;
}

pantograph::Pantograph parse_pantograph(const std::string& text, const std::string& source,
                                        const std::vector<std::string>& overrides) {
  pantograph::Pantograph p = parse_file(text, source, overrides);
  if (p.contact_marker < 0)
    throw ModelError(
        fmt::format("{}: the model has no 'pantograph: {{contact: <marker>}}' section; a catenary needs the head's "
                    "contact point",
                    source));
  return p;
}

mbs::Model load_model(const std::string& path, const std::vector<std::string>& overrides) {
  const numerics::PhaseTimer timer("load: model file");
  return parse_model(read_text(path), path, overrides);
}

pantograph::Pantograph parse_model_file(const std::string& text, const std::string& source,
                                        const std::vector<std::string>& overrides) {
  return parse_file(text, source, overrides);
}

pantograph::Pantograph load_model_file(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_file(read_text(path), path, overrides);
}

pantograph::Pantograph load_pantograph(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_pantograph(read_text(path), path, overrides);
}

pantograph::LumpedPantographData load_lumped_pantograph_data(const std::string& path,
                                                             const std::vector<std::string>& overrides) {
  YAML::Node root;
  try {
    root = YAML::Load(read_text(path));
  } catch (const YAML::ParserException& e) {
    yaml_syntax_error(path, e);
  }
  if (!detail::is_lumped_pantograph(root))
    throw ModelError(fmt::format("{}: not a lumped pantograph file (expected a top-level 'lumped_pantograph:')", path));
  try {
    if (!overrides.empty()) detail::apply_lumped_overrides(root, overrides, path);
    return detail::read_lumped_pantograph_data(root, path);
  } catch (const YAML::Exception& e) {
    throw ModelError(fmt::format("{}:{}: {}", path, e.mark.line + 1, e.msg));
  }
}

}  // namespace inerta::io
