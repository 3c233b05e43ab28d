// Figure 3 (Section 5.2, f = 0, u0 = 5, v0 = -1, T = 10, h = 1e-3): the key numbers of its two
// columns (experiments/figure3/no_cor.toml, cor075.toml), the COR's effect on the contact force,
// one step size that misses the impact, and an h sweep of the energy kept by the one impact. The
// trajectories the figure draws are written by `impact run` (experiments/figure3/experiment.mk).
#pragma once

#include <toml++/toml.h>

#include <optional>
#include <string_view>
#include <vector>

#include "analysis/experiment.hpp"
#include "analysis/rest.hpp"
#include "impact/run/scene.hpp"

namespace impact::figure3 {

// Figure 3's scene `name` (no_cor or cor075) solved by `method` (a name of capabilities.hpp), with
// the step h and the initial height u0 changed when given.
struct Figure3Run {
  std::string_view name;
  std::string_view method;
  std::optional<double> h = {}, u0 = {};
};
Scene figure3_scene(const ExperimentContext& context, const Figure3Run& run);

// One column at the scene's own h: the three methods' runs and what the figure compares.
struct Figure3Column {
  std::vector<Sample> direct, fb_newton, exact;
  ChannelDifference direct_vs_fb_newton, direct_vs_exact;
  RunStats direct_stats, fb_newton_stats, exact_stats;
};
Figure3Column figure3_column(const ExperimentContext& context, std::string_view name);

// max_l |N_no_cor - N_cor075| for one method (and h, u0 when given): the COR's effect on the
// contact force.
double cor_effect_on_force(const ExperimentContext& context, std::string_view method,
                           std::optional<double> h = {}, std::optional<double> u0 = {});

// The left column by `direct` at h = 3e-4, which puts t* = 5 at theta = 2/3 of step 16666.
inline constexpr double kFigure3OffGridH = 3e-4;
RestAnalysis figure3_off_grid(const ExperimentContext& context);

// The key numbers (the keys of experiments/figure3/reference.toml). Writes h_sweep.csv (h, theta,
// the energy kept by direct and fb_newton, and (1 - 2 theta)^2) and labels.gp (the differences
// the plot prints in its titles).
toml::table run_figure3(const ExperimentContext& context);

extern const Experiment kFigure3Experiment;

}  // namespace impact::figure3
