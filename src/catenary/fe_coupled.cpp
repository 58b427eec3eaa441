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
#include <array>
#include <chrono>
#include <stdexcept>
#include <cmath>

#include "inerta/catenary/fe_catenary.hpp"
#include "inerta/catenary/fe_modal.hpp"
#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"

namespace inerta::catenary {

namespace {

// The wires' heights at one pantograph's contact point over the current coupling step (in the
// pantograph model's coordinates): one track per contact wire it can touch (two on a line of
// tension sections). The coupling's input signal: set between integrations.
struct WireTrack {
  double t0 = 0, t1 = 1, y0 = 0, y1 = 0, v0 = 0, v1 = 0;
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
struct Tracks {
  std::array<WireTrack, 2> wire;
  std::array<bool, 2> present{true, false};  ///< the wire is at the contact point over this step
  int n = 1;                                  ///< contact wires of the line
  int primary = 0;                            ///< the wire of the static solve
  bool linear = false;  ///< the static solve: a linear spring on the primary wire (no contact loss), for a regular Jacobian
};

class TrackContact : public mbs::ForceElement {
 public:
  TrackContact(int body, mbs::Vec2 u, std::shared_ptr<const Tracks> track, double ks, double cs)
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
  /// The force of contact wire i alone (N).
  double wire_force(int i, double t, const mbs::Workspace& ws) const {
    return wire_force_at(i, t, mbs::point_kinematics(ws.frame(body_), u_));
  }
  double length(const mbs::Model& model, const mbs::State& x) const override {
    const WireTrack& w = track_->wire[static_cast<std::size_t>(track_->primary)];
    return mbs::point_kinematics(model.frame(x, body_), u_).r.y() - w.value(w.t0);
  }
  double energy(const mbs::Model& model, double t, const mbs::State& x) const override {
    double e = 0;
    for (int i = 0; i < track_->n; ++i) {
      if (!track_->present[static_cast<std::size_t>(i)]) continue;
      const double d = mbs::point_kinematics(model.frame(x, body_), u_).r.y() - track_->wire[static_cast<std::size_t>(i)].value(t);
      e += d > 0 ? 0.5 * ks_ * d * d : 0.0;
    }
    return e;
  }

 private:
  double wire_force_at(int i, double t, const mbs::PointKinematics& p) const {
    if (!track_->present[static_cast<std::size_t>(i)]) return 0.0;
    const WireTrack& w = track_->wire[static_cast<std::size_t>(i)];
    const double d = p.r.y() - w.value(t);
    if (track_->linear) return i == track_->primary ? ks_ * d : 0.0;
    if (d <= 0) return 0.0;
    return std::max(0.0, ks_ * d + cs_ * (p.v.y() - w.rate(t)));
  }
  // The sum over the wires at the contact point (one penalty contact per wire; issue 35).
  double force_at(double t, const mbs::PointKinematics& p) const {
    if (track_->n == 1) return wire_force_at(0, t, p);
    return wire_force_at(0, t, p) + wire_force_at(1, t, p);
  }
  int body_;
  mbs::Vec2 u_;
  std::shared_ptr<const Tracks> track_;
  double ks_, cs_;
};

// Pantographs on a line of one or more tension sections. Each section has its own structural
// solver; the sections share no element, so they meet only at the pantographs: a pantograph's
// contact force is the sum of one penalty contact per contact wire at its contact point, each
// section stepped with the penalty contacts of the pantographs on its wire (and, to place a modal
// window, a zero force at the nearest point of its line for the others). A section no pantograph
// has reached yet is at rest in its static state (nothing has acted on it): it starts when the
// first one reaches its anchor. Once the last pantograph has left it by more than window_behind + 1
// spans, it can no longer act on any contact: it is no longer stepped (its supports' uplift held).
//
// Several such systems with their pantographs at the same places (lanes: a study's designs, issue
// 50) share each section's solver group (FeLineLanes) and step through advance's parts together
// (advance_lanes); a lone system is a group of one and steps the same way.
struct LineGroup {
  std::vector<std::unique_ptr<FeLineLanes>> sections;  // a solver per lane on each section
  int lanes = 1;
};
std::shared_ptr<LineGroup> line_group(const std::vector<FeSectionLine>& sections, const std::vector<PantographOnLine>& ps,
                                      double length, int lanes) {
  double lo = length, hi = 0;
  for (const PantographOnLine& p : ps) lo = std::min(lo, p.x0), hi = std::max(hi, p.x0);
  auto g = std::make_shared<LineGroup>();
  g->lanes = lanes;
  for (const FeSectionLine& s : sections) {
    if (s.modal) {
      g->sections.push_back(make_modal_lanes(s.modal, std::max(0.0, hi - lo), lanes));
    } else {
      std::vector<std::unique_ptr<FeLineSolver>> d;
      for (int i = 0; i < lanes; ++i) d.push_back(make_direct_solver(*s.line));
      g->sections.push_back(make_separate_lanes(std::move(d)));
    }
  }
  return g;
}

class FeCoupled final : public Coupled {
 public:
  /// Lane `lane` of `group` (line_group of these sections and positions).
  FeCoupled(const std::vector<FeSectionLine>& sections, const std::vector<PantographOnLine>& ps, double speed,
            Section section, double length, double span, std::vector<Section> overlaps, std::shared_ptr<LineGroup> group,
            int lane)
      : v_(speed), section_(section), length_(length), span_(span), overlaps_(std::move(overlaps)), group_(std::move(group)),
        lane_(lane) {
    for (std::size_t i = 0; i < sections.size(); ++i) {
      const FeSectionLine& s = sections[i];
      Run r;
      r.sec = s;
      r.fe = &group_->sections[i]->lane(lane);
      const int behind = s.line->data().window_behind;
      r.stop_after = behind < 0 || sections.size() == 1 ? INFINITY : s.end + (behind + 1) * s.line->data().span;
      runs_.push_back(std::move(r));
    }
    wires_ = runs_.size() > 1 ? 2 : 1;
    for (std::size_t i = 0; i < runs_.size(); ++i) {  // the registrations, in line order (both at an overlap support)
      const FeLine& L = *runs_[i].sec.line;
      for (std::size_t j = 0; j < L.support_x().size(); ++j)
        supports_.push_back({runs_[i].sec.start + L.support_x()[j], static_cast<int>(i), static_cast<int>(j), runs_[i].sec.wire});
    }
    std::stable_sort(supports_.begin(), supports_.end(), [](const Support& a, const Support& b) {
      return a.x < b.x - 1e-6 || (a.x <= b.x + 1e-6 && a.wire < b.wire);
    });
    for (std::size_t k = 0; k < ps.size(); ++k) {
      const PantographOnLine& p = ps[k];
      if (p.contact.kind != Contact::Kind::Penalty)
        throw ModelError(fmt::format(
            "pantograph {}: the finite-element catenary needs a penalty contact (contact: {{type: penalty, stiffness: "
            "50000}}), not a bilateral one",
            k + 1));
      if (p.x0 < 0 || p.x0 > length_)
        throw ModelError(fmt::format("pantograph {}: x0 = {:g} m is off the line [0, {:g}] m", k + 1, p.x0, length_));
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
      part->primary = primary_run(p.x0);
      const int w = runs_[static_cast<std::size_t>(part->primary)].sec.wire - 1;
      const double y0 = static_height(part->primary, p.x0);
      const mbs::State x = mbs::assemble(m, 0.0);
      part->offset = mbs::point_kinematics(m.frame(x, point.body), point.u).r.y() - y0;
      part->track = std::make_shared<Tracks>();
      part->track->n = wires_;
      part->track->primary = w;
      part->track->present = {false, false};
      part->track->present[static_cast<std::size_t>(w)] = true;
      part->track->wire[static_cast<std::size_t>(w)].hold(0, part->offset + y0);
      part->contact = std::make_shared<TrackContact>(point.body, point.u, part->track, part->ks, part->cs);
      m.forces.push_back(part->contact);
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
  double span() const override { return span_; }
  const mbs::Model& model(ContactId c) const override { return part(c).model; }
  const mbs::State& state(ContactId c) const override {
    const Part& p = part(c);
    return p.stepper ? p.stepper->state() : p.x;
  }
  double time() const override { return runs_.size() == 1 ? runs_.front().fe->time() : t_; }
  double line_length() const override { return length_; }
  Section section() const override { return section_; }
  double end_time() const override {
    double lead = 0;
    for (const auto& p : parts_) lead = std::max(lead, p->x0);
    return (length_ - 1.0 - lead) / v_;
  }
  int wires() const override { return wires_; }
  std::vector<Section> overlaps() const override { return overlaps_; }
  std::vector<double> support_x() const override {
    std::vector<double> x;
    for (const Support& s : supports_) x.push_back(s.x);
    return x;
  }
  std::vector<std::string> support_names() const override {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < supports_.size(); ++i) {
      const bool shared = (i > 0 && std::abs(supports_[i - 1].x - supports_[i].x) < 1e-6) ||
                          (i + 1 < supports_.size() && std::abs(supports_[i + 1].x - supports_[i].x) < 1e-6);
      names.push_back(shared ? fmt::format("uplift@{:g}_w{}", supports_[i].x, supports_[i].wire)
                             : fmt::format("uplift@{:g}", supports_[i].x));
    }
    return names;
  }
  std::vector<double> support_uplift() const override {
    start_line();
    if (runs_.size() == 1) return runs_.front().fe->support_uplift();
    std::vector<std::vector<double>> per(runs_.size());
    for (std::size_t i = 0; i < runs_.size(); ++i) {
      const Run& r = runs_[i];
      per[i] = r.stopped ? r.held : r.started ? r.fe->support_uplift() : std::vector<double>(r.sec.line->support_x().size(), 0.0);
    }
    std::vector<double> u;
    for (const Support& s : supports_) u.push_back(per[static_cast<std::size_t>(s.run)][static_cast<std::size_t>(s.index)]);
    return u;
  }

  void equilibrate() override {
    // Fixed point between the pantographs' static forces (wire held still) and the line's static
    // uplift under them; the pantographs are soft compared with the wire's point stiffness. Each
    // pantograph presses on one wire in the static state (its primary: the lower one at x0).
    const std::size_t n = parts_.size();
    std::vector<double> xs(n), F(n, 0.0), y(n);
    std::vector<Eigen::VectorXd> u(runs_.size());
    for (std::size_t i = 0; i < runs_.size(); ++i) u[i] = Eigen::VectorXd::Zero(runs_[i].sec.line->n_dofs());
    for (std::size_t k = 0; k < n; ++k) xs[k] = parts_[k]->x0, y[k] = static_height(parts_[k]->primary, xs[k]);
    double change = 0;
    for (int iter = 0; iter < 100; ++iter) {
      change = 0;
      for (std::size_t k = 0; k < n; ++k) {
        Part& p = *parts_[k];
        const Run& r = runs_[static_cast<std::size_t>(p.primary)];
        const double xl = xs[k] - r.sec.start;
        const double yw = r.sec.line->static_height(xl) + r.sec.line->contact_displacement(u[static_cast<std::size_t>(p.primary)], xl);
        change = std::max(change, std::abs(yw - y[k]));
        y[k] = yw;
        p.track->wire[static_cast<std::size_t>(p.track->primary)].hold(0, p.offset + yw);
        p.track->linear = true;
        p.x = mbs::assemble(p.model, 0.0);
        mbs::static_equilibrium(p.model, 0.0, p.x);
        p.track->linear = false;
        p.ws->set_state(p.x);
        F[k] = mbs::evaluate_output(p.force, p.model, 0.0, p.x, *p.ws);
        const double d = mbs::point_kinematics(p.model.frame(p.x, p.body), p.u).r.y() - p.track->wire[static_cast<std::size_t>(p.track->primary)].value(0);
        if (!(d > 0))
          throw NumericalError(fmt::format(
              "pantograph {}: in its static equilibrium it does not press against the wire (contact force {:.4g} N); "
              "check its static uplift",
              k + 1, p.ks * d));
      }
      for (std::size_t i = 0; i < runs_.size(); ++i) {
        std::vector<double> xi, Fi;
        for (std::size_t k = 0; k < n; ++k)
          if (parts_[k]->primary == static_cast<int>(i)) xi.push_back(xs[k] - runs_[i].sec.start), Fi.push_back(F[k]);
        if (runs_.size() > 1 && xi.empty()) continue;
        std::vector<char> slack;
        u[i] = runs_[i].sec.line->static_displacement(xi, Fi, &slack);
      }
      if (iter > 0 && change < 1e-10) break;
    }
    if (change >= 1e-10)
      throw NumericalError(fmt::format(
          "finite-element catenary: the static uplift of the pantographs against the line did not converge (last "
          "change {:.3g} m)",
          change));
    // A pantograph that starts where a second wire hangs within its reach (an overlap's middle span).
    for (std::size_t k = 0; k < n; ++k) {
      const Part& p = *parts_[k];
      const double head = mbs::point_kinematics(p.model.frame(p.x, p.body), p.u).r.y() - p.offset;
      for (std::size_t i = 0; i < runs_.size(); ++i)
        if (static_cast<int>(i) != p.primary && covers(runs_[i], xs[k]) && head > static_height(static_cast<int>(i), xs[k]))
          throw ModelError(fmt::format(
              "pantograph {}: at x0 = {:g} m it would touch both contact wires of an overlap in its static state; start "
              "it where one wire runs alone (outside the overlap's middle span)",
              k + 1, xs[k]));
    }
    // The line's dynamic solve starts at the first advance: a static state alone (a study's operating
    // length) needs no modes.
    start_x_ = xs, start_F_ = F;
    line_started_ = false;
    for (std::size_t k = 0; k < n; ++k) {
      Part& p = *parts_[k];
      p.stepper.reset();  // made by the first advance, with its options
      p.y_wire = {y[k], y[k]};
      p.v_wire = {0, 0};
      p.acc_y = 0;
      p.F = F[k];
    }
    sampled_start_ = false;
    started_ = false;
  }

  solve::RunStats advance(double t_end, double dt, const solve::IntegratorOptions& options,
                          const SampleObserver& observer, bool accelerations) override {
    if (group_->lanes > 1)
      throw std::logic_error("finite-element catenary: a lane of several advances with the others (CoupledLanes::advance)");
    std::vector<FeCoupled*> one{this};
    std::vector<std::exception_ptr> error(1);
    const std::vector<solve::RunStats> st =
        advance_lanes(*group_, one, error, t_end, dt, options, [&](int, const Sample& s) { observer(s); }, accelerations);
    if (error[0]) std::rethrow_exception(error[0]);
    return st[0];
  }

  /// The lanes ls (of `group`, each at the same time) from their time() to t_end, step by step
  /// together: each lane's pantographs predicted, each section's lanes stepped as one group, each
  /// lane's pantographs integrated over the step and sampled. A lane's exception is caught into
  /// errors[j] (already set: not advanced); the others go on.
  static std::vector<solve::RunStats> advance_lanes(LineGroup& group, const std::vector<FeCoupled*>& ls,
                                                    std::vector<std::exception_ptr>& errors, double t_end, double dt,
                                                    const solve::IntegratorOptions& options, const LaneObserver& observer,
                                                    bool accelerations) {
    const std::size_t n = ls.size();
    std::vector<solve::RunStats> stats(n);
    auto each = [&](auto&& part) {
      for (std::size_t j = 0; j < n; ++j)
        if (!errors[j]) try {
            part(j);
          } catch (...) {
            errors[j] = std::current_exception();
          }
    };
    long n_steps = -1;
    each([&](std::size_t j) {
      const long k = ls[j]->begin(t_end, dt, options, [&observer, j](const Sample& s) { observer(static_cast<int>(j), s); },
                                  accelerations);
      if (n_steps >= 0 && k != n_steps)
        throw std::logic_error("finite-element catenary: lanes advanced together must be at the same time");
      n_steps = k;
    });
    std::vector<int> which;
    std::vector<std::size_t> of;
    std::vector<std::vector<FeLoad>> loads(n), batch;
    std::vector<std::vector<double>> forces;
    std::vector<std::exception_ptr> errs;
    for (long i = 0; i < n_steps; ++i) {
      each([&](std::size_t j) { ls[j]->predict(); });
      for (std::size_t sec = 0; sec < group.sections.size(); ++sec) {
        which.clear(), of.clear();
        std::size_t used = 0;
        each([&](std::size_t j) {
          if (ls[j]->load(sec, loads[used])) which.push_back(ls[j]->lane_), of.push_back(j), ++used;
        });
        if (which.empty()) continue;
        batch.resize(used);
        for (std::size_t u = 0; u < used; ++u) std::swap(batch[u], loads[u]);  // buffers kept from step to step
        group.sections[sec]->step(which, batch, forces, errs);
        for (std::size_t u = 0; u < used; ++u) std::swap(batch[u], loads[u]);
        for (std::size_t u = 0; u < of.size(); ++u)
          if (errs[u]) errors[of[u]] = errs[u];
        each([&](std::size_t j) {
          if (std::find(of.begin(), of.end(), j) != of.end()) ls[j]->stepped(sec);
        });
      }
      each([&](std::size_t j) { ls[j]->pantographs(); });
    }
    each([&](std::size_t j) { stats[j] = ls[j]->end(); });
    return stats;
  }

 private:
  // advance's parts (advance_lanes), with what they share over one advance.
  struct Advance {
    double h = 0;
    long every = 1, step_index = 0;
    SampleObserver observer;
    bool accelerations = false;
    std::chrono::steady_clock::time_point wall0;
    double t = 0, t1 = 0, rear = 0;  // the current step
    std::vector<double> heads, head_rates;
  } adv_;

  // Samples of every pantograph at t.
  void deliver(double t) {
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      Part& p = *parts_[k];
      const mbs::State& x = p.stepper->state();
      if (adv_.accelerations || mbs::needs_accelerations(p.force))
        mbs::accelerations(p.model, t, x, *p.ws);
      else
        p.ws->set_state(x);
      const double F = mbs::evaluate_output(p.force, p.model, t, x, *p.ws);
      const double xc = at(p.x0, t);
      if (adv_.observer) {
        Sample smp{ContactId{static_cast<int>(k)}, t, xc, F, p.model, x, *p.ws};
        if (runs_.size() == 1) {
          smp.wire_uplift = runs_.front().fe->uplift(xc);
          smp.force_wire[0] = F;
          smp.uplift_wire[0] = smp.wire_uplift;
        } else {
          double lowest = INFINITY;
          for (const Run& r : runs_)
            if (r.started && !r.stopped && covers(r, xc)) {
              const std::size_t w = static_cast<std::size_t>(r.sec.wire - 1);
              const double xl = xc - r.sec.start, up = r.fe->uplift(xl), y = r.sec.line->static_height(xl) + up;
              smp.uplift_wire[w] = up;
              smp.force_wire[w] = p.contact->wire_force(static_cast<int>(w), t, *p.ws);
              if (y < lowest) lowest = y, smp.wire_uplift = up;
            }
        }
        adv_.observer(smp);
      }
    }
  }

  // The start of an advance: the line at rest if not yet started, the steppers, the first sample.
  // Returns the number of structural steps to t_end.
  long begin(double t_end, double dt, const solve::IntegratorOptions& options, SampleObserver observer,
             bool accelerations) {
    if (!(dt > 0)) throw InvalidArgument("advance: the sample interval must be > 0 s");
    start_line();
    const double h = runs_.front().fe->dt();
    if (!started_ || options.method != options_.method || options.rtol != options_.rtol ||
        options.atol != options_.atol || options.max_step != options_.max_step) {
      options_ = options;
      for (auto& p : parts_) p->stepper = std::make_unique<solve::Stepper>(p->model, state_of(*p), time(), options_);
      started_ = true;
    }
    adv_.wall0 = std::chrono::steady_clock::now();
    adv_.h = h;
    // Samples every k-th structural step, k = round(dt / h) >= 1 (uniform; dt rounded to a multiple of h).
    adv_.every = std::max(1L, std::lround(dt / h));
    adv_.step_index = 0;
    adv_.observer = std::move(observer);
    adv_.accelerations = accelerations;
    adv_.heads.resize(parts_.size()), adv_.head_rates.resize(parts_.size());
    if (!sampled_start_) deliver(time());
    return static_cast<long>(std::floor((t_end - time()) / h + 1e-6));
  }

  // Each pantograph's contact point predicted at the step's end (second-order Taylor).
  void predict() {
    const double h = adv_.h, t = time(), t1 = t + h;
    adv_.t = t, adv_.t1 = t1;
    double rear = INFINITY;
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      Part& p = *parts_[k];
      const double xc1 = at(p.x0, t1);
      rear = std::min(rear, xc1);
      if (xc1 > length_)
        throw NumericalError(fmt::format(
            "t = {:.6g} s: pantograph {} (contact point at x = {:.6g} m) has run off the end of the line ({:g} m)", t1,
            k + 1, xc1, length_));
      const mbs::State& x = p.stepper->state();
      const mbs::PointKinematics pk = mbs::point_kinematics(p.model.frame(x, p.body), p.u);
      const double y = pk.r.y(), yd = pk.v.y();
      adv_.heads[k] = y + h * yd + 0.5 * h * h * p.acc_y - p.offset;
      adv_.head_rates[k] = yd + h * p.acc_y;
      p.yd_prev = yd;
    }
    adv_.rear = rear;
  }

  // Section sec's loads for this step (false: it is not stepped — stopped, or not reached yet); a
  // section a pantograph reaches now starts at rest.
  bool load(std::size_t sec, std::vector<FeLoad>& loads) {
    Run& r = runs_[sec];
    if (r.stopped) return false;
    const double t = adv_.t, t1 = adv_.t1;
    bool any = false;
    for (const auto& p : parts_) any = any || covers(r, at(p->x0, t1));
    if (!r.started) {
      if (!any) return false;
      std::vector<double> xs, F(parts_.size(), 0.0);
      for (const auto& p : parts_) xs.push_back(local(r, at(p->x0, t)));
      r.fe->start(xs, F, t);
      r.started = true;
    }
    loads.resize(parts_.size());
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      const Part& p = *parts_[k];
      const double xc1 = at(p.x0, t1);
      loads[k] = covers(r, xc1) ? FeLoad{xc1 - r.sec.start, true, 0, adv_.heads[k], adv_.head_rates[k], p.ks, p.cs, v_}
                                : FeLoad{local(r, xc1), false, 0, 0, 0, 0, 0, v_};
    }
    return true;
  }

  // After section sec's step: held once the rearmost pantograph has left it far enough.
  void stepped(std::size_t sec) {
    Run& r = runs_[sec];
    if (adv_.rear > r.stop_after) r.held = r.fe->support_uplift(), r.stopped = true;
  }

  // The pantographs over the step against the wires' motion at their contact points; the samples.
  void pantographs() {
    const double h = adv_.h, t = adv_.t, t1 = adv_.t1;
    if (runs_.size() > 1) t_ = t1;
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      Part& p = *parts_[k];
      const double xc = at(p.x0, t), xc1 = at(p.x0, t1);
      p.track->present = {false, false};
      for (const Run& r : runs_) {
        if (!r.started || r.stopped || !covers(r, xc1)) continue;
        const std::size_t w = static_cast<std::size_t>(r.sec.wire - 1);
        const double y1 = r.fe->height(xc1 - r.sec.start), v1 = r.fe->height_rate(xc1 - r.sec.start, v_);
        if (runs_.size() > 1 && !covers(r, xc)) {  // the wire reached at this step: from its anchor
          p.y_wire[w] = r.sec.line->static_height(local(r, xc));
          p.v_wire[w] = 0;
        }
        p.track->wire[w] = WireTrack{t, t1, p.offset + p.y_wire[w], p.offset + y1, p.v_wire[w], v1};
        p.track->present[w] = true;
        p.y_wire[w] = y1, p.v_wire[w] = v1;
      }
      p.stepper->advance(t1);
      const mbs::PointKinematics pk = mbs::point_kinematics(p.model.frame(p.stepper->state(), p.body), p.u);
      p.acc_y = (pk.v.y() - p.yd_prev) / h;
    }
    if (++adv_.step_index % adv_.every == 0) deliver(time());
  }

  solve::RunStats end() {
    sampled_start_ = true;
    solve::RunStats total;
    for (auto& p : parts_) {
      const solve::RunStats st = p->stepper->stats();
      total.steps += st.steps - p->steps_reported;
      total.rhs_evals += st.rhs_evals - p->rhs_reported;
      p->steps_reported = st.steps, p->rhs_reported = st.rhs_evals;
    }
    total.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - adv_.wall0).count();
    adv_.observer = nullptr;
    return total;
  }

  struct Part {
    mbs::Model model;
    mbs::State x;  // before the first advance
    std::unique_ptr<mbs::Workspace> ws;
    std::unique_ptr<solve::Stepper> stepper;
    std::shared_ptr<Tracks> track;
    std::shared_ptr<TrackContact> contact;
    mbs::Output force;
    int body = -1;
    int primary = 0;  // the run of its static contact
    mbs::Vec2 u = mbs::Vec2::Zero();
    double x0 = 0, ks = 0, cs = 0, offset = 0;
    std::array<double, 2> y_wire{}, v_wire{};
    double acc_y = 0, yd_prev = 0, F = 0;
    long steps_reported = 0, rhs_reported = 0;
  };
  struct Run {
    FeSectionLine sec;
    FeLineSolver* fe = nullptr;  // this lane's solver in the group's section
    bool started = false, stopped = false;
    double stop_after = INFINITY;  // m: past this (the rearmost pantograph) it is no longer stepped
    std::vector<double> held;
  };
  struct Support {
    double x;
    int run, index, wire;
  };
  const Part& part(ContactId c) const {
    if (c.index < 0 || c.index >= n_contacts())
      throw InvalidArgument(fmt::format("contact {} does not exist: the system has {} contact(s)", c.index,
                                        n_contacts()));
    return *parts_[static_cast<std::size_t>(c.index)];
  }
  static const mbs::State& state_of(const Part& p) { return p.stepper ? p.stepper->state() : p.x; }
  // The contact point of the pantograph started at x0, at time t (m): one rounding, so that every
  // place computes the same x whatever the compiler contracts.
  double at(double x0, double t) const { return std::fma(v_, t, x0); }
  static bool covers(const Run& r, double x) { return x >= r.sec.start - 1e-9 && x <= r.sec.end + 1e-9; }
  static double local(const Run& r, double x) { return std::clamp(x - r.sec.start, 0.0, r.sec.line->length()); }
  double static_height(int run, double x) const {
    const Run& r = runs_[static_cast<std::size_t>(run)];
    return r.sec.line->static_height(local(r, x));
  }
  // The section whose wire is lowest at x (the running wire).
  int primary_run(double x) const {
    int best = -1;
    for (std::size_t i = 0; i < runs_.size(); ++i)
      if (covers(runs_[i], x) && (best < 0 || static_height(static_cast<int>(i), x) < static_height(best, x))) best = static_cast<int>(i);
    if (best < 0) throw ModelError(fmt::format("x = {:g} m is on no tension section of the line", x));
    return best;
  }
  // The line at rest in the static state equilibrate() found (the modal solve's windows are made
  // here): the sections under a pantograph now; the others when a pantograph reaches them.
  void start_line() const {
    if (line_started_) return;
    for (std::size_t i = 0; i < runs_.size(); ++i) {
      Run& r = const_cast<Run&>(runs_[i]);
      r.started = r.stopped = false;
      std::vector<double> xs, F;
      bool any = false;
      for (std::size_t k = 0; k < parts_.size(); ++k) {
        const bool mine = parts_[k]->primary == static_cast<int>(i);
        any = any || covers(r, start_x_[k]);
        xs.push_back(runs_.size() == 1 ? start_x_[k] : local(r, start_x_[k]));
        F.push_back(mine ? start_F_[k] : 0.0);
      }
      if (runs_.size() > 1 && !any) continue;
      r.fe->start(xs, F, 0.0);
      r.started = true;
    }
    t_ = 0;
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      Part& p = *parts_[k];
      for (const Run& r : runs_)
        if (r.started && covers(r, start_x_[k])) {
          const std::size_t w = static_cast<std::size_t>(r.sec.wire - 1);
          p.y_wire[w] = r.fe->height(start_x_[k] - r.sec.start);
          p.v_wire[w] = r.fe->height_rate(start_x_[k] - r.sec.start, v_);
        }
    }
    line_started_ = true;
  }

  mutable std::vector<Run> runs_;
  std::vector<Support> supports_;
  int wires_ = 1;
  double v_;
  Section section_;
  double length_, span_;
  std::vector<Section> overlaps_;
  std::vector<std::unique_ptr<Part>> parts_;
  solve::IntegratorOptions options_;
  bool sampled_start_ = false, started_ = false;
  std::vector<double> start_x_, start_F_;
  mutable bool line_started_ = false;
  mutable double t_ = 0;
  std::shared_ptr<LineGroup> group_;
  int lane_ = 0;

  friend class FeLanes;
};

// Lanes on the finite-element line (Catenary::couple_lanes): FeCoupled lanes of one group.
class FeLanes final : public CoupledLanes {
 public:
  FeLanes(std::vector<std::unique_ptr<Coupled>> lanes, std::vector<FeCoupled*> fe, std::shared_ptr<LineGroup> group)
      : CoupledLanes(std::move(lanes)), fe_(std::move(fe)), group_(std::move(group)) {}
  void advance(double t_end, double dt, const solve::IntegratorOptions& options, const LaneObserver& observer,
               bool accelerations) override {
    FeCoupled::advance_lanes(*group_, fe_, errors_, t_end, dt, options, observer, accelerations);
  }

 private:
  std::vector<FeCoupled*> fe_;
  std::shared_ptr<LineGroup> group_;
};

}  // namespace

FeCatenary::FeCatenary(FeCatenaryData data) : data_(std::move(data)) {
  data_.join_sections();
  data_.validate();
}

void FeCatenary::build() const {
  std::call_once(built_, [&] {
    // Each tension section is a line of its own (form-finding per section); one for a plain file.
    std::vector<FeSectionLine> secs;
    std::vector<FeLinkedSection> linked = link_sections(data_);  // the sections pass (fe_sections.cpp)
    if (linked.empty()) linked.push_back({data_, 0, 0, 1});
    for (const FeLinkedSection& ls : linked) {
      const FeCatenaryData& d = ls.line;
      FeSectionLine s;
      auto line = std::make_shared<const FeLine>(d);
      if (d.solver == FeCatenaryData::Solver::Modal) s.modal = std::make_shared<FeModalLine>(line, ModeStore::from_environment());
      s.start = ls.line_start, s.end = ls.line_start + line->length(), s.wire = ls.wire_label;
      s.line = std::move(line);
      secs.push_back(std::move(s));
    }
    sections_ = std::move(secs);
    modal_ = sections_.front().modal;
    line_ = sections_.front().line;
    line_ready_.store(true);
  });
}

const std::vector<FeSectionLine>& FeCatenary::sections() const {
  build();
  return sections_;
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
  if (d.sectioned())
    s = fmt::format("a line of {} tension sections ({:g} m, {} spans; overlaps of {} spans, two contact wires there); "
                    "section 1: {}",
                    sections_.size(), line_length(), d.spans, d.overlap_spans, s);
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
  double lo = line_length(), hi = 0;
  for (const PantographOnLine& p : pantographs) lo = std::min(lo, p.x0), hi = std::max(hi, p.x0);
  for (const FeSectionLine& s : sections_) s.modal->prepare(s.modal->window_spans(std::max(0.0, hi - lo)));
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

std::vector<Section> FeCatenary::overlaps() const {
  std::vector<Section> o;
  const std::vector<FeLinkedSection> s = link_sections(data_);
  for (std::size_t k = 0; k + 1 < s.size(); ++k)
    o.push_back({s[k + 1].line_start, s[k].line_start + s[k].line.spans * s[k].line.span});
  return o;
}

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
  return std::make_unique<FeCoupled>(sections_, pantographs, speed, section(), line_length(), data_.span, overlaps(),
                                     line_group(sections_, pantographs, line_length(), 1), 0);
}

std::unique_ptr<CoupledLanes> FeCatenary::make_lanes(const std::vector<std::vector<PantographOnLine>>& trains,
                                                     double speed) const {
  build();
  const int n = static_cast<int>(trains.size());
  const std::shared_ptr<LineGroup> group = line_group(sections_, trains.front(), line_length(), n);
  std::vector<std::unique_ptr<Coupled>> lanes;
  std::vector<FeCoupled*> fe;
  for (int i = 0; i < n; ++i) {
    auto c = std::make_unique<FeCoupled>(sections_, trains[static_cast<std::size_t>(i)], speed, section(), line_length(),
                                         data_.span, overlaps(), group, i);
    fe.push_back(c.get());
    lanes.push_back(std::move(c));
  }
  return std::make_unique<FeLanes>(std::move(lanes), std::move(fe), group);
}

}  // namespace inerta::catenary

namespace inerta::catenary {

std::vector<LineFeature> FeCatenary::features() const {
  using K = LineFeature::Kind;
  std::vector<LineFeature> f;
  for (const FeSectionLine& s : sections()) {
    const FeLine& line = *s.line;
    const FeCatenaryData& d = line.data();
    for (int m = 0; m <= d.spans; ++m) f.push_back({K::Mast, s.start + m * d.span, s.start + m * d.span});
    for (const FeLine::Dropper& dr : line.droppers())
      f.push_back({dr.kind == FeLine::Dropper::Kind::Stitch ? K::StitchDropper : K::Dropper, s.start + dr.x, s.start + dr.x});
    if (d.stitch.present && d.stitch.enabled)
      for (double x : line.support_x()) f.push_back({K::StitchWire, s.start + x - d.stitch.length / 2, s.start + x + d.stitch.length / 2});
  }
  for (const Section& o : overlaps()) f.push_back({K::Overlap, o.from, o.to});
  std::sort(f.begin(), f.end(), [](const LineFeature& a, const LineFeature& b) { return a.from < b.from; });
  return f;
}

}  // namespace inerta::catenary
