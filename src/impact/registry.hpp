// The solvers by name: each method's parameters and stepper (the interface is stepper.hpp's
// concept), its row in registry.cpp's table, and the factory.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "impact/contact_law.hpp"
#include "impact/direct.hpp"
#include "impact/direct_located.hpp"
#include "impact/event_driven.hpp"
#include "impact/exact.hpp"
#include "impact/exact_bonded.hpp"
#include "impact/fb_newton.hpp"
#include "impact/internal_stepper.hpp"
#include "impact/model.hpp"
#include "impact/moreau_jean.hpp"
#include "impact/penalty.hpp"
#include "impact/stepper.hpp"

namespace impact {

// One method and its parameters: what a scene's [method] table says.
using MethodParams = std::variant<DirectParams, FbNewtonParams, MoreauJeanParams, PenaltyParams,
                                  ExactParams, EventDrivenParams, DirectLocatedParams>;

// The methods that follow a model's internal variables (internal_stepper.hpp, event_driven.hpp):
// their state is StateWithInternal.
using DirectInternal = WithInternal<DirectTimeDependent>;
using MoreauJeanInternal = WithInternal<MoreauJeanTimeDependent>;

// One stepper type per method, and more for some: DirectHarmonic, DirectTimeDependent and
// MoreauJeanTimeDependent are `direct` and `moreau_jean` with a time-dependent force,
// DirectAsPrinted `direct` with (5-1) as printed (direct.hpp says why more than one type), and the
// *Internal ones the methods with the model's internal variables.
using AnyStepper =
    std::variant<Direct, FbNewton, MoreauJean, Penalty, ExactStepper, EventDriven, DirectHarmonic,
                 DirectTimeDependent, MoreauJeanTimeDependent, DirectAsPrinted, DirectLocated,
                 DirectInternal, MoreauJeanInternal, EventDrivenInternal, ExactBonded>;
static_assert([]<class... S>(std::variant<S...>*) { return (Stepper<S> && ...); }(
                  static_cast<AnyStepper*>(nullptr)),
              "every method's stepper has the interface of stepper.hpp");

// What a method can honour and what it is: one table (registry.cpp) that the scene reader, the
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
// Whether `method` honours what `model` states (a COR, an expression, one that reads the state,
// internal variables; every method takes a harmonic part).
bool honours(const MethodInfo& method, const Model& model);
// Why `method` does not honour `model`, its first feature the method lacks ("it takes a force of
// t only, and force.expression reads u or v"); empty when it honours it.
std::string not_honoured(const MethodInfo& method, const Model& model);
// The reference for a model: the first method with `reference` that honours it (exact for a
// constant or harmonic force, event_driven for an expression, of t or of the state).
const MethodInfo& reference_for(const Model& model);
// nullptr for an unknown name.
const MethodInfo* find_method(std::string_view name);
const MethodInfo& method_info(const MethodParams& params);
inline std::string_view method_name(const MethodParams& params) {
  return method_info(params).name;
}

// The solver for one model and step; throws std::invalid_argument for parameters out of range
// and for what the method does not honour (a COR given to penalty).
AnyStepper make_stepper(const Model& model, double h, const MethodParams& params);

// The contact law a method applies to the model's floor, its family's reading of contact_law.hpp:
// the law its stepper resolves in its constructor. Throws std::invalid_argument for a COR given to
// penalty.
ContactLaw method_law(const Model& model, const MethodParams& params);

}  // namespace impact
