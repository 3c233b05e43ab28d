// The paper's future work (Section 6): an error analysis of its schemes, checked by a campaign of
// random scenes. The recipe is run_error_analysis (src/analysis/error_analysis/error_analysis.hpp),
// which tests/test_error_analysis.cpp calls too.
#include "analysis/error_analysis/error_analysis.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::error_analysis::kErrorAnalysisExperiment,
                                 IMPACT_SOURCE_DIR);
}
