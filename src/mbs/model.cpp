#include "inerta/mbs/model.hpp"

#include <fmt/format.h>

#include <cmath>

#include "inerta/mbs/parameter_check.hpp"
#include "inerta/mbs/state.hpp"

namespace inerta::mbs {

namespace {
template <class T, class Name>
int find_named(const std::vector<T>& items, const std::string& name, Name get) {
  for (std::size_t k = 0; k < items.size(); ++k)
    if (get(items[k]) == name) return static_cast<int>(k);
  return -1;
}
}  // namespace

int Model::find_body(const std::string& name) const {
  if (name == "ground") return kGround;
  int k = find_named(bodies, name, [](const Body& b) { return b.name; });
  return k < 0 ? -2 : k;
}
int Model::find_marker(const std::string& name) const {
  return find_named(markers, name, [](const Marker& m) { return m.name; });
}
int Model::find_joint(const std::string& name) const {
  return find_named(joints, name, [](const Joint& j) { return j.name; });
}
int Model::find_force(const std::string& name) const {
  return find_named(forces, name, [](const auto& f) { return f->name(); });
}

std::string Model::constraint_name(int r) const {
  for (const Joint& j : joints)
    if (r >= j.row && r < j.row + j.rows()) return fmt::format("joint '{}' (equation {})", j.name, r - j.row + 1);
  for (std::size_t b = 0; b < bodies.size() && spatial(); ++b)
    if (r == norm_row(static_cast<int>(b)))
      return fmt::format("the Euler-parameter normalisation of body '{}'", bodies[b].name);
  return fmt::format("constraint row {}", r);
}

std::string Model::coord_name(int k) const {
  static const char* names[] = {"x", "y", "theta"};
  static const char* names3[] = {"x", "y", "z", "e0", "e1", "e2", "e3"};
  const int nc = body_coords();
  return bodies[static_cast<std::size_t>(k / nc)].name + "." + (spatial() ? names3 : names)[k % nc];
}

void Body::validate() const {
  const check::Element who{"body", name};
  check::nonnegative(who, "mass", mass);
  check::nonnegative(who, "inertia", inertia);
  check::finite_vector(who, "inertia", inertia3);
  if (!inertia3.isApprox(inertia3.transpose(), 1e-12)) check::fail(who, "inertia", "the inertia tensor must be symmetric");
  const Vec3 I = Eigen::SelfAdjointEigenSolver<Mat3>(inertia3).eigenvalues();  // ascending
  if (!(I.minCoeff() >= 0) || I[0] + I[1] < I[2] * (1 - 1e-12))
    check::fail(who, "inertia",
                "must be positive semi-definite and satisfy the triangle inequality I1 + I2 >= I3 of a rigid body");
  check::finite_vector(who, "position", q0.head<2>().eval());
  check::finite(who, "angle", q0.z(), "rad");
  check::finite_vector(who, "velocity", qd0.head<2>().eval());
  check::finite(who, "angular_velocity", qd0.z(), "rad/s");
  check::finite_vector(who, "position", q0s.head<3>().eval());
  check::finite_vector(who, "quaternion", q0s.tail<4>().eval());
  check::finite_vector(who, "velocity", qd0s.head<3>().eval());
  check::finite_vector(who, "angular_velocity", qd0s.tail<4>().eval());
}

void Model::finalize() {
  for (const Body& b : bodies) b.validate();
  q_adr_.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) q_adr_[b] = body_coords() * static_cast<int>(b);
  n_states_ = 0;
  state_adr_.clear();
  for (auto& f : forces) {
    if (f->n_states() > 0 && f->state_offset() != n_states_) f = f->with_state_offset(n_states_);
    state_adr_.push_back(n_states_);
    n_states_ += f->n_states();
  }
  n_constraints_ = 0;
  for (Joint& j : joints) {
    j.spatial = spatial();
    j.row = n_constraints_;
    n_constraints_ += j.rows();
  }
  n_joint_rows_ = n_constraints_;
  if (spatial()) n_constraints_ += static_cast<int>(bodies.size());
}

bool Model::remove_joint(const std::string& name) {
  const int removed = find_joint(name);
  if (removed < 0) return false;
  joints.erase(joints.begin() + removed);
  std::vector<Output> kept;
  for (Output o : outputs) {
    const bool of_joint = o.kind == Output::Kind::Reaction || o.kind == Output::Kind::Multiplier;
    if (of_joint && o.index == removed) continue;
    if (of_joint && o.index > removed) --o.index;
    kept.push_back(o);
  }
  outputs = kept;
  finalize();
  return true;
}

namespace {
// Stacks each body's tabulated 2D (Vec3) or 3D (Vec7) vector.
template <class Planar, class Spatial>
Eigen::VectorXd stack(const Model& m, Planar planar, Spatial spatial) {
  Eigen::VectorXd v(m.n_coords());
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const int k = m.body_coords() * static_cast<int>(b);
    if (m.spatial())
      v.segment<7>(k) = spatial(m.bodies[b]);
    else
      v.segment<3>(k) = planar(m.bodies[b]);
  }
  return v;
}
}  // namespace

Eigen::VectorXd Model::q0() const {
  return stack(
      *this, [](const Body& b) { return b.q0; }, [](const Body& b) { return b.q0s; });
}
Eigen::VectorXd Model::qd0() const {
  return stack(
      *this, [](const Body& b) { return b.qd0; }, [](const Body& b) { return b.qd0s; });
}

Vec3 Model::q_of(const State& x, int body) const {
  return body < 0 ? Vec3::Zero() : Vec3(x.q.segment<3>(q_adr(body)));
}
Vec3 Model::qd_of(const State& x, int body) const {
  return body < 0 ? Vec3::Zero() : Vec3(x.qd.segment<3>(q_adr(body)));
}
BodyFrame Model::frame(const State& x, int body) const {
  return body < 0 ? BodyFrame{} : BodyFrame::of(q_of(x, body), qd_of(x, body));
}
SpatialFrame Model::sframe(const State& x, int body) const {
  return body < 0 ? SpatialFrame{} : SpatialFrame::of(x.q.segment<7>(q_adr(body)), x.qd.segment<7>(q_adr(body)));
}

double ForceElement::length(const Model&, const State&) const { return std::nan(""); }
double ForceElement::load_value(double) const { return std::nan(""); }

std::shared_ptr<const ForceElement> ForceElement::with_state_offset(int) const {
  throw std::logic_error("force element '" + name() + "' has internal states but does not implement with_state_offset");
}

Workspace::Workspace(const Model& model) {
  const int n = model.n_coords(), m = model.n_constraints(), ms = model.n_solved_rows();
  M = Eigen::MatrixXd::Zero(n, n);
  Q = Eigen::VectorXd::Zero(n);
  C = Eigen::VectorXd::Zero(m);
  Ct = Eigen::VectorXd::Zero(m);
  Cq = Eigen::MatrixXd::Zero(m, n);
  gamma = Eigen::VectorXd::Zero(m);
  llt_M.compute(Eigen::MatrixXd::Identity(n, n));  // sized, and with a defined info()
  YZ = Eigen::MatrixXd::Zero(n, ms + 1);
  S = Eigen::MatrixXd::Zero(ms, ms);
  llt_S.compute(Eigen::MatrixXd::Identity(ms, ms));
  c = Eigen::VectorXd::Zero(m);
  K = Eigen::MatrixXd::Zero(n + ms, n + ms);
  rhs = Eigen::VectorXd::Zero(n + ms);
  sol = Eigen::VectorXd::Zero(n + ms);
  lu = Eigen::PartialPivLU<Eigen::MatrixXd>(n + ms);
  nc_ = model.body_coords();
  {  // the block solve (dynamics.cpp, solve_blocks)
    // At most three mass terms an element (an actuator's network and its piston mass in x and y).
    const int r = 3 * static_cast<int>(model.forces.size());
    rank1.reserve(static_cast<std::size_t>(r));
    if (model.spatial()) llt_p.resize(model.bodies.size());
    else {
      inv_sqrt_d = Eigen::VectorXd::Zero(n);
      for (std::size_t b = 0; b < model.bodies.size(); ++b) {
        const Body& body = model.bodies[b];
        const int k = 3 * static_cast<int>(b);
        if (body.mass > 0) inv_sqrt_d[k] = inv_sqrt_d[k + 1] = 1 / std::sqrt(body.mass);
        if (body.inertia > 0) inv_sqrt_d[k + 2] = 1 / std::sqrt(body.inertia);
      }
    }
    // Each body's Schur rows: its joints' (ascending), room for the inerter rows of an evaluation.
    body_rows.assign(model.bodies.size(), {});
    for (auto& rows : body_rows) rows.reserve(static_cast<std::size_t>(ms + r));
    YB = Eigen::MatrixXd::Zero(n, ms + r + 1);
    SB = Eigen::MatrixXd::Zero(ms + r, ms + r);
    lm = Eigen::VectorXd::Zero(ms + r);
    column_nz.assign(static_cast<std::size_t>(ms + r), 0);
    row_bodies.assign(static_cast<std::size_t>(ms + r), {-1, -1});
    for (const Joint& j : model.joints)
      for (int k = 0; k < j.rows(); ++k) row_bodies[static_cast<std::size_t>(j.row + k)] = {j.body_i, j.body_j};
    for (int i = 0; i < ms; ++i) {
      const auto& bi = row_bodies[static_cast<std::size_t>(i)];
      if (bi[0] >= 0) body_rows[static_cast<std::size_t>(bi[0])].push_back(i);
      if (bi[1] >= 0 && bi[1] != bi[0]) body_rows[static_cast<std::size_t>(bi[1])].push_back(i);
    }
  }
  if (model.spatial())
    sframes.resize(model.bodies.size());
  else
    frames.resize(model.bodies.size());
  qdd = Eigen::VectorXd::Zero(n);
  zd = Eigen::VectorXd::Zero(model.n_states());
  lambda = Eigen::VectorXd::Zero(ms);
}

void Workspace::set_state(const State& x) {
  for (std::size_t b = 0; b < frames.size(); ++b)
    frames[b] = BodyFrame::of(x.q.segment<3>(3 * static_cast<Eigen::Index>(b)), x.qd.segment<3>(3 * static_cast<Eigen::Index>(b)));
  for (std::size_t b = 0; b < sframes.size(); ++b) sframes[b].set(x.q.data() + 7 * b, x.qd.data() + 7 * b);
}

void Workspace::add_Q(int body_i, int body_j, const VecJ& f) {
  if (nc_ == 3) {
    if (body_i >= 0) Q.segment<3>(3 * body_i) += f.head<3>();
    if (body_j >= 0) Q.segment<3>(3 * body_j) += f.segment<3>(3);
  } else {
    if (body_i >= 0) Q.segment<7>(7 * body_i) += f.head<7>();
    if (body_j >= 0) Q.segment<7>(7 * body_j) += f.segment<7>(7);
  }
}

void Workspace::add_M(int body_i, int body_j, const VecJ& J, double b) {
  if (b != 0) rank1.push_back({body_i, body_j, J, b});
  const int body[2] = {body_i, body_j};
  for (int a = 0; a < 2; ++a) {
    if (body[a] < 0) continue;
    for (int c = 0; c < 2; ++c) {
      if (body[c] < 0) continue;
      if (nc_ == 3)
        M.block<3, 3>(3 * body[a], 3 * body[c]) += b * J.segment<3>(3 * a) * J.segment<3>(3 * c).transpose();
      else
        M.block<7, 7>(7 * body[a], 7 * body[c]) += b * J.segment<7>(7 * a) * J.segment<7>(7 * c).transpose();
    }
  }
}

double Workspace::J_dot_qdd(int body_i, int body_j, const VecJ& J) const {
  double v = 0;
  if (body_i >= 0) v += J.head(nc_).dot(qdd.segment(nc_ * body_i, nc_));
  if (body_j >= 0) v += J.tail(nc_).dot(qdd.segment(nc_ * body_j, nc_));
  return v;
}

}  // namespace inerta::mbs
