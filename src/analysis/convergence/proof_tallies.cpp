#include "analysis/convergence/proof_tallies.hpp"

#include <stdexcept>
#include <type_traits>
#include <variant>

#include "impact/run/any_stepper.hpp"

namespace impact::convergence {

ConvergencePoint measure_convergence(const Scene& scene, const std::optional<Model>& reference) {
  AnyStepper stepper = make_stepper(scene);
  ConvergencePoint point;
  point.h = scene.grid.h;
  point.t_end = scene.grid.t(scene.grid.steps);
  point.initial = scene.initial;
  point.f = scene.model.f;
  point.tallies.last = scene.initial;
  std::visit(
      [&](auto& inner) {
        if constexpr (!ParticleStepper<std::remove_cvref_t<decltype(inner)>>) {
          throw std::logic_error("proof tallies: a method with internal variables");
        } else {
          TallyingStepper tallying(inner, scene.model, scene.grid.h, point.tallies);
          point.errors =
              measure_errors(tallying, reference.value_or(scene.model), scene.initial, scene.grid);
        }
      },
      stepper);
  point.final = point.tallies.last;
  return point;
}

}  // namespace impact::convergence
