// Error norms of a time-stepper against the exact event-driven solution, accumulated while the run
// streams (no trajectory is stored), against the reference of ReferenceSolution below.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "impact/contact.hpp"
#include "impact/event_track.hpp"
#include "impact/exact.hpp"
#include "impact/model.hpp"
#include "impact/ode_flight.hpp"
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

// The exact solution at the grid times, in increasing order, for any force: ExactSolution's closed
// form for a constant one, EventTrack for a harmonic one and the method event_driven's ODE track
// (default tolerances, f evaluated up to `end` only); impact_time(1) of a time-dependent force is
// known once the samples have passed it.
class ReferenceSolution {
 public:
  ReferenceSolution(const Model& model, const State& initial, double end) : initial_(initial) {
    if (constant_force(model))
      closed_form_.emplace(model, initial);
    else if (model.expression.empty())
      track_.emplace(model, initial, 0.0);
    else
      ode_track_.emplace(OdeLaw(model, OdeSettings{.end = end}), model, initial, 0.0);
  }
  State at(double t) {
    if (closed_form_) return closed_form_->at(t);
    if (!(t > 0)) return initial_;  // an impact at 0+ shows from the first step on (exact.hpp)
    double impulse = 0;
    return track_ ? track_->advance(t, impulse) : ode_track_->advance(t, impulse);
  }
  std::optional<double> first_impact() const {
    if (closed_form_) return closed_form_->impact_time(1);
    return track_ ? track_->first_impact() : ode_track_->first_impact();
  }

 private:
  State initial_;
  std::optional<ExactSolution> closed_form_;
  std::optional<EventTrack> track_;
  std::optional<EventTrackOf<OdeLaw>> ode_track_;
};

// Accumulates the norms as a run streams (an observer for simulate()), so that other observers can
// see the same run.
class ErrorObserver {
 public:
  ErrorObserver(const Model& model, const State& initial, const Grid& grid)
      : exact_(model, initial, grid.end()),
        model_(model),
        grid_(grid),
        previous_(initial),
        end_(initial) {}

  void operator()(std::int64_t l, const State& s, const StepInfo& info) {
    const State ref = exact_.at(grid_.t(l));
    if (l == grid_.steps) end_ = ref;
    e_.sup_u = std::fmax(e_.sup_u, std::fabs(s.u - ref.u));
    e_.l1_v += grid_.h * std::fabs(s.v - ref.v);
    if (!seen_contact_ && l > 0 && info.contact_force > 0) {
      seen_contact_ = true;
      first_crossing_ = grid_.t(l - 1) + floor_crossing(model_, previous_);
    }
    previous_ = s;
  }

  // The norms of the run that simulate() summarised as `run`.
  ErrorNorms result(const RunSummary& run) const {
    ErrorNorms e = e_;
    e.energy_end = std::fabs(energy(model_, previous_) - energy(model_, end_));
    if (const auto t1 = exact_.first_impact(); t1 && seen_contact_)
      e.first_impact = first_crossing_ - *t1;
    e.run = run;
    return e;
  }

 private:
  ReferenceSolution exact_;
  Model model_;
  Grid grid_;
  State previous_;
  State end_;
  double first_crossing_ = 0;
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
