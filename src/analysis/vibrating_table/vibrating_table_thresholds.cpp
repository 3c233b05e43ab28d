#include "analysis/vibrating_table/vibrating_table_thresholds.hpp"

#include "analysis/vibrating_table/vibrating_table_theory.hpp"

namespace impact::vibrating_table {

ThresholdMeasurement measure_thresholds(const MethodParams& method, double h, double e,
                                        const ThresholdSettings& settings) {
  ThresholdMeasurement m;
  const double g1 = period_one_existence_threshold(e, 1), gpd = period_doubling_threshold(e, 1);

  const double pd_bottom = gpd - settings.below_pd;
  SweepSettings pd_sweep = settings.sweep;
  pd_sweep.periods = settings.period_doubling_periods;
  pd_sweep.transient = settings.period_doubling_transient;
  pd_sweep.kick = settings.kick;
  m.period_doubling_window =
      sweep_table(table_scene_on_orbit(pd_bottom, e), method, h,
                  gamma_grid(pd_bottom, gpd + settings.above_pd, settings.step), pd_sweep);
  m.branch_crossing = split_crossing(m.period_doubling_window, settings.split_level);
  // The onset is fitted on a sweep back down the period-2 branch, from the first point of the
  // upward sweep past split_high: approached from above, each split settles from the larger one of
  // the previous Gamma, whereas going up it grows from the smaller one, and the critical slowing
  // down near the onset leaves it short (the fit on the upward sweep is later by ~5e-4 for exact
  // at e = 0.5).
  const std::vector<SweepPoint>& up = m.period_doubling_window;
  std::size_t past = 0;
  while (past < up.size() && !(up[past].classification.split > settings.split_high)) ++past;
  if (settings.fit_from_above && past < up.size()) {
    m.period_doubling_return = sweep_table(
        up[past].end, method, h,
        gamma_grid(up[past].gamma - settings.step, pd_bottom, -settings.step), pd_sweep);
    m.period_doubling = fit_period_doubling(m.period_doubling_return, settings.split_low,
                                            settings.split_high, &m.fit_points);
  } else {
    m.period_doubling =
        fit_period_doubling(up, settings.split_low, settings.split_high, &m.fit_points);
  }

  // A third of a step above the grid of Gamma_1 + k step, so that neither a point of the sweep nor
  // the first midpoint of the bisection falls on the saddle-node itself.
  const double top = g1 + settings.above_existence + settings.step / 3;
  m.existence_window =
      sweep_table(table_scene_on_orbit(top, e), method, h,
                  gamma_grid(top, g1 - settings.below_existence, -settings.step), settings.sweep);
  std::size_t last = 0, next = 0;
  m.existence = lowest_period_one(m.existence_window, &last, &next);
  if (m.existence == m.existence && settings.bisections > 0) {
    SweepSettings trial = settings.sweep;
    trial.periods = settings.bisection_periods;
    trial.transient =
        settings.bisection_periods - (settings.sweep.periods - settings.sweep.transient);
    trial.tolerance = settings.bisection_tolerance;
    m.existence =
        bisect_period_one_end(m.existence_window[last], m.existence_window[next].gamma, method, h,
                              trial, settings.bisections, &m.bisection_failure);
  }
  return m;
}

}  // namespace impact::vibrating_table
