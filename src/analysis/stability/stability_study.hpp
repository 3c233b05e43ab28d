// experiments/stability: every solver driven to its limits. The extreme cases (every method over
// h = 1e-9 .. 1, stability_cases.hpp), fb_newton over its smoothing parameter
// (stability_smoothing.hpp) and penalty as c_N grows (stability_stiffness.hpp), each run
// classified by check_stability (stability.hpp).
#pragma once

#include <toml++/toml.h>

#include "analysis/experiment.hpp"

namespace impact::stability {

// What to run; the defaults are the experiment. A cheaper run leaves out the sweeps whose
// summary keys are totals over them, and reports only the keys it reproduces.
struct StabilityStudyOptions {
  // The extreme-case map (950 runs) and its [outcomes]; without it only the two runs the summary
  // names are made.
  bool case_map = true;
  // fb_newton over eps x h (280 runs) and its [eps] table.
  bool smoothing_map = true;
  // Penalty over every c_N (bounce and rest), its rest_largest_c_N and the c_N x h map; without
  // them, only the bounce at c_N = 1e6 and 1e12 and resting contact at 1e6.
  bool stiffness_maps = true;
};

// Writes to the context's results directory: cases.csv, map_cases.dat (the extreme cases),
// eps.csv, map_eps.dat (the smoothing), stiff.csv, map_stiff.dat, penalty_h.csv,
// map_penalty.dat (penalty), labels.gp (tic labels for plot.gp) and table.md (the tables of the
// extreme cases). Returns the summary (reference.toml's keys).
toml::table run_stability(const ExperimentContext& context);
toml::table run_stability(const ExperimentContext& context, const StabilityStudyOptions& options);

extern const Experiment kStabilityExperiment;

}  // namespace impact::stability
