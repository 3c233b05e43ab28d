// The two thresholds of the period-1 orbit (vibrating_table_theory.hpp) as one method at one step h
// shows them: where its period-1 branch ends in a downward sweep (existence) and where a period-2
// orbit grows out of it (period doubling), each from a continuation sweep over a window around the
// closed-form value.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "analysis/vibrating_table/vibrating_table_sweep.hpp"

namespace impact::vibrating_table {

struct ThresholdSettings {
  double step = 0.005;  // Gamma spacing of the two windows
  // The period-doubling window, swept upward from the closed-form orbit at its bottom (stable
  // there), so that it follows the period-1 branch into the period-2 one:
  // [Gamma_pd - below_pd, Gamma_pd + above_pd] of the closed form.
  double above_pd = 0.2, below_pd = 0.05;
  int period_doubling_periods = 240, period_doubling_transient = 200;  // per Gamma
  double kick = 1e-4;  // SweepSettings::kick of the period-doubling window
  // Fit the onset on a sweep back down the period-2 branch (see measure_thresholds) rather than on
  // the upward one.
  bool fit_from_above = true;
  // The existence window, swept downward from the closed-form orbit at its top:
  // [Gamma_1 - below_existence, Gamma_1 + above_existence].
  double above_existence = 0.1, below_existence = 0.05;
  int bisections = 12;          // refinement of the end of the period-1 branch
  int bisection_periods = 300;  // per trial: a slow passage past the saddle-node's ghost shows as
                                // period 1 only if it lasts longer than this
  double bisection_tolerance = 1e-3;  // period 1 in a trial: flights and speeds repeat to this
  // The period-2 points of the fit (g / omega): close enough to the onset that
  // Gamma = Gamma_pd + c1 split^2 + c2 split^4 holds to ~1e-5 for exact at e = 0.5 (the range
  // [0.06, 0.2] gave +7e-5 at e = 0.5 and +2e-3 at e = 0.8, where the branch curves sooner).
  double split_low = 0.03, split_high = 0.12;
  // The amplitude at which the period-2 branch is compared between methods (split_crossing).
  double split_level = 0.1;
  SweepSettings sweep{};
};

struct ThresholdMeasurement {
  double existence = std::numeric_limits<double>::quiet_NaN();
  double period_doubling = std::numeric_limits<double>::quiet_NaN();
  int fit_points = 0;
  double branch_crossing =
      std::numeric_limits<double>::quiet_NaN();  // split_crossing at split_level
  std::vector<SweepPoint> existence_window, period_doubling_window, period_doubling_return;
  std::string bisection_failure;  // the message of a failed bisection trial, if one failed
};

ThresholdMeasurement measure_thresholds(const MethodParams& method, double h, double e,
                                        const ThresholdSettings& settings);

}  // namespace impact::vibrating_table
