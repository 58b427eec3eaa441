// Independent reference models used by the tests to cross-check the Cartesian multibody engine.
//
// Header-only, standard library only (no Eigen, no project code). Everything here is written in
// MINIMAL coordinates, derived by hand from Lagrange's equations, and integrated with classical
// fixed-step RK4, so that it shares no code path with the engine (which uses Cartesian coordinates,
// constraints and Lagrange multipliers, spec §1.3-§1.5).
//
// Spec references: /work/shared/spec/01-inerter.md (equation numbers are the thesis's).
//   - §1.1: uniaxial spring / damper / inerter, F_I = b l̈ (eq. 3.4, 3.9), textbook form b (r̈·ê) (3.8).
//   - §1.2: Example A, 1-DOF lumped mass (eq. 3.12, 3.14).
//   - §1.6: Example B, two-bar mechanism in a horizontal plane.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace inerta::testref {

namespace detail {

template <std::size_t N>
using Vec = std::array<double, N>;

template <std::size_t N>
inline Vec<N> axpy(const Vec<N>& x, double a, const Vec<N>& d) {
    Vec<N> r{};
    for (std::size_t i = 0; i < N; ++i) r[i] = x[i] + a * d[i];
    return r;
}

// One classical RK4 step of x' = f(t, x).
template <std::size_t N, class F>
inline Vec<N> rk4_step(const F& f, double t, const Vec<N>& x, double h) {
    const Vec<N> k1 = f(t, x);
    const Vec<N> k2 = f(t + 0.5 * h, axpy(x, 0.5 * h, k1));
    const Vec<N> k3 = f(t + 0.5 * h, axpy(x, 0.5 * h, k2));
    const Vec<N> k4 = f(t + h, axpy(x, h, k3));
    Vec<N> r{};
    for (std::size_t i = 0; i < N; ++i)
        r[i] = x[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    return r;
}

// Integer step counts so that sample times are exact multiples of h (no accumulated rounding).
struct StepPlan {
    long steps_per_sample;
    long n_samples;  // number of intervals; samples k = 0..n_samples
};

inline StepPlan make_plan(double t_end, double dt_sample, double h) {
    if (!(h > 0.0) || !(dt_sample > 0.0) || !(t_end >= 0.0))
        throw std::invalid_argument("testref: h, dt_sample must be > 0 and t_end >= 0");
    const double ratio = dt_sample / h;
    const long sps = std::lround(ratio);
    if (sps < 1 || std::abs(ratio - static_cast<double>(sps)) > 1e-6 * ratio)
        throw std::invalid_argument("testref: dt_sample must be an integer multiple of h");
    const long ns = std::lround(t_end / dt_sample);
    return {sps, ns};
}

}  // namespace detail

// =================================================================================================
// Example B (§1.6): two-bar mechanism, minimal coordinates θ = (θ1, θ2) (absolute bar angles).
// =================================================================================================
//
// Geometry (e(θ) = (cos θ, sin θ), n(θ) = de/dθ = (−sin θ, cos θ)):
//   bar 1: end a at A = origin, COM G1 = (L/2) e1, end b = B = L e1
//   bar 2: end a at B,          COM G2 = L e1 + (L/2) e2, end b = C = L e1 + L e2
//   D1 = d e1, D2 = L e1 + d e2 with d = 0.75 L (local x̄ = +0.25 L from the COM, spec §1.6)
//
// Kinetic energy T = ½ θ̇ᵀ M(θ) θ̇ with (double pendulum, Lagrange):
//   M11 = m L²/4 + I + m L², M22 = m L²/4 + I, M12 = M21 = (m L²/2) cos(θ1 − θ2)
// Velocity (Coriolis/centrifugal) terms, Δ = θ1 − θ2, a = m L²/2:
//   h1 = +a sin Δ θ̇2²,  h2 = −a sin Δ θ̇1²
//
// Uniaxial element D1–D2 (§1.1): r = D2 − D1 = (L − d) e1 + d e2, ṙ = J_r θ̇,
//   J_r = [ (L−d) n1 , d n2 ],  r̈ = J_r θ̈ + a_n,  a_n = −(L−d) θ̇1² e1 − d θ̇2² e2.
//   l = |r|, ê = r/l, l̇ = ê·ṙ, J_l = êᵀ J_r (= ∂l/∂θ).
//   l̈ = ê·r̈ + [ṙ·ṙ − l̇²]/l = J_l θ̈ + ê·a_n + [ṙ·ṙ − l̇²]/l           (eq. 3.4 / 3.9 / 3.20)
//   F_I (with correction)    = b (J_l θ̈ + ê·a_n + [ṙ·ṙ − l̇²]/l)
//   F_I (without correction) = b (r̈·ê) = b (J_l θ̈ + ê·a_n)                (eq. 3.8)
//   Tension F = k (l − L0) + c l̇ + F_I, generalised force Q = −F J_lᵀ.
//   The θ̈-part b J_lᵀ J_l goes to the mass matrix (same idea as eq. 3.31-3.33).
// Rotational spring on θ1: moment −k_r (θ1 − π/4) on bar 1.
// External force F_a = Fa sin(2π f t) along +Y at C: Q = J_Cᵀ [0, F_a], J_C = [L n1, L n2].

struct TwoBarParams {
    double m = 1.0;      // bar mass [kg]
    double I = 0.083;    // bar inertia about COM [kg m²]
    double L = 1.0;      // bar length [m]
    double kr = 1000.0;  // rotational spring at A [N m/rad], undeformed at θ1 = π/4
    double k = 100.0;    // D1–D2 spring [N/m], free length = |D2 − D1| at θ = (π/4, 3π/4)
    double c = 100.0;    // D1–D2 damper [N s/m]
    double b = 10.0;     // D1–D2 inerter [kg]
    double Fa = 8.0;     // excitation amplitude at C along +Y [N]
    double f = 1.0;      // excitation frequency [Hz]
    // Initial state (defaults: at rest in the undeformed configuration). Only used to allow
    // non-trivial free-vibration checks (e.g. energy conservation); spring free lengths / angles
    // always refer to the nominal configuration θ = (π/4, 3π/4).
    double theta1_0 = std::numbers::pi / 4.0;
    double theta2_0 = 3.0 * std::numbers::pi / 4.0;
    double omega1_0 = 0.0;
    double omega2_0 = 0.0;
};

struct TwoBarSample {
    double t, Cx, Cy;
};

// Full state sample (for diagnostics).
struct TwoBarState {
    double t, th1, th2, w1, w2;
};

namespace detail {

struct TwoBarKin {
    double l, ldot;          // element length and rate
    double Jl1, Jl2;         // ∂l/∂θ
    double quad_corr;        // ê·a_n (always part of r̈·ê)
    double quad_centripetal; // [ṙ·ṙ − l̇²]/l (centripetal correction, eq. 3.9)
};

inline TwoBarKin twobar_kin(const TwoBarParams& p, double th1, double th2, double w1, double w2) {
    const double d = 0.75 * p.L, s = p.L - d;
    const double c1 = std::cos(th1), s1 = std::sin(th1), c2 = std::cos(th2), s2 = std::sin(th2);
    // r = s e1 + d e2
    const double rx = s * c1 + d * c2, ry = s * s1 + d * s2;
    const double l = std::sqrt(rx * rx + ry * ry);
    const double ex = rx / l, ey = ry / l;
    // J_r columns: s n1, d n2
    const double J1x = -s * s1, J1y = s * c1, J2x = -d * s2, J2y = d * c2;
    const double vx = J1x * w1 + J2x * w2, vy = J1y * w1 + J2y * w2;  // ṙ
    const double Jl1 = ex * J1x + ey * J1y, Jl2 = ex * J2x + ey * J2y;
    const double ldot = ex * vx + ey * vy;
    // a_n = −s θ̇1² e1 − d θ̇2² e2
    const double anx = -s * w1 * w1 * c1 - d * w2 * w2 * c2;
    const double any = -s * w1 * w1 * s1 - d * w2 * w2 * s2;
    TwoBarKin k{};
    k.l = l;
    k.ldot = ldot;
    k.Jl1 = Jl1;
    k.Jl2 = Jl2;
    k.quad_corr = ex * anx + ey * any;
    k.quad_centripetal = (vx * vx + vy * vy - ldot * ldot) / l;
    return k;
}

inline double twobar_free_length(const TwoBarParams& p) {
    return twobar_kin(p, std::numbers::pi / 4.0, 3.0 * std::numbers::pi / 4.0, 0.0, 0.0).l;
}

// State x = (θ1, θ2, θ̇1, θ̇2); returns ẋ.
inline Vec<4> twobar_rhs(const TwoBarParams& p, double L0, bool centripetal, double t,
                         const Vec<4>& x) {
    const double th1 = x[0], th2 = x[1], w1 = x[2], w2 = x[3];
    const double mL2 = p.m * p.L * p.L;
    const double a = 0.5 * mL2;
    const double Dl = th1 - th2;
    // Mass matrix of the two bars
    double M11 = 0.25 * mL2 + p.I + mL2;
    double M22 = 0.25 * mL2 + p.I;
    double M12 = a * std::cos(Dl);
    // Velocity terms moved to the right-hand side
    double Q1 = -a * std::sin(Dl) * w2 * w2;
    double Q2 = +a * std::sin(Dl) * w1 * w1;
    // Rotational spring at A
    Q1 += -p.kr * (th1 - std::numbers::pi / 4.0);
    // External force at C along +Y: Q = J_Cᵀ [0, Fa], J_C = [L n1, L n2], n = (−sin, cos)
    const double Fa = p.Fa * std::sin(2.0 * std::numbers::pi * p.f * t);
    Q1 += p.L * std::cos(th1) * Fa;
    Q2 += p.L * std::cos(th2) * Fa;
    // Spring / damper / inerter between D1 and D2 (eq. 3.1/3.2/3.4 in minimal coordinates)
    const TwoBarKin kin = twobar_kin(p, th1, th2, w1, w2);
    double s_in = kin.quad_corr;                   // b (r̈·ê) minus its θ̈ part (eq. 3.8)
    if (centripetal) s_in += kin.quad_centripetal; // + centripetal correction (eq. 3.9, 3.20)
    const double Fv = p.k * (kin.l - L0) + p.c * kin.ldot + p.b * s_in;
    Q1 -= Fv * kin.Jl1;
    Q2 -= Fv * kin.Jl2;
    // Inerter θ̈-part in the mass matrix: b J_lᵀ J_l (cf. M_I of eq. 3.33)
    M11 += p.b * kin.Jl1 * kin.Jl1;
    M12 += p.b * kin.Jl1 * kin.Jl2;
    M22 += p.b * kin.Jl2 * kin.Jl2;
    // 2×2 solve by Cramer's rule
    const double det = M11 * M22 - M12 * M12;
    const double a1 = (Q1 * M22 - M12 * Q2) / det;
    const double a2 = (M11 * Q2 - M12 * Q1) / det;
    return {w1, w2, a1, a2};
}

}  // namespace detail

// Mechanical energy: kinetic + inerter ½ b l̇² + spring potentials (conserved for c = 0, Fa = 0
// with the centripetal correction on).
inline double twobar_energy(const TwoBarState& s, const TwoBarParams& p = {}) {
    const double mL2 = p.m * p.L * p.L;
    const double M11 = 0.25 * mL2 + p.I + mL2, M22 = 0.25 * mL2 + p.I;
    const double M12 = 0.5 * mL2 * std::cos(s.th1 - s.th2);
    const double T = 0.5 * (M11 * s.w1 * s.w1 + 2.0 * M12 * s.w1 * s.w2 + M22 * s.w2 * s.w2);
    const auto kin = detail::twobar_kin(p, s.th1, s.th2, s.w1, s.w2);
    const double L0 = detail::twobar_free_length(p);
    const double dth = s.th1 - std::numbers::pi / 4.0;
    return T + 0.5 * p.b * kin.ldot * kin.ldot + 0.5 * p.k * (kin.l - L0) * (kin.l - L0) +
           0.5 * p.kr * dth * dth;
}

// Full-state time history at t = k·dt_sample, k = 0..round(t_end/dt_sample).
inline std::vector<TwoBarState> twobar_states(bool centripetal, double t_end, double dt_sample,
                                              double h = 1e-4, const TwoBarParams& p = {}) {
    const auto plan = detail::make_plan(t_end, dt_sample, h);
    const double L0 = detail::twobar_free_length(p);
    detail::Vec<4> x{p.theta1_0, p.theta2_0, p.omega1_0, p.omega2_0};
    auto f = [&](double t, const detail::Vec<4>& y) {
        return detail::twobar_rhs(p, L0, centripetal, t, y);
    };
    std::vector<TwoBarState> out;
    out.reserve(static_cast<std::size_t>(plan.n_samples) + 1);
    long step = 0;
    out.push_back({0.0, x[0], x[1], x[2], x[3]});
    for (long k = 1; k <= plan.n_samples; ++k) {
        for (long i = 0; i < plan.steps_per_sample; ++i, ++step)
            x = detail::rk4_step(f, static_cast<double>(step) * h, x, h);
        out.push_back({static_cast<double>(k) * dt_sample, x[0], x[1], x[2], x[3]});
    }
    return out;
}

// Position of point C (end b of bar 2) at t = k·dt_sample. Starts from rest at θ = (π/4, 3π/4)
// (unless TwoBarParams overrides the initial state).
inline std::vector<TwoBarSample> twobar_reference(bool centripetal, double t_end, double dt_sample,
                                                  double h = 1e-4, const TwoBarParams& p = {}) {
    const auto st = twobar_states(centripetal, t_end, dt_sample, h, p);
    std::vector<TwoBarSample> out;
    out.reserve(st.size());
    for (const auto& s : st)
        out.push_back({s.t, p.L * (std::cos(s.th1) + std::cos(s.th2)),
                       p.L * (std::sin(s.th1) + std::sin(s.th2))});
    return out;
}

// =================================================================================================
// Example A (§1.2): 1-DOF mass sliding along x = La, coordinate y; spring k + inerter b from O.
// =================================================================================================
//
// l = sqrt(La² + y²), ê = (La, y)/l. Tension F acts on the mass as −F ê, so m ÿ = −F y/l.
//   With correction    F_I = b l̈ = b y ÿ / l + b La² ẏ² / l³                      (eq. 3.12)
//     → (m + b y²/l²) ÿ + b La² y ẏ² / l⁴ + k (l − L0) y / l = 0                 (eq. 3.14)
//   Without correction F_I = b (r̈·ê) = b y ÿ / l                                 (eq. 3.8)
//     → (m + b y²/l²) ÿ + k (l − L0) y / l = 0

struct OneDofParams {
    double m = 5.0, b = 100.0, k = 10000.0, La = 1.0, Lb = 1.0;
};

struct OneDofSample {
    double t, y, F_inerter;  // F_inerter: tension positive
};

namespace detail {

inline double onedof_accel(const OneDofParams& p, bool centripetal, double y, double yd) {
    const double L0 = std::sqrt(p.La * p.La + p.Lb * p.Lb);
    const double l2 = p.La * p.La + y * y;
    const double l = std::sqrt(l2);
    const double meff = p.m + p.b * y * y / l2;
    double rhs = -p.k * (l - L0) * y / l;
    if (centripetal) rhs -= p.b * p.La * p.La * y * yd * yd / (l2 * l2);
    return rhs / meff;
}

inline double onedof_inerter_force(const OneDofParams& p, bool centripetal, double y, double yd,
                                   double ydd) {
    const double l = std::sqrt(p.La * p.La + y * y);
    double F = p.b * y * ydd / l;
    if (centripetal) F += p.b * p.La * p.La * yd * yd / (l * l * l);  // eq. 3.12
    return F;
}

}  // namespace detail

// Released from rest at y0; samples at t = k·dt_sample, k = 0..round(t_end/dt_sample).
inline std::vector<OneDofSample> onedof_reference(bool centripetal, double y0, double t_end,
                                                  double dt_sample, double h = 1e-5,
                                                  OneDofParams p = {}) {
    const auto plan = detail::make_plan(t_end, dt_sample, h);
    detail::Vec<2> x{y0, 0.0};
    auto f = [&](double, const detail::Vec<2>& s) -> detail::Vec<2> {
        return {s[1], detail::onedof_accel(p, centripetal, s[0], s[1])};
    };
    auto sample = [&](double t) {
        const double ydd = detail::onedof_accel(p, centripetal, x[0], x[1]);
        return OneDofSample{t, x[0], detail::onedof_inerter_force(p, centripetal, x[0], x[1], ydd)};
    };
    std::vector<OneDofSample> out;
    out.reserve(static_cast<std::size_t>(plan.n_samples) + 1);
    long step = 0;
    out.push_back(sample(0.0));
    for (long k = 1; k <= plan.n_samples; ++k) {
        for (long i = 0; i < plan.steps_per_sample; ++i, ++step)
            x = detail::rk4_step(f, static_cast<double>(step) * h, x, h);
        out.push_back(sample(static_cast<double>(k) * dt_sample));
    }
    return out;
}

// Linearised natural frequency about y = Lb (spec §1.2, thesis appendix A.1):
// m_eq = m + (Lb/L0)² b, k_eq = k (Lb/L0)².
inline double onedof_linear_frequency_hz(OneDofParams p = {}) {
    const double L0sq = p.La * p.La + p.Lb * p.Lb;
    const double g = p.Lb * p.Lb / L0sq;
    return std::sqrt(p.k * g / (p.m + g * p.b)) / (2.0 * std::numbers::pi);
}

}  // namespace inerta::testref
