// Between contacts, (4-1)-(4-2) with N^l = 0 is the average-acceleration scheme, which is exact for
// a constant force: u^{l+1} = u^l + h v^l + h^2 f/2, v^{l+1} = v^l + h f reproduce the parabola.
// Stepping it one increment at a time accumulates one rounding per step (after 5000 steps of
// h = 0.001 the floor is missed by ~1e-12, and the scheme's impact then loses energy), and
// recovering v from (4-2), 2 (u^{l+1} - u^l)/h - v^l, multiplies the rounding of u by 2/h. So
// `direct` and `fb_newton` evaluate the same discrete solution from the last contact in closed
// form: u = u_a + s (v_a + s f/2), v = v_a + s f, s = (l + 1 - l_a) h.
// free_flight() is that formula, a template over the lane type so that the ensemble
// (ensemble.hpp), which steps a vector of particles at once, does the same operations in the same
// order as the single-particle solvers and so gets bit-identical results.
#pragma once

#include <cstdint>

#include "impact/model.hpp"

namespace impact {

// The free flight at time t after the anchor (u_a, v_a) under the force f (Real: double or a vector
// of lanes; Scalar: double or Real).
template <class Real, class Scalar>
void free_flight(const Real& u_a, const Real& v_a, const Real& t, const Scalar& f, Real& u,
                 Real& v) {
  u = u_a + t * (v_a + t * f / 2);
  v = v_a + t * f;
}

class FreeFlight {
 public:
  FreeFlight(double f, double h) : f_(f), h_(h) {}

  // The state at t_{l+1} if no contact force acts in the step from (t_l, s). Starts a new free
  // flight at (l, s) unless s is the state this predictor produced last at t_l.
  State predict(const State& s, std::int64_t l) {
    if (l != last_l_ || s.u != last_.u || s.v != last_.v) {
      anchor_l_ = l;
      anchor_ = s;
    }
    const double t = static_cast<double>(l + 1 - anchor_l_) * h_;
    State next;
    free_flight(anchor_.u, anchor_.v, t, f_, next.u, next.v);
    return next;
  }

  // Records the accepted state at t_l; a state that is not the free prediction (a contact step)
  // starts a new free flight there.
  void accept(std::int64_t l, const State& s, bool free) {
    if (!free) {
      anchor_l_ = l;
      anchor_ = s;
    }
    last_l_ = l;
    last_ = s;
  }

 private:
  double f_, h_;
  std::int64_t anchor_l_ = 0, last_l_ = -1;
  State anchor_, last_;
};

}  // namespace impact
