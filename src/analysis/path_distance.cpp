#include "analysis/path_distance.hpp"

#include <stdexcept>
#include <type_traits>
#include <variant>
#include <vector>

#include "analysis/impact_times.hpp"

namespace impact {

double sup_distance(const Scene& scene, const MethodParams& other) {
  AnyStepper a = make_stepper(scene);
  AnyStepper b = make_stepper(scene.model, scene.grid.h, other);
  return std::visit(
      [&](auto& stepper_a) -> double {
        if constexpr (!ParticleStepper<std::remove_cvref_t<decltype(stepper_a)>>) {
          throw std::logic_error("sup_distance: a method with internal variables");
        } else {
          LockstepStepper pair(stepper_a, b, scene.initial, scene.grid.h);
          simulate(pair, scene.initial, scene.grid,
                   [](std::int64_t, const State&, const StepInfo&) {});
          return pair.sup_distance();
        }
      },
      a);
}

StepInfo step_any(AnyStepper& stepper, State& s, std::int64_t l) {
  return std::visit(
      [&](auto& x) -> StepInfo {
        if constexpr (!ParticleStepper<std::remove_cvref_t<decltype(x)>>)
          throw std::logic_error("step_any: a method with internal variables");
        else
          return x.do_step(s, l);
      },
      stepper);
}

double sup_distance(const ExactSolution& u, const ExactSolution& w, double T) {
  constexpr int kSamples = 10000;
  std::vector<double> times = impact_times(u, T);
  const std::vector<double> w_times = impact_times(w, T);
  times.insert(times.end(), w_times.begin(), w_times.end());
  for (int i = 0; i <= kSamples; ++i) times.push_back(T * i / kSamples);
  double sup = 0;
  for (double t : times) sup = std::fmax(sup, std::fabs(u.at(t).u - w.at(t).u));
  return sup;
}

}  // namespace impact
