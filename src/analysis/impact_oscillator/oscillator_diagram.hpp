// Bifurcation diagrams of the impact oscillator from the exact-flight reference: continuation
// sweeps in sigma (omega fixed) and in omega (sigma fixed), up and down, each run starting where
// the previous one ended (its runs last whole forcing periods, so the forcing's phase carries over
// to the next run's t = 0), the impacts after a transient kept; and the closed-form branches of
// oscillator_theory.hpp to draw over them.
#pragma once

#include <string>
#include <vector>

#include "analysis/impact_oscillator/oscillator_theory.hpp"
#include "impact/model/event.hpp"

namespace impact::impact_oscillator {

enum class SweepParameter { sigma, omega };

struct DiagramPoint {
  Oscillator o;
  std::vector<Event> events;  // after the transient (at most DiagramSettings::max_events)
  int sticks = 0;             // rests after the transient
  bool converged = true;
};

struct DiagramSettings {
  int transient_periods = 100;
  int kept_periods = 50;
  std::size_t max_events = 64;
};

// The sweep over `values` of the parameter, the others from `base`, from `start` at the first.
std::vector<DiagramPoint> sweep(SweepParameter parameter, const Oscillator& base,
                                const std::vector<double>& values, const State& start,
                                const DiagramSettings& settings);

// from, from + step, ... up to `to` (step of either sign), the doubles nearest those decimals.
std::vector<double> parameter_grid(double from, double to, double step);

// direction,parameter,kind,phase,V rows of the kept events (phase = t mod 2 pi/omega).
std::string diagram_rows(const std::vector<DiagramPoint>& points, const std::string& direction,
                         SweepParameter parameter);

// The closed-form (1, 1) branches over the values: parameter, V and phase of the "+" root drawn
// as stable (|multiplier| < 1), unstable, and the "-" root (the saddle), NaN where a branch does
// not exist or its orbit is not admissible.
std::string branch_rows(SweepParameter parameter, const Oscillator& base,
                        const std::vector<double>& values);

}  // namespace impact::impact_oscillator
