// Error norms of a time-stepper against the exact event-driven solution, accumulated while the run
// streams (no trajectory is stored).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "impact/exact.hpp"
#include "impact/model.hpp"
#include "impact/run.hpp"

namespace impact {

struct ErrorNorms {
  double sup_u = 0;       // max_l |u^l - u(t_l)|
  double l1_v = 0;        // h sum_l |v^l - v(t_l)|
  double energy_end = 0;  // |E^n - E(t_n)|
  // First contact of the scheme, t_l + (u^l - phi) / |v^l| for the first step l with N^l > 0
  // (the floor crossing inside that step), minus the exact first impact time; NaN when either has
  // no impact.
  double first_impact = std::numeric_limits<double>::quiet_NaN();
  RunSummary run;
};

template <class Stepper>
ErrorNorms measure_errors(Stepper& stepper, const Model& model, const State& initial,
                          const Grid& grid) {
  const ExactSolution exact(model, initial);
  ErrorNorms e;
  State previous = initial;
  bool seen_contact = false;
  e.run =
      simulate(stepper, initial, grid, [&](std::int64_t l, const State& s, const StepInfo& info) {
        const State ref = exact.at(grid.t(l));
        e.sup_u = std::fmax(e.sup_u, std::fabs(s.u - ref.u));
        e.l1_v += grid.h * std::fabs(s.v - ref.v);
        if (!seen_contact && l > 0 && info.contact_force > 0) {
          seen_contact = true;
          const double crossing =
              previous.v < 0 ? std::fmax(0.0, (previous.u - model.phi) / -previous.v) : 0.0;
          if (auto t1 = exact.impact_time(1)) e.first_impact = grid.t(l - 1) + crossing - *t1;
        }
        previous = s;
      });
  e.energy_end = std::fabs(energy(model, previous) - energy(model, exact.at(grid.t(grid.steps))));
  return e;
}

}  // namespace impact
