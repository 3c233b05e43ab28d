// Figure 4 (Section 5.2, f = -9.80665): rest time and energy loss of `direct` and `fb_newton`
// against the exact solution at h = 1e-3, over an h sweep and over an ensemble of u0 perturbed by a
// few ulps; the recipe is run_figure4 (src/analysis/figure4/figure4.hpp).
//
// Usage: exp_figure4 [--source DIR] RESULTS_DIR. Reads experiments/figure4/{no_cor,cor075}.toml
// of DIR, writes RESULTS_DIR/summary.toml, h_sweep.csv, ensemble.csv and labels.gp.
#include "analysis/figure4/figure4.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::figure4::kFigure4Experiment,
                                 IMPACT_SOURCE_DIR);
}
