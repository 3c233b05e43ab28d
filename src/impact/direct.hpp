// The paper's scheme (4-1)-(4-3), solved in closed form at each step as in (5-1).
#pragma once

#include <cstdint>

#include "impact/free_flight.hpp"
#include "impact/model.hpp"
#include "impact/restitution.hpp"
#include "impact/scheme_flight.hpp"

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
// ensemble is bit-identical to the single-particle solver. `cor` is read only where has_cor holds.
template <class Real, class Mask>
void direct_contact(DirectLanes<Real>& s, const Real& since, const Real& gap_free,
                    const Real& v_free, const Real& cor, const Mask& has_cor, double h) {
  const auto free = gap_free > 0;
  // Otherwise (4-3) forces u^{l+1} = phi; (5-1) solved for N^l,
  // N^l = (2/h)((phi - u^l)/h - v^l) - f^l = (2/h^2)(phi - u_free) >= 0.
  const Real force = 2 / (h * h) * (Real{} - gap_free);
  const Real v_scheme = v_free + h * force;  // (4-1), equal to (4-2) here
  // The COR law of restitution.hpp: v^{l+1} = -COR v^l on a step with N^l > 0.
  Real v_contact;
  velocity_after_step(has_cor, cor, force > 0, s.v, v_scheme, v_contact);
  s.contact_force = free ? Real{} : force;
  s.gap = free ? gap_free : Real{};
  s.v = free ? v_free : v_contact;
  s.anchor_gap = free ? s.anchor_gap : Real{};
  s.anchor_v = free ? s.anchor_v : v_contact;
  s.since = free ? since : Real{};
}

// One step of direct under a constant force f: (5-1) with N^l = 0 in closed form from the anchor,
// then the contact rule.
template <class Real, class Mask>
void direct_step(DirectLanes<Real>& s, const Real& f, const Real& cor, const Mask& has_cor,
                 double h) {
  const Real since = s.since + 1;
  const Real t = since * h;
  // (5-1) with N^l = 0: where the particle would be if the floor were not there.
  Real gap_free, v_free;
  free_flight(s.anchor_gap, s.anchor_v, t, f, gap_free, v_free);
  direct_contact(s, since, gap_free, v_free, cor, has_cor, h);
}

struct DirectParams {
  FreeFlightForm free_flight = FreeFlightForm::closed_form;
  bool operator==(const DirectParams&) const = default;
};

// With a time-dependent force f(t) the step's discrete force is its mean f^l
// (scheme_flight.hpp): the free flight is SchemeFlight's, the contact rule the same.
class Direct {
 public:
  Direct(const Model& model, double h, const DirectParams& params)
      : phi_(model.phi),
        f_(model.f),
        cor_(model.cor.value_or(0.0)),
        has_cor_(model.cor),
        h_(h),
        paper_(params.free_flight == FreeFlightForm::paper),
        flight_(model, h),
        constant_(flight_.constant_force()) {}

  // A free flight starts at s: the anchor of the closed form (free_flight.hpp).
  void initialize(const State& s, std::int64_t l) {
    lanes_.anchor_gap = lanes_.gap = s.u - phi_;
    lanes_.anchor_v = lanes_.v = s.v;
    lanes_.since = 0;
    if (!constant_) flight_.start(l, {lanes_.gap, lanes_.v});
  }

  StepInfo do_step(State& s, std::int64_t l) {
    if (paper_) return paper_step(s, l);
    if (constant_) {
      direct_step(lanes_, f_, cor_, has_cor_, h_);
    } else {
      const State free = flight_.step(l);
      direct_contact(lanes_, lanes_.since + 1, free.u, free.v, cor_, has_cor_, h_);
      if (lanes_.since == 0) flight_.start(l + 1, {0.0, lanes_.v});
    }
    s = {phi_ + lanes_.gap, lanes_.v};
    StepInfo info;
    info.contact_force = lanes_.contact_force;
    return info;
  }

 private:
  // (5-1) and (4-2) as printed, from the caller's state (free_flight.hpp): with N^l = 0 when
  // u^{l+1} > phi, else u^{l+1} = phi and N^l = (2/h)((phi - u^l)/h - v^l) - f^l; the COR law as
  // in direct_step.
  StepInfo paper_step(State& s, std::int64_t l) {
    double f = f_;
    if (!constant_) {
      flight_.step(l);
      f = flight_.step_force();
    }
    const State free = paper_free_step(s, f, h_);
    StepInfo info;
    if (free.u > phi_) {
      s = free;
      return info;
    }
    info.contact_force = 2 / h_ * ((phi_ - s.u) / h_ - s.v) - f;
    const double v_scheme = 2 / h_ * (phi_ - s.u) - s.v;
    double v_next;
    velocity_after_step(has_cor_, cor_, info.contact_force > 0, s.v, v_scheme, v_next);
    s = {phi_, v_next};
    return info;
  }

  double phi_, f_, cor_;
  bool has_cor_;
  double h_;
  bool paper_;
  DirectLanes<double> lanes_;
  SchemeFlight flight_;  // the free flight under a time-dependent force
  bool constant_;
};

}  // namespace impact
