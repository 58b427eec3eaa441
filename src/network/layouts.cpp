#include "inerta/network/layouts.hpp"

#include <fmt/format.h>

namespace inerta::network {

const std::vector<Layout>& layouts() {
  // spec/03 §3.2; "‖" written "|", "—" written "-".
  static const std::vector<Layout> table = {
      {"S1-default", "c", {{"c", 600.0}}, "chapter-4 pantograph base damper"},
      {"S1-0", "b", {}, "single inerter"},
      {"S1-1", "b|c", {}, ""},
      {"S1-2", "b-c", {}, ""},
      {"S1-3", "b-(k|c)", {}, "tuned inerter damper (TID)"},
      {"S1-1*", "b|c", {{"c", 600.0}}, "keeps the original damper"},
      {"S2-default", "k-c", {{"k", 141e3}, {"c", 10.44e3}}, "HSX actuator dynamics (Maxwell element)"},
      {"S2-1", "b|c|k", {}, ""},
      {"S2-2", "k-(b|c)", {}, "tuned viscous mass damper (TVMD) form"},
      {"S2-3", "b|c", {}, "S2-1 without the spring"},
      {"S2-4", "c|k", {}, "S2-1 without the inerter"},
      {"S2-5", "k", {}, ""},
      {"S2-1*", "b|c|k", {{"c", 10.44e3}}, "S2-1 keeping the actuator damping"},
  };
  return table;
}

std::optional<Layout> find_layout(const std::string& name) {
  for (const auto& l : layouts())
    if (l.name == name) return l;
  return std::nullopt;
}

Network resolve(const std::string& text, const Params& params) {
  std::optional<Layout> layout = find_layout(text);
  Params all;
  Network net;
  if (layout) {
    net = parse(layout->expression);
    all = layout->fixed;
    for (const auto& [k, v] : params) {
      if (all.count(k))
        throw NetworkError(fmt::format("layout {} fixes {} = {:g}; it cannot be set (use the expression '{}' to "
                                       "choose every value)",
                                       layout->name, k, all.at(k), layout->expression),
                           0);
      all[k] = v;
    }
  } else {
    net = parse(text);
    all = params;
  }
  return assign(net, all);
}

}  // namespace inerta::network
