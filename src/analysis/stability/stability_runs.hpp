// One run of the stability maps (experiments/stability): the scene's check_stability with its
// duration and wall time, and how the map files and the CSV files write it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/stability/stability.hpp"
#include "impact/run/scene.hpp"

namespace impact::stability {

// The body force of the gravity scenes of the study: f = -g.
inline constexpr double kGravity = -9.80665;
// Grid steps per run of the maps (penalty: fewer, it costs ~1 us per step): a run at step h covers
// min(T, max_steps h), so the smallest steps see the start of a scene only.
inline constexpr double kMaxSteps = 1e5, kMaxPenaltySteps = 2e4;

struct StabilityRun {
  StabilityCheck check;
  double T = 0, h = 0;
  double seconds = 0;  // wall time of the run on this machine: the CSV files only
};

// check_stability of the scene, timed.
StabilityRun run_stability_check(const Scene& scene, const StabilityOptions& options = {});

// The CSV columns of a run, after the columns its caller puts first ("h,T,...,message\n").
extern const std::string_view kStabilityRunColumns;
// prefix (the caller's columns, without the trailing comma), then the run's columns.
std::string stability_csv_row(const std::string& prefix, const StabilityRun& run);

// One point of a map for plot.gp: the indices of its cell, then the outcome's code.
std::string map_point(const std::vector<int>& indices, Outcome outcome);

}  // namespace impact::stability
