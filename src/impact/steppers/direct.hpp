// The paper's scheme (4-1)-(4-3), solved in closed form at each step as in (5-1).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <type_traits>

#include "impact/forces/force.hpp"
#include "impact/forces/free_flight.hpp"
#include "impact/forces/scheme_flight.hpp"
#include "impact/loop/repeats.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/methods/method_params.hpp"
#include "impact/model/model.hpp"
#include "impact/model/restitution.hpp"

namespace impact {

// What direct carries from step to step, for one particle (Real = double) or for a vector of
// particles (the ensemble, ensemble.hpp), in gap coordinates g = u - phi: a state resting on a
// floor far from the origin (phi = 1e6) is then exactly g = 0, where u = phi would be rounded to
// the floor's ulp and the closed form below would turn that rounding into velocity (2 ulp / h).
// Between contacts the scheme is the closed-form free flight from the anchor (free_flight.hpp
// explains why it is not stepped increment by increment).
template <class Real>
struct DirectLanes {
  Real anchor_gap{}, anchor_v{};  // the state where the free flight started: the end of the last
                                  // contact step, or the initial state
  Real since{};                   // l - l_anchor at t_l, a whole number (exact in a double)
  Real gap{}, v{};                // the state at t_l
  Real contact_force{};           // N^{l-1}, of the step that ended at t_l
};

// The contact rule of one step of direct from t_l to t_{l+1}, given where the free flight would
// end, (gap_free, v_free) at t_{l+1}, since = l + 1 - l_anchor. Real is double (with Mask = bool)
// or a vector of lanes (with Mask its comparison result): the same operations in the same order
// for both, every value computed and the branches taken as selections, so that each lane of the
// ensemble is bit-identical to the single-particle solver. `cor` and `fixed_point`
// (restitution_fixed_point of the COR, restitution.hpp; Bits is std::int64_t or the lanes' integer
// vector) are read only where has_cor holds. Without Outputs, s.gap and s.contact_force are left
// as they were: the next steps do not read them, so the ensemble sets them on its last step only
// (2 of about 30 vector operations a step: AVX2 1.0 -> 1.1e9 particle-steps/s on an Intel Xeon
// family 6 model 167).
template <bool Outputs = true, class Real, class Mask, class Bits>
[[gnu::always_inline]] inline void direct_contact(DirectLanes<Real>& s, const Real& since,
                                                  const Real& gap_free, const Real& v_free,
                                                  const Real& cor, const Mask& has_cor,
                                                  const Bits& fixed_point, double h,
                                                  double contact_factor) {
  const auto free = gap_free > 0;
  // Otherwise (4-3) forces u^{l+1} = phi; (5-1) solved for N^l,
  // N^l = (2/h)((phi - u^l)/h - v^l) - f^l = (2/h^2)(phi - u_free) >= 0, contact_factor = 2/h^2.
  const Real force = contact_factor * (Real{} - gap_free);
  const Real v_scheme = v_free + h * force;  // (4-1), equal to (4-2) here
  // The COR law of restitution.hpp: v^{l+1} = -COR v^l on a step with N^l > 0.
  Real v_contact;
  velocity_after_step(has_cor, cor, fixed_point, force > 0, s.v, v_scheme, v_contact);
  if constexpr (Outputs) {
    s.contact_force = free ? Real{} : force;
    s.gap = free ? gap_free : Real{};
  }
  s.v = free ? v_free : v_contact;
  s.anchor_gap = free ? s.anchor_gap : Real{};
  s.anchor_v = free ? s.anchor_v : v_contact;
  s.since = free ? since : Real{};
}

// One step of direct under a constant force f: (5-1) with N^l = 0 in closed form from the anchor,
// then the contact rule (Outputs as there).
template <bool Outputs = true, class Real, class Mask, class Bits>
[[gnu::always_inline]] inline void direct_step(DirectLanes<Real>& s, const Real& f, const Real& cor,
                                               const Mask& has_cor, const Bits& fixed_point,
                                               double h) {
  const Real since = s.since + 1;
  const Real t = since * h;
  // (5-1) with N^l = 0: where the particle would be if the floor were not there.
  Real gap_free, v_free;
  free_flight(s.anchor_gap, s.anchor_v, t, f, gap_free, v_free);
  direct_contact<Outputs>(s, since, gap_free, v_free, cor, has_cor, fixed_point, h, 2 / (h * h));
}

// The stepper, one per force kind (ForceKind, force.hpp): `Direct` for a constant force,
// `DirectHarmonic` for a harmonic one and BasicDirect<ForceKind::general> for any other f(t) (an
// expression, of t or of the state, read at the step's start), whose step's discrete force is its
// mean f^l (scheme_flight.hpp): the free flight is SchemeFlight's, the contact rule the same; the
// general kind is stepped as DirectGeneral (with_internal.hpp), with the internal variables, if
// any. `DirectAsPrinted` evaluates (5-1) as printed (FreeFlightForm::paper) for any force.
// make_stepper picks the one the scene needs.
//
// Separate types rather than one with branches, for the step loop of simulate.hpp, which keeps a
// local stepper in registers (measured with 1e7 steps of h = 1e-6, free flight under gravity): a
// call in the loop body, even on a branch never taken, made GCC keep the whole state on the stack
// (5.4 instead of 2.8 ns per step for a constant force, 8.4 instead of 5.2 for a harmonic one,
// whose expression part is a call), and a branch to the printed form kept 2/h^2 from being taken
// out of the loop (on an Intel Xeon family 6 model 167: 3.2 instead of 2.9 ns). And the steps since
// the anchor are l + 1 - l_a from the loop's own l, not a counter carried in DirectLanes, which
// GCC's SLP vectorizer packed with the gap into one vector register, chaining every step's free
// flight to the next (6.5 instead of 2.8 ns).
template <ForceKind Kind>
class BasicDirect {
  static constexpr bool kTimeDependent = Kind != ForceKind::constant;

 public:
  // The closed-form free flight only: throws std::invalid_argument for FreeFlightForm::paper
  // (DirectAsPrinted).
  BasicDirect(const Model& model, double h, const DirectParams& params)
      : BasicDirect(model, contact_law(model, MethodParams(params)), h, params) {}
  // `law`: the contact law the method applies (contact_law(model, params), capabilities.hpp),
  // computed once by make_stepper.
  BasicDirect(const Model& model, const ContactLaw& law, double h, const DirectParams& params)
      : phi_(model.phi),
        f_(model.f),
        restitution_(restitution_rule(law)),
        h_(h),
        contact_factor_(2 / (h * h)),
        flight_(model, h) {
    if (params.free_flight != FreeFlightForm::closed_form)
      throw std::invalid_argument("direct with (5-1) as printed is DirectAsPrinted");
  }
  BasicDirect(const BasicDirect&) = default;
  BasicDirect(BasicDirect&&) noexcept = default;
  BasicDirect& operator=(const BasicDirect&) = default;
  BasicDirect& operator=(BasicDirect&&) noexcept = default;
  // Inlined even on a step loop's exception path (heap_value.hpp).
  [[gnu::always_inline]] ~BasicDirect() {}

  // A free flight starts at s: the anchor of the closed form (free_flight.hpp).
  [[gnu::always_inline]] void initialize(const State& s, std::int64_t l) {
    lanes_.anchor_gap = lanes_.gap = s.u - phi_;
    lanes_.anchor_v = lanes_.v = s.v;
    anchor_l_ = l;
    if constexpr (kTimeDependent) flight_.start(l, {lanes_.gap, lanes_.v});
    if constexpr (!kTimeDependent) repeats_.reset();
  }

  // Repeating steps (repeats.hpp), under a constant force: the steps after a contact step depend
  // on the velocity it ended with alone (the free flight starts from it at gap 0).
  std::int64_t repeat_period() const requires(!kTimeDependent) { return repeats_.period(); }
  void skip_steps(std::int64_t n) requires(!kTimeDependent) {
    anchor_l_ += n;
    repeats_.skip(n);
  }

  // The internal variables at t_l that the next step's force of the state reads (internal.hpp).
  void set_internal(const std::array<double, kMaxInternal>& z) const
      requires(Kind == ForceKind::general) {
    flight_.set_internal(z);
  }

  // Inlined into the step loop: its StepInfo (24 bytes, returned through memory when the call
  // stays a call) then lives in registers. Measured on an Intel Xeon family 6 model 167 (1e8
  // steps of Figure 3's scene in free flight, user time): 0.37 s inlined, 0.50 s as a call (0.43 s
  // with the 16-byte StepInfo before the scheme's force joined it).
  [[gnu::always_inline]] StepInfo do_step(State& s, std::int64_t l) {
    const double since = static_cast<double>(l + 1 - anchor_l_);
    double gap_free, v_free;
    if constexpr (kTimeDependent) {
      const State free = flight_.template step<Kind == ForceKind::general>(l);
      gap_free = free.u;
      v_free = free.v;
    } else {
      free_flight(lanes_.anchor_gap, lanes_.anchor_v, since * h_, f_, gap_free, v_free);
    }
    // In free flight, what direct_contact selects there, without computing the contact rule: the
    // same bits, and on an Intel Xeon family 6 model 167 1.8 instead of 2.9 ns per step.
    bool restituted = false;  // Newton's law replaced (4-1)'s velocity on this contact step
    if (gap_free > 0) {
      lanes_.gap = gap_free;
      lanes_.v = v_free;
      lanes_.contact_force = 0;
      lanes_.since = since;
    } else {  // a contact step: the next free flight starts at t_{l+1}
      direct_contact(lanes_, since, gap_free, v_free, restitution_.cor, restitution_.has_cor,
                     restitution_.fixed_point, h_, contact_factor_);
      anchor_l_ = l + 1;
      if constexpr (kTimeDependent)
        flight_.start(l + 1, {0.0, lanes_.v});
      else
        repeats_.contact(l, {0.0, lanes_.v});
      restituted = restitution_.has_cor && lanes_.contact_force > 0;
    }
    s = {phi_ + lanes_.gap, lanes_.v};
    StepInfo info;
    info.contact_force = lanes_.contact_force;
    // The floor's impulse where Newton's law acted: arithmetic, no call (a call in the loop body,
    // even on a branch never taken, moves the loop's state to the stack; see above).
    if (restituted) [[unlikely]]
      restitute(info, lanes_.v, v_free, h_);
    return info;
  }

 private:
  // The constant force needs no flight state; a time-dependent one does not repeat.
  struct NoFlight {
    NoFlight(const Model&, double) {}
  };
  struct NoRepeats {};

  double phi_, f_;
  RestitutionRule restitution_;  // the contact law (contact_law.hpp) as direct_contact reads it
  double h_;
  double contact_factor_;  // 2/h^2 of (5-1)
  DirectLanes<double> lanes_;
  std::int64_t anchor_l_ = 0;
  [[no_unique_address]] std::conditional_t<kTimeDependent, NoRepeats, RepeatWatch> repeats_;
  [[no_unique_address]] std::conditional_t<kTimeDependent, SchemeFlight, NoFlight> flight_;
};

using Direct = BasicDirect<ForceKind::constant>;
using DirectHarmonic = BasicDirect<ForceKind::harmonic>;

// (5-1) and (4-2) as printed, from the caller's state (free_flight.hpp), for any body force: with
// N^l = 0 when u^{l+1} > phi, else u^{l+1} = phi and N^l = (2/h)((phi - u^l)/h - v^l) - f^l, f^l
// the step's discrete force (scheme_flight.hpp); the COR law as in direct_contact.
class DirectAsPrinted {
 public:
  DirectAsPrinted(const Model& model, double h, const DirectParams& params)
      : DirectAsPrinted(model, contact_law(model, MethodParams(params)), h, params) {}
  DirectAsPrinted(const Model& model, const ContactLaw& law, double h, const DirectParams&)
      : phi_(model.phi), restitution_(restitution_rule(law)), h_(h), flight_(model, h) {}

  void initialize(const State& s, std::int64_t l) { flight_.start(l, {s.u - phi_, s.v}); }

  StepInfo do_step(State& s, std::int64_t l) {
    flight_.restate({s.u - phi_, s.v});
    flight_.step(l);
    const double f = flight_.step_force();
    const State free = paper_free_step(s, f, h_);
    StepInfo info;
    if (free.u > phi_) {
      s = free;
      return info;
    }
    info.contact_force = 2 / h_ * ((phi_ - s.u) / h_ - s.v) - f;
    const double v_scheme = 2 / h_ * (phi_ - s.u) - s.v;
    double v_next;
    velocity_after_step(restitution_.has_cor, restitution_.cor, restitution_.fixed_point,
                        info.contact_force > 0, s.v, v_scheme, v_next);
    s = {phi_, v_next};
    if (restitution_.has_cor && info.contact_force > 0) restitute(info, v_next, free.v, h_);
    return info;
  }

 private:
  double phi_;
  RestitutionRule restitution_;  // the contact law (contact_law.hpp), as in BasicDirect
  double h_;
  SchemeFlight flight_;  // f^l
};

}  // namespace impact
