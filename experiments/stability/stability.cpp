// exp_stability RESULTS_DIR: the stability study (src/analysis/stability/stability_study.hpp).
#include "analysis/stability/stability_study.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::stability::kStabilityExperiment,
                                 IMPACT_SOURCE_DIR);
}
