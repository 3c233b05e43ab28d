// Figure 3 (Section 5.2, f = 0): the key numbers of the two columns and an h sweep of the energy
// kept by the one impact; the recipe is run_figure3 (src/analysis/figure3/figure3.hpp). The
// trajectories themselves are written by `impact run` (experiment.mk).
#include "analysis/figure3/figure3.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::figure3::kFigure3Experiment,
                                 IMPACT_SOURCE_DIR);
}
