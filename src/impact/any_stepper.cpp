#include "impact/any_stepper.hpp"

#include <stdexcept>
#include <string>
#include <variant>

#include "impact/event_log.hpp"
#include "impact/force.hpp"
#include "impact/format.hpp"
#include "impact/free_flight.hpp"

namespace impact {

AnyStepper make_stepper(const Model& given, double h, const MethodParams& params) {
  const MethodInfo& method = method_info(params);
  if (given.cor && !method.can.restitution)
    throw std::invalid_argument("method '" + std::string(method.name) +
                                "' has no restitution law: it cannot take a COR");
  if (!method.can.state_force && expression_of_state(given))
    throw std::invalid_argument("method '" + std::string(method.name) +
                                "' takes a force of t only: force.expression reads u or v");
  if (!method.can.linear_force && given.linear)
    throw std::invalid_argument("method '" + std::string(method.name) +
                                "' takes no force of the state: force.linear is given");
  // exact follows a linear force in closed form; the others take it as the force of the state it
  // is, an expression (force.hpp).
  const Model model =
      std::holds_alternative<ExactParams>(params) ? given : linear_as_expression(given);
  if (!method.can.internal_variables && !model.internal.empty())
    throw std::invalid_argument("method '" + std::string(method.name) +
                                "' does not follow internal variables: [[internal]] is given");
  if (!method.can.bonding && bonded(model))
    throw std::invalid_argument("method '" + std::string(method.name) +
                                "' takes no bonding field: [bonding] is given");
  if ((std::holds_alternative<DirectParams>(params) ||
       std::holds_alternative<FbNewtonParams>(params)) &&
      !scheme_step_representable(h))
    throw std::invalid_argument("method '" + std::string(method_name(params)) +
                                "': 2/h^2 of (5-1) is not representable for h = " + shortest(h) +
                                " (time.h must be in [1.1e-154, 9.4e153])");
  return std::visit(
      [&](const auto& p) -> AnyStepper {
        using Params = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<Params, DirectParams>) {
          if (p.free_flight == FreeFlightForm::paper) {
            if (!model.internal.empty())
              throw std::invalid_argument(
                  "method 'direct' with free_flight = \"paper\" does not follow internal "
                  "variables: [[internal]] is given (the closed form does)");
            return DirectAsPrinted(model, h, p);
          }
          if (!model.internal.empty()) return DirectInternal(model, h, p);
          switch (force_kind(model)) {
            case ForceKind::constant:
              return Direct(model, h, p);
            case ForceKind::harmonic:
              return DirectHarmonic(model, h, p);
            case ForceKind::time_dependent:
              break;
          }
          return DirectTimeDependent(model, h, p);
        }
        if constexpr (std::is_same_v<Params, FbNewtonParams>) return FbNewton(model, h, p);
        if constexpr (std::is_same_v<Params, MoreauJeanParams>) {
          if (!model.internal.empty()) return MoreauJeanInternal(model, h, p);
          if (constant_force(model)) return MoreauJean(model, h, p);
          return MoreauJeanTimeDependent(model, h, p);
        }
        if constexpr (std::is_same_v<Params, PenaltyParams>) return Penalty(model, h, p);
        if constexpr (std::is_same_v<Params, ExactParams>) {
          if (bonded(model)) return ExactBonded(model, h, p);
          return ExactStepper(model, h, p);
        }
        if constexpr (std::is_same_v<Params, EventDrivenParams>) {
          if (!model.internal.empty() || bonded(model)) return EventDrivenInternal(model, h, p);
          return EventDriven(model, h, p);
        }
        if constexpr (std::is_same_v<Params, DirectLocatedParams>)
          return DirectLocated(model, h, p);
      },
      params);
}

AnyStepper make_stepper(const Scene& scene) {
  AnyStepper stepper = make_stepper(scene.model, scene.grid.h, scene.method);
  // A force expression need only be defined up to the scene's end: event_driven looks no further.
  if (auto* event_driven = std::get_if<EventDriven>(&stepper))
    event_driven->set_end(scene.grid.end());
  if (auto* event_driven = std::get_if<EventDrivenInternal>(&stepper))
    event_driven->set_end(scene.grid.end());
  return stepper;
}

bool attach_event_sink(AnyStepper& stepper, const EventSink& sink) {
  return std::visit([&](auto& s) { return attach_event_sink(s, sink); }, stepper);
}

}  // namespace impact
