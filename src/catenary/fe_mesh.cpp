// Pass 1 of compiling a line (fe_compile.hpp): marks, stations and DOFs.
#include <algorithm>
#include <cmath>

#include "fe_compile.hpp"

namespace inerta::catenary::compile {

void add_block(Triplets& t, const std::array<int, 4>& d, const Eigen::Matrix4d& k) {
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      if (d[a] >= 0 && d[b] >= 0 && k(a, b) != 0) t.emplace_back(d[a], d[b], k(a, b));
}

Mesh mesh(const FeCatenaryData& d) {
  Mesh m;
  // Per span its marks in order. A stitch wire at every interior mast (FeStitch); the stitch droppers
  // on the line's side of an end mast, and all of them without the stitch wire, hang from the messenger.
  const FeStitch& st = d.stitch;
  const bool stitched = d.has_stitch();
  using K = Mark::Kind;
  for (int s = 0; s < d.spans; ++s) {
    std::vector<Mark> it{{K::Mast, 0.0, 0, false}};  // x from the span's first mast
    for (std::size_t j = 0; j < d.dropper_x.size(); ++j) it.push_back({K::SpanDropper, d.dropper_x[j], static_cast<int>(j), false});
    if (st.present) {
      const bool behind_stitch = stitched && s > 0, ahead_stitch = stitched && s + 1 < d.spans;  // the masts at s, s + 1
      for (std::size_t j = 0; j < st.dropper_x.size(); ++j) {
        const double p = st.dropper_x[j];
        if (p > 0) it.push_back({K::StitchDropper, p, static_cast<int>(j), behind_stitch});
        if (p < 0) it.push_back({K::StitchDropper, d.span + p, static_cast<int>(j), ahead_stitch});
      }
      if (behind_stitch) it.push_back({K::StitchEnd, 0.5 * st.length, 0, false});
      if (ahead_stitch) it.push_back({K::StitchEnd, d.span - 0.5 * st.length, 1, false});
      std::stable_sort(it.begin(), it.end(), [](const Mark& a, const Mark& b) { return a.x < b.x; });
    }
    for (Mark& k : it) {
      k.x = k.kind == K::Mast ? s * d.span : s * d.span + k.x;
      m.marks.push_back(k);
    }
  }
  // Stations at the marks, each interval divided into equal elements <= h.
  const double end = d.spans * d.span;
  for (std::size_t i = 0; i < m.marks.size(); ++i) {
    const double a = m.marks[i].x, b = i + 1 < m.marks.size() ? m.marks[i + 1].x : end;
    m.mark_node.push_back(static_cast<int>(m.x.size()));
    const int n = std::max(1, static_cast<int>(std::ceil((b - a) / d.element_length - 1e-9)));
    for (int k = 0; k < n; ++k) m.x.push_back(a + (b - a) * k / n);
  }
  m.mark_node.push_back(static_cast<int>(m.x.size()));
  m.x.push_back(end);
  const int N = static_cast<int>(m.x.size());
  for (std::size_t i = 1; i < m.marks.size(); ++i)
    if (m.marks[i].kind == K::Mast) m.mast_nodes.push_back(m.mark_node[i]);
  if (!d.anchor.pinned) m.end_nodes = {0, N - 1};
  // The stitch wire's stations: from its clamp behind a mast to its clamp ahead.
  m.on_stitch.assign(static_cast<std::size_t>(N), 0);
  if (stitched)
    for (std::size_t i = 0; i < m.marks.size(); ++i)
      if (m.marks[i].kind == K::StitchEnd && m.marks[i].index == 1) {
        std::size_t e = i + 1;
        while (!(m.marks[e].kind == K::StitchEnd && m.marks[e].index == 0)) ++e;
        for (int n = m.mark_node[i]; n <= m.mark_node[e]; ++n) m.on_stitch[static_cast<std::size_t>(n)] = 1;
        m.on_stitch[static_cast<std::size_t>(m.mark_node[i])] = m.on_stitch[static_cast<std::size_t>(m.mark_node[e])] = 2;
      }
  m.dof.assign(static_cast<std::size_t>(N) * 2 * FeLine::kWires, -1);
  for (int i = 0; i < N; ++i)
    for (int w = 0; w < FeLine::kWires; ++w)
      for (int c = 0; c < 2; ++c) {
        int& slot = m.dof[static_cast<std::size_t>((i * FeLine::kWires + w) * 2 + c)];
        if (w == 2) {
          const char o = m.on_stitch[static_cast<std::size_t>(i)];
          if (o == 0) continue;
          if (o == 2 && c == 0) {  // clamped to the messenger: the same vertical displacement
            slot = m.at(0, i, 0);
            continue;
          }
        }
        if (!(c == 0 && (i == 0 || i == N - 1) && d.anchor.pinned)) slot = m.n_dofs++;
      }
  return m;
}

}  // namespace inerta::catenary::compile
