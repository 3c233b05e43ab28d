// The solvers by name. Adding a method: write its file (a class with the stepper interface
// below) and add it to AnyStepper and to methods() in registry.cpp.
//
// The stepper interface, in the spirit of Boost.Odeint's steppers:
//   static XParams read_params(MethodParams&);  // the method's [method] keys, range-checked
//   StepInfo step(State& s, std::int64_t l);    // advance s from t_l = l h to t_{l+1}
#pragma once

#include <span>
#include <string_view>
#include <variant>

#include "impact/direct.hpp"
#include "impact/exact.hpp"
#include "impact/fb_newton.hpp"
#include "impact/moreau_jean.hpp"
#include "impact/penalty.hpp"

namespace impact {

struct Scene;

struct MethodInfo {
  std::string_view name;
  bool has_iterations;  // can write the "iterations" channel
  std::string_view summary;
};

std::span<const MethodInfo> methods();
const MethodInfo* find_method(std::string_view name);

using AnyStepper = std::variant<Direct, FbNewton, MoreauJean, Penalty, ExactStepper>;

// Builds the scene's solver; throws SceneError for a bad [method] key or value.
AnyStepper make_stepper(const Scene& scene);

}  // namespace impact
