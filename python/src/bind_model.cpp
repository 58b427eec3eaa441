// Models: loading with overrides, inspection, transformations, and the multibody functions that
// work on one state (assembly, equilibrium, accelerations, energies, outputs, integration).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <fstream>
#include <sstream>

#include "common.hpp"
#include "inerta/catenary/contact.hpp"
#include "inerta/catenary/lumped.hpp"
#include "inerta/catenary/wire_profile.hpp"
#include "inerta/error.hpp"
#include "inerta/io/file_kind.hpp"
#include "inerta/io/files.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/pantograph/lumped.hpp"
#include "inerta/mbs/applied_forces.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/mbs/model_check.hpp"
#include "inerta/mbs/network_strut.hpp"
#include "inerta/mbs/output.hpp"
#include "inerta/mbs/road.hpp"
#include "inerta/mbs/struts.hpp"
#include "inerta/network/layouts.hpp"
#include "inerta/pantograph/suspension.hpp"

namespace inerta::python {

// ---- Model handle ---------------------------------------------------------------------------------

Model make_model(pantograph::Pantograph p) {
  Model m;
  m.p = std::move(p);
  m.source = m.p.model.source;
  return m;
}

Model make_model(mbs::Model m) {
  pantograph::Pantograph p;
  p.model = std::move(m);
  return make_model(std::move(p));
}

Model parse_model_handle(const std::string& text, const std::string& source, const std::vector<std::string>& overrides) {
  Model m;
  m.p = io::parse_model_file(text, source, overrides);
  m.text = text;
  m.source = source;
  for (const auto& o : overrides) {
    const auto eq = o.find('=');
    m.overrides.emplace_back(o.substr(0, eq), eq == std::string::npos ? "" : o.substr(eq + 1));
  }
  return m;
}

Model load_model_handle(const std::string& path, const std::vector<std::string>& overrides) {
  // The CLI's reader: regular files only (a device such as /dev/zero or a FIFO is refused, never read
  // without end), at most 256 MiB.
  return parse_model_handle(io::read_input_text(path, "model file"), path, overrides);
}

std::vector<std::string> Model::override_list() const {
  std::vector<std::string> out;
  for (const auto& [k, v] : overrides) out.push_back(k + "=" + v);
  return out;
}

Model Model::with_overrides(const std::vector<std::string>& more) const {
  if (text.empty())
    throw ModelError(fmt::format("model '{}' was not read from a file (it was built by the library), so it cannot be "
                                 "reloaded with overrides",
                                 p.model.name));
  std::vector<std::pair<std::string, std::string>> merged = overrides;
  for (const auto& o : more) {
    const auto eq = o.find('=');
    std::string k = o.substr(0, eq), v = eq == std::string::npos ? "" : o.substr(eq + 1);
    auto it = std::find_if(merged.begin(), merged.end(), [&](const auto& kv) { return kv.first == k; });
    if (it != merged.end())
      it->second = v;
    else
      merged.emplace_back(k, v);
  }
  std::vector<std::string> list;
  for (const auto& [k, v] : merged) list.push_back(k + "=" + v);
  Model m = parse_model_handle(text, source, list);
  for (const auto& f : transforms) f(m.p);
  m.transforms = transforms;
  m.history = history;
  return m;
}

Model Model::transformed(std::function<void(pantograph::Pantograph&)> f, std::string what) const {
  Model m = *this;
  f(m.p);
  m.transforms.push_back(std::move(f));
  m.history.push_back(std::move(what));
  return m;
}

std::string number_text(double v) { return fmt::format("{:.17g}", v); }

std::vector<std::string> override_strings(const py::object& o) {
  std::vector<std::string> out;
  if (o.is_none()) return out;
  if (py::isinstance<py::str>(o)) return {o.cast<std::string>()};
  if (py::isinstance<py::dict>(o)) {
    for (auto [k, v] : o.cast<py::dict>()) {
      const std::string key = py::str(k).cast<std::string>();
      std::string value;
      if (py::isinstance<py::bool_>(v))  // before numbers: bool is an int in Python (False was "0")
        value = v.cast<bool>() ? "true" : "false";
      else if (py::isinstance<py::str>(v))
        value = v.cast<std::string>();
      else if (py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v) || py::hasattr(v, "__float__"))
        value = number_text(v.cast<double>());
      else
        throw py::type_error(fmt::format("overrides: '{}': expected a number, a string or True/False, got {}", key,
                                         py::str(py::type::of(v)).cast<std::string>()));
      out.push_back(key + "=" + value);
    }
    return out;
  }
  for (auto item : o) out.push_back(item.cast<std::string>());
  return out;
}

std::vector<double> doubles(const py::object& o) {
  if (py::isinstance<py::float_>(o) || py::isinstance<py::int_>(o)) return {o.cast<double>()};
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(o);
  if (!a) throw py::type_error("expected a sequence of numbers");
  if (a.ndim() != 1) throw py::value_error("expected a one-dimensional sequence of numbers");
  return std::vector<double>(a.data(), a.data() + a.size());
}

solve::IntegratorOptions integrator_arg(const py::object& base, const py::object& method, const py::object& rtol,
                                        const py::object& atol, const py::object& max_step) {
  solve::IntegratorOptions o = base.is_none() ? solve::IntegratorOptions{} : base.cast<solve::IntegratorOptions>();
  if (!method.is_none()) o.method = solve::parse_method(method.cast<std::string>());
  // Given or from `base`: the CLI's rule and words (--rtol, --atol, --max-step).
  o.rtol = rule_arg(rtol, "rtol", solve::rtol_rule, o.rtol);
  o.atol = rule_arg(atol, "atol", solve::atol_rule, o.atol);
  o.max_step = rule_arg(max_step, "max_step", solve::max_step_rule, o.max_step);
  return o;
}

namespace {

// An ISO 8608 class given as a one-letter string ("C").
char road_class(const std::string& c) {
  if (c.size() != 1) throw InvalidArgument("ISO 8608 road", "class", "expected a class A to H, got '" + c + "'");
  return c[0];
}

// ---- Force elements, for inspection ----------------------------------------------------------------

struct ForceElementInfo {
  std::shared_ptr<const mbs::ForceElement> e;
  std::string type() const {
    const auto* p = e.get();
    if (dynamic_cast<const mbs::Actuator*>(p)) return "actuator";
    if (dynamic_cast<const mbs::NetworkStrut*>(p)) return "network_strut";
    if (dynamic_cast<const mbs::Spring*>(p)) return "spring";
    if (dynamic_cast<const mbs::Damper*>(p)) return "damper";
    if (dynamic_cast<const mbs::Inerter*>(p)) return "inerter";
    if (dynamic_cast<const mbs::AxialForce*>(p)) return "axial_force";
    if (dynamic_cast<const mbs::Gravity*>(p)) return "gravity";
    if (dynamic_cast<const mbs::PointForce*>(p)) return "point_force";
    if (dynamic_cast<const mbs::PointTorque*>(p)) return "point_torque";
    if (dynamic_cast<const mbs::RotationalSpringDamper*>(p)) return "rotational_spring_damper";
    if (dynamic_cast<const catenary::PenaltyContact*>(p)) return "penalty_contact";
    if (dynamic_cast<const catenary::CatenaryElement*>(p)) return "catenary";
    if (dynamic_cast<const catenary::ProfileContact*>(p)) return "profile_contact";
    return "force_element";
  }
  const mbs::Strut* strut() const { return dynamic_cast<const mbs::Strut*>(e.get()); }
  const mbs::NetworkStrut* net() const { return dynamic_cast<const mbs::NetworkStrut*>(e.get()); }
};

std::string body_name(const mbs::Model& m, int b) {
  return b < 0 ? "ground" : m.bodies.at(static_cast<std::size_t>(b)).name;
}

const char* joint_type_name(mbs::JointType t) {
  switch (t) {
    case mbs::JointType::Revolute: return "revolute";
    case mbs::JointType::Spherical: return "spherical";
    case mbs::JointType::Prismatic: return "prismatic";
    case mbs::JointType::Fixed: return "fixed";
    case mbs::JointType::Driving: return "driving";
    case mbs::JointType::Distance: return "distance";
    case mbs::JointType::Coupling: return "coupling";
  }
  return "?";
}

int output_index(const mbs::Model& m, const py::object& o) {
  if (py::isinstance<py::int_>(o)) {
    const int k = o.cast<int>();
    if (k < 0 || k >= static_cast<int>(m.outputs.size()))
      throw InvalidArgument(fmt::format("output index {} out of range (the model has {} outputs)", k, m.outputs.size()));
    return k;
  }
  const std::string name = o.cast<std::string>();
  std::string names;
  for (std::size_t k = 0; k < m.outputs.size(); ++k) {
    if (m.outputs[k].name == name) return static_cast<int>(k);
    names += (names.empty() ? "" : ", ") + m.outputs[k].name;
  }
  throw py::key_error(fmt::format("no output '{}' in model '{}'; outputs: {}", name, m.name, names));
}

mbs::State state_or_assembled(const Model& m, const py::object& state, double t0) {
  return state.is_none() ? mbs::assemble(m.model(), t0) : state.cast<mbs::State>();
}

void check_state(const mbs::Model& m, const mbs::State& x) {
  if (x.q.size() != m.n_coords() || x.qd.size() != m.n_coords() || x.z.size() != m.n_states())
    throw InvalidArgument(fmt::format(
        "state of {} coordinates, {} velocities and {} internal states does not fit model '{}' ({} coordinates, {} "
        "internal states)",
        x.q.size(), x.qd.size(), x.z.size(), m.name, m.n_coords(), m.n_states()));
}

}  // namespace

network::Network network_arg(const py::object& net, const py::object& params) {
  if (py::isinstance<network::Network>(net)) {
    if (!params.is_none()) return network::assign(net.cast<network::Network>(), params.cast<network::Params>());
    return net.cast<network::Network>();
  }
  return network::resolve(net.cast<std::string>(),
                          params.is_none() ? network::Params{} : params.cast<network::Params>());
}

namespace {

// The parts of a model: bodies, markers, joints, outputs, options, state, force elements, reports.
void bind_model_parts(py::module_& m) {
  using mbs::Body, mbs::Joint, mbs::Marker, mbs::Output, mbs::State;

  py::enum_<mbs::JointType>(m, "JointType", "Joint types (constraint equations C(q, t) = 0, docs/model-format.md).")
      .value("revolute", mbs::JointType::Revolute)
      .value("spherical", mbs::JointType::Spherical)
      .value("prismatic", mbs::JointType::Prismatic)
      .value("fixed", mbs::JointType::Fixed)
      .value("driving", mbs::JointType::Driving)
      .value("distance", mbs::JointType::Distance)
      .value("coupling", mbs::JointType::Coupling);

  py::class_<Body>(m, "Body", "A rigid body (read-only copy). 2D coordinates [x y θ] of the centre of mass (m, rad).")
      .def_readonly("name", &Body::name)
      .def_readonly("mass", &Body::mass, "kg")
      .def_readonly("inertia", &Body::inertia, "kg·m² about the centre of mass (2D)")
      .def_readonly("q0", &Body::q0, "tabulated initial position [x y θ] (m, m, rad), 2D")
      .def_readonly("qd0", &Body::qd0, "initial velocity (m/s, m/s, rad/s), 2D")
      .def_readonly("inertia3", &Body::inertia3, "3D: centroidal inertia tensor in the body frame, kg·m²")
      .def_readonly("q0s", &Body::q0s, "3D: tabulated [R; p] (m; Euler parameters)")
      .def_readonly("qd0s", &Body::qd0s, "3D: [Ṙ; ṗ]")
      .def_readonly("weighs", &Body::weighs, "gravity acts on it")
      .def("__repr__", [](const Body& b) { return fmt::format("Body('{}', mass={:g} kg)", b.name, b.mass); });

  py::class_<Marker>(m, "Marker", "A body-fixed point (body −1: ground, u then global), m.")
      .def_readonly("name", &Marker::name)
      .def_readonly("body", &Marker::body)
      .def_readonly("u", &Marker::u, "local coordinates, m")
      .def_readonly("u3", &Marker::u3, "3D local coordinates, m")
      .def("__repr__", [](const Marker& k) { return fmt::format("Marker('{}')", k.name); });

  py::class_<Joint>(m, "Joint", "A joint (read-only copy): bodies by index (−1: ground).")
      .def_readonly("name", &Joint::name)
      .def_readonly("type", &Joint::type)
      .def_readonly("body_i", &Joint::body_i)
      .def_readonly("body_j", &Joint::body_j)
      .def_readonly("u_i", &Joint::u_i, "joint point in body i's frame, m")
      .def_readonly("u_j", &Joint::u_j, "joint point in body j's frame, m")
      .def_readonly("axis", &Joint::axis, "prismatic: unit axis in body i's frame")
      .def_readonly("theta0", &Joint::theta0, "prismatic, fixed: locked θ_j − θ_i, rad")
      .def_readonly("component", &Joint::component, "driving: 0 x, 1 y, 2 θ")
      .def_readonly("value0", &Joint::value0, "driving, coupling: constant part of the value (m or rad)")
      .def_readonly("length0", &Joint::length0, "distance joint length, m")
      .def_readonly("row", &Joint::row, "first constraint row")
      .def_readonly("spatial", &Joint::spatial)
      .def_property_readonly("rows", &Joint::rows, "number of constraint equations")
      .def("__repr__", [](const Joint& j) { return fmt::format("Joint('{}', {})", j.name, joint_type_name(j.type)); });

  py::enum_<Output::Kind>(m, "OutputKind", "What an output measures (docs/model-format.md#outputs).")
      .value("coordinate", Output::Kind::Coordinate)
      .value("position", Output::Kind::Position)
      .value("velocity", Output::Kind::Velocity)
      .value("acceleration", Output::Kind::Acceleration)
      .value("element_force", Output::Kind::ElementForce)
      .value("element_length", Output::Kind::ElementLength)
      .value("reaction", Output::Kind::Reaction)
      .value("multiplier", Output::Kind::Multiplier);

  py::class_<Output>(m, "Output", "A named output of a model (a column of a simulation Result), SI units.")
      .def_readonly("name", &Output::name)
      .def_readonly("kind", &Output::kind)
      .def_readonly("index", &Output::index, "body, marker, force element or joint index")
      .def_readonly("component", &Output::component)
      .def_readonly("scale", &Output::scale)
      .def_property_readonly("needs_accelerations", [](const Output& o) { return mbs::needs_accelerations(o); })
      .def("__repr__", [](const Output& o) { return fmt::format("Output('{}')", o.name); });
  m.def("needs_accelerations", &mbs::needs_accelerations, py::arg("output"),
        "True if the output needs accelerations or multipliers (eq. 4.12 solved at the state).");

  py::class_<mbs::Options>(m, "Options", "Model-wide options (a copy; change them with Model.with_options).")
      .def_readonly("gravity", &mbs::Options::gravity)
      .def_readonly("g", &mbs::Options::g, "m/s² (2D)")
      .def_readonly("g3", &mbs::Options::g3, "m/s² (3D)")
      .def_readonly("alpha", &mbs::Options::alpha, "Baumgarte α, 1/s (eq. 4.11)")
      .def_readonly("beta", &mbs::Options::beta, "Baumgarte β, 1/s")
      .def_readonly("centripetal", &mbs::Options::centripetal, "the inerter's centripetal correction (eq. 3.20) on")
      .def_readonly("t_end", &mbs::Options::t_end, "default simulation end time, s")
      .def_readonly("sample", &mbs::Options::sample, "default output sampling interval, s")
      .def_readonly("max_violation", &mbs::Options::max_violation,
                    "a run fails when max |C| exceeds this, m or rad (options.max_violation)");

  py::class_<State>(m, "State",
                    "A mutable state: coordinates q (m, rad; Euler parameters in 3D), velocities qd and the internal "
                    "states z of network struts (m). The attributes are NumPy views of the state's memory.")
      .def(py::init<>())
      .def(py::init([](Eigen::VectorXd q, Eigen::VectorXd qd, Eigen::VectorXd z) {
             return State{std::move(q), std::move(qd), std::move(z)};
           }),
           py::arg("q"), py::arg("qd"), py::arg("z") = Eigen::VectorXd())
      .def_property("q", [](State& s) -> Eigen::VectorXd& { return s.q; },
                    [](State& s, const Eigen::VectorXd& v) { s.q = v; }, py::return_value_policy::reference_internal,
                    "coordinates (a writable view)")
      .def_property("qd", [](State& s) -> Eigen::VectorXd& { return s.qd; },
                    [](State& s, const Eigen::VectorXd& v) { s.qd = v; }, py::return_value_policy::reference_internal,
                    "velocities (a writable view)")
      .def_property("z", [](State& s) -> Eigen::VectorXd& { return s.z; },
                    [](State& s, const Eigen::VectorXd& v) { s.z = v; }, py::return_value_policy::reference_internal,
                    "internal states (a writable view)")
      .def("copy", [](const State& s) { return s; })
      .def("__repr__", [](const State& s) {
        return fmt::format("State({} coordinates, {} internal states)", s.q.size(), s.z.size());
      });

  py::class_<ForceElementInfo>(m, "ForceElement",
                               "A force element of a model (read-only view; the element is shared with the model).")
      .def_property_readonly("name", [](const ForceElementInfo& f) { return f.e->name(); })
      .def_property_readonly("type", &ForceElementInfo::type,
                             "spring, damper, inerter, axial_force, network_strut, actuator, gravity, point_force, "
                             "point_torque, rotational_spring_damper, penalty_contact, catenary, profile_contact")
      .def_property_readonly("n_states", [](const ForceElementInfo& f) { return f.e->n_states(); })
      .def_property_readonly("state_offset", [](const ForceElementInfo& f) { return f.e->state_offset(); })
      .def_property_readonly("body_i", [](const ForceElementInfo& f) -> py::object {
        return f.strut() ? py::int_(f.strut()->body_i()) : py::object(py::none());
      }, "a strut's first body (−1 ground), None for other elements")
      .def_property_readonly("body_j", [](const ForceElementInfo& f) -> py::object {
        return f.strut() ? py::int_(f.strut()->body_j()) : py::object(py::none());
      })
      .def_property_readonly("network", [](const ForceElementInfo& f) -> py::object {
        return f.net() ? py::cast(f.net()->network()) : py::object(py::none());
      }, "the Network of a network strut or actuator (simplified, with values), else None")
      .def_property_readonly("reference_length", [](const ForceElementInfo& f) -> py::object {
        return f.net() ? py::float_(f.net()->reference_length()) : py::object(py::none());
      }, "m: length at which a network strut is relaxed")
      .def_property_readonly("free_length", [](const ForceElementInfo& f) -> py::object {
        auto* s = dynamic_cast<const mbs::Spring*>(f.e.get());
        return s ? py::float_(s->free_length()) : py::object(py::none());
      }, "m: a spring's free length")
      .def_property_readonly("actuator", [](const ForceElementInfo& f) -> py::object {
        auto* a = dynamic_cast<const mbs::Actuator*>(f.e.get());
        if (!a) return py::none();
        py::dict d;
        d["constant_force"] = a->params().constant_force;
        d["piston_mass"] = a->params().piston_mass;
        d["friction"] = a->params().friction;
        d["friction_velocity"] = a->params().friction_velocity;
        return d;
      }, "an actuator's parameters: constant_force (N, tension positive), piston_mass (kg), friction (N), "
         "friction_velocity (m/s); None for other elements")
      .def("energy", [](const ForceElementInfo& f, const Model& mo, double t, const State& x) {
        return f.e->energy(mo.model(), t, x);
      }, py::arg("model"), py::arg("t"), py::arg("state"), "stored energy, J")
      .def("power", [](const ForceElementInfo& f, const Model& mo, double t, const State& x) {
        return f.e->power(mo.model(), t, x);
      }, py::arg("model"), py::arg("t"), py::arg("state"), "power delivered beyond −d(energy)/dt, W")
      .def("length", [](const ForceElementInfo& f, const Model& mo, const State& x) {
        return f.e->length(mo.model(), x);
      }, py::arg("model"), py::arg("state"), "strut length (m) or joint relative angle (rad); NaN elsewhere")
      .def("__repr__", [](const ForceElementInfo& f) {
        return fmt::format("ForceElement('{}', {})", f.e->name(), f.type());
      });

  py::class_<mbs::AssemblyReport>(m, "AssemblyReport", "Result of the assembly (Newton solve of C(q) = 0).")
      .def_readonly("iterations", &mbs::AssemblyReport::iterations)
      .def_readonly("residual", &mbs::AssemblyReport::residual, "max |C| after assembly (m or rad)")
      .def_readonly("initial_residual", &mbs::AssemblyReport::initial_residual, "max |C| of the tabulated positions")
      .def_readonly("dq", &mbs::AssemblyReport::dq, "correction applied to the tabulated positions")
      .def_readonly("largest", &mbs::AssemblyReport::largest, "coordinate with the largest correction (−1: none)");
  py::class_<mbs::EquilibriumReport>(m, "EquilibriumReport", "Result of the static equilibrium (damped Newton).")
      .def_readonly("iterations", &mbs::EquilibriumReport::iterations)
      .def_readonly("force_residual", &mbs::EquilibriumReport::force_residual, "max |Q − C_qᵀλ|, N or N·m")
      .def_readonly("max_move", &mbs::EquilibriumReport::max_move, "largest coordinate change from assembly")
      .def_readonly("largest", &mbs::EquilibriumReport::largest);
  py::class_<mbs::ModelCheck>(m, "ModelCheck", "What `inerta check` reports (mbs::check_model).")
      .def_readonly("state", &mbs::ModelCheck::state, "the assembled state at t = 0")
      .def_readonly("assembly", &mbs::ModelCheck::assembly)
      .def_readonly("rank", &mbs::ModelCheck::rank, "numerical rank of C_q")
      .def_readonly("dof", &mbs::ModelCheck::dof, "degrees of freedom n_coords − rank")
      .def_readonly("redundant", &mbs::ModelCheck::redundant, "redundant constraint equations");

}

// The model handle.
void bind_model_class(py::module_& m) {
  using mbs::Body, mbs::Joint, mbs::Marker, mbs::Output, mbs::State;

  py::class_<Model>(m, "Model",
                    "An immutable multibody model (mbs::Model) with, for a pantograph, its contact marker and rig "
                    "joint (pantograph::Pantograph). Change parameters with with_overrides (the file is read again) "
                    "and transform it with with_options, with_suspension, release_head, without_joint: each returns "
                    "a new Model.")
      .def(py::pickle(  // the file's text and overrides, read again in the other process (Dask workers)
          [](const Model& h) {
            if (h.text.empty() || !h.transforms.empty())
              throw py::type_error(fmt::format(
                  "model '{}' cannot be sent to another process: {}; load it from a file and change it with overrides",
                  h.model().name, h.text.empty() ? "it was not read from a file" : "it was transformed (" + fmt::format("{}", fmt::join(h.history, ", ")) + ")"));
            return py::make_tuple(h.text, h.source, h.override_list());
          },
          [](const py::tuple& t) {
            return parse_model_handle(t[0].cast<std::string>(), t[1].cast<std::string>(), t[2].cast<std::vector<std::string>>());
          }))
      .def_property_readonly("name", [](const Model& h) { return h.model().name; })
      .def_property_readonly("source", [](const Model& h) { return h.source; }, "the file it was read from")
      .def_property_readonly("text", [](const Model& h) { return h.text; }, "the file's text ('' if not from a file)")
      .def_property_readonly("overrides", &Model::override_list, "the overrides applied, 'NAME.KEY=VALUE'")
      .def_property_readonly("history", [](const Model& h) { return h.history; },
                             "the transformations applied after loading, in words")
      .def_property_readonly("dimension", [](const Model& h) { return h.model().dimension; }, "2 or 3")
      .def_property_readonly("n_coords", [](const Model& h) { return h.model().n_coords(); })
      .def_property_readonly("n_constraints", [](const Model& h) { return h.model().n_constraints(); })
      .def_property_readonly("dof", [](const Model& h) { return h.model().dof(); },
                             "degrees of freedom n_coords − n_constraints (check().dof counts redundant ones)")
      .def_property_readonly("n_states", [](const Model& h) { return h.model().n_states(); },
                             "internal states of network struts")
      .def_property_readonly("bodies", [](const Model& h) { return h.model().bodies; })
      .def_property_readonly("markers", [](const Model& h) { return h.model().markers; })
      .def_property_readonly("joints", [](const Model& h) { return h.model().joints; })
      .def_property_readonly("forces", [](const Model& h) {
        std::vector<ForceElementInfo> v;
        for (const auto& f : h.model().forces) v.push_back({f});
        return v;
      })
      .def_property_readonly("outputs", [](const Model& h) { return h.model().outputs; })
      .def_property_readonly("output_names", [](const Model& h) {
        std::vector<std::string> v;
        for (const auto& o : h.model().outputs) v.push_back(o.name);
        return v;
      })
      .def_property_readonly("coordinate_names", [](const Model& h) {
        std::vector<std::string> v;
        for (int k = 0; k < h.model().n_coords(); ++k) v.push_back(h.model().coord_name(k));
        return v;
      }, "'bar1.x', 'bar1.theta', ... (3D: 'bar1.e2')")
      .def_property_readonly("options", [](const Model& h) { return h.model().options; })
      .def_property_readonly("held", [](const Model& h) { return h.model().held; },
                             "coordinates held fixed during assembly")
      .def_property_readonly("notes", [](const Model& h) { return h.model().notes; },
                             "what the loader decided that a user should read")
      .def_property_readonly("is_pantograph", [](const Model& h) { return h.p.contact_marker >= 0; },
                             "the file has a `pantograph:` section (a contact point for a catenary)")
      .def_property_readonly("has_rig", [](const Model& h) { return h.p.has_rig(); },
                             "the head is held by a rig joint (FRFs on the test rig)")
      .def_property_readonly("contact_marker", [](const Model& h) { return h.p.contact_marker; },
                             "index of the head's contact marker (−1: none)")
      .def_property_readonly("rig_joint", [](const Model& h) { return h.p.rig_joint; },
                             "index of the rig joint (−1: none)")
      .def_property_readonly("aero", [](const Model& h) -> py::object {
        if (!h.p.aero.active()) return py::none();
        py::dict d;
        d["body"] = h.p.aero.body, d["a"] = h.p.aero.a, d["b"] = h.p.aero.b, d["c"] = h.p.aero.c;
        return d;
      }, "the aerodynamic uplift a v² + b v + c on the head (N, v in m/s): {'body', 'a', 'b', 'c'}, or None")
      .def("aero_force", [](const Model& h, double v) { return h.p.aero.active() ? h.p.aero.force(v) : 0.0; },
           py::arg("speed"), "the aerodynamic uplift at speed v (m/s), N")
      .def("at_speed", [](const Model& h, double v) {
        return h.transformed([v](pantograph::Pantograph& p) { p = pantograph::at_speed(p, v); },
                             fmt::format("at speed {:g} m/s", v));
      }, py::arg("speed"),
           "The pantograph running at speed v (m/s): its aerodynamic uplift added as a constant force "
           "(pantograph::at_speed; Catenary couplings do it themselves).")
      .def("find_body", [](const Model& h, const std::string& n) { return h.model().find_body(n); }, py::arg("name"),
           "index, −1 for 'ground', −2 if unknown")
      .def("find_marker", [](const Model& h, const std::string& n) { return h.model().find_marker(n); },
           py::arg("name"), "index, −1 if unknown")
      .def("find_joint", [](const Model& h, const std::string& n) { return h.model().find_joint(n); },
           py::arg("name"), "index, −1 if unknown")
      .def("find_force", [](const Model& h, const std::string& n) { return h.model().find_force(n); },
           py::arg("name"), "index, −1 if unknown")
      .def("coord_name", [](const Model& h, int k) { return h.model().coord_name(k); }, py::arg("k"))
      .def("body_name", [](const Model& h, int b) { return body_name(h.model(), b); }, py::arg("index"))
      .def("q0", [](const Model& h) { return h.model().q0(); }, "initial coordinates from the tabulated positions")
      .def("qd0", [](const Model& h) { return h.model().qd0(); }, "initial velocities")
      .def("value", [](const Model& h, const std::string& key) -> py::object {
        for (const auto& [k, v] : h.overrides)
          if (k == key) return py::float_(std::stod(v));
        if (h.text.empty()) throw ModelError(fmt::format("model '{}' was not read from a file", h.model().name));
        auto x = io::model_value(h.text, h.source, key);
        return x ? py::object(py::float_(*x)) : py::object(py::none());
      }, py::arg("key"),
           "The number at an override key ('c2.c', 'kf_cf.k', 'actuator.params.k') as loaded (with the overrides), "
           "SI; None for a network value the file leaves to its layout's default.")
      .def("with_overrides", [](const Model& h, const py::object& o) { return h.with_overrides(override_strings(o)); },
           py::arg("overrides"),
           "The model read again from its file with more overrides ({'c2.c': 70} or ['c2.c=70']; a key given again "
           "replaces its value), then the same transformations. ModelError with file:line for a bad key.")
      .def("with_options", [](const Model& h, py::object centripetal, py::object gravity, py::object alpha,
                              py::object beta, py::object t_end, py::object sample) {
        auto flag = [](const py::object& o) { return o.is_none() ? std::optional<bool>() : o.cast<bool>(); };
        auto num = [](const py::object& o) { return o.is_none() ? std::optional<double>() : o.cast<double>(); };
        const std::optional<bool> c = flag(centripetal), g = flag(gravity);
        const std::optional<double> a = num(alpha), b = num(beta), te = num(t_end), sa = num(sample);
        auto f = [=](pantograph::Pantograph& p) {
          auto& o = p.model.options;
          if (c) o.centripetal = *c;
          if (g) o.gravity = *g;
          if (a) o.alpha = *a;
          if (b) o.beta = *b;
          if (te) o.t_end = *te;
          if (sa) o.sample = *sa;
        };
        std::string text;
        for (auto [k, v] : std::vector<std::pair<const char*, py::object>>{
                 {"centripetal", centripetal}, {"gravity", gravity}, {"alpha", alpha}, {"beta", beta},
                 {"t_end", t_end}, {"sample", sample}})
          if (!v.is_none()) text += fmt::format("{}{}={}", text.empty() ? "" : ", ", k, py::str(v).cast<std::string>());
        return h.transformed(f, "options: " + text);
      }, py::kw_only(), py::arg("centripetal") = py::none(), py::arg("gravity") = py::none(),
           py::arg("alpha") = py::none(), py::arg("beta") = py::none(), py::arg("t_end") = py::none(),
           py::arg("sample") = py::none(),
           "A copy with model options changed: centripetal (the inerter's centripetal correction, eq. 3.20; False "
           "= the CLI's --no-centripetal), gravity, alpha and beta (Baumgarte, 1/s), t_end and sample (s).")
      .def("with_suspension", [](const Model& h, const py::object& net, const py::object& params,
                                 double reference_length) {
        const network::Network n = network_arg(net, params);
        return h.transformed(
            [n, reference_length](pantograph::Pantograph& p) {
              p.model = pantograph::with_suspension(p.model, n, reference_length);
            },
            "suspension " + network::to_string(n, true));
      }, py::arg("network"), py::arg("params") = py::none(), py::arg("reference_length") = -1.0,
           "The model with its actuator's dynamic network replaced (pantograph::with_suspension): `network` is a "
           "Network, a named layout ('S2-1') or an expression ('k-(b|c)'), `params` the element values {'k': 9e4} "
           "(N/m, N·s/m, kg; 0 open, inf rigid). reference_length > 0: the length (m) at which it is relaxed.")
      .def("release_head", [](const Model& h) {
        auto out = std::make_shared<double>(0.0);
        Model r = h.transformed(
            [out](pantograph::Pantograph& p) {
              p.model = pantograph::release_head(p, out.get());
              p.rig_joint = -1;
            },
            "head released from the rig");
        return py::make_tuple(r, *out);
      }, "(model, static contact force in N): the head released from the rig joint and loaded by the joint's static "
         "reaction instead (pantograph::release_head). ModelError without a rig joint.")
      .def("without_joint", [](const Model& h, const std::string& name) {
        if (h.model().find_joint(name) < 0) throw InvalidArgument(fmt::format("model '{}' has no joint '{}'", h.model().name, name));
        return h.transformed([name](pantograph::Pantograph& p) {
          const int j = p.model.find_joint(name);
          if (p.rig_joint == j) p.rig_joint = -1;
          else if (p.rig_joint > j) --p.rig_joint;
          p.model.remove_joint(name);
        }, "without joint " + name);
      }, py::arg("name"), "A copy without joint `name` (its outputs go; mbs::Model::remove_joint).")
      .def("check", [](const Model& h) { return mbs::check_model(h.model()); },
           "Assembles at t = 0 and reports rank, DOF and redundant constraints, as `inerta check` (NumericalError "
           "if the system matrix is singular).")
      .def("__repr__", [](const Model& h) {
        return fmt::format("Model('{}', {} bodies, {} joints, {} force elements, {} outputs, dof {})", h.model().name,
                           h.model().bodies.size(), h.model().joints.size(), h.model().forces.size(),
                           h.model().outputs.size(), h.model().dof());
      });

}

// Loading models and pantographs; the stepper; the model check.
void bind_model_files(py::module_& m) {
  using mbs::Body, mbs::Joint, mbs::Marker, mbs::Output, mbs::State;

  m.def("load_model", [](const py::object& path, const py::object& o) { return load_model_handle(path_arg(path), override_strings(o)); },
        py::arg("path"), py::arg("overrides") = py::none(),
        "Reads a YAML model file (io::load_model_file): the model and, if present, its `pantograph:` section. "
        "overrides: {'c2.c': 70} or ['c2.c=70', 'head.mass=5.5'] (NAME.KEY=VALUE, docs/model-format.md#overrides). "
        "ModelError 'file:line: key: ...' for a bad file.");
  m.def("load_pantograph", [](const py::object& path, const py::object& o) {
    Model h = load_model_handle(path_arg(path), override_strings(o));
    if (h.p.contact_marker < 0) (void)io::parse_pantograph(h.text, h.source, override_strings(o));  // its error
    return h;
  }, py::arg("path"), py::arg("overrides") = py::none(),
        "As load_model, but ModelError if the file has no `pantograph:` section (io::load_pantograph).");
  m.def("parse_model", [](const std::string& text, const std::string& source, const py::object& o) {
    return parse_model_handle(text, source, override_strings(o));
  }, py::arg("text"), py::arg("source") = "<text>", py::arg("overrides") = py::none(),
        "A model from YAML text (io::parse_model_file); `source` names it in error messages.");
  m.def("split_overrides", [](const py::object& path, const py::object& overrides) {
    return io::split_overrides(path_arg(path), override_strings(overrides));
  }, py::arg("path"), py::arg("overrides"),
        "(model overrides, catenary overrides): --set routing of the CLI (io::split_overrides): NAME a force "
        "element, body or joint (with that motion key) of the model file goes to the model.");
  m.def("model_value", [](const std::string& text, const std::string& source, const std::string& key) {
    return io::model_value(text, source, key);
  }, py::arg("text"), py::arg("source"), py::arg("key"),
        "The number at an override key in model text (io::model_value), or None.");
  m.def("at_speed", [](const Model& h, double v) { return py::cast(h).attr("at_speed")(v).cast<Model>(); },
        py::arg("model"), py::arg("speed"), "Same as Model.at_speed.");

  py::class_<pantograph::LumpedPantographData>(m, "LumpedPantographData",
                                               "A lumped n-mass pantograph (head first): masses (kg), stiffness (N/m) "
                                               "and damping (N·s/m) below each mass, the static uplift (N) and the "
                                               "aerodynamic uplift a v² + b v + c (N).")
      .def(py::init([](std::vector<double> mass, std::vector<double> k, std::vector<double> c, double F0, double a,
                       double b, double cc) {
             pantograph::LumpedPantographData d;
             d.mass = std::move(mass), d.stiffness = std::move(k), d.damping = std::move(c);
             d.static_uplift = F0, d.aero_a = a, d.aero_b = b, d.aero_c = cc;
             return d;
           }),
           py::arg("mass"), py::arg("stiffness"), py::arg("damping"), py::arg("static_uplift") = 0.0,
           py::arg("aero_a") = 0.0, py::arg("aero_b") = 0.0, py::arg("aero_c") = 0.0)
      .def_readwrite("mass", &pantograph::LumpedPantographData::mass, "kg")
      .def_readwrite("stiffness", &pantograph::LumpedPantographData::stiffness, "N/m")
      .def_readwrite("damping", &pantograph::LumpedPantographData::damping, "N·s/m")
      .def_readwrite("static_uplift", &pantograph::LumpedPantographData::static_uplift, "N")
      .def_readwrite("aero_a", &pantograph::LumpedPantographData::aero_a, "N·s²/m²")
      .def_readwrite("aero_b", &pantograph::LumpedPantographData::aero_b, "N·s/m")
      .def_readwrite("aero_c", &pantograph::LumpedPantographData::aero_c, "N")
      .def("validate", &pantograph::LumpedPantographData::validate);
  m.def("make_lumped_pantograph", [](const pantograph::LumpedPantographData& d) {
    return make_model(pantograph::make_lumped_pantograph(d));
  }, py::arg("data"), "The lumped pantograph's model (rig joint, contact marker head.cm, outputs y_*, F_contact).");
  m.def("load_lumped_pantograph_data", [](const py::object& path, const py::object& o) {
    return io::load_lumped_pantograph_data(path_arg(path), override_strings(o));
  }, py::arg("path"), py::arg("overrides") = py::none(),
        "The data of a lumped-pantograph file (load_model reads the file as a model).");
  m.def("file_kind", [](const py::object& path) {
    switch (io::file_kind(path_arg(path))) {
      case io::FileKind::Model: return std::string("model");
      case io::FileKind::LumpedPantograph: return std::string("lumped_pantograph");
      case io::FileKind::Catenary: return std::string("catenary");
    }
    return std::string("?");
  }, py::arg("path"), "What an input file is: 'model', 'lumped_pantograph' or 'catenary' (ModelError otherwise).");

  py::class_<solve::Stepper>(m, "Stepper",
                             "An integrator kept alive between calls (solve::Stepper): advance(t_end) integrates from "
                             "time to t_end (s), stopping exactly there.")
      .def(py::init([](const Model& h, const State& x0, double t0, const py::object& integrator) {
             check_state(h.model(), x0);
             return std::make_unique<solve::Stepper>(h.model(), x0, t0,
                                                     integrator_arg(integrator, py::none(), py::none(), py::none(),
                                                                    py::none()));
           }),
           py::arg("model"), py::arg("state"), py::arg("t0") = 0.0, py::arg("integrator") = py::none(),
           py::keep_alive<1, 2>())
      .def("advance", [](solve::Stepper& s, double t_end) {
        run(py::none(), [&](Call&) {
          s.advance(t_end);
          return 0;
        });
      }, py::arg("t_end"), "NumericalError with the time on failure")
      .def_property_readonly("state", &solve::Stepper::state)
      .def_property_readonly("time", &solve::Stepper::time, "s")
      .def_property_readonly("stats", &solve::Stepper::stats);

  m.def("check_model", [](const Model& h) { return mbs::check_model(h.model()); }, py::arg("model"),
        "Same as Model.check().");

}

// Functions of one state.
void bind_state_functions(py::module_& m) {
  using mbs::Body, mbs::Joint, mbs::Marker, mbs::Output, mbs::State;

  // ---- Functions of one state -----------------------------------------------------------------------
  m.def("assemble", [](const Model& h, double t0) {
    mbs::AssemblyReport rep;
    State x = mbs::assemble(h.model(), t0, &rep);
    return py::make_tuple(x, rep);
  }, py::arg("model"), py::arg("t0") = 0.0,
        "(State, AssemblyReport): Newton solve of C(q, t0) = 0 from the tabulated positions, then velocities "
        "projected on C_q q̇ = −C_t. NumericalError if it does not converge.");
  m.def("static_equilibrium", [](const Model& h, const py::object& state, double t0) {
    State x = state_or_assembled(h, state, t0);
    check_state(h.model(), x);
    mbs::EquilibriumReport rep;
    {
      py::gil_scoped_release nogil;
      mbs::static_equilibrium(h.model(), t0, x, &rep);
    }
    return py::make_tuple(x, rep);
  }, py::arg("model"), py::arg("state") = py::none(), py::arg("t0") = 0.0,
        "(State, EquilibriumReport): static equilibrium under all loads from `state` (default: assembled), "
        "velocities zero, internal states relaxed.");
  m.def("consistent_velocities", [](const Model& h, const State& state, double t) {
    State x = state;
    check_state(h.model(), x);
    mbs::consistent_velocities(h.model(), t, x);
    return x;
  }, py::arg("model"), py::arg("state"), py::arg("t") = 0.0,
        "State: a copy of `state` whose velocities are corrected (least norm) onto C_q q̇ = −C_t (eq. 4.2), e.g. the "
        "driving joints' velocities after static_equilibrium.");
  m.def("iso8608_gd0", [](const std::string& c) { return mbs::iso8608_gd0(road_class(c)); }, py::arg("road_class"),
        "G_d(n0) of ISO 8608 class 'A'..'H', m³ (one-sided, n0 = 0.1 cycles/m): 16e-6 · 4^k.");
  m.def("iso8608_psd", [](const std::string& c, double n) { return mbs::iso8608_psd(road_class(c), n); },
        py::arg("road_class"), py::arg("n"), "G_d(n) = G_d(n0) (n/n0)^-2, m³ (n in cycles/m).");
  m.def("iso8608_velocity_psd", [](const std::string& c, double v) { return mbs::iso8608_velocity_psd(road_class(c), v); },
        py::arg("road_class"), py::arg("speed"),
        "White one-sided PSD of the vertical velocity at speed v (m/s): 4π² n0² G_d(n0) v, m²/s² per Hz.");
  m.def("iso8608_variance",
        [](const std::string& c, double lo, double hi) { return mbs::iso8608_variance(road_class(c), lo, hi); },
        py::arg("road_class"), py::arg("n_min"), py::arg("n_max"),
        "∫ G_d dn over [n_min, n_max] (cycles/m), m²: the profile variance in that band.");
  m.def("accelerations", [](const Model& h, double t, const State& x) {
    check_state(h.model(), x);
    mbs::Workspace ws(h.model());
    mbs::accelerations(h.model(), t, x, ws);
    return py::make_tuple(ws.qdd, ws.lambda, ws.zd);
  }, py::arg("model"), py::arg("t"), py::arg("state"),
        "(q̈, λ, ż): eq. 4.12 solved at (t, state) — accelerations (m/s², rad/s²), Lagrange multipliers and the "
        "derivatives of the internal states.");
  m.def("constraints", [](const Model& h, double t, const State& x) {
    check_state(h.model(), x);
    mbs::Workspace ws(h.model());
    mbs::evaluate_constraints(h.model(), t, x, ws);
    return py::make_tuple(ws.C, ws.Ct, ws.Cq, ws.gamma);
  }, py::arg("model"), py::arg("t"), py::arg("state"),
        "(C, C_t, C_q, γ): constraint values, ∂C/∂t, Jacobian and Q_d of eq. 4.3 (mbs::evaluate_constraints).");
  m.def("forces", [](const Model& h, double t, const State& x) {
    check_state(h.model(), x);
    mbs::Workspace ws(h.model());
    ws.set_state(x);
    mbs::evaluate_forces(h.model(), t, x, ws);
    return py::make_tuple(ws.M, ws.Q);
  }, py::arg("model"), py::arg("t"), py::arg("state"),
        "(M + M_I, Q_e + Q_Iv): mass matrix with the inerter mass term (eq. 3.33) and generalised forces "
        "(mbs::evaluate_forces).");
  m.def("joint_reaction", [](const Model& h, const py::object& joint, double t, const State& x,
                             const Eigen::VectorXd& lambda) {
    const int j = py::isinstance<py::str>(joint) ? h.model().find_joint(joint.cast<std::string>()) : joint.cast<int>();
    if (j < 0 || j >= static_cast<int>(h.model().joints.size()))
      throw InvalidArgument(fmt::format("no joint {} in model '{}'", py::str(joint).cast<std::string>(), h.model().name));
    return mbs::joint_reaction(h.model(), j, t, x, lambda);
  }, py::arg("model"), py::arg("joint"), py::arg("t"), py::arg("state"), py::arg("lam"),
        "[Fx, Fy, moment] (N, N·m): reaction of a joint (name or index) on its body j, eq. 4.6.");
  m.def("kinetic_energy", [](const Model& h, const State& x) { return mbs::kinetic_energy(h.model(), x); },
        py::arg("model"), py::arg("state"), "½ q̇ᵀ M q̇ of the bodies, J");
  m.def("stored_energy", [](const Model& h, double t, const State& x) { return mbs::stored_energy(h.model(), t, x); },
        py::arg("model"), py::arg("t"), py::arg("state"), "Σ energy of the force elements, J");
  m.def("element_power", [](const Model& h, double t, const State& x) { return mbs::element_power(h.model(), t, x); },
        py::arg("model"), py::arg("t"), py::arg("state"), "Σ power of the force elements, W");
  m.def("evaluate_output", [](const Model& h, const py::object& output, double t, const State& x) {
    check_state(h.model(), x);
    const mbs::Output& o = h.model().outputs[static_cast<std::size_t>(output_index(h.model(), output))];
    mbs::Workspace ws(h.model());
    ws.set_state(x);
    if (mbs::needs_accelerations(o)) mbs::accelerations(h.model(), t, x, ws);
    return mbs::evaluate_output(o, h.model(), t, x, ws);
  }, py::arg("model"), py::arg("output"), py::arg("t"), py::arg("state"),
        "The value of an output (name or index) at (t, state), SI.");
  m.def("integrate", [](const Model& h, const State& state, double t0, double t_end, double dt_sample,
                        const py::object& integrator, const py::object& method, const py::object& rtol,
                        const py::object& atol, const py::object& max_step) {
    check_state(h.model(), state);
    const solve::IntegratorOptions o = integrator_arg(integrator, method, rtol, atol, max_step);
    return run(py::none(), [&](Call&) {
      State x = state;
      solve::RunStats st = solve::integrate(h.model(), x, t0, t_end, dt_sample, o);
      return std::make_pair(x, st);
    });
  }, py::arg("model"), py::arg("state"), py::arg("t0"), py::arg("t_end"), py::arg("dt_sample"), py::kw_only(),
        py::arg("integrator") = py::none(), py::arg("method") = py::none(), py::arg("rtol") = py::none(),
        py::arg("atol") = py::none(), py::arg("max_step") = py::none(),
        "(final State, RunStats): integrates from (t0, state) to t_end (s) without sampling outputs "
        "(solve::integrate; use simulate for the outputs).");
  m.def("with_suspension", [](const Model& h, const py::object& net, const py::object& params, double l) {
    return py::cast(h).attr("with_suspension")(net, params, l).cast<Model>();
  }, py::arg("model"), py::arg("network"), py::arg("params") = py::none(), py::arg("reference_length") = -1.0,
        "Same as Model.with_suspension.");
  m.def("suspension_index", [](const Model& h) { return pantograph::suspension_index(h.model()); }, py::arg("model"),
        "Index in the model's force elements of its single actuator, the suspension that with_suspension replaces "
        "(pantograph::suspension_index); ModelError if the model has none or more than one.");
  m.def("release_head", [](const Model& h) { return py::cast(h).attr("release_head")(); }, py::arg("model"),
        "Same as Model.release_head: (model, static contact force N).");
}

}  // namespace

void bind_model(py::module_& m) {
  bind_model_parts(m);
  bind_model_class(m);
  bind_model_files(m);
  bind_state_functions(m);
}

}  // namespace inerta::python
