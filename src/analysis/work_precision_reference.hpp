// The reference of a work-precision point when the body force depends on time. For a constant
// force it is ExactSolution in closed form (error_norms.hpp); for f(t) it is the event-driven
// solution run on the same grid: method `exact` (closed-form flights, impact times bracketed
// rigorously) for a constant + harmonic force, method `event_driven` (GSL odeiv2 between impacts)
// for an expression. The reference is run once per grid, its states kept, and the errors of the
// method follow the same definitions as ErrorNorms, except the energy: with f(t), v^2/2 - f u
// is not conserved, so energy_end compares E(T) = v^2/2 - f(T) u, the mechanical energy in the
// field of the force at the final time T, of the method and of the reference (for a constant f
// this is the energy (3-1) that error_norms.hpp compares).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "impact/contact.hpp"
#include "impact/error_norms.hpp"
#include "impact/event_log.hpp"
#include "impact/events.hpp"
#include "impact/model.hpp"
#include "impact/registry.hpp"
#include "impact/run.hpp"
#include "impact/scene.hpp"

namespace impact {

// The method whose run is the reference for this force: "exact" or "event_driven".
std::string_view reference_method(const Model& model);

// The impacts of one run of the scene (its method, grid), from the stepper's event log; 0 for a
// stepper without one.
std::int64_t count_impacts(const Scene& scene);

// The reference sampled on a grid: states[l] at t_l, and its first impact time (from the
// stepper's event log), if it has one before the end of the grid.
struct ReferenceTrajectory {
  std::vector<State> states;
  std::optional<double> first_impact;
};
// Runs reference_method(model) from `initial` over the grid. Throws std::runtime_error when that
// method is not registered.
ReferenceTrajectory reference_trajectory(const Model& model, const State& initial,
                                         const Grid& grid);

// The error measures of ErrorNorms against a reference trajectory (an observer for simulate()).
class ReferenceErrorObserver {
 public:
  ReferenceErrorObserver(const Model& model, const ReferenceTrajectory& reference,
                         const Grid& grid);
  void operator()(std::int64_t l, const State& s, const StepInfo& info) {
    const State& ref = reference_->states[static_cast<std::size_t>(l)];
    e_.sup_u = std::fmax(e_.sup_u, std::fabs(s.u - ref.u));
    e_.l1_v += grid_.h * std::fabs(s.v - ref.v);
    if (!seen_contact_ && l > 0 && info.contact_force > 0) {
      seen_contact_ = true;
      if (reference_->first_impact)
        e_.first_impact =
            grid_.t(l - 1) + floor_crossing(model_, previous_) - *reference_->first_impact;
    }
    previous_ = s;
  }
  ErrorNorms result(const RunSummary& run) const;

 private:
  Model model_;
  const ReferenceTrajectory* reference_;
  Grid grid_;
  double f_end_;  // f(T)
  State previous_;
  bool seen_contact_ = false;
  ErrorNorms e_;
};

// The errors of a run of `stepper` against the reference of the model: ExactSolution for a
// constant force (measure_errors), the reference trajectory otherwise.
template <class Stepper>
ErrorNorms measure_errors_any_force(Stepper& stepper, const Model& model, const State& initial,
                                    const Grid& grid) {
  if (constant_force(model)) return measure_errors(stepper, model, initial, grid);
  const ReferenceTrajectory reference = reference_trajectory(model, initial, grid);
  ReferenceErrorObserver errors(model, reference, grid);
  const RunSummary run = simulate(stepper, initial, grid, errors);
  return errors.result(run);
}

}  // namespace impact
