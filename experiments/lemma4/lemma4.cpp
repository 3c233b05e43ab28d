// Lemma 4 (uniqueness) and its proof (4-11)-(4-13). The recipe is run_lemma4
// (src/analysis/lemma4/lemma4.hpp), which tests/test_lemma4.cpp calls too.
#include "analysis/lemma4/lemma4.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::lemma4::kLemma4Experiment, IMPACT_SOURCE_DIR);
}
