// Lemma 5 (Section 5.1): N_eps = S''/6 paired with smooth test functions; the recipe is
// run_lemma5 (src/analysis/lemma5/lemma5.hpp).
#include "analysis/lemma5/lemma5.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::lemma5::kLemma5Experiment, IMPACT_SOURCE_DIR);
}
