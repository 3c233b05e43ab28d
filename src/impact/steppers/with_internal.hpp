// A time-stepper that follows the model's internal variables (model.hpp, internal.hpp) beside the
// particle: its state is StateWithInternal (StateOf, stepper.hpp), and every observer of a run
// sees z with u and v (rows, summary, errors, events).
//
// A step from t_l: the particle's step of the base method with its force of the state read at
// (u^l, v^l, z^l) (the explicit reading of scheme_flight.hpp), then
//   z^{l+1} = z^l + h g(t_l, u^l, v^l, z^l),
// explicit Euler: a local error O(h^2), first order over a run, as the force of the state is; an
// impact changes v alone, so z is continuous across it, and a rate read at a step's start does not
// see a contact inside the step (an error O(h) there, again first order). The base method is one
// whose force of the state is taken at the step's start (set_internal): direct and moreau_jean,
// whose general force kind (ForceKind, force.hpp) always steps this way: DirectGeneral and
// MoreauJeanGeneral, with z zero-sized (m = 0, the rates' loop runs no time) where the model has
// no internal variables, the bits of the particle the same as the base method's alone.
//
// A bonding field that acts (bonded(), model.hpp) rides in z too, beta = z[kBondFraction] and
// D = z[kBondEnergy]: the base method's force reads beta at the step's start for the pull (the
// explicit reading above, scheme_flight.hpp), and the bonds then take one step of bond_step
// (bonding.hpp), implicit Euler's closed form at the gap the particle's step ended at, which keeps
// beta in [0, beta_n] for any h, where explicit Euler would not (h (gamma R^2 - eps_a) > 1 makes
// it negative). Here and nowhere else: both steppers share it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "impact/forces/internal.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/model/model.hpp"
#include "impact/steppers/direct.hpp"
#include "impact/steppers/moreau_jean.hpp"

namespace impact {

template <class Base>
class WithInternal {
 public:
  using StateType = StateWithInternal;

  template <class Params>
  WithInternal(const Model& model, double h, const Params& params)
      : WithInternal(model, contact_law(model, MethodParams(params)), h, params) {}
  template <class Params>
  WithInternal(const Model& model, const ContactLaw& law, double h, const Params& params)
      : base_(model, law, h, params),
        rates_(model),
        model_internal_(with_internal(model, {}).z),
        h_(h),
        phi_(model.phi) {
    if (bonded(model)) bonds_ = model.bonding;
  }

  // The full initial state of a run from the particle's: z at the model's initial values.
  StateWithInternal initial_state(const State& s) const { return {s, model_internal_}; }

  void initialize(const StateWithInternal& s, std::int64_t l) {
    base_.set_internal(s.z);
    base_.initialize(s, l);
  }

  // m, the model's internal variables (beta and D for a bonding field): 0 for a force of t or of
  // (u, v) alone, whose failure message then names u and v alone (simulate.hpp).
  std::size_t internal_count() const { return rates_.size() + (bonds_ ? 2 : 0); }

  StepInfo do_step(StateWithInternal& s, std::int64_t l) {
    std::array<double, kMaxInternal> rate{};
    // A call, skipped where there are no rates (a bonding field or a force of the state alone).
    if (rates_.size() != 0) rates_.evaluate(static_cast<double>(l) * h_, s, rate);
    base_.set_internal(s.z);
    State particle = s;
    const StepInfo info = base_.do_step(particle, l);
    static_cast<State&>(s) = particle;
    for (std::size_t i = 0; i < rates_.size(); ++i) s.z[i] += h_ * rate[i];
    if (bonds_) bond_step(*bonds_, h_, s.u - phi_, s.z[kBondFraction], s.z[kBondEnergy]);
    return info;
  }

 private:
  Base base_;
  InternalRates rates_;
  std::array<double, kMaxInternal> model_internal_;
  double h_;
  double phi_;
  std::optional<Bonding> bonds_;  // a bonding field that acts, or none
};

// The general force kind of direct and moreau_jean (ForceKind, force.hpp).
using DirectGeneral = WithInternal<BasicDirect<ForceKind::general>>;
using MoreauJeanGeneral = WithInternal<BasicMoreauJean<ForceKind::general>>;

}  // namespace impact
