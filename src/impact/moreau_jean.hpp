// Moreau-Jean time-stepping (velocity level, theta-method, Newton's impact law), as in Siconos's
// MoreauJeanOSI with a one-contact LCP, for comparison with the paper's position-level scheme:
//   v^{l+1} = v^l + h f + P^{l+1},  u^{l+1} = u^l + h (theta v^{l+1} + (1 - theta) v^l),
//   if the contact is active (u^l - phi + gamma h v^l <= 0, gamma = 1/2):
//     0 <= v^{l+1} + e v^l  ⟂  P^{l+1} >= 0,
// with e = COR, or e = 1 when the scene gives none (the elastic limit of the exact reference).
// The position is not projected, so u may dip below phi by O(h |v|).
#pragma once

#include <cstdint>

#include "impact/model.hpp"

namespace impact {

// One step of Moreau-Jean for one particle (Real = double) or a vector of particles (the ensemble,
// ensemble.hpp): the same operations in the same order for both, the branches taken as
// selections, so that each lane of the ensemble is bit-identical to the single-particle solver.
// The position is the gap g = u - phi: far from the origin (phi = 1e9) the increments h v of u
// fall below the floor's ulp and u would freeze while v grows; the gap keeps them.
// e is the COR (1 without one); contact_force is set to P^{l+1} / h.
template <class Real>
void moreau_jean_step(Real& gap, Real& v, Real& contact_force, const Real& f, const Real& e,
                      double theta, double h) {
  const Real v_free = v + h * f;
  // The contact is active when u^l - phi + gamma h v^l <= 0; then the one-contact LCP in closed
  // form: the smallest impulse that makes v^{l+1} >= -e v^l. `bound` is -e v^l where the contact
  // is active and v_free (so no impulse) elsewhere: a selection feeding a comparison, because
  // nested selections or `active & (v_free < target)` made GCC build the AVX-512 masks lane by
  // lane (the ensemble ran 2.3x slower).
  const Real target = -e * v;
  const Real bound = gap + 0.5 * h * v <= 0.0 ? target : v_free;
  const Real impulse = v_free < bound ? bound - v_free : Real{};
  const Real v_next = v_free + impulse;
  gap += h * (theta * v_next + (1 - theta) * v);
  v = v_next;
  contact_force = impulse / h;
}

struct MoreauJeanParams {
  double theta = 0.5;
  bool operator==(const MoreauJeanParams&) const = default;
};

class MoreauJean {
 public:
  MoreauJean(const Model& model, double h, const MoreauJeanParams& params)
      : phi_(model.phi), f_(model.f), h_(h), theta_(params.theta), e_(model.cor.value_or(1.0)) {}

  void initialize(const State& s, std::int64_t) { state_ = {s.u - phi_, s.v}; }

  StepInfo do_step(State& s, std::int64_t) {
    StepInfo info;
    moreau_jean_step(state_.u, state_.v, info.contact_force, f_, e_, theta_, h_);
    s = {phi_ + state_.u, state_.v};
    return info;
  }

 private:
  double phi_, f_;
  double h_;
  double theta_;
  double e_;
  State state_;  // (u - phi, v) at t_l
};

}  // namespace impact
