// What each method can honour and what it is: the method table (capabilities.cpp), plain data that
// the scene reader, the help, the channels and the CLI read without including any stepper.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "impact/methods/method_params.hpp"
#include "impact/model/contact_law.hpp"
#include "impact/model/model.hpp"

namespace impact {

// What a method can honour and what it is: one table (capabilities.cpp) that the scene reader, the
// help, the CLI and the analyses ask, instead of lists of names. A scene feature a method cannot
// honour is refused (exit 2, naming the key), never ignored; a test runs every method against
// every feature.
struct Capabilities {
  bool restitution = false;         // floor.cor: an impact law a COR acts on
  bool time_expression = false;     // force.expression (a function of t)
  bool state_force = false;         // force.expression reads u or v: f(t, u, v)
  bool linear_force = false;        // force.linear: -k (u - u_eq) - c v beside f
  bool internal_variables = false;  // [[internal]]: z' = g(t, u, v, z), read by the force
  bool bonding = false;             // [bonding]: adhesion with damage (bonding.hpp), beta and D
  bool iterations_channel = false;  // output.channels "iterations": Newton iterations, ODE steps
  // output.channels "N_scheme": the paper's scheme solves (4-3) for N^l, which Newton's law does
  // not change (channels.cpp)
  bool scheme_force_channel = false;
  bool reference = false;     // samples an exact solution (--against's reference, tight tolerances)
  bool energy_bound = false;  // the discrete energy (3-1) never rises (Lemma 1, (4-5), stability)
  bool exact_events = false;  // reports its own events (EventSource), else read off its steps
};

struct MethodInfo {
  std::string_view name;
  std::string_view summary;
  MethodParams defaults;
  Capabilities can;
};

std::span<const MethodInfo> methods();
// The names of the methods that have a capability, for messages ("direct, fb_newton or exact").
std::vector<std::string_view> methods_with(bool Capabilities::*capability);
// Why a method refuses a problem: the scene key that asks for what the method cannot do (table
// "method", key "name" when the method lacks a capability; the key itself, such as floor.cor or
// time.h, otherwise), and the message that says so and names the methods that do take it.
struct Refusal {
  std::string_view table, key;
  std::string message;
};
// The one decision whether `method` refuses `model` stepped with `h` (left out by a caller that
// chooses h itself, as work-precision does): the first row of the feature table (capabilities.cpp)
// it refuses, in the order the scene reader reports them; nullopt when it takes the problem. The
// scene reader, the sweep's points, make_stepper and the analyses all ask this.
std::optional<Refusal> refusal(const MethodParams& method, const Model& model, double h);
std::optional<Refusal> refusal(const MethodParams& method, const Model& model);
// The same refusal as a clause for a list of methods ("it takes a force of t only, and
// force.expression reads u or v"); empty when `method` (by its default parameters) takes `model`.
std::string refusal_reason(const MethodInfo& method, const Model& model);
// The reference for a model: the first method with `reference` that takes it (exact for a
// constant or harmonic force, event_driven for an expression, of t or of the state).
const MethodInfo& reference_for(const Model& model);
// Why the errors against the reference (error_norms.hpp's ReferenceSolution: `--against exact`,
// Python's exact()) cannot be measured for `model`, as a refusal of the key that asks for what the
// reference does not follow; nullopt when they can. It follows what a method with `reference`
// takes, and no bonding field yet (its march carries no beta), although the methods with
// `bonding` run one. Every surface asks this, so a new law or force that no reference takes is
// refused there with exit 2, not measured wrong.
std::optional<Refusal> reference_refusal(const Model& model);
// Whether the model's force expression reads u, v or an internal variable (a linear part is its
// own capability).
bool expression_of_state(const Model& model);
// nullptr for an unknown name.
const MethodInfo* find_method(std::string_view name);
const MethodInfo& method_info(const MethodParams& params);
inline std::string_view method_name(const MethodParams& params) {
  return method_info(params).name;
}
// The row of the method whose parameters are P.
template <class P>
const MethodInfo& method_of() {
  return methods()[method_index<P>];
}

// The contact law a method applies to the model's floor, its family's reading of contact_law.hpp:
// the law its stepper resolves in its constructor. Throws std::invalid_argument for a COR given to
// penalty. Inline: make_stepper asks it on every run.
inline ContactLaw contact_law(const Model& model, const MethodParams& params) {
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
