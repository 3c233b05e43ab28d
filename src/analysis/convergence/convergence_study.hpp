// Section 4: does u_h of the scheme (4-1)-(4-3) converge, and to what, as h -> 0? The sup-norm
// error on the grid against the exact solution, the effective COR of the first impact, and the
// discrete identities (4-9) and (4-10) of the existence proof, over a sweep of h, for the direct
// scheme and for moreau_jean on the same data (the series). Then the subsequences
// h = t* / (m + theta) with a fixed fraction theta of the step before the impact: each converges,
// at first order, to the exact solution with COR = |1 - 2 theta|.
//
// run_convergence writes to the results directory:
//   series_<name>.csv       h, theta, sup_u, effective_cor, impulse, res49_printed,
//                           res49_corrected, compl410, energy_drop, energy_loss (one row per h)
//   subsequence_<name>.csv  m, h, theta, effective_cor, sup_u (against the exact solution with
//                           COR |1 - 2 theta|)
//   path_theta_<k>.csv      t, u_h, u_exact for theta = 0, 1/4, 1/2, 3/4 (k = 0..3) at m = 250,
//                           with the exact solution of COR |1 - 2 theta| on the same grid
// and returns the numbers of experiments/convergence/reference.toml.
#pragma once

#include <toml++/toml.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/convergence/proof_tallies.hpp"
#include "analysis/experiment.hpp"
#include "analysis/fit.hpp"
#include "analysis/step_sweep.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/model/model.hpp"

namespace impact::convergence {

inline constexpr double kConvergenceT = 10.0;  // the paper's T
// u0 = 5.0123 m, v0 = -1 m/s, f = 0: the first impact at t* = 5.0123 s, off the grid for generic
// h (on it for h = 1e-6: t* = 5012300 h).
inline constexpr double kOffGridU0 = 5.0123;

// What run_convergence computes; the defaults are the experiment.
struct ConvergenceOptions {
  StepSweep free{2e-2, 1e-6, 20};  // the f = 0 series
  // Under gravity the exact reference costs more per step (~300 ns), so the sweep stops at 1e-5.
  StepSweep gravity{2e-2, 1e-5, 16};
  // The subsequences' m (h = t* / (m + theta)).
  std::vector<std::int64_t> subsequence_m = {250,   500,   1000,   2500,   5000,    10000,
                                             25000, 50000, 100000, 250000, 1000000, 5000000};
  // Only the h >= h_floor of each series and subsequence are run (0: all): the first rows of the
  // experiment, for a test.
  double h_floor = 0;
};

// One series: a method on one scene over a sweep of h.
struct ConvergenceSeries {
  std::string name, label;
  MethodParams method;
  Model model;
  State initial;
  std::vector<double> h;
};
// f0_direct_aligned (u0 = 5, h = 5/m: the impact on the grid), f0_direct, f0_direct_cor, f0_mj,
// f0_mj_cor (u0 = 5.0123, f = 0), g_direct, g_direct_cor, g_mj, g_mj_cor (u0 = 5, gravity);
// COR 0.75 where named _cor.
std::vector<ConvergenceSeries> convergence_series(const ConvergenceOptions& options);

// The runs of a series, and the order fitted to their sup errors. On the off-grid scene a step
// that puts the first impact on a grid point (theta within 1e-6 of 0 or 1) is a different regime
// (no COR: an elastic bounce; COR: no error at all): it is left out of the fit.
struct SeriesRun {
  std::vector<ConvergencePoint> points;  // one per h, in the series' order
  OrderFit fit;
  std::size_t on_grid_left_out = 0;
};
SeriesRun run_series(const ConvergenceSeries& series);

// The subsequence h = t* / (m + theta) of direct without COR on the off-grid scene, each run
// measured against the exact solution with COR |1 - 2 theta|.
struct SubsequenceRun {
  double theta = 0, limit_cor = 0;
  std::vector<std::int64_t> m;
  std::vector<ConvergencePoint> points;
  OrderFit fit;
  double limit_distance_to_elastic = 0;  // sup |u_limit - u_elastic| on [0, T]
};
SubsequenceRun run_subsequence(double theta, const std::vector<std::int64_t>& m);

// The whole experiment: the series and the subsequences with their data files, and the table of
// summary.toml.
toml::table run_convergence(const ExperimentContext& context, const ConvergenceOptions& options);
toml::table run_convergence(const ExperimentContext& context);

extern const Experiment kConvergenceExperiment;

}  // namespace impact::convergence
