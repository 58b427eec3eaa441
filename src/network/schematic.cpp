// A network as a mechanical schematic in SVG (network/schematic.hpp).
#include "inerta/network/schematic.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace inerta::network {

namespace {

constexpr double kElementW = 120, kElementH = 52, kElementAxis = 16;  // px: symbol above, label below
constexpr double kGap = 10, kLead = 14, kStack = 8, kMargin = 20, kTitle = 22;

// A node's extent and the height of its terminal line from its top.
struct Box {
  double w = 0, h = 0, axis = 0;
};

Box measure(const Network& n) {
  switch (n.kind) {
    case Network::Kind::Spring:
    case Network::Kind::Damper:
    case Network::Kind::Inerter:
    case Network::Kind::Admittance: return {kElementW, kElementH, kElementAxis};
    case Network::Kind::Rigid: return {40, 24, 12};
    case Network::Kind::Open: return {50, 30, 12};
    case Network::Kind::Series: {
      Box b;
      double below = 0;
      for (const Network& c : n.children) {
        const Box cb = measure(c);
        b.w += cb.w + (b.w > 0 ? kGap : 0);
        b.axis = std::max(b.axis, cb.axis);
        below = std::max(below, cb.h - cb.axis);
      }
      b.h = b.axis + below;
      return b;
    }
    case Network::Kind::Parallel: {
      Box b;
      double y = 0, first = 0, last = 0;
      for (std::size_t i = 0; i < n.children.size(); ++i) {
        const Box cb = measure(n.children[i]);
        if (i > 0) y += kStack;
        if (i == 0) first = y + cb.axis;
        last = y + cb.axis;
        y += cb.h;
        b.w = std::max(b.w, cb.w);
      }
      b.w += 2 * kLead;
      b.h = y;
      b.axis = 0.5 * (first + last);
      return b;
    }
  }
  return {};
}

std::string escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '&') r += "&amp;";
    else if (c == '<') r += "&lt;";
    else if (c == '>') r += "&gt;";
    else if (c == '"') r += "&quot;";
    else r += c;
  }
  return r;
}

// "528 kN/m", "61.9 kN·s/m", "526 kg": three digits in the unit an engineer reads.
std::string value_text(Network::Kind k, double v) {
  if (std::isinf(v)) return "∞";
  if (k == Network::Kind::Inerter) return v < 1e3 ? fmt::format("{:.3g} kg", v) : fmt::format("{:.3g} t", 1e-3 * v);
  const char* unit = k == Network::Kind::Spring ? "N/m" : "N·s/m";
  if (v < 1e3) return fmt::format("{:.3g} {}", v, unit);
  if (v < 1e6) return fmt::format("{:.3g} k{}", 1e-3 * v, unit);
  return fmt::format("{:.3g} M{}", 1e-6 * v, unit);
}

class Painter {
 public:
  explicit Painter(const SchematicOptions& o) : o_(o) {}
  std::string svg;

  void line(double x0, double y0, double x1, double y1) {
    svg += fmt::format(R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}"/>)", x0, y0, x1, y1) + "\n";
  }
  void text(double x, double y, const std::string& t, const char* cls) {
    svg += fmt::format(R"(<text x="{:.1f}" y="{:.1f}" class="{}">{}</text>)", x, y, cls, escape(t)) + "\n";
  }

  // Draws n with its top-left corner at (x, y); its terminal line is at y + measure(n).axis.
  void draw(const Network& n, double x, double y) {
    const Box b = measure(n);
    const double a = y + b.axis;
    switch (n.kind) {
      case Network::Kind::Spring:
      case Network::Kind::Damper:
      case Network::Kind::Inerter:
      case Network::Kind::Admittance: element(n, x, a); return;
      case Network::Kind::Rigid: line(x, a, x + b.w, a); return;
      case Network::Kind::Open:
        line(x, a, x + 15, a), line(x + b.w - 15, a, x + b.w, a);
        text(x + 0.5 * b.w, a + 14, "open", "note");
        return;
      case Network::Kind::Series: {
        double cx = x;
        for (std::size_t i = 0; i < n.children.size(); ++i) {
          const Box cb = measure(n.children[i]);
          if (i > 0) line(cx - kGap, a, cx, a);
          draw(n.children[i], cx, a - cb.axis);
          cx += cb.w + kGap;
        }
        return;
      }
      case Network::Kind::Parallel: {
        const double left = x + kLead, right = x + b.w - kLead;
        double cy = y, first = 0, last = 0;
        for (std::size_t i = 0; i < n.children.size(); ++i) {
          const Box cb = measure(n.children[i]);
          if (i > 0) cy += kStack;
          const double ca = cy + cb.axis;
          if (i == 0) first = ca;
          last = ca;
          const double cx = left + 0.5 * (right - left - cb.w);  // centred between the bars
          line(left, ca, cx, ca);
          draw(n.children[i], cx, cy);
          line(cx + cb.w, ca, right, ca);
          cy += cb.h;
        }
        line(left, first, left, last), line(right, first, right, last);
        line(x, a, left, a), line(right, a, x + b.w, a);
        return;
      }
    }
  }

 private:
  void element(const Network& n, double x, double a) {
    const double s0 = x + 0.5 * kElementW - 30, s1 = s0 + 60;  // the symbol's 60 px
    static const char* kinds[] = {"spring", "damper", "inerter"};
    const char* kind = n.is_element() ? kinds[static_cast<int>(n.kind)] : "admittance";
    svg += fmt::format(R"(<g class="element {}" data-name="{}">)", kind, escape(n.name)) + "\n";
    switch (n.kind) {
      case Network::Kind::Spring: {  // a zigzag of 6 teeth
        line(x, a, s0, a), line(s1, a, x + kElementW, a);
        std::string pts = fmt::format("{:.1f},{:.1f}", s0, a);
        for (int i = 0; i < 12; ++i) pts += fmt::format(" {:.1f},{:.1f}", s0 + 5 * (i + 0.5), a + (i % 2 == 0 ? -8.0 : 8.0));
        pts += fmt::format(" {:.1f},{:.1f}", s1, a);
        svg += fmt::format(R"(<polyline points="{}" class="spring"/>)", pts) + "\n";
        break;
      }
      case Network::Kind::Damper: {  // a cup open to the left, the piston in it on the left rod
        line(x, a, s0 + 22, a), line(s0 + 22, a - 7, s0 + 22, a + 7);
        line(s0 + 12, a - 10, s1 - 8, a - 10), line(s0 + 12, a + 10, s1 - 8, a + 10), line(s1 - 8, a - 10, s1 - 8, a + 10);
        line(s1 - 8, a, x + kElementW, a);
        break;
      }
      case Network::Kind::Inerter: {  // a housing with a flywheel, rods to both terminals
        line(x, a, s0 + 8, a), line(s1 - 8, a, x + kElementW, a);
        svg += fmt::format(R"(<rect x="{:.1f}" y="{:.1f}" width="44" height="20" class="inerter"/>)", s0 + 8, a - 10) + "\n";
        svg += fmt::format(R"(<circle cx="{:.1f}" cy="{:.1f}" r="7" class="flywheel"/>)", s0 + 30, a) + "\n";
        break;
      }
      default: {  // a rational admittance
        line(x, a, s0 + 8, a), line(s1 - 8, a, x + kElementW, a);
        svg += fmt::format(R"(<rect x="{:.1f}" y="{:.1f}" width="44" height="20" class="admittance"/>)", s0 + 8, a - 10) + "\n";
        text(s0 + 30, a + 4, "Y(s)", "symbol");
        svg += "</g>\n";
        return;
      }
    }
    std::string label = n.name;
    if (o_.values && n.value > 0) label += " = " + value_text(n.kind, n.value);
    text(x + 0.5 * kElementW, a + 30, label, "label");
    svg += "</g>\n";
  }
  const SchematicOptions& o_;
};

}  // namespace

std::string schematic_svg(const Network& net, const SchematicOptions& options) {
  const Box b = measure(net);
  const std::string title = options.title.empty() ? to_string(net) : options.title;
  const double w = std::max(b.w + 2 * kMargin + 20, 160.0), h = b.h + 2 * kMargin + kTitle;
  const double x0 = 0.5 * (w - b.w), y0 = kMargin + kTitle;
  Painter p(options);
  p.svg = fmt::format(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0:.0f}" height="{1:.0f}" viewBox="0 0 {0:.0f} {1:.0f}" role="img" class="schematic">)"
      "\n<title>{2}</title>\n"
      // scoped to the schematic: inlined in a report, the page's other drawings keep their own style
      "<style>svg.schematic line,svg.schematic polyline,svg.schematic rect,svg.schematic circle{{stroke:#222;"
      "stroke-width:1.6;fill:none}} svg.schematic circle.flywheel{{fill:#222}} svg.schematic circle.terminal{{fill:#fff}} "
      "svg.schematic text{{font-family:sans-serif;font-size:11px;text-anchor:middle;fill:#222}} "
      "svg.schematic text.title{{font-size:13px;font-weight:bold}} svg.schematic text.note{{fill:#777}}</style>\n",
      w, h, escape(title));
  p.text(0.5 * w, kMargin, title, "title");
  const double a = y0 + b.axis;
  p.line(x0 - 10, a, x0, a), p.line(x0 + b.w, a, x0 + b.w + 10, a);
  p.draw(net, x0, y0);
  p.svg += fmt::format(R"(<circle cx="{:.1f}" cy="{:.1f}" r="4" class="terminal"/>)", x0 - 10, a) + "\n";
  p.svg += fmt::format(R"(<circle cx="{:.1f}" cy="{:.1f}" r="4" class="terminal"/>)", x0 + b.w + 10, a) + "\n";
  p.svg += "</svg>\n";
  return p.svg;
}

}  // namespace inerta::network
