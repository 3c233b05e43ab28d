// Lemma 3 (Section 4): the a priori bounds, the energy inequality (4-6) and the impulse bound after
// (4-9) over the 144 runs of lemma3_sweep(); the recipe is run_lemma3
// (src/analysis/lemma3/lemma3.hpp).
//
// Usage: exp_lemma3 [--source DIR] RESULTS_DIR. Writes RESULTS_DIR/runs.csv (one row per run) and
// RESULTS_DIR/summary.toml (the keys of experiments/lemma3/reference.toml).
#include "analysis/lemma3/lemma3.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::lemma3::kLemma3Experiment, IMPACT_SOURCE_DIR);
}
