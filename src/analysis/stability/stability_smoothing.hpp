// fb_newton over its smoothing parameter (experiments/stability): eps = 1e-15 .. 1e-2 against
// h = 1e-9 .. 1, on an elastic bounce and on resting contact, each run classified by
// check_stability.
#pragma once

#include <string>
#include <vector>

#include "analysis/stability/stability_runs.hpp"

namespace impact::stability {

struct SmoothingRun {
  std::size_t scene = 0;  // index into smoothing_scene_names()
  int log_eps = 0, log_h = 0;
  StabilityRun run;
};

struct SmoothingMap {
  std::vector<SmoothingRun> runs;  // scene, then eps, then h ascending
  // Over all runs: the largest iteration counts, and the runs that failed or broke the energy
  // bound E^{l+1} <= E^l + eps/2.
  int max_iterations = 0;
  double max_mean_iterations = 0;
  int failures = 0, energy_violations = 0;

  static SmoothingMap run();
  std::string csv() const;  // eps.csv
  std::string dat() const;  // map_eps.dat: scene_index log10_eps log10_h code, per scene
};

// "bounce", "rest"
const std::vector<std::string>& smoothing_scene_names();

}  // namespace impact::stability
