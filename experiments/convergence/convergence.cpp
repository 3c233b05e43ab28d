// Section 4: does u_h of (4-1)-(4-3) converge as h -> 0? The recipe is run_convergence
// (src/analysis/convergence/convergence_study.hpp), which tests/test_convergence.cpp calls too.
#include "analysis/convergence/convergence_study.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::convergence::kConvergenceExperiment,
                                 IMPACT_SOURCE_DIR);
}
