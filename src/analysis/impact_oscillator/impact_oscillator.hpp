// The experiment impact_oscillator: the forced impact oscillator u'' = -u - cos(omega t) + N,
// u >= phi, COR r (paper_notes/impact_oscillator.md), beyond the paper. Its period-one orbit in
// closed form against runs of the exact-flight reference (oscillator_law.hpp) and of the method
// event_driven on the force expression; the saddle-node and period-doubling thresholds in sigma and
// omega from the impact map's Jacobian against the runs; bifurcation diagrams with the closed-form
// branches; Nordmark's square-root law at grazing; chatter, its accumulation time and sticking;
// work against precision of every method that takes a force of the state.
#pragma once

#include <toml++/toml.h>

#include <optional>

#include "analysis/experiment.hpp"
#include "analysis/impact_oscillator/oscillator_diagram.hpp"
#include "analysis/impact_oscillator/oscillator_theory.hpp"
#include "analysis/work_precision.hpp"

namespace impact::impact_oscillator {

// The acceptance scene: omega = 2.8, r = 0.8, sigma = -0.5 (phi = 0.5) from u0 = 1, v0 = 0.
inline constexpr double kOmega = 2.8, kRestitution = 0.8, kSigma = -0.5;
inline constexpr double kAcceptanceT = 500;
inline const Oscillator kAcceptance{kOmega, kRestitution, kSigma};
inline constexpr State kAcceptanceStart{1.0, 0.0};

// Each piece writes its data files (when the context writes) and returns its summary table.
toml::table orbit_summary(const ExperimentContext& context);
toml::table branch_summary(const ExperimentContext& context, SweepParameter parameter);
toml::table thresholds_summary();
toml::table grazing_summary(const ExperimentContext& context);
toml::table chatter_summary(const ExperimentContext& context);
toml::table diagram_summary(const ExperimentContext& context);
// The work-precision scenes of experiments/impact_oscillator (periodic.toml, chaotic.toml); CPU
// times only with a timing rule (they go to work_precision.csv, not to the summary).
toml::table work_precision_summary(const ExperimentContext& context,
                                   const std::optional<TimingRule>& timing);

// The branch points: sigma in [-1.75, -0.10] (omega = 2.8) and omega in [2.15, 4.20]
// (sigma = -0.5), steps of 0.05, and those of them event_driven runs too.
std::vector<double> branch_values(SweepParameter parameter);
std::vector<double> event_driven_branch_values(SweepParameter parameter);

// The periodic work-precision scene's initial state: on the (1, 1) orbit at sigma = -0.5, its
// state at t = 0.
State periodic_scene_start();

toml::table run_impact_oscillator(const ExperimentContext& context,
                                  const std::optional<TimingRule>& timing);
// With timing when the context writes (the driver), without (the tests).
toml::table run_impact_oscillator(const ExperimentContext& context);

extern const Experiment kImpactOscillatorExperiment;

}  // namespace impact::impact_oscillator
