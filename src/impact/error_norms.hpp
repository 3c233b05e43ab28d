// Error norms of a time-stepper against the exact event-driven solution, accumulated while the run
// streams (no trajectory is stored).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "impact/contact.hpp"
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

// Accumulates the norms as a run streams (an observer for simulate()), so that other observers can
// see the same run.
class ErrorObserver {
 public:
  ErrorObserver(const Model& model, const State& initial, const Grid& grid)
      : exact_(model, initial), model_(model), grid_(grid), previous_(initial) {}

  void operator()(std::int64_t l, const State& s, const StepInfo& info) {
    const State ref = exact_.at(grid_.t(l));
    e_.sup_u = std::fmax(e_.sup_u, std::fabs(s.u - ref.u));
    e_.l1_v += grid_.h * std::fabs(s.v - ref.v);
    if (!seen_contact_ && l > 0 && info.contact_force > 0) {
      seen_contact_ = true;
      if (auto t1 = exact_.impact_time(1))
        e_.first_impact = grid_.t(l - 1) + floor_crossing(model_, previous_) - *t1;
    }
    previous_ = s;
  }

  // The norms of the run that simulate() summarised as `run`.
  ErrorNorms result(const RunSummary& run) const {
    ErrorNorms e = e_;
    e.energy_end =
        std::fabs(energy(model_, previous_) - energy(model_, exact_.at(grid_.t(grid_.steps))));
    e.run = run;
    return e;
  }

 private:
  ExactSolution exact_;
  Model model_;
  Grid grid_;
  State previous_;
  bool seen_contact_ = false;
  ErrorNorms e_;
};

template <class Stepper>
ErrorNorms measure_errors(Stepper& stepper, const Model& model, const State& initial,
                          const Grid& grid) {
  ErrorObserver errors(model, initial, grid);
  const RunSummary run = simulate(stepper, initial, grid, errors);
  return errors.result(run);
}

}  // namespace impact
