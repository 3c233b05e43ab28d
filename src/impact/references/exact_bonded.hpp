// The method exact with a bonding field (bonding.hpp), where it is in closed form: in the well with
// no damage. While gamma R(g)^2 <= eps_a along a flight beta stays beta0, and while g <= L the pull
// is gamma beta0^2 g, so with a constant f the flight is the linear-force flight of the impact
// oscillator, k = gamma beta0^2, c = 0, u_eq = phi (linear_flight.hpp, with its certified
// bracketing of impacts): a flight from the floor at speed v0 under f = -G returns after
// 2 atan(v0 omega / G) / omega at speed -v0, omega = beta0 sqrt(gamma) (well_return_time).
//
// That holds for the whole run when the first flight's highest gap stays within both bounds: every
// later flight has less of the well's energy E_w = v^2/2 - f g + k g^2/2 (an impact keeps or lowers
// it, a rest has none), so it rises less. no_damage_well_refusal() checks it; where it fails exact
// refuses the scene (exit 2 from the scene reader) and event_driven runs it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "impact/model/event.hpp"
#include "impact/model/model.hpp"
#include "impact/references/exact.hpp"

namespace impact {

// Why exact cannot follow this bonded model from `initial` in closed form (a force that is not
// constant, a flight that rises past L or into damage), with the bound and the height; nullopt when
// it can.
std::optional<std::string> no_damage_well_refusal(const Model& model, const State& initial);

class ExactBonded {
 public:
  using StateType = StateWithInternal;  // z: beta (= beta0 throughout) and D (= 0), model.hpp

  // Throws std::invalid_argument for a model that is not bonded or whose force is not constant.
  ExactBonded(const Model& model, double h, const ExactParams& params);

  StateWithInternal initial_state(const State& s) const { return with_internal(model_, s); }
  // Throws std::invalid_argument with no_damage_well_refusal()'s reason.
  void initialize(const StateWithInternal& s, std::int64_t l);
  StepInfo do_step(StateWithInternal& s, std::int64_t l) {
    State particle = s;
    const StepInfo info = well_.do_step(particle, l);
    static_cast<State&>(s) = particle;
    return info;
  }
  // The events carry beta (beta0 throughout) and D (0), as event_driven's do.
  void set_event_sink(EventSink sink) {
    well_.set_event_sink([sink = std::move(sink), beta0 = model_.bonding->beta0](Event e) {
      e.internal[kBondFraction] = beta0;
      sink(e);
    });
  }
  std::string failure_reason() const { return well_.failure_reason(); }

 private:
  Model model_;
  ExactStepper well_;  // the linear-force flights of the well
};

}  // namespace impact
