#include "impact/methods/capabilities.hpp"

#include <stdexcept>
#include <string>

#include "impact/forces/force.hpp"
#include "impact/forces/free_flight.hpp"
#include "impact/format.hpp"

namespace impact {
namespace {

// In the order of the MethodParams alternatives, so that method_info() and method_of() can index by
// them (test_capabilities holds the two in step).
const MethodInfo kMethods[] = {
    {.name = "direct",
     .summary = "the paper's scheme (4-1)-(4-3) solved in closed form, (5-1)",
     .defaults = DirectParams{},
     .can = {.restitution = true,
             .time_expression = true,
             .state_force = true,
             .linear_force = true,
             .internal_variables = true,
             .bonding = true,
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
             .internal_variables = true,
             .bonding = true}},
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

namespace {

// What a row of the feature table reads: the method, by its table row and its parameters, and the
// problem.
struct Asked {
  const MethodInfo& method;
  const MethodParams& params;
  const Model& model;
  // The step, or none (nullptr). Not an optional by value: refusal() is on every make_stepper's
  // path, and a copied optional was written as two halves and read back as one (a
  // store-forwarding stall of ~15 cycles on the AMD EPYC this was measured on).
  const double* h;
};

// "a, b, c".
std::string listed(const std::vector<std::string_view>& names) {
  std::string out;
  for (const std::string_view name : names) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

// "a, b or c".
std::string listed_or(std::vector<std::string_view> names) {
  if (names.size() < 2) return listed(names);
  const std::string_view last = names.back();
  names.pop_back();
  return listed(names) + " or " + std::string(last);
}

// 'name', built by appending (GCC 12 warns, wrongly, of an overlap in "'" + std::string).
std::string quoted(const Asked& a) {
  std::string text = "'";
  text += a.method.name;
  text += '\'';
  return text;
}

// One thing a problem may ask of a method: the methods with `capability` take it (nullptr: the
// method's parameters decide, in `asks`); `asks` says whether the problem asks for it, table.key
// is the key a refusal names, `message` what it says and `reason` the clause for a list of methods.
struct Feature {
  bool Capabilities::*capability;
  bool (*asks)(const Asked&);
  std::string_view table, key;
  std::string (*message)(const Asked&);
  std::string_view (*reason)(const Asked&);
};

// Whether `method`, by its default parameters, refuses nothing of `model` (the table below).
bool takes(const MethodInfo& method, const Model& model);

constexpr std::string_view kClosedForm =
    " has closed-form flights for a constant or harmonic force only";

bool scheme_method(const MethodParams& params) {
  return std::holds_alternative<DirectParams>(params) ||
         std::holds_alternative<FbNewtonParams>(params);
}

// In the order the scene reader reports them: [[internal]], force.linear, force.expression (of the
// state, then of t), [bonding], floor.cor, then what the method's parameters cannot do.
constexpr Feature kFeatures[] = {
    {&Capabilities::internal_variables, [](const Asked& a) { return !a.model.internal.empty(); },
     "method", "name",
     [](const Asked& a) {
       return quoted(a) + " does not follow internal variables, and [[internal]] gives " +
              std::to_string(a.model.internal.size()) + ": use " +
              listed(methods_with(&Capabilities::internal_variables));
     },
     [](const Asked&) -> std::string_view {
       return "it does not follow internal variables ([[internal]])";
     }},
    {&Capabilities::linear_force, [](const Asked& a) { return a.model.linear.has_value(); },
     "method", "name",
     [](const Asked& a) {
       return quoted(a) +
              " takes no force of the state, and force.linear adds -k (u - u_eq) - c v: use "
              "method.name = \"exact\", its closed-form reference (" +
              listed(methods_with(&Capabilities::linear_force)) + " take one)";
     },
     [](const Asked&) -> std::string_view {
       return "it takes no linear force of the state (force.linear)";
     }},
    {&Capabilities::state_force, [](const Asked& a) { return expression_of_state(a.model); },
     "method", "name",
     [](const Asked& a) {
       const bool of_t = a.method.can.time_expression;
       return quoted(a) +
              (of_t ? std::string(" takes a force expression of t alone")
                    : std::string(kClosedForm)) +
              ", and force.expression reads u or v, a force of the state f(t, u, v)" +
              (of_t ? "" : " (which has no closed-form flight)") +
              ": use method.name = \"event_driven\", the event-driven reference for f(t, u, v) (" +
              listed(methods_with(&Capabilities::state_force)) + " take one)";
     },
     [](const Asked& a) -> std::string_view {
       return a.method.can.time_expression
                  ? "it takes a force of t only, and force.expression reads u or v"
                  : "it takes no force expression (force.expression)";
     }},
    {&Capabilities::time_expression, [](const Asked& a) { return !a.model.expression.empty(); },
     "method", "name",
     [](const Asked& a) {
       return quoted(a) + std::string(kClosedForm) +
              ", and force.expression is set: use method.name = \"event_driven\", the "
              "event-driven reference for any f(t)";
     },
     [](const Asked&) -> std::string_view {
       return "it takes no force expression (force.expression)";
     }},
    {&Capabilities::bonding, [](const Asked& a) { return bonded(a.model); }, "method", "name",
     [](const Asked& a) {
       return quoted(a) + " takes no bonding field, and [bonding] gives gamma beta0^2 != 0: use " +
              listed(methods_with(&Capabilities::bonding)) +
              " (or bonding.gamma = 0 for the paper's model)";
     },
     [](const Asked&) -> std::string_view { return "it takes no bonding field ([bonding])"; }},
    // Compliance has no impact law to apply a COR to: refused rather than run elastic.
    {&Capabilities::restitution, [](const Asked& a) { return a.model.cor.has_value(); }, "floor",
     "cor",
     [](const Asked& a) {
       // The methods that take a COR and the rest of the model (exact takes no expression).
       std::vector<std::string_view> taking;
       for (const MethodInfo& m : methods())
         if (takes(m, a.model)) taking.push_back(m.name);
       std::string choose = "remove floor.cor (--unset floor.cor)";
       if (!taking.empty()) choose += " or choose " + listed_or(taking);
       return "method " + quoted(a) +
              " has no restitution law (its compliance contact is elastic); " + choose;
     },
     [](const Asked&) -> std::string_view { return "it has no restitution law for floor.cor"; }},
    // (5-1)'s 2/h^2 overflows or underflows (free_flight.hpp).
    {nullptr,
     [](const Asked& a) {
       return scheme_method(a.params) && a.h && !scheme_step_representable(*a.h);
     },
     "time", "h",
     [](const Asked& a) {
       return "method " + quoted(a) +
              ": 2/h^2 of (5-1) is not representable for h = " + shortest(*a.h) +
              " (time.h must be in [1.1e-154, 9.4e153])";
     },
     [](const Asked&) -> std::string_view {
       return "2/h^2 of (5-1) is not representable for this time.h";
     }},
    // (5-1) as printed steps (u, v) alone; the closed form follows internal variables and bonds.
    {nullptr,
     [](const Asked& a) {
       const auto* direct = std::get_if<DirectParams>(&a.params);
       return direct && direct->free_flight == FreeFlightForm::paper &&
              (!a.model.internal.empty() || bonded(a.model));
     },
     "method", "free_flight",
     [](const Asked& a) {
       return "method " + quoted(a) + " with free_flight = \"paper\" does not follow " +
              (a.model.internal.empty()
                   ? std::string("a bonding field: [bonding] gives gamma beta0^2 != 0")
                   : std::string("internal variables: [[internal]] is given")) +
              " (the closed form does)";
     },
     [](const Asked& a) -> std::string_view {
       return a.model.internal.empty()
                  ? "with free_flight = \"paper\" it does not follow a bonding field ([bonding])"
                  : "with free_flight = \"paper\" it does not follow internal variables "
                    "([[internal]])";
     }},
};

const Feature* refused_feature(const Asked& asked) {
  // A constexpr table, unrolled: GCC then tests each row's capability and calls its `asks`
  // directly, not through loads from the table (make_stepper asks this on every run).
#pragma GCC unroll 16
  for (const Feature& f : kFeatures)
    if ((!f.capability || !(asked.method.can.*f.capability)) && f.asks(asked)) return &f;
  return nullptr;
}

bool takes(const MethodInfo& method, const Model& model) {
  return !refused_feature(Asked{method, method.defaults, model, nullptr});
}

std::optional<Refusal> refusal_of(const Asked& asked) {
  const Feature* f = refused_feature(asked);
  if (!f) return std::nullopt;
  return Refusal{f->table, f->key, f->message(asked)};
}

}  // namespace

std::optional<Refusal> refusal(const MethodParams& method, const Model& model, double h) {
  return refusal_of(Asked{method_info(method), method, model, &h});
}

std::optional<Refusal> refusal(const MethodParams& method, const Model& model) {
  return refusal_of(Asked{method_info(method), method, model, nullptr});
}

std::string refusal_reason(const MethodInfo& method, const Model& model) {
  const Asked asked{method, method.defaults, model, nullptr};
  const Feature* f = refused_feature(asked);
  return f ? std::string(f->reason(asked)) : std::string();
}

const MethodInfo& reference_for(const Model& model) {
  // exact follows a bonding field only in the well with no damage: the reference of a bonded
  // model is event_driven's track (ReferenceSolution, error_norms.hpp).
  if (bonded(model)) return *find_method("event_driven");
  for (const auto& m : kMethods)
    if (m.can.reference && takes(m, model)) return m;
  throw std::logic_error("no reference method takes this model");
}

std::optional<Refusal> reference_refusal(const Model& model) {
  const MethodInfo* first = nullptr;
  for (const auto& m : kMethods) {
    if (!m.can.reference) continue;
    if (takes(m, model)) return std::nullopt;
    if (!first) first = &m;
  }
  // No reference takes the model: what the first refuses.
  std::optional<Refusal> r = refusal(first->defaults, model);
  r->message = "no reference takes this model: " + r->message;
  return r;
}

}  // namespace impact
