// The time-steppers' discrete body force for a time-dependent f(t) of (2-1), and the free flight of
// the scheme (4-1)-(4-2) under it.
//
// The discrete force of step l is the step's mean, f^l = (1/h) int_{t_l}^{t_{l+1}} f (the
// ForceFunction::step_mean of force.hpp), split as f^l = f + (1/h) I^l: the constant part f of the
// model exactly as the constant-force code uses it, and the impulse I^l of the varying part
// f(t) - f over the step. With that split a harmonic part of amplitude 0 adds +-0 and changes no
// bit. Since h f^l is the exact integral, the scheme's free-flight velocity is the exact one,
// v^l = v_a + int_{t_a}^{t_l} f, and h sum N^l = v^n - v^0 - int_0^T f holds to rounding (4-9).
//
// In free flight (4-1)-(4-2) give u^{l+1} = u^l + h (v^l + v^{l+1})/2: the trapezoidal rule of that
// exact velocity. For a harmonic part a sin(w t + p), theta_l = w t_l + p, it sums in closed form:
//   v^m = v_a + f s + (a/w)(cos theta_a - cos theta_m),
//   u^m = u_a + s (v_a + s f/2) + (a/w)(s cos theta_a - c (sin theta_m - sin theta_a)),
//   s = t_m - t_a, c = (h/2) cot(w h/2) = (1/w)(1 - (w h)^2/12 + ...),
// since sum_{j<n} (cos theta_j + cos theta_{j+1})/2 = (1/2) cot(w h/2)(sin theta_n - sin theta_0).
// The exact flight has c = 1/w (ForceFunction::flight): the scheme's u is second order,
// (a/w)|1/w - c| |sin theta_m - sin theta_a| <= a h^2/6 (1 + O((w h)^2)), and its v is exact.
// For w h > kMaxClosedFormPhase (c loses its digits as w h nears 2 pi) and for an expression the
// varying part is stepped, u += h (V + I/2), V += I, from the last anchor.
#pragma once

#include <cstdint>
#include <optional>

#include "impact/force.hpp"
#include "impact/model.hpp"

namespace impact {

// (cos theta_l, sin theta_l), theta_l = omega l h + phase, at consecutive grid times, by rotating
// with (cos omega h, sin omega h): one sin/cos per step cost 5 times a constant-force direct step.
// Every kReanchorSteps steps (at the multiples of kReanchorSteps, whatever the start) the pair is
// computed afresh from theta_l, so that it is a function of l alone. Drift bound: the rounded
// rotation is a rotation by omega h + O(u) scaled by 1 + O(u) (u = 2^-53), and each rotation rounds
// 4 products and 2 sums, so j steps after an anchor the pair is off by at most (1 + 5 j) u, below
// 5 kReanchorSteps u = 3.6e-14 (tests/test_forcing_steppers.cpp measures it).
class GridPhasor {
 public:
  static constexpr int kReanchorSteps = 64;

  GridPhasor(const Harmonic& w, double h);
  // To theta_l.
  void seek(std::int64_t l);
  // From theta_l to theta_{l+1}.
  void advance() {
    ++l_;
    if (--countdown_ == 0) return anchor();
    const double c = c_ * rot_c_ - s_ * rot_s_;
    s_ = s_ * rot_c_ + c_ * rot_s_;
    c_ = c;
  }
  double cos() const { return c_; }
  double sin() const { return s_; }
  std::int64_t l() const { return l_; }

 private:
  void anchor();

  double omega_, phase_, h_, rot_c_, rot_s_;
  std::int64_t l_ = 0;
  int countdown_ = kReanchorSteps;
  double c_ = 1, s_ = 0;
};

// The varying part f(t) - f of the body force on the grid: its impulse I^l over each step.
class SchemeForce {
 public:
  SchemeForce(const Model& model, double h);

  bool constant() const { return !phasor_ && !expression_; }
  // I^l, the integral of f(t) - f over [t_l, t_{l+1}], as its harmonic and expression parts; the
  // phasor is moved to t_{l+1} (from wherever it was: a call for another l than the last + 1
  // seeks first).
  struct Impulse {
    double harmonic = 0, expression = 0;
  };
  Impulse advance(std::int64_t l);
  // The phasor at t_l.
  void seek(std::int64_t l) {
    if (phasor_ && phasor_->l() != l) phasor_->seek(l);
  }
  // The harmonic part: a / w and the phasor at the current time (closed-form flights).
  const std::optional<GridPhasor>& phasor() const { return phasor_; }
  double amplitude_over_omega() const { return amplitude_over_omega_; }

 private:
  double h_;
  std::optional<GridPhasor> phasor_;
  double amplitude_over_omega_ = 0;
  std::optional<ForceFunction> expression_;  // the expression part alone (f = 0, no harmonic)
};

// The largest w h for which the harmonic flight is summed in closed form (c above keeps all but a
// few ulp up to w h ~ pi; beyond, the grid no longer resolves the force).
inline constexpr double kMaxClosedFormPhase = 1.0;

// The scheme's free flight (4-1)-(4-2) with N^l = 0 from an anchor (the end of the last contact
// step, or the initial state), in gap coordinates, for any body force; the constant part is the
// closed form of free_flight.hpp, bit for bit.
class SchemeFlight {
 public:
  SchemeFlight(const Model& model, double h);

  bool constant_force() const { return force_.constant(); }
  // A free flight starts at (t_l, s).
  void start(std::int64_t l, const State& s);
  // The state at t_{l+1} if no contact force acts in step l (l: consecutive after start), and
  // f^l, the step's discrete force, in step_force().
  State step(std::int64_t l);
  double step_force() const { return step_force_; }

 private:
  double f_, h_;
  SchemeForce force_;
  bool closed_form_ = false;  // the harmonic part in closed form (else stepped with the rest)
  double trapezoid_ = 0;      // c = (h/2) cot(w h/2)
  std::int64_t anchor_l_ = 0;
  State anchor_;
  double anchor_cos_ = 0, anchor_sin_ = 0;
  State stepped_;  // the stepped varying part since the anchor (U, V)
  double step_force_ = 0;
};

}  // namespace impact
