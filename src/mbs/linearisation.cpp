#include "inerta/mbs/linearisation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "inerta/error.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "inerta/numerics/finite_difference.hpp"

namespace inerta::mbs {

namespace {

// Coordinate partitioning (spec/02 §2.5): QR of C_q with column pivoting; the pivot columns are the
// dependent coordinates, the others (ascending) are ξ, and N = [I; −C_d⁻¹ C_i] in that partition.
void partition(const Model& model, const Workspace& ws, LinearModel& L, std::vector<int>& dependent) {
  const int n = model.n_coords();
  dependent.clear();
  if (model.n_constraints() > 0) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(ws.Cq);
    qr.setThreshold(1e-10);
    const auto& perm = qr.colsPermutation().indices();
    for (Eigen::Index k = 0; k < qr.rank(); ++k) dependent.push_back(perm[k]);
    std::sort(dependent.begin(), dependent.end());
  }
  L.independent.clear();
  for (int k = 0; k < n; ++k)
    if (!std::binary_search(dependent.begin(), dependent.end(), k)) L.independent.push_back(k);
  const int d = static_cast<int>(L.independent.size());
  L.N = Eigen::MatrixXd::Zero(n, d);
  L.Nt = Eigen::MatrixXd::Zero(d, n);
  for (int k = 0; k < d; ++k) L.N(L.independent[static_cast<std::size_t>(k)], k) = L.Nt(k, L.independent[static_cast<std::size_t>(k)]) = 1;
  if (!dependent.empty() && d > 0) {
    const Eigen::MatrixXd Cd = ws.Cq(Eigen::all, dependent), Ci = ws.Cq(Eigen::all, L.independent);
    const Eigen::MatrixXd Nd = -Cd.colPivHouseholderQr().solve(Ci);
    for (std::size_t r = 0; r < dependent.size(); ++r) L.N.row(dependent[r]) = Nd.row(static_cast<Eigen::Index>(r));
  }
  L.dof = d;
  L.nz = model.n_states();
}

// M, C, K of the reduced model from A (z held) and the mass matrix at the equilibrium.
void reduced_matrices(const Model& model, LinearModel& L, Workspace& ws) {
  const int d = L.dof;
  evaluate_forces(model, L.t, L.equilibrium, ws);
  L.M = L.N.transpose() * ws.M * L.N;
  L.K = -L.M * L.A.block(d, 0, d, d);
  L.C = -L.M * L.A.block(d, d, d, d);
}

// The time function with value a, rate b and second derivative c at t0.
TimeFunction motion_at(double t0, double a, double b, double c) { return TimeFunction::polynomial({a, b, 0.5 * c}, t0); }

}  // namespace

LinearModel linearise(const Model& model, const State& x, double t) {
  const int nz = model.n_states();
  Workspace ws(model);
  LinearModel L;
  L.equilibrium = x;
  L.t = t;
  evaluate_constraints(model, t, x, ws);
  std::vector<int> dependent;
  partition(model, ws, L, dependent);
  const int d = L.dof, S = 2 * d + nz;
  auto g = [&](const Eigen::VectorXd& X) {
    State s{x.q + L.N * X.head(d), L.N * X.segment(d, d), x.z + X.tail(nz)};
    accelerations(model, t, s, ws);
    Eigen::VectorXd out(S);
    out << X.segment(d, d), L.Nt * ws.qdd, ws.zd;
    return out;
  };
  // A = ∂g/∂X at X = 0; absolute step 1e-6 (X is a perturbation about the equilibrium).
  L.A = numerics::central_difference_jacobian(g, Eigen::VectorXd::Zero(S), 1e-6, numerics::Step::Absolute);
  reduced_matrices(model, L, ws);
  return L;
}

std::vector<std::string> state_names(const Model& model, const LinearModel& lin) {
  std::vector<std::string> names;
  for (int k : lin.independent) names.push_back(model.coord_name(k));
  for (int k : lin.independent) names.push_back(model.coord_name(k) + "_dot");
  for (std::size_t f = 0; f < model.forces.size(); ++f)
    for (int j = 0; j < model.forces[f]->n_states(); ++j) names.push_back(fmt::format("{}.z{}", model.forces[f]->name(), j));
  return names;
}

namespace {
// "head.y 100 %, upper_main.theta 31 %": the dominant coordinates of a shape scaled to max |·| = 1.
std::string describe(const Model& model, const Eigen::VectorXd& shape) {
  std::vector<std::pair<double, int>> big;
  for (int k = 0; k < shape.size(); ++k) big.push_back({std::abs(shape[k]), k});
  std::stable_sort(big.begin(), big.end(), [](auto a, auto b) { return a.first > b.first; });
  std::string out;
  for (std::size_t j = 0; j < std::min<std::size_t>(3, big.size()); ++j) {
    if (j > 0 && big[j].first < 0.2) break;
    out += fmt::format("{}{} {:.0f} %", j ? ", " : "", model.coord_name(big[j].second),
                       100 * big[j].first * (shape[big[j].second] < 0 ? -1 : 1));
  }
  return out;
}
}  // namespace

std::vector<Mode> modes(const Model& model, const LinearModel& L) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(L.A);
  std::vector<Mode> out;
  const int d = L.dof;
  for (int i = 0; i < L.A.rows(); ++i) {
    const std::complex<double> lam = es.eigenvalues()[i];
    if (std::abs(lam) < 1e-6 || lam.imag() < -1e-9) continue;  // neutral, or the conjugate twin
    Mode m;
    m.eigenvalue = lam;
    m.frequency_hz = std::abs(lam) / (2 * std::numbers::pi);
    m.damped_frequency_hz = std::max(0.0, lam.imag()) / (2 * std::numbers::pi);
    m.damping_ratio = -lam.real() / std::abs(lam);
    Eigen::VectorXcd v = es.eigenvectors().col(i);
    Eigen::VectorXcd q = L.N.cast<std::complex<double>>() * v.head(d);
    // Rotate so that the largest component is real and +1, then keep the real part.
    Eigen::Index kmax = 0;
    q.cwiseAbs().maxCoeff(&kmax);
    if (std::abs(q[kmax]) < 1e-14) continue;  // an internal-state mode that does not move the bodies
    q /= q[kmax];
    m.shape = q.real();
    m.description = describe(model, m.shape);
    out.push_back(m);
  }
  std::sort(out.begin(), out.end(), [](const Mode& a, const Mode& b) { return a.frequency_hz < b.frequency_hz; });
  return out;
}

std::vector<UndampedMode> undamped_modes(const Model& model, const LinearModel& L) {
  std::vector<UndampedMode> out;
  if (L.dof == 0) return out;
  const Eigen::MatrixXd Ks = 0.5 * (L.K + L.K.transpose()), Ms = 0.5 * (L.M + L.M.transpose());
  if (Eigen::LLT<Eigen::MatrixXd>(Ms).info() != Eigen::Success) return out;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Ks, Ms);
  if (es.info() != Eigen::Success) return out;
  for (int i = 0; i < L.dof; ++i) {
    const double w2 = es.eigenvalues()[i];
    UndampedMode m;
    m.frequency_hz = (w2 >= 0 ? 1 : -1) * std::sqrt(std::abs(w2)) / (2 * std::numbers::pi);
    Eigen::VectorXd q = L.N * es.eigenvectors().col(i);
    Eigen::Index kmax = 0;
    q.cwiseAbs().maxCoeff(&kmax);
    m.shape = q / q[kmax];
    m.description = describe(model, m.shape);
    out.push_back(m);
  }
  return out;
}

LinearSystem linearise(const Model& model, const State& x, const std::vector<std::string>& inputs,
                       const std::vector<std::string>& outputs, double t) {
  LinearSystem sys;
  LinearModel& L = sys.lin;
  Workspace ws(model);
  L.equilibrium = x;
  L.t = t;
  evaluate_constraints(model, t, x, ws);
  std::vector<int> dependent;
  partition(model, ws, L, dependent);
  const int n = model.n_coords(), d = L.dof, nz = model.n_states(), S = 2 * d + nz;

  // Inputs: loads (the element, its value at t) and driving joints (the joint, G: q = q_e + N ξ + G u).
  Model mw = model;  // the working copy whose loads and driving values carry u
  struct In {
    int force = -1, joint = -1;
    double f0 = 0;
    Eigen::VectorXd G;
  };
  std::vector<In> in;
  for (const std::string& name : inputs) {
    In k;
    if (const int f = model.find_force(name); f >= 0 && model.forces[static_cast<std::size_t>(f)]->with_value(TimeFunction::constant(0))) {
      k.force = f;
      k.f0 = model.forces[static_cast<std::size_t>(f)]->load_value(t);
    } else if (const int j = model.find_joint(name); j >= 0 && model.joints[static_cast<std::size_t>(j)].type == JointType::Driving) {
      k.joint = j;
      const Joint& jt = model.joints[static_cast<std::size_t>(j)];
      Eigen::VectorXd e = Eigen::VectorXd::Zero(model.n_constraints());
      e[jt.row] = 1;  // C_q G = e: the driven coordinate moves by u
      k.G = Eigen::VectorXd::Zero(n);
      if (!dependent.empty()) {
        const Eigen::VectorXd g = ws.Cq(Eigen::all, dependent).colPivHouseholderQr().solve(e);
        for (std::size_t r = 0; r < dependent.size(); ++r) k.G[dependent[r]] = g[static_cast<Eigen::Index>(r)];
      }
      if (!((ws.Cq * k.G - e).norm() < 1e-8)) throw InvalidArgument(fmt::format("{}: input '{}': the driving joint's row is redundant with the other constraints", model.source, name));
    } else {
      std::string known;
      for (const auto& f : model.forces)
        if (f->with_value(TimeFunction::constant(0))) known += (known.empty() ? "" : ", ") + f->name();
      for (const auto& jt : model.joints)
        if (jt.type == JointType::Driving) known += (known.empty() ? "" : ", ") + jt.name;
      throw InvalidArgument(fmt::format("{}: no input '{}': an input is a point_force or point_torque element or a driving joint; "
                                        "this model has: {}", model.source, name, known.empty() ? "none" : known));
    }
    in.push_back(std::move(k));
  }
  std::vector<int> out;
  for (const std::string& name : outputs) {
    int found = -1;
    for (std::size_t k = 0; k < model.outputs.size(); ++k)
      if (model.outputs[k].name == name) found = static_cast<int>(k);
    if (found < 0) {
      std::string known;
      for (const auto& o : model.outputs) known += (known.empty() ? "" : ", ") + o.name;
      throw InvalidArgument(fmt::format("{}: no output '{}'; outputs: {}", model.source, name, known.empty() ? "none" : known));
    }
    out.push_back(found);
  }
  sys.inputs = inputs;
  sys.outputs = outputs;
  for (const In& k : in) sys.motion.push_back(k.joint >= 0), sys.joint.push_back(k.joint);
  // A load enters linearly and is stepped by ±1 (below): its two perturbed elements are made once.
  std::vector<std::array<std::shared_ptr<const ForceElement>, 2>> stepped(in.size());
  for (std::size_t k = 0; k < in.size(); ++k)
    if (in[k].force >= 0)
      for (int sign : {0, 1}) {
        const ForceElement& f = *model.forces[static_cast<std::size_t>(in[k].force)];
        stepped[k][static_cast<std::size_t>(sign)] = f.with_value(TimeFunction::constant(in[k].f0 + (sign ? 1.0 : -1.0)));
      }

  // F(V) = [Ẋ; y] over V = [X; u; u̇; ü].
  const int ni = static_cast<int>(in.size()), no = static_cast<int>(out.size());
  auto F = [&](const Eigen::VectorXd& V) {
    State s{x.q + L.N * V.head(d), L.N * V.segment(d, d), x.z + V.segment(2 * d, nz)};
    for (int k = 0; k < ni; ++k) {
      const In& ik = in[static_cast<std::size_t>(k)];
      const double u = V[S + k], ud = V[S + ni + k], udd = V[S + 2 * ni + k];
      if (ik.force >= 0) {  // u ∈ {−1, 0, 1}: the element made for that step, or the model's own
        mw.forces[static_cast<std::size_t>(ik.force)] =
            u == 0 ? model.forces[static_cast<std::size_t>(ik.force)] : stepped[static_cast<std::size_t>(k)][u > 0 ? 1 : 0];
      } else {
        const Joint& j0 = model.joints[static_cast<std::size_t>(ik.joint)];
        Joint& jw = mw.joints[static_cast<std::size_t>(ik.joint)];
        jw.motion = motion_at(t, j0.motion.value(t) + u, j0.motion.d1(t) + ud, j0.motion.d2(t) + udd);
        s.q += ik.G * u;
        s.qd += ik.G * ud;
      }
    }
    accelerations(mw, t, s, ws);
    Eigen::VectorXd r(S + no);
    r << V.segment(d, d), L.Nt * ws.qdd, ws.zd, Eigen::VectorXd::Zero(no);
    for (int i = 0; i < no; ++i) r[S + i] = evaluate_output(mw.outputs[static_cast<std::size_t>(out[static_cast<std::size_t>(i)])], mw, t, s, ws);
    return r;
  };
  const int nv = S + 3 * ni;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(S + no, nv);
  Eigen::VectorXd V = Eigen::VectorXd::Zero(nv);
  for (int c = 0; c < nv; ++c) {
    // States and a driven displacement or rate: 1e-6 (absolute, as linearise). Loads and
    // accelerations enter linearly: a unit step, exact.
    const int kind = c < S ? -1 : (c - S) / std::max(ni, 1), k = c < S ? 0 : (c - S) % std::max(ni, 1);
    const bool load = kind >= 0 && in[static_cast<std::size_t>(k)].force >= 0;
    if (load && kind > 0) continue;  // a load has no rate terms
    const double h = (load || kind == 2) ? 1.0 : 1e-6;
    V[c] = h;
    const Eigen::VectorXd fp = F(V);
    V[c] = -h;
    J.col(c) = (fp - F(V)) / (2 * h);
    V[c] = 0;
  }
  L.A = J.topLeftCorner(S, S);
  reduced_matrices(model, L, ws);
  sys.B0 = J.block(0, S, S, ni);
  sys.B1 = J.block(0, S + ni, S, ni);
  sys.B2 = J.block(0, S + 2 * ni, S, ni);
  sys.Cy = J.block(S, 0, no, S);
  sys.D0 = J.block(S, S, no, ni);
  sys.D1 = J.block(S, S + ni, no, ni);
  sys.D2 = J.block(S, S + 2 * ni, no, ni);
  return sys;
}

}  // namespace inerta::mbs
