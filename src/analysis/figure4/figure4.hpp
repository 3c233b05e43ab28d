// Figure 4 (Section 5.2, f = -9.80665, u0 = 5, v0 = -1, T = 10), the experiment: when the particle
// comes to rest and how much energy it loses, for `direct` (5-1) and `fb_newton` (5-3) against the
// exact solution, at the paper's h = 1e-3, over a sweep of h, and over an ensemble of u0 moved by
// a few ulps. The h = 1e-3 trajectories themselves are written by `impact run` (experiment.mk).
#pragma once

#include <toml++/toml.h>

#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "analysis/experiment.hpp"
#include "analysis/figure4/figure4_readings.hpp"
#include "analysis/rest.hpp"
#include "impact/run/scene.hpp"

namespace impact::figure4 {

// The columns of the figure (experiments/figure4/<scene>.toml) and the two schemes.
inline constexpr std::array<std::string_view, 2> kFigure4Scenes = {"no_cor", "cor075"};
inline constexpr std::array<std::string_view, 2> kFigure4Methods = {"direct", "fb_newton"};

struct Figure4Options {
  // The sweep: h = 10^-(2 + i/n), i = 0..3n, from 1e-2 to 1e-5, n = sweep_per_decade (a multiple
  // of 4). Its quarter decades, h = 10^-(2 + k/4), k = 0..12, go into summary.toml; n = 4 computes
  // only those (the sweep's minima, maxima and order in summary.toml are then over 13 points).
  int sweep_per_decade = 40;
};

// One column at the scene's own h = 1e-3.
struct Figure4Column {
  Scene scene;                   // the scene file, method `direct`
  RestAnalysis rest[2];          // [method] as in kFigure4Methods
  ChannelDifference difference;  // max_l |direct - fb_newton| of each channel
};

struct Figure4SweepRow {
  double h = 0;
  RestAnalysis run[2][2];  // [scene][method]
};

struct Figure4Data {
  Figure4Column column[2];  // [scene]
  int sweep_per_decade = 0;
  std::vector<Figure4SweepRow> sweep;
  // u0 moved by k ulps, k = -200..200, at h = 1e-3, and the rest time of each member (none: it
  // still bounces at T).
  std::vector<double> ensemble_u0;
  std::vector<std::optional<double>> ensemble_rest[2][2];  // [scene][method]
  // The same runs in the alternative arithmetic or reading, and C32's contact step
  // (figure4_readings.hpp).
  Figure4Readings readings;
};

Figure4Data figure4_data(const ExperimentContext& context, const Figure4Options& options = {});

// The energy removed by the first contact episode.
double first_impact_loss(const RestAnalysis& analysis);

// The key numbers of figure4_data (reference.toml's keys), and the files plot.gp reads besides the
// trajectories: h_sweep.csv, ensemble.csv, contact_energy.csv and labels.gp (the numbers in titles
// and keys).
toml::table run_figure4(const ExperimentContext& context, const Figure4Options& options = {});

extern const Experiment kFigure4Experiment;

}  // namespace impact::figure4
