// Moreau-Jean time-stepping (velocity level, theta-method, Newton's impact law), as in Siconos's
// MoreauJeanOSI with a one-contact LCP, for comparison with the paper's position-level scheme:
//   v^{l+1} = v^l + h f^l + P^{l+1},  u^{l+1} = u^l + h (theta v^{l+1} + (1 - theta) v^l),
//   if the contact is active (u^l - phi + gamma h v^l <= 0, gamma = 1/2):
//     0 <= v^{l+1} + e v^l  ⟂  P^{l+1} >= 0,
// with e = COR, or e = 1 when the scene gives none (the elastic reading of contact_law.hpp).
// The position is not projected, so u may dip below phi by O(h |v|).
#pragma once

#include <cstdint>
#include <type_traits>

#include "impact/forces/force.hpp"
#include "impact/forces/scheme_flight.hpp"
#include "impact/loop/repeats.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/methods/method_params.hpp"
#include "impact/model/contact_law.hpp"
#include "impact/model/model.hpp"

namespace impact {

// One step of Moreau-Jean for one particle (Real = double) or a vector of particles (the ensemble,
// ensemble.hpp), from v_free = v^l + h f^l (the velocity without contact impulse): the same
// operations in the same order for both, the branches taken as selections, so that each lane of
// the ensemble is bit-identical to the single-particle solver.
// The position is the gap g = u - phi: far from the origin (phi = 1e9) the increments h v of u
// fall below the floor's ulp and u would freeze while v grows; the gap keeps them.
// e is the COR (1 without one); contact_force is set to P^{l+1} / h.
template <class Real>
[[gnu::always_inline]] inline void moreau_jean_update(Real& gap, Real& v, Real& contact_force,
                                                      const Real& v_free, const Real& e,
                                                      double theta, double h) {
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

// The step under a constant force f.
template <class Real>
[[gnu::always_inline]] inline void moreau_jean_step(Real& gap, Real& v, Real& contact_force,
                                                    const Real& f, const Real& e, double theta,
                                                    double h) {
  moreau_jean_update(gap, v, contact_force, Real(v + h * f), e, theta, h);
}

// With a time-dependent force the step's impulse of f is its integral over the step,
// h f^l = int_{t_l}^{t_{l+1}} f (the step mean of scheme_flight.hpp, as direct uses): the impulse
// identity h sum N^l = v^n - v^0 - int_0^T f then holds to rounding as for a constant force, the
// free-flight velocity is exact at the grid times, and with theta = 1/2 the position is its
// trapezoidal rule, second order (Siconos's MoreauJeanOSI weights f(t_l), f(t_{l+1}) by theta
// instead, which is second order too but keeps neither). One type per force kind (ForceKind,
// force.hpp), as for direct (direct.hpp says why): `MoreauJean` the constant force,
// `MoreauJeanHarmonic` a harmonic one, BasicMoreauJean<ForceKind::general> any other, stepped as
// MoreauJeanGeneral (with_internal.hpp) with the internal variables, if any. A force of the
// state f(t, u, v) is taken at the step's start, h f^l = int_{t_l}^{t_{l+1}} f(t, u^l, v^l) dt
// (scheme_flight.hpp): explicit in the state, so first order in h whatever theta.
template <ForceKind Kind>
class BasicMoreauJean {
  static constexpr bool kTimeDependent = Kind != ForceKind::constant;

 public:
  BasicMoreauJean(const Model& model, double h, const MoreauJeanParams& params)
      : BasicMoreauJean(model, contact_law(model, MethodParams(params)), h, params) {}
  // `law`: contact_law(model, params) (capabilities.hpp), computed once by make_stepper.
  BasicMoreauJean(const Model& model, const ContactLaw& law, double h,
                  const MoreauJeanParams& params)
      : phi_(model.phi),
        f_(model.f),
        h_(h),
        theta_(params.theta),
        e_(newton_e(law)),
        force_(model, h) {}
  BasicMoreauJean(const BasicMoreauJean&) = default;
  BasicMoreauJean(BasicMoreauJean&&) noexcept = default;
  BasicMoreauJean& operator=(const BasicMoreauJean&) = default;
  BasicMoreauJean& operator=(BasicMoreauJean&&) noexcept = default;
  // Inlined even on a step loop's exception path (heap_value.hpp).
  [[gnu::always_inline]] ~BasicMoreauJean() {}

  [[gnu::always_inline]] void initialize(const State& s, std::int64_t l) {
    state_ = {s.u - phi_, s.v};
    if constexpr (kTimeDependent) force_.seek(l);
    if constexpr (!kTimeDependent) repeats_.reset();
  }

  // Repeating steps (repeats.hpp), under a constant force: a step depends on the state it starts
  // from alone; contact steps are watched.
  std::int64_t repeat_period() const requires(!kTimeDependent) { return repeats_.period(); }
  void skip_steps(std::int64_t n) requires(!kTimeDependent) { repeats_.skip(n); }

  // The internal variables at t_l that the next step's force of the state reads (internal.hpp).
  void set_internal(const std::array<double, kMaxInternal>& z) const
      requires(Kind == ForceKind::general) {
    force_.set_internal(z);
  }

  [[gnu::always_inline]] StepInfo do_step(State& s, std::int64_t l) {
    StepInfo info;
    if constexpr (kTimeDependent) {
      const SchemeForce::Impulse impulse = force_.advance(l, state_);
      const double v_free = state_.v + h_ * f_ + (impulse.harmonic + impulse.expression);
      moreau_jean_update(state_.u, state_.v, info.contact_force, v_free, e_, theta_, h_);
    } else {
      moreau_jean_step(state_.u, state_.v, info.contact_force, f_, e_, theta_, h_);
      if (info.contact_force > 0) repeats_.contact(l, state_);
    }
    s = {phi_ + state_.u, state_.v};
    return info;
  }

 private:
  // The constant force needs no state; a time-dependent one does not repeat.
  struct NoForce {
    NoForce(const Model&, double) {}
  };
  struct NoRepeats {};

  double phi_, f_;
  double h_;
  double theta_;
  double e_;
  State state_;  // (u - phi, v) at t_l
  [[no_unique_address]] std::conditional_t<kTimeDependent, NoRepeats, RepeatWatch> repeats_;
  [[no_unique_address]] std::conditional_t<kTimeDependent, SchemeForce, NoForce> force_;
};

using MoreauJean = BasicMoreauJean<ForceKind::constant>;
using MoreauJeanHarmonic = BasicMoreauJean<ForceKind::harmonic>;

}  // namespace impact
