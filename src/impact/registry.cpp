#include "impact/registry.hpp"

#include <stdexcept>
#include <string>

#include "impact/force.hpp"
#include "impact/format.hpp"

namespace impact {
namespace {

// In the order of the MethodParams alternatives, so that method_info() can index by them.
const MethodInfo kMethods[] = {
    {.name = "direct",
     .summary = "the paper's scheme (4-1)-(4-3) solved in closed form, (5-1)",
     .defaults = DirectParams{},
     .can = {.restitution = true,
             .time_expression = true,
             .state_force = true,
             .linear_force = true,
             .internal_variables = true,
             .scheme_force_channel = true,
             .energy_bound = true}},
    {.name = "fb_newton",
     .summary = "(4-1)-(4-3) as the smoothed Fischer-Burmeister equation (5-3), Newton",
     .defaults = FbNewtonParams{},
     .can = {.restitution = true,
             .time_expression = true,
             .iterations_channel = true,
             .scheme_force_channel = true,
             .energy_bound = true}},
    {.name = "moreau_jean",
     .summary = "Moreau-Jean theta time-stepping with Newton's impact law",
     .defaults = MoreauJeanParams{},
     .can = {.restitution = true,
             .time_expression = true,
             .state_force = true,
             .linear_force = true,
             .internal_variables = true}},
    // Compliance has no impact law to apply a COR to: it refuses one rather than run elastic.
    {.name = "penalty",
     .summary = "normal compliance N = c_N max(phi - u, 0), GSL odeiv2",
     .defaults = PenaltyParams{},
     .can = {.time_expression = true, .iterations_channel = true}},
    {.name = "exact",
     .summary = "event-driven closed-form solution sampled on t = l h",
     .defaults = ExactParams{},
     .can = {.restitution = true,
             .linear_force = true,
             .bonding = true,
             .reference = true,
             .energy_bound = true,
             .exact_events = true}},
    {.name = "event_driven",
     .summary = "event-driven solution for any f(t): GSL odeiv2 rk8pd between certified impacts",
     .defaults = EventDrivenParams{},
     .can = {.restitution = true,
             .time_expression = true,
             .state_force = true,
             .linear_force = true,
             .internal_variables = true,
             .bonding = true,
             .reference = true,
             .exact_events = true}},
    {.name = "direct_located",
     .summary = "(5-1) with each impact located inside its step and the rest of the step flown "
                "after it",
     .defaults = DirectLocatedParams{},
     .can = {.restitution = true, .time_expression = true}},
};
static_assert(std::size(kMethods) == std::variant_size_v<MethodParams>);

}  // namespace

std::span<const MethodInfo> methods() {
  return kMethods;
}

const MethodInfo* find_method(std::string_view name) {
  for (const auto& m : kMethods)
    if (m.name == name) return &m;
  return nullptr;
}

const MethodInfo& method_info(const MethodParams& params) {
  return kMethods[params.index()];
}

std::vector<std::string_view> methods_with(bool Capabilities::*capability) {
  std::vector<std::string_view> names;
  for (const auto& m : kMethods)
    if (m.can.*capability) names.push_back(m.name);
  return names;
}

namespace {

// An expression that reads u, v or an internal variable (a linear part is its own capability).
bool expression_of_state(const Model& model) {
  return !model.expression.empty() && state_force(model);
}

}  // namespace

std::string not_honoured(const MethodInfo& method, const Model& model) {
  if (model.cor && !method.can.restitution) return "it has no restitution law for floor.cor";
  if (!model.expression.empty() && !method.can.time_expression)
    return "it takes no force expression (force.expression)";
  if (!method.can.state_force && expression_of_state(model))
    return "it takes a force of t only, and force.expression reads u or v";
  if (!method.can.linear_force && model.linear)
    return "it takes no linear force of the state (force.linear)";
  if (!method.can.internal_variables && !model.internal.empty())
    return "it does not follow internal variables ([[internal]])";
  if (!method.can.bonding && bonded(model)) return "it takes no bonding field ([bonding])";
  return {};
}

bool honours(const MethodInfo& method, const Model& model) {
  return not_honoured(method, model).empty();
}

const MethodInfo& reference_for(const Model& model) {
  for (const auto& m : kMethods)
    if (m.can.reference && honours(m, model)) return m;
  throw std::logic_error("no reference method honours this model");
}

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

ContactLaw method_law(const Model& model, const MethodParams& params) {
  return std::visit(
      [&](const auto& p) -> ContactLaw {
        using Params = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<Params, DirectParams> ||
                      std::is_same_v<Params, FbNewtonParams>)
          return contact_law(model, SchemeLaw{});
        else if constexpr (std::is_same_v<Params, PenaltyParams>)
          return contact_law(model, ComplianceLaw{p.stiffness});
        else
          return contact_law(model, kElasticReading);
      },
      params);
}

}  // namespace impact
