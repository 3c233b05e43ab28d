// The forced impact oscillator u'' = -u - cos(omega t) + N, u >= phi, COR r: period-one orbits in
// closed form against runs, their thresholds, bifurcation diagrams, grazing, chatter and
// work-precision; the recipe is run_impact_oscillator
// (src/analysis/impact_oscillator/impact_oscillator.hpp).
//
// Usage: exp_impact_oscillator [--source DIR] RESULTS_DIR. Writes RESULTS_DIR/summary.toml (the
// keys of experiments/impact_oscillator/reference.toml) and the CSV files plot.gp reads.
#include "analysis/impact_oscillator/impact_oscillator.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::impact_oscillator::kImpactOscillatorExperiment,
                                 IMPACT_SOURCE_DIR);
}
