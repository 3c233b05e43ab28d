// The solvers by name. Adding a method: write its file (a class with the stepper interface below
// and a plain parameter struct), add both to the variants here and a row to kMethods in
// registry.cpp, and read its [method] keys in src/scene/method_keys.cpp.
//
// The stepper interface, in the spirit of Boost.Odeint's steppers:
//   Stepper(const Model&, double h, const Params&);  // throws std::invalid_argument on bad params
//   void initialize(const State& s, std::int64_t l); // (re)start at t_l = l h from s
//   StepInfo do_step(State& s, std::int64_t l);      // s: the state at t_l that the stepper
//                                                    // produced (or was initialized with);
//                                                    // advanced to t_{l+1}
// A stepper may carry state of its own between steps (direct's free-flight anchor, fb_newton's
// gap, penalty's ODE driver); to start from any other state, call initialize() again.
#pragma once

#include <span>
#include <string_view>
#include <variant>

#include "impact/direct.hpp"
#include "impact/direct_located.hpp"
#include "impact/event_driven.hpp"
#include "impact/exact.hpp"
#include "impact/fb_newton.hpp"
#include "impact/model.hpp"
#include "impact/moreau_jean.hpp"
#include "impact/penalty.hpp"

namespace impact {

// One method and its parameters: what a scene's [method] table says.
using MethodParams = std::variant<DirectParams, FbNewtonParams, MoreauJeanParams, PenaltyParams,
                                  ExactParams, EventDrivenParams, DirectLocatedParams>;

// DirectHarmonic, DirectTimeDependent and MoreauJeanTimeDependent are `direct` and `moreau_jean`
// with a time-dependent force (direct.hpp says why more than one type).
using AnyStepper =
    std::variant<Direct, FbNewton, MoreauJean, Penalty, ExactStepper, EventDriven, DirectHarmonic,
                 DirectTimeDependent, MoreauJeanTimeDependent, DirectLocated>;

struct MethodInfo {
  std::string_view name;
  bool has_iterations;  // can write the "iterations" channel
  bool takes_cor;       // has an impact law a COR can act on
  std::string_view summary;
  MethodParams defaults;
};

std::span<const MethodInfo> methods();
// nullptr for an unknown name.
const MethodInfo* find_method(std::string_view name);
const MethodInfo& method_info(const MethodParams& params);
inline std::string_view method_name(const MethodParams& params) {
  return method_info(params).name;
}

// The solver for one model and step; throws std::invalid_argument for parameters out of range
// and for a COR given to a method without an impact law (penalty).
AnyStepper make_stepper(const Model& model, double h, const MethodParams& params);

}  // namespace impact
