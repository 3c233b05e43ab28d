// The sweeps of experiments/error_analysis: each statement of paper_notes/error_analysis.md on
// fixed scenes over h, measured by the campaign's own checks (error_checks.hpp) so that the
// figures draw what the campaign checks:
//   flight.csv      Statement 1: f(t) = -g + 30 sin(5 t + 0.3) before the first impact (direct,
//                   moreau_jean, the bound of Lemma 1.2); fb_newton's smoothing before Figure 4's
//                   first impact (Lemma 1.3)
//   impact.csv      Statement 2: Figure 4's first impact (COR 0.75, and without COR) at 300 h:
//                   theta, the errors one step later, their bounds, the effective COR
//   zeno.csv        Statement 3 on Figure 4 with COR 0.75 over h: sup error, rest time, impacts
//   zeno_k_<i>.csv  Statement 3 impact by impact at h = 1e-2, 1e-3, 1e-4 (i = 2, 3, 4)
//   no_cor.csv      Statement 4 on the off-grid scene (f = 0, t* = pi): direct's error at T and its
//                   lower bound, moreau_jean's sup error and its bound
//   located.csv     direct_located against direct and moreau_jean on Figure 3, Figure 4 (COR) and
//                   the period-1 vibrating table, over the work-precision steps
#pragma once

#include <toml++/toml.h>

#include "analysis/experiment.hpp"

namespace impact::error_analysis {

struct ErrorSweepOptions {
  int impact_points = 300;  // h values of impact.csv
  int sweep_points = 20;    // h values of zeno.csv and no_cor.csv
  double located_h_min = 1e-5;
};

// Writes the files above and returns their key numbers (located's order, the largest ratios).
toml::table run_sweeps(const ExperimentContext& context, const ErrorSweepOptions& options);

}  // namespace impact::error_analysis
