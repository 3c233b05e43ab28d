// The experiment vibrating_table: the bouncing ball on a sinusoidally vibrating table
// (vibrating_table_runs.hpp) as the paper's model with f(t) = -g + a omega^2 sin(omega t):
// bifurcation diagrams (impact phase against Gamma, continuation sweeps up and down) from the exact
// solution and from the time-steppers, the period-1 thresholds each method shows against the closed
// forms of paper_notes/vibrating_table.md, and one trajectory per regime.
#pragma once

#include <toml++/toml.h>

#include <array>
#include <cstddef>
#include <string_view>

#include "analysis/experiment.hpp"
#include "analysis/vibrating_table/vibrating_table_thresholds.hpp"

namespace impact::vibrating_table {

inline constexpr std::array<double, 2> kTableRestitutions{0.5, 0.8};
// The diagrams' range of Gamma and the step of each method's grid of Gamma.
inline constexpr double kTableGammaMin = 0.2, kTableGammaMax = 2.6;
inline constexpr double kTableExactGammaStep = 0.01, kTableStepperGammaStep = 0.02;
// Table periods per value of Gamma in a diagram, and how many of them are the transient: the
// sweep continues from the previous attractor, so a short transient suffices away from thresholds.
inline constexpr int kTableDiagramPeriods = 60, kTableDiagramTransient = 40;
// Events drawn per value of Gamma: a chatter's dozens of impacts at one phase need no more.
inline constexpr std::size_t kTableDiagramEvents = 64;
// The exact solution is sampled every 1/16 period (its events do not depend on the samples).
inline constexpr double kTableExactStep = 0.1 / 16;
inline constexpr std::array<std::string_view, 2> kTableSteppers{"direct", "moreau_jean"};
inline constexpr std::array<double, 2> kTableDiagramSteps{1e-3, 1e-4};
inline constexpr std::array<double, 4> kTableThresholdSteps{3e-3, 1e-3, 3e-4, 1e-4};

// The settings of measure_thresholds for a method at step h: exact with its fit on the way back
// down the period-2 branch and a tight classification, a time-stepper with the tolerance of its
// grid (one and a half steps of phase) and its fit on the upward sweep.
ThresholdSettings table_threshold_settings(std::string_view method, double h);

// The thresholds of exact (bisected to the end of its period-1 branch) and of each time-stepper at
// each of kTableThresholdSteps, for restitution e.
struct TableThresholds {
  double e = 0.0;
  ThresholdMeasurement exact;
  // [stepper][step]
  std::array<std::array<ThresholdMeasurement, kTableThresholdSteps.size()>, kTableSteppers.size()>
      steppers;
};
TableThresholds measure_table_thresholds(double e);

// The summary's table for one restitution (the keys of reference.toml under e_0_5, e_0_8).
toml::table table_thresholds_summary(const TableThresholds& t);

toml::table run_vibrating_table(const ExperimentContext& context);

extern const Experiment kVibratingTableExperiment;

}  // namespace impact::vibrating_table
