// Between contacts, (4-1)-(4-2) with N^l = 0 is the average-acceleration scheme, which is exact for
// a constant force: u^{l+1} = u^l + h v^l + h^2 f/2, v^{l+1} = v^l + h f reproduce the parabola.
// Stepping it one increment at a time accumulates one rounding per step (after 5000 steps of
// h = 0.001 the floor is missed by ~1e-12, and the scheme's impact then loses energy), and
// recovering v from (4-2), 2 (u^{l+1} - u^l)/h - v^l, multiplies the rounding of u by 2/h. So
// `direct` and `fb_newton` evaluate the same discrete solution from the last contact in closed
// form: u = u_a + s (v_a + s f/2), v = v_a + s f, s = (l + 1 - l_a) h.
// For a time-dependent force, scheme_flight.hpp adds the varying part to it.
// free_flight() is that formula, a template over the lane type so that the ensemble
// (ensemble.hpp), which steps a vector of particles at once, does the same operations in the same
// order as the single-particle solvers and so gets bit-identical results.
#pragma once

#include <cmath>

#include "impact/model/model.hpp"

namespace impact {

// The scheme (4-1)-(4-3) solves for N^l with the factor 2/h^2 of (5-1): for h below ~1.06e-154 it
// overflows, above ~9.48e153 it is subnormal or 0, and the step's contact force is then inf or 0/0.
// direct and fb_newton refuse such an h (the scene reader says so before the run).
inline bool scheme_step_representable(double h) {
  const double k = 2 / (h * h);
  return h > 0 && std::isnormal(k);
}

// One step of (5-1) with N^l = 0 and (4-2) as printed, from (u, v); `u` may be a gap u - phi.
inline State paper_free_step(const State& s, double f, double h) {
  const double u = h * (h * f / 2 + s.v) + s.u;
  return {u, 2 / h * (u - s.u) - s.v};
}

// The free flight at time t after the anchor (u_a, v_a) under the force f (Real: double or a vector
// of lanes; Scalar: double or Real).
template <class Real, class Scalar>
[[gnu::always_inline]] inline void free_flight(const Real& u_a, const Real& v_a, const Real& t,
                                               const Scalar& f, Real& u, Real& v) {
  u = u_a + t * (v_a + t * f / 2);
  v = v_a + t * f;
}

}  // namespace impact
