#include "impact/registry.hpp"

#include <charconv>
#include <stdexcept>
#include <string>

namespace impact {
namespace {

// The shortest decimal that reads back as x, for a message.
std::string shortest(double x) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

// In the order of the MethodParams alternatives, so that method_info() can index by them.
const MethodInfo kMethods[] = {
    {"direct", false, true, "the paper's scheme (4-1)-(4-3) solved in closed form, (5-1)",
     DirectParams{}},
    {"fb_newton", true, true,
     "(4-1)-(4-3) as the smoothed Fischer-Burmeister equation (5-3), Newton", FbNewtonParams{}},
    {"moreau_jean", false, true, "Moreau-Jean theta time-stepping with Newton's impact law",
     MoreauJeanParams{}},
    {"penalty", true, false, "normal compliance N = c_N max(phi - u, 0), GSL odeiv2",
     PenaltyParams{}},
    {"exact", false, true, "event-driven closed-form solution sampled on t = l h", ExactParams{}},
    {"event_driven", false, true,
     "event-driven solution for any f(t): GSL odeiv2 rk8pd between certified impacts",
     EventDrivenParams{}},
    {"direct_located", false, true,
     "(5-1) with each impact located inside its step and the rest of the step flown after it",
     DirectLocatedParams{}},
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

AnyStepper make_stepper(const Model& model, double h, const MethodParams& params) {
  // Compliance has no impact law to apply a COR to: refuse rather than silently run elastic.
  if (model.cor && !method_info(params).takes_cor)
    throw std::invalid_argument("method '" + std::string(method_name(params)) +
                                "' has no restitution law: it cannot take a COR");
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
          if (constant_force(model)) return MoreauJean(model, h, p);
          return MoreauJeanTimeDependent(model, h, p);
        }
        if constexpr (std::is_same_v<Params, PenaltyParams>) return Penalty(model, h, p);
        if constexpr (std::is_same_v<Params, ExactParams>) return ExactStepper(model, h, p);
        if constexpr (std::is_same_v<Params, EventDrivenParams>) return EventDriven(model, h, p);
        if constexpr (std::is_same_v<Params, DirectLocatedParams>)
          return DirectLocated(model, h, p);
      },
      params);
}

}  // namespace impact
