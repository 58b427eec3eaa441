// Tension sections and overlaps (docs/model-format.md "Tension sections"): each section placed along the
// line, its heights from the overlaps' profiles — the pass before each section is compiled as a line of
// its own (fe_compile.hpp).
#include <fmt/format.h>

#include <cmath>
#include <tuple>

#include "inerta/catenary/fe_data.hpp"
#include "inerta/catenary/fe_schema.hpp"
#include "inerta/error.hpp"

namespace inerta::catenary {

std::vector<FeLinkedSection> link_sections(const FeCatenaryData& line) {
  std::vector<FeLinkedSection> out;
  if (!line.sectioned()) return out;
  const std::vector<FeCatenaryData>& tension_sections = line.tension_sections;
  const std::size_t ns = tension_sections.size();
  const int N = line.overlap_spans;
  const double encumbrance = line.encumbrance;
  const std::vector<double>&overlap_outgoing = line.overlap_outgoing, &overlap_incoming = line.overlap_incoming,
                       &overlap_outgoing_x = line.overlap_outgoing_x, &overlap_incoming_x = line.overlap_incoming_x;
  auto fail = [](int k, const std::string& key, const std::string& problem) { throw FeKeyError({k, key, -1}, problem); };
  if (ns < 2) fail(-1, "tension_sections", fmt::format("a line of tension sections needs at least two, got {}", ns));
  if (ns > 100) fail(-1, "tension_sections", fmt::format("at most 100 sections, got {}", ns));
  if (N < 1 || N > 20)
    throw FeKeyError({-1, "overlap.spans", -1},
                          fmt::format("must be 1 … 20 spans (3 and 5 are the usual designs), got {}", N));
  // Each wire's profile over the overlap: (x from its first support, height); at the supports alone
  // without overlap_*_x. Its heights at the supports are checked below.
  const double ov_span = tension_sections.front().span, ov_length = N * ov_span;
  auto profile = [&](const std::vector<double>& z, const std::vector<double>& xs, const char* key) {
    std::vector<std::pair<double, double>> p;
    if (xs.empty()) {
      if (z.size() != static_cast<std::size_t>(N + 1))
        throw FeKeyError({-1, std::string("overlap.") + key, -1},
                              fmt::format("needs one height per overlap support (overlap.spans + 1 = {}), got {}", N + 1, z.size()));
      for (int j = 0; j <= N; ++j) p.emplace_back(j * ov_span, z[static_cast<std::size_t>(j)]);
      return p;
    }
    const std::string k = std::string(key) + ".x";
    if (xs.size() != z.size())
      throw FeKeyError({-1, "overlap." + std::string(key) + ".z", -1},
                            fmt::format("needs one height per point of {} ({} points), got {}", k, xs.size(), z.size()));
    if (xs.size() < 2 || std::abs(xs.front()) > 1e-9 || std::abs(xs.back() - ov_length) > 1e-6 * ov_length)
      throw FeKeyError({-1, "overlap." + k, -1},
                            fmt::format("must run from 0 (the overlap's first support) to overlap.spans spans ({:g} m), got "
                                        "{} point(s) from {:g} to {:g} m",
                                        ov_length, xs.size(), xs.empty() ? 0.0 : xs.front(), xs.empty() ? 0.0 : xs.back()));
    for (std::size_t i = 0; i < xs.size(); ++i) {
      if (!std::isfinite(xs[i]) || (i > 0 && !(xs[i] > xs[i - 1])))
        throw FeKeyError({-1, "overlap." + k, static_cast<int>(i)},
                              fmt::format("must be finite and strictly increasing, got {} m", xs[i]));
      p.emplace_back(xs[i], z[i]);
    }
    p.back().first = ov_length;
    return p;
  };
  const auto out_p = profile(overlap_outgoing, overlap_outgoing_x, "outgoing"),
             in_p = profile(overlap_incoming, overlap_incoming_x, "incoming");
  auto at = [](const std::vector<std::pair<double, double>>& p, double x) {
    std::size_t i = 1;
    while (i + 1 < p.size() && p[i].first < x) ++i;
    const double t = (x - p[i - 1].first) / (p[i].first - p[i - 1].first);
    return p[i - 1].second * (1 - t) + p[i].second * t;
  };
  for (const auto& [p, xs, key] : {std::tuple{&out_p, &overlap_outgoing_x, "outgoing"}, std::tuple{&in_p, &overlap_incoming_x, "incoming"}})
    for (std::size_t i = 0; i < p->size(); ++i)
      if (const double v = (*p)[i].second; !std::isfinite(v) || std::abs(v) >= encumbrance)
        throw FeKeyError({-1, fmt::format("overlap.{}{}", key, xs->empty() ? "" : ".z"), static_cast<int>(i)},
                              fmt::format("must be finite and smaller than the encumbrance ({} m), got {} m", encumbrance, v));
  for (int j = 0; j <= N; ++j) {
    const double o = at(out_p, j * ov_span), in = at(in_p, j * ov_span);
    // Towards its anchor a wire is out of running: the incoming one before the overlap's middle,
    // the outgoing one after it; it must not hang below the running wire there (strictly above
    // at the anchors).
    if (2 * j < N && (j == 0 ? !(in > o) : !(in >= o)))
      throw FeKeyError(overlap_incoming_x.empty() ? FeLocation{-1, "overlap.incoming", j} : FeLocation{-1, "overlap.incoming.z", -1},
                            fmt::format("{} m puts the incoming wire, out of running at overlap support {} (its anchor "
                                        "side), below the running outgoing wire ({} m); it must be above{}",
                                        in, j, o, j == 0 ? " (strictly, at its anchor)" : ""));
    if (2 * j > N && (j == N ? !(o > in) : !(o >= in)))
      throw FeKeyError(overlap_outgoing_x.empty() ? FeLocation{-1, "overlap.outgoing", j} : FeLocation{-1, "overlap.outgoing.z", -1},
                            fmt::format("{} m puts the outgoing wire, out of running at overlap support {} (its anchor "
                                        "side), below the running incoming wire ({} m); it must be above{}",
                                        o, j, in, j == N ? " (strictly, at its anchor)" : ""));
  }
  double start = 0;
  int first = 0;
  for (std::size_t k = 0; k < ns; ++k) {
    const FeCatenaryData& given = tension_sections[k];
    FeLinkedSection linked{given, 0, 0, 1};
    FeCatenaryData& s = linked.line;
    const bool middle = k > 0 && k + 1 < ns;
    const int need = middle ? 2 * N + 1 : N + 1;
    if (s.spans < need)
      fail(static_cast<int>(k), "spans",
           fmt::format("{} span(s) cannot hold {}: an overlap of {} spans is longer than the section allows (at least {} "
                       "spans{})",
                       s.spans, middle ? "its two overlaps" : "its overlap", N, need,
                       middle ? ": its two overlaps must not cross" : ": one of its own besides the overlap"));
    if (k > 0) {
      const FeLinkedSection& p = out[k - 1];
      for (int i = 0; i <= N; ++i) {
        const double mine = start + i * s.span, theirs = p.line_start + (p.line.spans - N + i) * p.line.span;
        if (std::abs(mine - theirs) > 1e-6)
          fail(static_cast<int>(k), "span",
               fmt::format("section {} does not share its overlap supports with section {}: its mast {} is at {:.6g} m, "
                           "theirs at {:.6g} m (spans {} m and {} m); consecutive sections share overlap.spans + 1 = {} masts",
                           k + 1, k, i + 1, mine, theirs, s.span, p.line.span, N + 1));
      }
    }
    linked.line_start = start;
    linked.first_span = first;
    linked.wire_label = static_cast<int>(k % 2) + 1;
    // The section's profile: 0 at its masts outside the overlaps, each overlap's profile over it.
    const double len = s.spans * s.span, out_from = (s.spans - N) * s.span;
    s.height_x.clear(), s.height_z.clear();
    if (k > 0)
      for (const auto& [x, z] : in_p) s.height_x.push_back(x), s.height_z.push_back(z);
    for (int i = 0; i <= s.spans; ++i)
      if (const double x = i * s.span; (k == 0 || x > ov_length + 1e-9) && (k + 1 == ns || x < out_from - 1e-9))
        s.height_x.push_back(x), s.height_z.push_back(0.0);
    if (k + 1 < ns)
      for (const auto& [x, z] : out_p) s.height_x.push_back(out_from + x), s.height_z.push_back(z);
    s.height_x.back() = len;
    s.mast_height.assign(static_cast<std::size_t>(s.spans) + 1, 0.0);
    for (int i = 0; i <= s.spans; ++i) s.mast_height[static_cast<std::size_t>(i)] = s.height_at(i * s.span);
    s.tension_sections.clear();
    start += (s.spans - N) * s.span;
    first += s.spans - N;
    out.push_back(std::move(linked));
  }
  return out;
}

void FeCatenaryData::join_sections() {
  if (!sectioned()) return;
  (void)link_sections(*this);  // they form a line (FeKeyError otherwise)
  spans = line_spans();
  span = tension_sections.front().span;
}

}  // namespace inerta::catenary
