// Catenaries through the generic interface (catenary::Catenary, io::load_catenary): every type
// that the catenary-file reader knows works without changes here; the lumped catenary and the
// wire profile can also be built from Python objects.
#include <cxxabi.h>
#include <fmt/format.h>

#include <typeinfo>

#include "common.hpp"
#include "inerta/catenary/contact.hpp"
#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/catenary/lumped.hpp"
#include "inerta/catenary/wire_profile.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"

namespace inerta::python {

CatenaryArg catenary_arg(const py::object& o) {
  if (py::isinstance<io::CatenaryFile>(o)) {
    const auto& f = o.cast<const io::CatenaryFile&>();
    if (!f.catenary)
      throw InvalidArgument(fmt::format("catenary file '{}' was read without making its catenary (read_catenary_file); "
                                        "use load_catenary",
                                        f.name));
    return {f.catenary, f.contact};
  }
  if (py::isinstance<catenary::Catenary>(o)) return {o.cast<std::shared_ptr<catenary::Catenary>>(), std::nullopt};
  if (py::isinstance<py::str>(o) || py::hasattr(o, "__fspath__")) {
    io::CatenaryFile f = io::load_catenary(path_arg(o));
    return {f.catenary, f.contact};
  }
  throw py::type_error("expected a Catenary, a CatenaryFile (load_catenary) or a catenary file name");
}

namespace {

catenary::Contact::Kind kind_of(const std::string& s) {
  if (s == "bilateral") return catenary::Contact::Kind::Bilateral;
  if (s == "penalty") return catenary::Contact::Kind::Penalty;
  throw InvalidArgument(fmt::format("contact: expected 'bilateral' or 'penalty', got '{}'", s));
}

std::string type_name(const catenary::Catenary& c) {
  if (dynamic_cast<const catenary::Lumped*>(&c)) return "lumped";
  if (dynamic_cast<const catenary::WireProfileCatenary*>(&c)) return "wire_profile";
  if (dynamic_cast<const catenary::FeCatenary*>(&c)) return "finite_element";
  int status = 0;
  char* d = abi::__cxa_demangle(typeid(c).name(), nullptr, nullptr, &status);
  std::string n = status == 0 && d ? d : typeid(c).name();
  std::free(d);
  return n;
}

std::shared_ptr<catenary::Catenary> mutable_ptr(std::shared_ptr<const catenary::Catenary> c) {
  return std::const_pointer_cast<catenary::Catenary>(std::move(c));
}

}  // namespace

catenary::Contact contact_arg(const py::object& contact, const CatenaryArg& cat) {
  if (!contact.is_none()) {
    if (py::isinstance<py::str>(contact)) {
      catenary::Contact c = cat.contact.value_or(catenary::Contact{});
      c.kind = kind_of(contact.cast<std::string>());
      return c;
    }
    return contact.cast<catenary::Contact>();
  }
  return cat.contact.value_or(catenary::Contact{});
}

void bind_catenary(py::module_& m) {
  using catenary::Contact;
  py::class_<Contact> contact(m, "Contact",
                              "The contact law of a pantograph: bilateral (the thesis's joint; the force must stay >= 0) "
                              "or a unilateral penalty F = max(0, k_s δ + c_s δ̇).");
  contact
      .def(py::init([](const std::string& kind, double stiffness, double damping) {
             Contact c;
             c.kind = kind_of(kind);
             c.stiffness = stiffness;
             c.damping = damping;
             c.validate();
             return c;
           }),
           py::arg("kind") = "bilateral", py::arg("stiffness") = 50e3, py::arg("damping") = 0.0,
           "kind 'bilateral' or 'penalty'; stiffness k_s (N/m, > 0), damping c_s (N·s/m, >= 0). InvalidArgument for "
           "other values.")
      .def_property("kind", [](const Contact& c) { return std::string(catenary::kind_name(c.kind)); },
                    [](Contact& c, const std::string& k) { c.kind = kind_of(k); }, "'bilateral' or 'penalty'")
      .def_readwrite("stiffness", &Contact::stiffness, "penalty k_s, N/m")
      .def_readwrite("damping", &Contact::damping, "penalty c_s, N·s/m")
      .def("validate", &Contact::validate)
      .def("__repr__", [](const Contact& c) {
        return fmt::format("Contact('{}', stiffness={:g}, damping={:g})", catenary::kind_name(c.kind), c.stiffness,
                           c.damping);
      });
  m.def("kind_name", [](const Contact& c) { return std::string(catenary::kind_name(c.kind)); }, py::arg("contact"),
        "'bilateral' or 'penalty'");

  py::class_<catenary::LumpedCatenary>(m, "LumpedCatenary",
                                       "Parameters of the time-varying lumped catenary (eq. 7.1): span L (m) and the "
                                       "harmonics x_0..x_3 of mass m (kg), damping c (N·s/m) and stiffness k (N/m). "
                                       "Assign whole lists: cat.k = [5000, 1500, 250, 100].")
      .def(py::init([](double span, std::array<double, 4> mass, std::array<double, 4> damping,
                       std::array<double, 4> stiffness) {
             catenary::LumpedCatenary c;
             c.span = span, c.m = mass, c.c = damping, c.k = stiffness;
             return c;
           }),
           py::arg("span") = 60.0, py::arg("m") = std::array<double, 4>{177.3, 0, 0, 0},
           py::arg("c") = std::array<double, 4>{111.0, 0, 0, 0},
           py::arg("k") = std::array<double, 4>{7000.0, 2100.0, 350.0, 140.0})
      .def_readwrite("span", &catenary::LumpedCatenary::span, "m")
      .def_readwrite("m", &catenary::LumpedCatenary::m, "m_c0..m_c3, kg")
      .def_readwrite("c", &catenary::LumpedCatenary::c, "c_c0..c_c3, N·s/m")
      .def_readwrite("k", &catenary::LumpedCatenary::k, "k_c0..k_c3, N/m")
      .def("natural_frequency", &catenary::LumpedCatenary::natural_frequency, "(1/2π) sqrt(k_c0/m_c0), Hz")
      .def("validate", &catenary::LumpedCatenary::validate)
      .def_static("harmonic", &catenary::LumpedCatenary::harmonic, py::arg("x"), py::arg("fp"), py::arg("t"),
                  "Σ x_i cos(2π i f_p t)")
      .def_static("harmonic_rate", &catenary::LumpedCatenary::harmonic_rate, py::arg("x"), py::arg("fp"), py::arg("t"));

  py::class_<catenary::WireProfile>(m, "WireProfile",
                                    "A rigid wire of prescribed heights: x (m, increasing) and h (m); periodic (the "
                                    "last height equals the first) or with a span (m) for the statistics windows.")
      .def(py::init([](std::vector<double> x, std::vector<double> h, bool periodic, double span) {
             return catenary::WireProfile{std::move(x), std::move(h), periodic, span};
           }),
           py::arg("x"), py::arg("h"), py::arg("periodic") = true, py::arg("span") = 0.0)
      .def_readwrite("x", &catenary::WireProfile::x)
      .def_readwrite("h", &catenary::WireProfile::h)
      .def_readwrite("periodic", &catenary::WireProfile::periodic)
      .def_readwrite("span", &catenary::WireProfile::span);

  py::class_<catenary::Section>(m, "Section", "A stretch of the line, m along it; unpacks as (from_, to).")
      .def(py::init([](double a, double b) { return catenary::Section{a, b}; }), py::arg("from_"), py::arg("to"))
      .def_readwrite("from_", &catenary::Section::from, "m")
      .def_readwrite("to", &catenary::Section::to, "m")
      .def("__len__", [](const catenary::Section&) { return 2; })
      .def("__getitem__", [](const catenary::Section& s, int i) {
        if (i == 0 || i == -2) return s.from;
        if (i == 1 || i == -1) return s.to;
        throw py::index_error("a Section has two values");
      })
      .def("__repr__", [](const catenary::Section& s) { return fmt::format("Section({:g}, {:g})", s.from, s.to); });

  py::class_<catenary::Catenary, std::shared_ptr<catenary::Catenary>>(
      m, "Catenary",
      "A catenary of any type (the library's catenary::Catenary interface): lumped, wire profile, and every type "
      "that catenary files can name. Analyses take it with a Contact.")
      .def_property_readonly("type", [](const catenary::Catenary& c) { return type_name(c); },
                             "'lumped', 'wire_profile', 'finite_element', or the C++ class name of another type")
      .def("describe", &catenary::Catenary::describe, "one line with its key numbers")
      .def_property_readonly("span", &catenary::Catenary::span, "m: the period of the line (statistics windows)")
      .def_property_readonly("max_pantographs", &catenary::Catenary::max_pantographs)
      .def_property_readonly("line_length", &catenary::Catenary::line_length, "m (inf for a periodic catenary)")
      .def("section", &catenary::Catenary::section, "Section (from_, to; m): the analysis section of a finite line")
      .def("mean", [](const catenary::Catenary& c) { return mutable_ptr(c.mean()); },
           "The catenary without its variation along the line (modes about a static equilibrium).")
      .def("point_model", [](const catenary::Catenary& c) -> py::object {
        const auto* p = c.point_model();
        return p ? py::cast(*p) : py::object(py::none());
      }, "The LumpedCatenary parameters if the catenary is a point model (the periodic fast path needs it), else None.")
      .def("__repr__", [](const catenary::Catenary& c) { return fmt::format("Catenary({})", c.describe()); });

  py::class_<catenary::Lumped, catenary::Catenary, std::shared_ptr<catenary::Lumped>>(
      m, "Lumped", "The lumped catenary as a catenary type (embedded, one pantograph).")
      .def(py::init<catenary::LumpedCatenary>(), py::arg("params"),
           "InvalidArgument unless span > 0, m_c0 > 0, k_c0 > 0, c_c0 >= 0 and the coefficients stay positive.")
      .def(py::init([]() { return catenary::Lumped(catenary::LumpedCatenary{}); }), "The default set (models/catenary.yaml).")
      .def_property_readonly("params", &catenary::Lumped::params);

  py::class_<catenary::WireProfileCatenary, catenary::Catenary, std::shared_ptr<catenary::WireProfileCatenary>>(
      m, "WireProfileCatenary", "A rigid wire of prescribed heights touched through a penalty contact (several pantographs).")
      .def(py::init<catenary::WireProfile>(), py::arg("profile"))
      .def_property_readonly("profile", &catenary::WireProfileCatenary::profile);

  py::class_<io::CatenaryFile>(m, "CatenaryFile", "A catenary file as read: its name, the catenary and the contact law.")
      .def_readonly("name", &io::CatenaryFile::name)
      .def_property_readonly("catenary", [](const io::CatenaryFile& f) { return mutable_ptr(f.catenary); },
                             "the catenary (None after read_catenary_file for a finite-element file)")
      .def_readonly("contact", &io::CatenaryFile::contact)
      .def_readonly("fe", &io::CatenaryFile::fe, "type finite_element: the data it was made from, else None")
      .def_readonly("path", &io::CatenaryFile::path, "the file it was read from")
      .def_readonly("overrides", &io::CatenaryFile::overrides, "the overrides applied, NAME.KEY=VALUE")
      .def(py::pickle(  // a Dask worker reads the same file again (docs/distributed.md): the path must be visible there
          [](const io::CatenaryFile& f) {
            if (f.path.empty() || !f.catenary)
              throw py::type_error("this CatenaryFile was not read by load_catenary, so it cannot be sent to another process");
            return py::make_tuple(f.path, f.overrides);
          },
          [](const py::tuple& t) {
            return io::load_catenary(t[0].cast<std::string>(), t[1].cast<std::vector<std::string>>());
          }))
      .def("describe", [](const io::CatenaryFile& f) { return f.catenary ? f.catenary->describe() : f.name; })
      .def("__repr__", [](const io::CatenaryFile& f) {
        return fmt::format("CatenaryFile('{}': {}, {} contact)", f.name, f.catenary ? f.catenary->describe() : "not made",
                           catenary::kind_name(f.contact.kind));
      });
  m.def("load_catenary", [](const py::object& path, const py::object& overrides) {
    return io::load_catenary(path_arg(path), override_strings(overrides));
  }, py::arg("path"), py::arg("overrides") = py::none(),
        "Reads a catenary file of any type (io::load_catenary) with overrides {'catenary.kc0': 5000, "
        "'contact.type': 'penalty'} or ['catenary.kc0=5000']. ModelError 'file:line: ...' for a bad file.");

  py::class_<catenary::PantographOnLine>(m, "PantographOnLine",
                                         "One pantograph on the line: the model, the position x0 (m) of its contact "
                                         "point along the line at t = 0, and its contact law.")
      .def(py::init([](const Model& model, double x0, const Contact& c) {
             return catenary::PantographOnLine{model.p, x0, c};
           }),
           py::arg("model"), py::arg("x0") = 0.0, py::arg("contact") = Contact{})
      .def_property_readonly("model", [](const catenary::PantographOnLine& p) { return make_model(p.pantograph); })
      .def_readwrite("x0", &catenary::PantographOnLine::x0, "m")
      .def_readwrite("contact", &catenary::PantographOnLine::contact);

  py::class_<catenary::LumpedCoupling>(m, "LumpedCoupling",
                                       "One pantograph coupled to a lumped catenary: the multibody model with the wire "
                                       "and its typed handles (catenary::couple_lumped).")
      .def_property_readonly("model", [](const catenary::LumpedCoupling& c) { return make_model(c.model); })
      .def_readonly("wire_body", &catenary::LumpedCoupling::wire_body)
      .def_readonly("wire_y", &catenary::LumpedCoupling::wire_y, "index of the wire's vertical coordinate in q")
      .def_readonly("element", &catenary::LumpedCoupling::element, "index of the catenary element in the forces")
      .def_readonly("contact_force", &catenary::LumpedCoupling::contact_force, "output F_contact (compression +)")
      .def_readonly("y_unloaded", &catenary::LumpedCoupling::y_unloaded, "m")
      .def_readonly("bilateral", &catenary::LumpedCoupling::bilateral);
  m.def("couple_lumped", [](const Model& p, const catenary::LumpedCatenary& cat, const Contact& c, double speed) {
    return catenary::couple_lumped(p.p, cat, c, speed);
  }, py::arg("model"), py::arg("catenary"), py::arg("contact"), py::arg("speed"),
        "The pantograph coupled to a lumped catenary at `speed` (m/s): rig hold removed, wire body, catenary element, "
        "contact and the output F_contact added.");
}

}  // namespace inerta::python
