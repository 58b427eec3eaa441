// Pass 2 of compiling a line (fe_compile.hpp): the messenger's and the contact wire's elements, and
// what the masts and anchors add to them.
#include "fe_compile.hpp"

namespace inerta::catenary {

// Element matrices on [w_i, θ_i, w_j, θ_j] (fe_line.hpp's header comment).
Eigen::Matrix4d beam_stiffness(double EI, double T, double l) {
  Eigen::Matrix4d kb, kg;
  const double l2 = l * l;
  kb << 12, 6 * l, -12, 6 * l, 6 * l, 4 * l2, -6 * l, 2 * l2, -12, -6 * l, 12, -6 * l, 6 * l, 2 * l2, -6 * l, 4 * l2;
  kg << 36, 3 * l, -36, 3 * l, 3 * l, 4 * l2, -3 * l, -l2, -36, -3 * l, 36, -3 * l, 3 * l, -l2, -3 * l, 4 * l2;
  return EI / (l2 * l) * kb + T / (30 * l) * kg;
}

Eigen::Matrix4d beam_mass(double rhoA, double l) {
  Eigen::Matrix4d m;
  const double l2 = l * l;
  m << 156, 22 * l, 54, -13 * l, 22 * l, 4 * l2, 13 * l, -3 * l2, 54, 13 * l, 156, -22 * l, -13 * l, -3 * l2, -22 * l,
      4 * l2;
  return rhoA * l / 420 * m;
}

namespace compile {

Wires wires(const FeCatenaryData& d, const Mesh& mesh) {
  Wires out;
  const int N = static_cast<int>(mesh.x.size());
  const FeWire* wire[2] = {&d.messenger, &d.contact_wire};
  for (int w = 0; w < 2; ++w) {
    out.EI[w].assign(static_cast<std::size_t>(N - 1), wire[w]->EI);
    out.mass_per_length[w].assign(static_cast<std::size_t>(N - 1), wire[w]->mass_per_length);
  }
  if (d.wear.any())  // the contact wire's section remaining at each element's middle (FeWear): ρA × p, EI × p²
    for (int i = 0; i + 1 < N; ++i) {
      const std::size_t e = static_cast<std::size_t>(i);
      const double p = d.wear.at(0.5 * (mesh.x[e] + mesh.x[e + 1])) / 100;
      out.mass_per_length[1][e] *= p;
      out.EI[1][e] *= p * p;
    }
  for (int w = 0; w < 2; ++w) {
    out.fg[w] = Eigen::VectorXd::Zero(mesh.n_dofs);
    for (int i = 0; i + 1 < N; ++i) {
      const double l = mesh.x[static_cast<std::size_t>(i) + 1] - mesh.x[static_cast<std::size_t>(i)];
      const double EI = out.EI[w][static_cast<std::size_t>(i)], rhoA = out.mass_per_length[w][static_cast<std::size_t>(i)];
      const std::array<int, 4> dd{mesh.at(w, i, 0), mesh.at(w, i, 1), mesh.at(w, i + 1, 0), mesh.at(w, i + 1, 1)};
      add_block(out.k[w], dd, beam_stiffness(EI, wire[w]->tension, l));
      add_block(out.m[w], dd, beam_mass(rhoA, l));
      const double q = -rhoA * d.gravity;  // consistent load of a uniform weight
      const std::array<double, 4> f{q * l / 2, q * l * l / 12, q * l / 2, -q * l * l / 12};
      for (int a = 0; a < 4; ++a)
        if (dd[a] >= 0) out.fg[w][dd[a]] += f[a];
    }
    for (int n : mesh.mast_nodes) {  // messenger supports, contact-wire registrations
      const int k = mesh.at(w, n, 0);
      out.k[w].emplace_back(k, k, w == 0 ? d.support_stiffness : d.registration_stiffness);
      const double m = w == 0 ? d.support_mass : d.registration_mass;
      out.m[w].emplace_back(k, k, m);
      out.fg[w][k] -= m * d.gravity;
    }
    for (int n : mesh.end_nodes) {  // a tensioning device at the anchors: its vertical stiffness and mass
      const int k = mesh.at(w, n, 0);
      out.k[w].emplace_back(k, k, d.anchor.stiffness);
      out.m[w].emplace_back(k, k, d.anchor.mass);
      out.fg[w][k] -= d.anchor.mass * d.gravity;
    }
  }
  return out;
}

}  // namespace compile
}  // namespace inerta::catenary
