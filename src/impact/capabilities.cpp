#include "impact/capabilities.hpp"

#include <stdexcept>
#include <string>

#include "impact/force.hpp"

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

bool expression_of_state(const Model& model) {
  return !model.expression.empty() && state_force(model);
}

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

ContactLaw contact_law(const Model& model, const MethodParams& params) {
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
