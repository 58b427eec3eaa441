// Pantographs on the finite-element line, co-simulated (catenary/fe_catenary.hpp, spec/05 §5.3).
//
// One coupling step [t_n, t_{n+1}] of length h = the structural step, for every pantograph k:
//   1. predict its contact point's height and velocity at t_{n+1} from its state and its last
//      acceleration (second-order Taylor): y*, ẏ*;
//   2. step the line (HHT-α) with a penalty contact to that predicted head, implicit in the wire;
//   3. give the pantograph the wire's height at its moving contact point over the step as a cubic
//      Hermite in time between (Y_n, Ẏ_n) and (Y_{n+1}, Ẏ_{n+1}), and integrate its multibody model
//      to t_{n+1} with the penalty force F = max(0, k_s δ + c_s δ̇), δ = y_P − Y(t), implicit in
//      the head (the multibody integrator's own error control).
// Each side treats the penalty spring implicitly in its own coordinates; only the other side's
// motion is extrapolated, so the scheme converges as h shrinks (the force mismatch between the
// two sides is O(h³) per step; tests/catenary/fe_catenary_test.cpp shows the convergence). The
// reported contact force is the pantograph's.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/catenary/fe_modal.hpp"
#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"

namespace inerta::catenary {

namespace {

// The wire's height at one pantograph's contact point over the current coupling step (in the
// pantograph model's coordinates). The coupling's input signal: set between integrations.
struct WireTrack {
  double t0 = 0, t1 = 1, y0 = 0, y1 = 0, v0 = 0, v1 = 0;
  bool linear = false;  ///< the static solve: a linear spring (no contact loss), for a regular Jacobian
  void hold(double t, double y) { t0 = t, t1 = t + 1, y0 = y1 = y, v0 = v1 = 0; }
  double value(double t) const {
    const double h = t1 - t0, s = (t - t0) / h, s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * h * v0 + (-2 * s3 + 3 * s2) * y1 + (s3 - s2) * h * v1;
  }
  double rate(double t) const {
    const double h = t1 - t0, s = (t - t0) / h, s2 = s * s;
    return ((6 * s2 - 6 * s) * y0 + (-6 * s2 + 6 * s) * y1) / h + (3 * s2 - 4 * s + 1) * v0 + (3 * s2 - 2 * s) * v1;
  }
};

class TrackContact : public mbs::ForceElement {
 public:
  TrackContact(int body, mbs::Vec2 u, std::shared_ptr<const WireTrack> track, double ks, double cs)
      : ForceElement("contact"), body_(body), u_(u), track_(std::move(track)), ks_(ks), cs_(cs) {}
  void add(const mbs::Model& model, double t, const mbs::State&, mbs::Workspace& ws) const override {
    const mbs::PointKinematics p = mbs::point_kinematics(ws.frame(body_), u_);
    const double F = force_at(t, p);
    if (F == 0) return;
    const int a = model.q_adr(body_);
    ws.Q[a + 1] -= F;  // down on the contact point: G_Pᵀ (0, −F)
    ws.Q[a + 2] -= p.Atu.y() * F;
  }
  double force(const mbs::Model&, double t, const mbs::State&, const mbs::Workspace& ws) const override {
    return force_at(t, mbs::point_kinematics(ws.frame(body_), u_));
  }
  double length(const mbs::Model& model, const mbs::State& x) const override {
    return mbs::point_kinematics(model.frame(x, body_), u_).r.y() - track_->value(track_->t0);
  }
  double energy(const mbs::Model& model, double t, const mbs::State& x) const override {
    const double d = mbs::point_kinematics(model.frame(x, body_), u_).r.y() - track_->value(t);
    return d > 0 ? 0.5 * ks_ * d * d : 0.0;
  }

 private:
  double force_at(double t, const mbs::PointKinematics& p) const {
    const double d = p.r.y() - track_->value(t);
    if (track_->linear) return ks_ * d;
    if (d <= 0) return 0.0;
    return std::max(0.0, ks_ * d + cs_ * (p.v.y() - track_->rate(t)));
  }
  int body_;
  mbs::Vec2 u_;
  std::shared_ptr<const WireTrack> track_;
  double ks_, cs_;
};

class FeCoupled final : public Coupled {
 public:
  FeCoupled(std::shared_ptr<const FeLine> line, std::shared_ptr<const FeModalLine> modal,
            const std::vector<PantographOnLine>& ps, double speed, Section section)
      : line_(std::move(line)), v_(speed), section_(section) {
    double lo = line_->length(), hi = 0;
    for (const PantographOnLine& p : ps) lo = std::min(lo, p.x0), hi = std::max(hi, p.x0);
    fe_ = modal ? make_modal_solver(std::move(modal), std::max(0.0, hi - lo)) : make_direct_solver(*line_);
    for (std::size_t k = 0; k < ps.size(); ++k) {
      const PantographOnLine& p = ps[k];
      if (p.contact.kind != Contact::Kind::Penalty)
        throw ModelError(fmt::format(
            "pantograph {}: the finite-element catenary needs a penalty contact (contact: {{type: penalty, stiffness: "
            "50000}}), not a bilateral one",
            k + 1));
      if (p.x0 < 0 || p.x0 > line_->length())
        throw ModelError(fmt::format("pantograph {}: x0 = {:g} m is off the line [0, {:g}] m", k + 1, p.x0,
                                     line_->length()));
      auto part = std::make_unique<Part>();
      part->x0 = p.x0;
      part->ks = p.contact.stiffness;
      part->cs = p.contact.damping;
      part->model = p.pantograph.model;
      mbs::Model& m = part->model;
      if (p.pantograph.rig_joint >= 0)
        m.remove_joint(m.joints[static_cast<std::size_t>(p.pantograph.rig_joint)].name);
      std::erase_if(m.outputs, [](const mbs::Output& o) { return o.name == "F_contact"; });
      m.finalize();
      const mbs::Marker point = p.pantograph.contact();
      part->body = point.body;
      part->u = point.u;
      if (part->body < 0) throw ModelError(fmt::format("pantograph {}: its contact point is not on a body", k + 1));
      const mbs::State x = mbs::assemble(m, 0.0);
      part->offset = mbs::point_kinematics(m.frame(x, point.body), point.u).r.y() - line_->static_height(p.x0);
      part->track = std::make_shared<WireTrack>();
      part->track->hold(0, part->offset + line_->static_height(p.x0));
      m.forces.push_back(std::make_shared<TrackContact>(point.body, point.u, part->track, part->ks, part->cs));
      part->force.name = "F_contact";
      part->force.kind = mbs::Output::Kind::ElementForce;
      part->force.index = static_cast<int>(m.forces.size()) - 1;
      m.outputs.push_back(part->force);
      m.finalize();
      part->x = mbs::assemble(m, 0.0);
      part->ws = std::make_unique<mbs::Workspace>(m);
      parts_.push_back(std::move(part));
    }
    equilibrate();
  }

  int n_contacts() const override { return static_cast<int>(parts_.size()); }
  double speed() const override { return v_; }
  double span() const override { return line_->data().span; }
  const mbs::Model& model(ContactId c) const override { return part(c).model; }
  const mbs::State& state(ContactId c) const override {
    const Part& p = part(c);
    return p.stepper ? p.stepper->state() : p.x;
  }
  double time() const override { return fe_->time(); }
  double line_length() const override { return line_->length(); }
  Section section() const override { return section_; }
  double end_time() const override {
    double lead = 0;
    for (const auto& p : parts_) lead = std::max(lead, p->x0);
    return (line_->length() - 1.0 - lead) / v_;
  }
  std::vector<double> support_x() const override { return line_->support_x(); }
  std::vector<double> support_uplift() const override {
    start_line();
    return fe_->support_uplift();
  }

  void equilibrate() override {
    // Fixed point between the pantographs' static forces (wire held still) and the line's static
    // uplift under them; the pantographs are soft compared with the wire's point stiffness.
    const std::size_t n = parts_.size();
    std::vector<double> xs(n), F(n, 0.0), y(n);
    for (std::size_t k = 0; k < n; ++k) xs[k] = parts_[k]->x0, y[k] = line_->static_height(xs[k]);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(line_->n_dofs());
    double change = 0;
    for (int iter = 0; iter < 100; ++iter) {
      change = 0;
      for (std::size_t k = 0; k < n; ++k) {
        Part& p = *parts_[k];
        const double yw = line_->static_height(xs[k]) + line_->contact_displacement(u, xs[k]);
        change = std::max(change, std::abs(yw - y[k]));
        y[k] = yw;
        p.track->hold(0, p.offset + yw);
        p.track->linear = true;
        p.x = mbs::assemble(p.model, 0.0);
        mbs::static_equilibrium(p.model, 0.0, p.x);
        p.track->linear = false;
        p.ws->set_state(p.x);
        F[k] = mbs::evaluate_output(p.force, p.model, 0.0, p.x, *p.ws);
        const double d = mbs::point_kinematics(p.model.frame(p.x, p.body), p.u).r.y() - p.track->value(0);
        if (!(d > 0))
          throw NumericalError(fmt::format(
              "pantograph {}: in its static equilibrium it does not press against the wire (contact force {:.4g} N); "
              "check its static uplift",
              k + 1, p.ks * d));
      }
      std::vector<char> slack;
      u = line_->static_displacement(xs, F, &slack);
      if (iter > 0 && change < 1e-10) break;
    }
    if (change >= 1e-10)
      throw NumericalError(fmt::format(
          "finite-element catenary: the static uplift of the pantographs against the line did not converge (last "
          "change {:.3g} m)",
          change));
    // The line's dynamic solve starts at the first advance: a static state alone (a study's operating
    // length) needs no modes.
    start_x_ = xs, start_F_ = F;
    line_started_ = false;
    for (std::size_t k = 0; k < n; ++k) {
      Part& p = *parts_[k];
      p.stepper.reset();  // made by the first advance, with its options
      p.y_wire = y[k];
      p.v_wire = 0;
      p.acc_y = 0;
      p.F = F[k];
    }
    sampled_start_ = false;
    started_ = false;
  }

  solve::RunStats advance(double t_end, double dt, const solve::IntegratorOptions& options,
                          const SampleObserver& observer, bool accelerations) override {
    if (!(dt > 0)) throw InvalidArgument("advance: the sample interval must be > 0 s");
    start_line();
    const double h = fe_->dt();
    if (!started_ || options.method != options_.method || options.rtol != options_.rtol ||
        options.atol != options_.atol || options.max_step != options_.max_step) {
      options_ = options;
      for (auto& p : parts_) p->stepper = std::make_unique<solve::Stepper>(p->model, state_of(*p), fe_->time(), options_);
      started_ = true;
    }
    const auto wall0 = std::chrono::steady_clock::now();
    // Samples every k-th structural step, k = round(dt / h) >= 1 (uniform; dt rounded to a multiple of h).
    const long every = std::max(1L, std::lround(dt / h));
    long step_index = 0;
    auto deliver = [&](double t) {
      for (std::size_t k = 0; k < parts_.size(); ++k) {
        Part& p = *parts_[k];
        const mbs::State& x = p.stepper->state();
        if (accelerations || mbs::needs_accelerations(p.force))
          mbs::accelerations(p.model, t, x, *p.ws);
        else
          p.ws->set_state(x);
        const double F = mbs::evaluate_output(p.force, p.model, t, x, *p.ws);
        const double xc = p.x0 + v_ * t;
        if (observer) {
          Sample smp{ContactId{static_cast<int>(k)}, t, xc, F, p.model, x, *p.ws};
          smp.wire_uplift = fe_->uplift(xc);
          observer(smp);
        }
      }
    };
    if (!sampled_start_) deliver(fe_->time());
    std::vector<FeLoad> loads(parts_.size());
    std::vector<double> forces;
    const int n_steps = static_cast<int>(std::floor((t_end - fe_->time()) / h + 1e-6));
    for (int i = 0; i < n_steps; ++i) {
      const double t = fe_->time(), t1 = t + h;
      for (std::size_t k = 0; k < parts_.size(); ++k) {
        Part& p = *parts_[k];
        const double xc1 = p.x0 + v_ * t1;
        if (xc1 > line_->length())
          throw NumericalError(fmt::format(
              "t = {:.6g} s: pantograph {} (contact point at x = {:.6g} m) has run off the end of the line ({:g} m)", t1,
              k + 1, xc1, line_->length()));
        const mbs::State& x = p.stepper->state();
        const mbs::PointKinematics pk = mbs::point_kinematics(p.model.frame(x, p.body), p.u);
        const double y = pk.r.y(), yd = pk.v.y();
        loads[k] = FeLoad{xc1, true, 0, y + h * yd + 0.5 * h * h * p.acc_y - p.offset, yd + h * p.acc_y,
                          p.ks, p.cs, v_};
        p.yd_prev = yd;
      }
      fe_->step(loads, forces);
      for (std::size_t k = 0; k < parts_.size(); ++k) {
        Part& p = *parts_[k];
        const double xc1 = p.x0 + v_ * t1;
        const double y1 = fe_->height(xc1), v1 = fe_->height_rate(xc1, v_);
        *p.track = WireTrack{t, t1, p.offset + p.y_wire, p.offset + y1, p.v_wire, v1};
        p.y_wire = y1, p.v_wire = v1;
        p.stepper->advance(t1);
        const mbs::PointKinematics pk = mbs::point_kinematics(p.model.frame(p.stepper->state(), p.body), p.u);
        p.acc_y = (pk.v.y() - p.yd_prev) / h;
      }
      if (++step_index % every == 0) deliver(fe_->time());
    }
    sampled_start_ = true;
    solve::RunStats total;
    for (auto& p : parts_) {
      const solve::RunStats st = p->stepper->stats();
      total.steps += st.steps - p->steps_reported;
      total.rhs_evals += st.rhs_evals - p->rhs_reported;
      p->steps_reported = st.steps, p->rhs_reported = st.rhs_evals;
    }
    total.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return total;
  }

 private:
  struct Part {
    mbs::Model model;
    mbs::State x;  // before the first advance
    std::unique_ptr<mbs::Workspace> ws;
    std::unique_ptr<solve::Stepper> stepper;
    std::shared_ptr<WireTrack> track;
    mbs::Output force;
    int body = -1;
    mbs::Vec2 u = mbs::Vec2::Zero();
    double x0 = 0, ks = 0, cs = 0, offset = 0;
    double y_wire = 0, v_wire = 0, acc_y = 0, yd_prev = 0, F = 0;
    long steps_reported = 0, rhs_reported = 0;
  };
  const Part& part(ContactId c) const {
    if (c.index < 0 || c.index >= n_contacts())
      throw InvalidArgument(fmt::format("contact {} does not exist: the system has {} contact(s)", c.index,
                                        n_contacts()));
    return *parts_[static_cast<std::size_t>(c.index)];
  }
  static const mbs::State& state_of(const Part& p) { return p.stepper ? p.stepper->state() : p.x; }
  // The line at rest in the static state equilibrate() found (the modal solve's windows are made here).
  void start_line() const {
    if (line_started_) return;
    fe_->start(start_x_, start_F_, 0.0);
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      Part& p = *parts_[k];
      p.y_wire = fe_->height(start_x_[k]);
      p.v_wire = fe_->height_rate(start_x_[k], v_);
    }
    line_started_ = true;
  }

  std::shared_ptr<const FeLine> line_;
  std::unique_ptr<FeLineSolver> fe_;
  double v_;
  Section section_;
  std::vector<std::unique_ptr<Part>> parts_;
  solve::IntegratorOptions options_;
  bool sampled_start_ = false, started_ = false;
  std::vector<double> start_x_, start_F_;
  mutable bool line_started_ = false;
};

}  // namespace

FeCatenary::FeCatenary(FeCatenaryData data) : data_(std::move(data)) { data_.validate(); }

void FeCatenary::build() const {
  std::call_once(built_, [&] {
    auto line = std::make_shared<const FeLine>(data_);
    if (data_.solver == FeCatenaryData::Solver::Modal)
      modal_ = std::make_shared<FeModalLine>(line, ModeStore::from_environment());
    line_ = std::move(line);
    line_ready_.store(true);
  });
}

const FeLine& FeCatenary::line() const {
  build();
  return *line_;
}

std::shared_ptr<const FeModalLine> FeCatenary::modal() const {
  build();
  return modal_;
}

std::string FeCatenary::describe() const {
  build();
  std::string s = line_->describe();
  const FeCatenaryData& d = data_;
  if (modal_)
    s += d.window_behind < 0 || d.window_ahead < 0
             ? fmt::format("; modal solve below {:g} Hz, the whole line", d.modal_cutoff)
             : fmt::format("; modal solve below {:g} Hz, a window of {} span(s) behind and {} ahead", d.modal_cutoff,
                           d.window_behind, d.window_ahead);
  else
    s += "; direct solve";
  return s;
}

void FeCatenary::prepare(const std::vector<PantographOnLine>& pantographs) const {
  build();
  if (!modal_ || pantographs.empty()) return;
  double lo = line_->length(), hi = 0;
  for (const PantographOnLine& p : pantographs) lo = std::min(lo, p.x0), hi = std::max(hi, p.x0);
  modal_->prepare(modal_->window_spans(std::max(0.0, hi - lo)));
}

FeCostEstimate FeCatenary::estimate(const std::vector<PantographOnLine>& pantographs, double speed, double t_end) const {
  // Before the line is built (the cost guard runs first): its setup and first modes too.
  bool built = false, modes = false;
  if (line_ready_.load()) {
    built = true;
    modes = !modal_ || modal_->decompositions() + modal_->loaded() > 0;
  }
  std::vector<double> x0;
  for (const PantographOnLine& p : pantographs) x0.push_back(p.x0);
  return estimate_cost(data_, x0, speed, t_end, !built, !modes);
}

double FeCatenary::estimated_seconds(const std::vector<PantographOnLine>& pantographs, double speed, double t_end) const {
  return estimate(pantographs, speed, t_end).total();
}

double FeCatenary::estimated_bytes(const std::vector<PantographOnLine>& pantographs, double speed, double t_end) const {
  return speed > 0 ? estimate(pantographs, speed, t_end).bytes : estimate(pantographs, 1.0, data_.time_step).bytes;
}

double FeCatenary::estimated_setup_seconds(const std::vector<PantographOnLine>& pantographs) const {
  const FeCostEstimate e = estimate(pantographs, 1.0, data_.time_step);
  return e.setup + e.modes;
}

double FeCatenary::line_length() const { return data_.span * data_.spans; }

Section FeCatenary::section() const {
  const FeCatenaryData& d = data_;
  int first = d.section_first, last = d.section_last;
  if (first < 0) {  // default: without the first and last quarter of the spans (at least one span each end)
    const int skip = d.spans >= 3 ? std::max(1, d.spans / 4) : 0;
    first = 1 + skip, last = d.spans - skip;
  }
  return {(first - 1) * d.span, last * d.span};
}

std::shared_ptr<const Catenary> FeCatenary::mean() const {
  // The fitted lumped catenary without its variation along the span (modes about a static state).
  LumpedCatenary c = fit_lumped(line()).lumped;
  for (int i = 1; i < 4; ++i) c.k[static_cast<std::size_t>(i)] = c.m[static_cast<std::size_t>(i)] = c.c[static_cast<std::size_t>(i)] = 0;
  return std::make_shared<Lumped>(c);
}

std::unique_ptr<Coupled> FeCatenary::make_coupled(const std::vector<PantographOnLine>& pantographs,
                                                  double speed) const {
  build();
  return std::make_unique<FeCoupled>(line_, modal_, pantographs, speed, section());
}

}  // namespace inerta::catenary
