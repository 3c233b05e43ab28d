// The reference of the work-precision study when the body force depends on time: the event-driven
// solution, `exact` (closed-form flights, impact times bracketed rigorously) for a constant +
// harmonic force and `event_driven` (GSL rk8pd between impacts) for an expression. The errors of a
// point are measured against it by error_norms.hpp's ErrorObserver (ReferenceSolution follows the
// same solutions as it streams); here: which method that is, its run sampled on a grid (for the
// Lyapunov estimate), and its impacts (for its cost per impact).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "impact/model/model.hpp"
#include "impact/run/scene.hpp"

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

}  // namespace impact
