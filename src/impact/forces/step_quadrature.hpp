// The integral of a force expression over an interval with its error under control: the
// time-steppers' discrete force is a step's mean (scheme_flight.hpp), and a force that varies
// faster than the step (f = -9.80665 + 1e4 sin(1e5 t) at h = 1e-3: 16 periods per step) aliases a
// fixed rule (16-point Gauss-Legendre gave u_T = 72.86 where the step means' exact values give
// 80.59), as a singular one (1 / (t - 0.5)) is summed to finite nonsense.
//
// 16-point Gauss-Legendre (GSL's table, summed in gsl_integration_glfixed's order, so a resolved
// step keeps its value bit for bit) is taken when the rule's own samples show a resolved f: the
// top two Legendre coefficients of their interpolating polynomial (exact discrete projections:
// the rule is exact to degree 31) are below kResolvedTail of the samples' largest |f|. Otherwise
// it is checked against the same rule on both halves, and kept when they agree to kStepTolerance
// (b - a) max |f|; else GSL's adaptive QAG (61-point Gauss-Kronrod, up to kMaxSubintervals pieces)
// integrates to that tolerance, and a step it cannot resolve (a pole inside, a force faster than
// 1/kMaxSubintervals of the step) is refused with an error naming the interval and where |f| was
// largest.
#pragma once

namespace impact {

inline constexpr double kResolvedTail = 1e-12;
inline constexpr double kStepTolerance = 1e-12;
inline constexpr int kMaxSubintervals = 1000;

// f(t, self); it may throw (an expression that is not finite), which the integral passes on.
struct Integrand {
  double (*f)(double, void*);
  void* self;
};

// The integral of f over [a, b]; std::runtime_error when it cannot be resolved (see above).
double controlled_integral(const Integrand& f, double a, double b);

}  // namespace impact
