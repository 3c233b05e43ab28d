#include "impact/run/any_stepper.hpp"

#include <stdexcept>
#include <string>
#include <variant>

#include "impact/forces/force.hpp"
#include "impact/run/step_events.hpp"

namespace impact {

namespace {

// The stepper for a model as the method steps it (a linear force already an expression where the
// method takes it as one).
AnyStepper stepper_for(const Model& model, double h, const MethodParams& params) {
  // The law the method applies, read from the model once (capabilities.hpp) and given to the
  // time-steppers; exact and event_driven read Newton's law themselves, as their references do.
  const ContactLaw law = contact_law(model, params);
  // The force kind, read once (force.hpp): the time-steppers' type for it.
  const ForceKind kind = force_kind(model);
  return std::visit(
      [&](const auto& p) -> AnyStepper {
        using Params = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<Params, DirectParams>) {
          if (p.free_flight == FreeFlightForm::paper) return DirectAsPrinted(model, law, h, p);
          switch (kind) {
            case ForceKind::constant:
              return Direct(model, law, h, p);
            case ForceKind::harmonic:
              return DirectHarmonic(model, law, h, p);
            case ForceKind::general:
              break;
          }
          return DirectGeneral(model, law, h, p);
        }
        if constexpr (std::is_same_v<Params, FbNewtonParams>) return FbNewton(model, law, h, p);
        if constexpr (std::is_same_v<Params, MoreauJeanParams>) {
          switch (kind) {
            case ForceKind::constant:
              return MoreauJean(model, law, h, p);
            case ForceKind::harmonic:
              return MoreauJeanHarmonic(model, law, h, p);
            case ForceKind::general:
              break;
          }
          return MoreauJeanGeneral(model, law, h, p);
        }
        if constexpr (std::is_same_v<Params, PenaltyParams>) return Penalty(model, law, h, p);
        if constexpr (std::is_same_v<Params, ExactParams>) {
          if (bonded(model)) return ExactBonded(model, h, p);
          return ExactStepper(model, h, p);
        }
        if constexpr (std::is_same_v<Params, EventDrivenParams>) {
          return EventDriven(model, h, p);
        }
        if constexpr (std::is_same_v<Params, DirectLocatedParams>)
          return DirectLocated(model, law, h, p);
      },
      params);
}

}  // namespace

AnyStepper make_stepper(const Model& model, double h, const MethodParams& params) {
  if (const auto refused = refusal(params, model, h)) throw std::invalid_argument(refused->message);
  // exact follows a linear force in closed form; the others take it as the force of the state it
  // is, an expression (force.hpp). The model is copied only where it is rewritten: make_stepper
  // runs once a run, and its cost is the whole cost of a run that replays a period.
  if (model.linear && !std::holds_alternative<ExactParams>(params))
    return stepper_for(linear_as_expression(model), h, params);
  return stepper_for(model, h, params);
}

AnyStepper make_stepper(const Scene& scene) {
  AnyStepper stepper = make_stepper(scene.model, scene.grid.h, scene.method);
  // A force expression need only be defined up to the scene's end: event_driven looks no further.
  if (auto* event_driven = std::get_if<EventDriven>(&stepper))
    event_driven->set_end(scene.grid.end());
  return stepper;
}

bool attach_event_sink(AnyStepper& stepper, const EventSink& sink) {
  return std::visit([&](auto& s) { return attach_event_sink(s, sink); }, stepper);
}

}  // namespace impact
