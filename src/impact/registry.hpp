// The solvers by name: each method's parameters and stepper (the interface is stepper.hpp's
// concept), its row in registry.cpp's table, and the factory.
#pragma once

#include <span>
#include <string_view>
#include <variant>

#include "impact/direct.hpp"
#include "impact/event_driven.hpp"
#include "impact/exact.hpp"
#include "impact/fb_newton.hpp"
#include "impact/model.hpp"
#include "impact/moreau_jean.hpp"
#include "impact/penalty.hpp"
#include "impact/stepper.hpp"

namespace impact {

// One method and its parameters: what a scene's [method] table says.
using MethodParams = std::variant<DirectParams, FbNewtonParams, MoreauJeanParams, PenaltyParams,
                                  ExactParams, EventDrivenParams>;

// DirectHarmonic, DirectTimeDependent and MoreauJeanTimeDependent are `direct` and `moreau_jean`
// with a time-dependent force (direct.hpp says why more than one type).
using AnyStepper = std::variant<Direct, FbNewton, MoreauJean, Penalty, ExactStepper, EventDriven,
                                DirectHarmonic, DirectTimeDependent, MoreauJeanTimeDependent>;
static_assert([]<class... S>(std::variant<S...>*) { return (Stepper<S> && ...); }(
                  static_cast<AnyStepper*>(nullptr)),
              "every method's stepper has the interface of stepper.hpp");

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
