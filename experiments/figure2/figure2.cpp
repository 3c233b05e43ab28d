// Figure 2 (Section 5.1): the spline approximation S_eps of an impact; the recipe is run_figure2
// (src/analysis/figure2/figure2.hpp).
#include "analysis/figure2/figure2.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::figure2::kFigure2Experiment,
                                 IMPACT_SOURCE_DIR);
}
