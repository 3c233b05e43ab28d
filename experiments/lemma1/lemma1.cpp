// Lemma 1 (Section 3): (L E)(s) = E(0) / s for s > 1, checked on the exact solution and on the
// direct scheme with the scenes of Figures 3 and 4; the recipe is run_lemma1
// (src/analysis/lemma1/lemma1.hpp).
//
// Usage: exp_lemma1 [--source DIR] RESULTS_DIR. Writes RESULTS_DIR/deviation.csv,
// RESULTS_DIR/energy_<case>.csv and RESULTS_DIR/summary.toml (the keys of
// experiments/lemma1/reference.toml).
#include "analysis/lemma1/lemma1.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::lemma1::kLemma1Experiment, IMPACT_SOURCE_DIR);
}
