// The ball on a vibrating table: bifurcation diagrams from the exact solution and the
// time-steppers, the period-1 thresholds each method shows against the closed forms, and one
// trajectory per regime; the recipe is run_vibrating_table
// (src/analysis/vibrating_table/vibrating_table.hpp).
//
// Usage: exp_vibrating_table [--source DIR] RESULTS_DIR. Writes RESULTS_DIR/diagram.csv,
// regimes.csv, thresholds.csv, trajectories.csv and summary.toml (the keys of
// experiments/vibrating_table/reference.toml).
#include "analysis/vibrating_table/vibrating_table.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::vibrating_table::kVibratingTableExperiment,
                                 IMPACT_SOURCE_DIR);
}
