// Error norms of a time-stepper against the exact event-driven solution, accumulated while the run
// streams (no trajectory is stored), against the reference of ReferenceSolution below.
#pragma once

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "impact/forces/work_energy.hpp"
#include "impact/format.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/model/contact.hpp"
#include "impact/model/model.hpp"
#include "impact/references/exact.hpp"
#include "impact/references/exact_march.hpp"
#include "impact/references/linear_law.hpp"
#include "impact/references/ode_flight.hpp"

namespace impact {

struct ErrorNorms {
  double sup_u = 0;       // max_l |u^l - u(t_l)|
  double l1_v = 0;        // h sum_l |v^l - v(t_l)|
  double energy_end = 0;  // |E^n - E(t_n)|
  // First contact of the scheme, t_l + (u^l - phi) / |v^l| for the first step l with N^l > 0
  // (the floor crossing inside that step), minus the exact first impact time; NaN when either has
  // no impact.
  double first_impact = std::numeric_limits<double>::quiet_NaN();
  // max over l and i of |z_i^l - z_i(t_l)|, the model's internal variables (0 without them)
  double sup_internal = 0;
  RunSummary run;
};

// The exact solution at the grid times, in increasing order, for any force: ExactSolution's closed
// form for a constant one, ClosedFormMarch for a harmonic one, LinearTrack for a linear one and the
// method event_driven's ODE track (default tolerances, f evaluated up to `end` only);
// impact_time(1) of a time-dependent force is known once the samples have passed it. The closed
// form is sampled flight by flight (the flight that held the last sample is kept while the samples
// stay in it: a polynomial per sample, bit for bit at()).
class ReferenceSolution {
 public:
  // With internal variables or a bonding field: event_driven's track, z from their initial values
  // (model.hpp; a bonded model's beta0 and D = 0).
  ReferenceSolution(const Model& model, const State& initial, double end) : initial_(initial) {
    if (!model.internal.empty() || bonded(model)) {
      OdeLaw law(model, OdeSettings{.end = end});
      law.set_internal(with_internal(model, initial).z);
      ode_track_.emplace(std::move(law), model, initial, 0.0);
    } else if (model.linear) {
      linear_.emplace(linear_track(model, initial, 0.0));
    } else if (constant_force(model)) {
      closed_form_.emplace(model, initial);
    } else if (model.expression.empty()) {
      track_.emplace(model, initial, 0.0);
    } else {
      ode_track_.emplace(OdeLaw(model, OdeSettings{.end = end}), model, initial, 0.0);
    }
    if (closed_form_)
      rest_ = closed_form_->rest_time().value_or(std::numeric_limits<double>::infinity());
    // The impacts' changes of v^2/2, for E(t) as the E channel defines it (work_energy.hpp).
    const EventSink sink = [this](const Event& e) {
      if (e.kind == EventKind::impact)
        impact_energy_ += 0.5 * e.v_after * e.v_after - 0.5 * e.v_before * e.v_before;
    };
    if (track_) track_->set_event_sink(sink);
    if (linear_) linear_->set_event_sink(sink);
    if (ode_track_) ode_track_->set_event_sink(sink);
  }
  ReferenceSolution(const ReferenceSolution&) = delete;  // the sink points to this one
  ReferenceSolution& operator=(const ReferenceSolution&) = delete;
  State at(double t) {
    if (closed_form_) {
      if (!(t > 0) || t >= rest_) return closed_form_->at(t);
      if (!(t >= flight_.begin && t < flight_.end)) flight_ = closed_form_->flight_at(t);
      return closed_form_->flight_state(flight_, t);
    }
    if (!(t > 0)) return initial_;  // an impact at 0+ shows from the first step on (exact.hpp)
    double impulse = 0;
    if (linear_) return linear_->advance(t, impulse);
    return track_ ? track_->advance(t, impulse) : ode_track_->advance(t, impulse);
  }
  // The internal variables at the t of the last at(t) (with internal variables).
  std::array<double, kMaxInternal> internal_at(double t) const {
    return ode_track_->law().internal_at(t);
  }
  // What the impacts up to the t of the last at(t) changed v^2/2 by (with f(t): the reference's E
  // at t is E(0) plus this, work_energy.hpp).
  double impact_energy() const { return impact_energy_; }
  std::optional<double> first_impact() const {
    if (closed_form_) return closed_form_->impact_time(1);
    if (linear_) return linear_->first_impact();
    return track_ ? track_->first_impact() : ode_track_->first_impact();
  }

 private:
  State initial_;
  std::optional<ExactSolution> closed_form_;
  ExactSolution::Flight flight_;
  double rest_ = 0;
  std::optional<ClosedFormMarch> track_;
  std::optional<LinearTrack> linear_;  // a linear force of the state (linear_law.hpp)
  std::optional<ExactMarch<OdeLaw>> ode_track_;
  double impact_energy_ = 0;
};

// Accumulates the norms as a run streams (an observer for simulate()), so that other observers can
// see the same run. The samples are compared with the reference a chunk at a time, and that work is
// timed, so that a run can report its method's time apart from the reference's.
class ErrorObserver {
 public:
  ErrorObserver(const Model& model, const State& initial, const Grid& grid)
      : exact_(model, initial, grid.end()),
        initial_energy_(initial_energy(model, initial)),
        internal_(model.internal.size() + (bonded(model) ? 2 : 0)),
        model_(model),
        grid_(grid),
        initial_(initial),
        previous_(initial),
        end_(initial) {
    pending_.reserve(kChunk);
  }

  // St: State, or StateWithInternal (the internal variables are compared too).
  template <class St>
  void operator()(std::int64_t l, const St& s, const StepInfo& info) {
    if (!seen_contact_ && l > 0 && scheme_force(info) > 0) {
      seen_contact_ = true;
      first_crossing_ = grid_.t(l - 1) + floor_crossing(model_, previous_);
    }
    previous_ = s;
    pending_.push_back({l, s});
    if constexpr (std::is_same_v<St, StateWithInternal>)
      if (internal_ > 0) pending_internal_.push_back(s.z);
    if (pending_.size() == kChunk) compare_pending();
  }

  // The norms of the run that simulate() summarised as `run`. energy_end compares v^2/2 - f u at T
  // with f the force's constant part, a function of the state at T, the same for the method and
  // the reference (the work-precision study's measure).
  ErrorNorms result(const RunSummary& run) {
    compare_pending();
    ErrorNorms e = e_;
    // A bonded model's E holds the bonds' energy, at each one's beta (model.hpp).
    e.energy_end = bonded(model_)
                       ? std::fabs(energy(model_, StateWithInternal{previous_, last_internal_}) -
                                   energy(model_, StateWithInternal{end_, end_internal_}))
                       : std::fabs(energy(model_, previous_) - energy(model_, end_));
    if (const auto t1 = exact_.first_impact(); t1 && seen_contact_)
      e.first_impact = first_crossing_ - *t1;
    e.run = run;
    return e;
  }
  // The same with energy_end = |E^n - E(T)| for E as the E channel defines it with f(t)
  // (work_energy.hpp): `energy_final` is the method's E^n, the reference's is E(0) plus what its
  // impacts changed v^2/2 by, with a bonding field less the D it integrated (E + D = E(0) in
  // flight, the bonds' energy at t = 0 in E(0)).
  ErrorNorms result(const RunSummary& run, double energy_final) {
    ErrorNorms e = result(run);
    double reference = initial_energy_ + exact_.impact_energy();
    if (bonded(model_))
      reference += energy(model_, with_internal(model_, initial_)) - energy(model_, initial_) -
                   end_internal_[kBondEnergy];
    e.energy_end = std::fabs(energy_final - reference);
    return e;
  }
  // The method's state at the last step seen.
  const State& final_state() const { return previous_; }
  // The reference's first impact time (known once the samples have passed it).
  std::optional<double> reference_first_impact() const { return exact_.first_impact(); }
  // The time spent evaluating the reference so far (wall clock, seconds).
  double reference_seconds() const { return reference_seconds_; }

 private:
  static constexpr std::size_t kChunk = 1024;
  struct Sample {
    std::int64_t l;
    State s;
  };
  void compare_pending() {
    const auto start = std::chrono::steady_clock::now();
    if (!pending_internal_.empty()) last_internal_ = pending_internal_.back();
    for (std::size_t k = 0; k < pending_.size(); ++k) {
      const Sample& p = pending_[k];
      const State ref = exact_.at(grid_.t(p.l));
      if (p.l == grid_.steps) {
        end_ = ref;
        if (internal_ > 0)
          end_internal_ = p.l == 0 ? last_internal_ : exact_.internal_at(grid_.t(p.l));
      }
      e_.sup_u = std::fmax(e_.sup_u, std::fabs(p.s.u - ref.u));
      add_l1_v(std::fabs(p.s.v - ref.v));
      if (k < pending_internal_.size()) {
        const auto z = p.l == 0 ? pending_internal_[k] : exact_.internal_at(grid_.t(p.l));
        for (std::size_t i = 0; i < internal_; ++i)
          e_.sup_internal = std::fmax(e_.sup_internal, std::fabs(pending_internal_[k][i] - z[i]));
      }
    }
    pending_.clear();
    pending_internal_.clear();
    reference_seconds_ += seconds_since(start);
  }

  // l1_v += h dv, skipping the product when it cannot change l1_v: a particle at rest carries
  // v = +-2^-1073 (restitution.hpp), and a product with a subnormal operand costs ~100 cycles on
  // some processors (measured on an Intel Xeon family 6 model 167: the reference's share of a run
  // at rest fell from 47 to 10 ns per step). h dv < 2^-1022 h is below half an ulp of any
  // l1_v >= 2^-900 for h < 2^60, so the sum is the same bits.
  void add_l1_v(double dv) {
    if (dv < std::numeric_limits<double>::min() && e_.l1_v >= 0x1p-900 && grid_.h < 0x1p60) return;
    e_.l1_v += grid_.h * dv;
  }

  ReferenceSolution exact_;
  double initial_energy_;  // E(0), work_energy.hpp
  std::size_t internal_;   // the model's internal variables (a bonded model's beta and D)
  Model model_;
  Grid grid_;
  State initial_;
  State previous_;
  State end_;
  // The method's internal variables at the last step and the reference's at T (with some).
  std::array<double, kMaxInternal> last_internal_{}, end_internal_{};
  double first_crossing_ = 0;
  bool seen_contact_ = false;
  ErrorNorms e_;
  std::vector<Sample> pending_;
  std::vector<std::array<double, kMaxInternal>> pending_internal_;
  double reference_seconds_ = 0;
};

// S: a Stepper, or AnyStepper.
template <class S>
ErrorNorms measure_errors(S& stepper, const Model& model, const State& initial, const Grid& grid) {
  ErrorObserver errors(model, initial, grid);
  const RunSummary run = simulate(stepper, initial, grid, errors);
  return errors.result(run);
}

}  // namespace impact
