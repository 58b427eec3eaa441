// Pass 3 of compiling a line (fe_compile.hpp): the stitch wires (docs/catenary-fe.md "Stitch wire").
#include "fe_compile.hpp"

namespace inerta::catenary::compile {

void stitch_wires(const FeCatenaryData& d, const Mesh& mesh, Wires& w) {
  if (!d.has_stitch()) return;
  const FeStitch& st = d.stitch;
  const int N = static_cast<int>(mesh.x.size());
  for (int i = 0; i + 1 < N; ++i) {  // part of the upper structure (with the messenger)
    const char a = mesh.on_stitch[static_cast<std::size_t>(i)], b = mesh.on_stitch[static_cast<std::size_t>(i) + 1];
    if (!a || !b || (a == 2 && b == 2)) continue;  // two clamps in a row: of two stitch wires
    const double l = mesh.x[static_cast<std::size_t>(i) + 1] - mesh.x[static_cast<std::size_t>(i)];
    const std::array<int, 4> dd{mesh.at(2, i, 0), mesh.at(2, i, 1), mesh.at(2, i + 1, 0), mesh.at(2, i + 1, 1)};
    add_block(w.k[0], dd, beam_stiffness(st.wire.EI, st.wire.tension, l));
    add_block(w.m[0], dd, beam_mass(st.wire.mass_per_length, l));
    const double q = -st.wire.mass_per_length * d.gravity;
    const std::array<double, 4> f{q * l / 2, q * l * l / 12, q * l / 2, -q * l * l / 12};
    for (int a2 = 0; a2 < 4; ++a2)
      if (dd[a2] >= 0) w.fg[0][dd[a2]] += f[a2];
  }
  for (int i = 0; i < N; ++i)  // clamp masses on the messenger
    if (mesh.on_stitch[static_cast<std::size_t>(i)] == 2) {
      const int k = mesh.at(0, i, 0);
      w.m[0].emplace_back(k, k, st.clamp_mass);
      w.fg[0][k] -= st.clamp_mass * d.gravity;
    }
}

}  // namespace inerta::catenary::compile
