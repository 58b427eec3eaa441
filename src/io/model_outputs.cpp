// Model files: named outputs, one CSV column each (docs/model-format.md#outputs). Each output
// type is one registry line below.
#include <fmt/format.h>

#include <cmath>

#include "element_registry.hpp"
#include "model_loader.hpp"

namespace inerta::io::detail {

namespace {

struct OutputSite {
  const Loader& ld;
  const YAML::Node& node;  ///< the output's mapping, keys already checked
  const std::string& what;
  mbs::Output& out;
};
using OutputBuilder = void (*)(const OutputSite&);

// `component:` by name, its index in `names`.
int component(const OutputSite& s, std::initializer_list<const char*> names) {
  std::string c = s.ld.rd.text(s.node, "component", s.what);
  int k = 0;
  for (const char* nm : names) {
    if (c == nm) return k;
    ++k;
  }
  std::string list;
  for (const char* nm : names) list += std::string(list.empty() ? "" : ", ") + nm;
  s.ld.rd.fail(s.node["component"], "component", fmt::format("unknown component '{}'; expected {}", c, list));
}

void coordinate(const OutputSite& s) {
  s.out.kind = mbs::Output::Kind::Coordinate;
  s.out.index = s.ld.body(s.ld.rd.need(s.node, "body", s.what), "body");
  if (s.out.index < 0) s.ld.rd.fail(s.node["body"], "body", "ground has no coordinates");
  s.out.component = s.ld.model.spatial() ? component(s, {"x", "y", "z", "e0", "e1", "e2", "e3"})
                                         : component(s, {"x", "y", "theta"});
}

void point(const OutputSite& s, mbs::Output::Kind kind) {
  s.out.kind = kind;
  s.out.index = s.ld.marker(s.ld.rd.need(s.node, "marker", s.what), "marker");
  s.out.component = s.ld.model.spatial() ? component(s, {"x", "y", "z"}) : component(s, {"x", "y"});
}
void position(const OutputSite& s) { point(s, mbs::Output::Kind::Position); }
void velocity(const OutputSite& s) { point(s, mbs::Output::Kind::Velocity); }
void acceleration(const OutputSite& s) { point(s, mbs::Output::Kind::Acceleration); }

// The force element named by `element`; a rigid network (a distance joint) gets a hint.
void of_element(const OutputSite& s, mbs::Output::Kind kind) {
  const mbs::Model& model = s.ld.model;
  const std::string e = s.ld.rd.text(s.node, "element", s.what);
  const int k = model.find_force(e), j = model.find_joint(e);
  if (k < 0 && j >= 0 && model.joints[static_cast<std::size_t>(j)].type == mbs::JointType::Distance)
    s.ld.rd.fail(s.node["element"], "element",
                 fmt::format("'{}' is a rigid network (a distance joint); expected type: multiplier, joint: {}, "
                             "component: 0 for its tension",
                             e, e));
  if (k < 0) s.ld.rd.fail(s.node["element"], "element", fmt::format("unknown force element '{}'", e));
  s.out.kind = kind;
  s.out.index = k;
}
void force(const OutputSite& s) { of_element(s, mbs::Output::Kind::ElementForce); }
void length(const OutputSite& s) { of_element(s, mbs::Output::Kind::ElementLength); }

int joint(const OutputSite& s) {
  const std::string jn = s.ld.rd.text(s.node, "joint", s.what);
  const int j = s.ld.model.find_joint(jn);
  if (j < 0) s.ld.rd.fail(s.node["joint"], "joint", fmt::format("unknown joint '{}'", jn));
  return j;
}

void reaction(const OutputSite& s) {  // −C_q,jᵀλ on body j (eq. 4.6)
  s.out.index = joint(s);
  s.out.kind = mbs::Output::Kind::Reaction;
  s.out.component = s.ld.model.spatial() ? component(s, {"x", "y", "z"}) : component(s, {"x", "y", "moment"});
}

void multiplier(const OutputSite& s) {
  s.out.index = joint(s);
  s.out.kind = mbs::Output::Kind::Multiplier;
  const double c = s.ld.rd.number(s.node, "component", s.what);
  const int rows = s.ld.model.joints[static_cast<std::size_t>(s.out.index)].rows();
  if (c != std::floor(c) || c < 0 || c >= rows)
    s.ld.rd.fail(s.node["component"], "component", fmt::format("expected an equation index 0..{}", rows - 1));
  s.out.component = static_cast<int>(c);
}

const ElementRegistry<OutputBuilder>& output_types() {
  static const ElementRegistry<OutputBuilder> registry = [] {
    ElementRegistry<OutputBuilder> r("output");
    r.add("coordinate", {"body", "component", "scale"}, coordinate)
        .add("position", {"marker", "component", "scale"}, position)
        .add("velocity", {"marker", "component", "scale"}, velocity)
        .add("acceleration", {"marker", "component", "scale"}, acceleration)
        .add("force", {"element", "scale"}, force)
        .add("length", {"element", "scale"}, length)
        .add("reaction", {"joint", "component", "scale"}, reaction)
        .add("multiplier", {"joint", "component", "scale"}, multiplier);
    return r;
  }();
  return registry;
}

}  // namespace

void Loader::outputs(const YAML::Node& n) {
  if (!n.IsDefined()) return;
  if (!n.IsSequence()) rd.fail(n, "outputs", "expected a list of outputs");
  names_unique(n, "output");
  for (const auto& o : n) {
    mbs::Output out;
    out.name = rd.text(o, "name", "output");
    if (out.name == "t" || out.name.find(',') != std::string::npos)
      rd.fail(o["name"], "name", "an output may not be called 't' or contain ','");
    const std::string what = "output '" + out.name + "'";
    output_types().entry(rd, o, what).build({*this, o, what, out});
    out.scale = rd.number_or(o, "scale", 1.0);
    model.outputs.push_back(out);
  }
}

}  // namespace inerta::io::detail
