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
//
// A force of the state, f(t, u, v) (force.hpp): its discrete force replaces the step mean of
// (4-1) by the explicit one, f^l = (1/h) int_{t_l}^{t_{l+1}} f(t, u^l, v^l) dt, the state frozen
// at the step's start and t integrated as for f(t) (Gauss-Legendre, step_quadrature.hpp). For a
// force of t alone it is the step mean above, bit for bit. The state's part of f is then taken as
// by explicit Euler: a local error O(h^2) in v, first order over a run, as the schemes are across
// impacts; and the impulse identity (4-9) holds with int f replaced by h sum f^l.
//
// A bonding field's pull -gamma beta^2 R(g) (bonding.hpp) is a force of the state too, and is taken
// the same way: its impulse over step l is -h gamma (beta^l)^2 R(g^l), beta^l the bonds' fraction
// at the step's start (set_internal, z[kBondFraction]) and g^l the gap there. Explicit, as every
// force of the state in these steppers, so that a step stays a closed form with no solve: the
// particle's step then costs what it costs without bonds, and beta is updated after it by the
// closed form of bond_step (bonding.hpp) at the gap the step gave. First order, as the schemes
// are across impacts; an implicit pull would need g^{l+1} inside the impulse, a solve per step.
//
// A slow force, w h < kSlowPhase (harmonic_series.hpp): the same sums in terms of x = w s,
//   v^m = ... + a s (cos theta_a C1(x) + sin theta_a S1(x)),
//   u^m = ... + a s^2 (cos theta_a S2(x) + sin theta_a C2(x))
//         + a (h^2/12) (cos theta_a sin x - sin theta_a (1 - cos x)),
// since c = 1/w - w h^2/12 to rounding there, and I^l = a h sinc(w h/2) sin(theta_l + w h/2):
// the forms above carry the phasor's rounding times a/w and a/w^2 (u off by 524 287 m after 2 s
// at w = 1e-20, N = inf at w = 1e-300), these are accurate for every w, and a force with w = 0 is
// the constant a sin(phase) to rounding.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "impact/forces/force.hpp"
#include "impact/forces/free_flight.hpp"
#include "impact/forces/harmonic_series.hpp"
#include "impact/heap_value.hpp"
#include "impact/model/model.hpp"

namespace impact {

// (cos theta_l, sin theta_l), theta_l = omega l h + phase, at consecutive grid times (l < 2^54),
// without a sin or cos per step and without any call in the step: a call in the step loop, even
// one every 64 steps (a rotation by omega h re-anchored with sin and cos), made GCC keep the whole
// stepper in memory (a harmonic direct step took 8.4-13 instead of 5.2-7.1 ns). With l in base 64,
// l = sum_k d_k 64^k, theta_l = phase + sum_k d_k 64^k omega h, so the pair is the complex product
// of phase's and of one table entry per digit, table[k][d] = (cos, sin)(omega (d 64^k h)), all
// computed with std::cos/std::sin when the phasor is made (kLevels 64 entries). Each step
// multiplies the product of the upper digits (recomputed when d_0 wraps) by table[0][d_0]: no
// error accumulates from step to step, and the pair is a function of l alone. Error bound: with n
// factors other than (1, 0) (phase and the non-zero digits, n <= kLevels + 1), each rounded to u
// (u = 2^-53) and n - 1 products each rounding 2 products and a sum, every component is within
// (4 n - 3) u of (cos, sin) of the sum of the factors' angles (tests/test_forcing_steppers.cpp
// measures it): 1.9e-15 for 1e7 steps (n <= 5). The angles themselves are rounded as
// ForceFunction::at rounds omega t + phase, a few ulp of theta.
class GridPhasor {
 public:
  static constexpr int kDigitBits = 6;
  static constexpr int kBase = 1 << kDigitBits;
  static constexpr int kLevels = 9;  // 64^9 = 2^54 grid points, more than a grid has (2^53)
  // The error bound above for any l: (4 (kLevels + 1) - 3) u = 4.1e-15.
  static constexpr double kError = (4 * (kLevels + 1) - 3) * 0x1p-53;

  GridPhasor() = default;
  GridPhasor(const Harmonic& w, double h);
  GridPhasor(const GridPhasor&) = default;
  GridPhasor(GridPhasor&&) noexcept = default;
  GridPhasor& operator=(const GridPhasor&) = default;
  GridPhasor& operator=(GridPhasor&&) noexcept = default;
  // Inlined even on a step loop's exception path (heap_value.hpp).
  [[gnu::always_inline]] ~GridPhasor() {}
  // To theta_l.
  [[gnu::always_inline]] void seek(std::int64_t l) {
    l_ = l;
    Pair upper = phase_;
    for (int k = kLevels - 1; k >= 1; --k)
      upper = times(upper, (*table_)[k * kBase + ((l >> (kDigitBits * k)) & (kBase - 1))]);
    upper_ = upper;
    digit_ = static_cast<int>(l & (kBase - 1));
    now_ = times(upper_, (*table_)[digit_]);
  }
  // From theta_l to theta_{l+1}.
  [[gnu::always_inline]] void advance() {
    if (++digit_ == kBase) [[unlikely]] {
      seek(l_ + 1);
      return;
    }
    ++l_;
    now_ = times(upper_, (*table_)[digit_]);
  }
  double cos() const { return now_.c; }
  double sin() const { return now_.s; }
  std::int64_t l() const { return l_; }

  // The angle table[k][d] stands for, as the table computed it (for tests).
  double angle(int k, int d) const;

 private:
  struct Pair {
    double c = 1, s = 0;
  };
  [[gnu::always_inline]] static Pair times(const Pair& a, const Pair& b) {
    return {a.c * b.c - a.s * b.s, a.s * b.c + a.c * b.s};
  }

  double omega_ = 0, h_ = 0;
  // table[k][d] at k * kBase + d, on the heap (heap_value.hpp): 9 KiB a stepper need not move
  HeapValue<std::array<Pair, kLevels * kBase>> table_;
  Pair phase_;
  std::int64_t l_ = 0;
  int digit_ = 0;  // d_0 of l
  Pair upper_;     // phase times the entries of d_1 .. d_{kLevels - 1}
  Pair now_;       // (cos, sin) theta_l
};

// The varying part f(t) - f of the body force on the grid: its impulse I^l over each step.
class SchemeForce {
 public:
  SchemeForce(const Model& model, double h);
  SchemeForce(const SchemeForce&) = default;
  SchemeForce(SchemeForce&&) noexcept = default;
  SchemeForce& operator=(const SchemeForce&) = default;
  SchemeForce& operator=(SchemeForce&&) noexcept = default;
  // Inlined even on a step loop's exception path (heap_value.hpp).
  [[gnu::always_inline]] ~SchemeForce() {}

  bool constant() const { return !has_phasor_ && !expression_ && !bonds_; }
  // I^l, the integral of f(t) - f over [t_l, t_{l+1}], as its harmonic and expression parts; the
  // phasor is moved to t_{l+1} (from wherever it was: a call for another l than the last + 1
  // seeks first).
  struct Impulse {
    double harmonic = 0, expression = 0;
  };
  // Expression = false leaves the expression part out (for a model without one): its evaluation
  // is a call, and a call in the step loop keeps a stepper in memory (see GridPhasor). `at` is the
  // state (u^l - phi, v^l) at t_l, which a force of the state is evaluated at; by value, since a
  // reference to the caller's state kept it in memory (a harmonic moreau_jean step took 7.2
  // instead of 5.6 ns on an Intel Xeon family 6 model 167).
  template <bool Expression = true>
  [[gnu::always_inline]] Impulse advance(std::int64_t l, State at = {}) {
    Impulse impulse;
    if (has_phasor_) {
      seek(l);
      const double c0 = phasor_.cos(), s0 = phasor_.sin();
      phasor_.advance();
      // (a/w)(cos theta_l - cos theta_{l+1}); the difference cancels for short steps, to an
      // absolute error of a few ulp of a/w, the scale of the harmonic part of the velocity. A slow
      // force: a h sinc(w h/2) sin(theta_l + w h/2), without the difference.
      impulse.harmonic = slow_ ? slow_impulse_ * (s0 * cos_half_ + c0 * sin_half_)
                               : amplitude_over_omega_ * (c0 - phasor_.cos());
    }
    if constexpr (Expression) {
      if (expression_) impulse.expression = expression_integral(*expression_, l, h_, phi_, at);
      // The bonds' pull at the step's start, with the state's part of the force (file comment).
      if (bonds_) impulse.expression -= h_ * adhesive_pull(*bonds_, bond_fraction_, at.u);
    }
    return impulse;
  }
  // The phasor at t_l.
  [[gnu::always_inline]] void seek(std::int64_t l) {
    if (has_phasor_ && phasor_.l() != l) [[unlikely]]
      phasor_.seek(l);
  }
  // The internal variables a force of the state reads from the next advance() on (force.hpp).
  void set_internal(const std::array<double, kMaxInternal>& z) const {
    if (expression_) expression_->set_internal(z);
    bond_fraction_ = z[kBondFraction];
  }
  // The harmonic part: whether there is one, whether it is slow (harmonic_series.hpp), a / w and
  // the phasor at the current time.
  bool harmonic() const { return has_phasor_; }
  bool slow() const { return slow_; }
  const GridPhasor& phasor() const { return phasor_; }
  double amplitude_over_omega() const { return amplitude_over_omega_; }

 private:
  static double expression_integral(const ForceFunction& expression, std::int64_t l, double h,
                                    double phi, State at);

  double phi_, h_;
  bool has_phasor_ = false, slow_ = false;
  GridPhasor phasor_;
  double amplitude_over_omega_ = 0;
  // A slow force: a h sinc(w h/2), cos and sin of w h/2.
  double slow_impulse_ = 0, cos_half_ = 1, sin_half_ = 0;
  // The expression part alone (f = 0, no harmonic), on the heap: its parser binds t by address.
  HeapValue<ForceFunction> expression_;
  // A bonding field that acts (bonded(), model.hpp), and beta at the step's start (set_internal).
  std::optional<Bonding> bonds_;
  mutable double bond_fraction_ = 0;
};

// The largest w h for which the harmonic flight is summed in closed form (c above keeps all but a
// few ulp up to w h ~ pi; beyond, the grid no longer resolves the force).
inline constexpr double kMaxClosedFormPhase = 1.0;

// The scheme's free flight (4-1)-(4-2) with N^l = 0 from an anchor (the end of the last contact
// step, or the initial state), in gap coordinates, for any body force; the constant part is the
// closed form of free_flight.hpp, bit for bit.
class SchemeFlight {
 public:
  // The harmonic terms (a/w)(cos theta_a - cos theta_m) of v and (a/w)(s cos theta_a -
  // c (sin theta_m - sin theta_a)) of u are within (a/w) d and (a/w)(s + 2/w) d of their values for
  // the exact cos and sin, d = 2 GridPhasor::kError + 4 u: each phasor value is off by kError, the
  // difference of two and the products round by at most 4 u of those scales (c <= 1/w).
  static constexpr double kHarmonicTermError = 2 * GridPhasor::kError + 4 * 0x1p-53;

  SchemeFlight(const Model& model, double h);
  SchemeFlight(const SchemeFlight&) = default;
  SchemeFlight(SchemeFlight&&) noexcept = default;
  SchemeFlight& operator=(const SchemeFlight&) = default;
  SchemeFlight& operator=(SchemeFlight&&) noexcept = default;
  // Inlined even on a step loop's exception path (heap_value.hpp).
  [[gnu::always_inline]] ~SchemeFlight() {}

  bool constant_force() const { return force_.constant(); }
  // A free flight starts at (t_l, s).
  [[gnu::always_inline]] void start(std::int64_t l, const State& s) {
    anchor_l_ = l;
    anchor_ = now_ = s;
    stepped_ = {};
    force_.seek(l);
    if (closed_form_ || force_.slow()) {
      anchor_cos_ = force_.phasor().cos();
      anchor_sin_ = force_.phasor().sin();
    }
  }
  // The state at t_{l+1} if no contact force acts in step l (l: consecutive after start, the state
  // at t_l the last step's or restate's); Expression as for SchemeForce::advance.
  template <bool Expression = true>
  [[gnu::always_inline]] State step(std::int64_t l) {
    State next;
    const double s = static_cast<double>(l + 1 - anchor_l_) * h_;
    free_flight(anchor_.u, anchor_.v, s, f_, next.u, next.v);
    if (force_.constant()) return next;
    const SchemeForce::Impulse impulse = force_.template advance<Expression>(l, now_);
    impulse_ = impulse.harmonic + impulse.expression;
    if (stepped_part_) {
      const double stepped = closed_form_ || force_.slow() ? impulse.expression : impulse_;
      // (4-1)-(4-2) with N^l = 0 for the stepped part: u += h (V + I/2), V += I.
      stepped_.u += h_ * (stepped_.v + stepped / 2);
      stepped_.v += stepped;
      next.u += stepped_.u;
      next.v += stepped_.v;
    }
    if (closed_form_) {
      // The harmonic terms of the file's comment: differences of the phasor's values (exact when
      // they are close) times a/w and (a/w) c, rather than folded into the anchor, whose rounding
      // (of the anchor's size) would then enter every step (kHarmonicTermError).
      const double k = force_.amplitude_over_omega();
      next.v += k * (anchor_cos_ - force_.phasor().cos());
      next.u += k * (s * anchor_cos_) - k_trapezoid_ * (force_.phasor().sin() - anchor_sin_);
    } else if (force_.slow()) {
      add_slow_terms(s, next);
    }
    // The state a force of the state reads at the next step's start: the whole state, the harmonic
    // terms included (a bonding field's pull with a harmonic force reads the gap there).
    if constexpr (Expression) now_ = next;
    return next;
  }
  // The state at t_l (gap, v) for the next step(l), where it is not the flight's own (a stepper
  // that solves contact from its own state: DirectAsPrinted).
  void restate(const State& s) { now_ = s; }
  // The internal variables a force of the state reads from the next step(l) on (force.hpp).
  void set_internal(const std::array<double, kMaxInternal>& z) const { force_.set_internal(z); }
  // f^l of the last step(l), the step's discrete force: f + I^l / h.
  double step_force() const { return force_.constant() ? f_ : f_ + impulse_ / h_; }

 private:
  // The slow force's terms of the file's comment at s = t_m - t_a: x below 1/2 by the series,
  // above from the phasor's rotation since the anchor (no call in either).
  [[gnu::always_inline]] void add_slow_terms(double s, State& next) const {
    const double x = omega_ * s, c = force_.phasor().cos(), sn = force_.phasor().sin();
    const SlowAngle w = std::fabs(x) < 0.5 ? slow_angle_series(x)
                                           : slow_angle(x, sn * anchor_cos_ - c * anchor_sin_,
                                                        c * anchor_cos_ + sn * anchor_sin_);
    const double as = amplitude_ * s;
    next.v += as * (anchor_cos_ * w.c1 + anchor_sin_ * w.s1);
    next.u += as * s * (anchor_cos_ * w.s2 + anchor_sin_ * w.c2) +
              amplitude_ * h2_over_12_ * x * (anchor_cos_ * w.s1 - anchor_sin_ * w.c1);
  }

  double f_, h_;
  SchemeForce force_;
  bool closed_form_ = false;   // the harmonic part in closed form (a slow one: add_slow_terms)
  bool stepped_part_ = false;  // an expression, or a harmonic part not in closed form
  double k_trapezoid_ = 0;     // (a/w) c, c = (h/2) cot(w h/2)
  double amplitude_ = 0, omega_ = 0, h2_over_12_ = 0;  // a slow force's a, w and h^2/12
  std::int64_t anchor_l_ = 0;
  State anchor_;
  State now_;  // the state at t_l of the next step (gap, v): a force of the state is taken there
  double anchor_cos_ = 0, anchor_sin_ = 0;  // the phasor at the anchor
  State stepped_;                           // the stepped varying part since the anchor (U, V)
  double impulse_ = 0;
};

}  // namespace impact
