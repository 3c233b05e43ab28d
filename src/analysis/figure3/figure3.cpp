#include "analysis/figure3/figure3.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "impact/methods/capabilities.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/scene.hpp"
#include "scene/read_scene.hpp"

namespace impact::figure3 {
namespace {

toml::table column_table(const Figure3Column& c) {
  return toml::table{
      {"max_diff_u", c.direct_vs_fb_newton.u},
      {"max_diff_v", c.direct_vs_fb_newton.v},
      {"max_diff_N", c.direct_vs_fb_newton.N},
      {"max_diff_E", c.direct_vs_fb_newton.E},
      {"max_error_u_direct", c.direct_vs_exact.u},
      {"energy_initial", c.direct.front().E},
      {"energy_final_direct", c.direct.back().E},
      {"energy_final_fb_newton", c.fb_newton.back().E},
      {"energy_final_exact", c.exact.back().E},
      {"energy_drift_direct", c.direct_stats.energy_drift},
      {"energy_drift_fb_newton", c.fb_newton_stats.energy_drift},
      {"peak_N_direct", c.direct_stats.peak_N},
      {"peak_N_time_direct", c.direct_stats.peak_t},
      {"peak_N_fb_newton", c.fb_newton_stats.peak_N},
      {"peak_N_exact", c.exact_stats.peak_N},
      {"peak_N_time_exact", c.exact_stats.peak_t},
      {"impulse_direct", c.direct_stats.impulse},
      {"impulse_exact", c.exact_stats.impulse},
      {"velocity_change_direct", c.direct.back().v - c.direct.front().v},
  };
}

// At the paper's h the impact t* = 5 is on the grid (theta = 0); u0 one ulp above 5 moves it
// just after the grid point; h = 6e-4 and 3e-4 put it at theta = 1/3 and 2/3 of a step.
toml::table cor_effect_table(const ExperimentContext& context) {
  return toml::table{
      {"max_diff_N_direct", cor_effect_on_force(context, "direct")},
      {"max_diff_N_fb_newton", cor_effect_on_force(context, "fb_newton")},
      {"max_diff_N_direct_u0_plus_ulp",
       cor_effect_on_force(context, "direct", {}, std::nextafter(5.0, 6.0))},
      {"max_diff_N_direct_theta_third", cor_effect_on_force(context, "direct", 6e-4)},
      {"max_diff_N_direct_theta_two_thirds", cor_effect_on_force(context, "direct", 3e-4)}};
}

// By (4-6) the impact at theta removes N^l (u^l - phi) = 2 theta (1 - theta) v^2 (f = 0).
toml::table off_grid_table(const ExperimentContext& context) {
  const RestAnalysis off_grid = figure3_off_grid(context);
  const ContactEpisode& impact = off_grid.episodes.front();
  const double theta = impact.linear_fraction;
  return toml::table{
      {"h", kFigure3OffGridH},
      {"theta", theta},
      {"energy_loss", impact.energy_before - impact.energy_after},
      {"energy_loss_predicted",
       2 * theta * (1 - theta) * impact.speed_before * impact.speed_before},
      {"energy_final", off_grid.energy_final},
  };
}

// The left column at step sizes that do not put the impact t* = 5 on the grid: the energy kept is
// (1 - 2 theta)^2 E^0 (paper_notes/restitution.md), theta from the scheme's own last free step.
// Returns the sweep's summary; writes h_sweep.csv.
toml::table energy_sweep(const ExperimentContext& context) {
  std::ostringstream csv;
  csv << "h,theta,energy_ratio_direct,energy_ratio_fb_newton,energy_ratio_predicted\n";
  constexpr int kSteps = 200;  // h = 10^(-4 + 2 i / 200), i = 0..200: 1e-4 .. 1e-2
  double worst_ratio = 1.0, worst_h = 0.0;
  for (int i = 0; i <= kSteps; ++i) {
    const double h = std::pow(10.0, -4.0 + 2.0 * i / kSteps);
    const RestAnalysis direct = analyse_rest(figure3_scene(context, {"no_cor", "direct", h}));
    const RestAnalysis fb_newton = analyse_rest(figure3_scene(context, {"no_cor", "fb_newton", h}));
    const double theta = direct.episodes.front().linear_fraction;
    const double ratio = direct.energy_final / direct.energy_initial;
    csv << round_trip(h) << ',' << round_trip(theta) << ',' << round_trip(ratio) << ','
        << round_trip(fb_newton.energy_final / fb_newton.energy_initial) << ','
        << round_trip((1 - 2 * theta) * (1 - 2 * theta)) << '\n';
    if (ratio < worst_ratio) {
      worst_ratio = ratio;
      worst_h = h;
    }
  }
  context.write("h_sweep.csv", [&] { return csv.str(); });
  return toml::table{{"points", kSteps + 1},
                     {"h_min", 1e-4},
                     {"h_max", 1e-2},
                     {"min_energy_ratio_direct", worst_ratio},
                     {"h_of_min_energy_ratio", worst_h}};
}

// The numbers the plot prints in its titles: max_l |direct - fb_newton| of each channel.
std::string labels(const toml::table& summary) {
  std::ostringstream text;
  for (const char* scene : {"no_cor", "cor075"})
    for (const char* channel : {"u", "v", "N", "E"})
      text << "diff_" << scene << "_" << channel << " = "
           << round_trip(*summary[scene][std::string("max_diff_") + channel].value<double>())
           << '\n';
  return text.str();
}

}  // namespace

Scene figure3_scene(const ExperimentContext& context, const Figure3Run& run) {
  Scene scene = load_scene(context.scene_path("figure3", std::string(run.name) + ".toml"));
  const MethodInfo* method = find_method(run.method);
  if (method == nullptr)
    throw std::invalid_argument("figure3: unknown method '" + std::string(run.method) + "'");
  scene.method = method->defaults;
  if (run.h) scene.grid = Grid::covering(scene.T, *run.h);
  if (run.u0) scene.initial.u = *run.u0;
  return scene;
}

Figure3Column figure3_column(const ExperimentContext& context, std::string_view name) {
  Figure3Column c;
  const Scene direct = figure3_scene(context, {name, "direct"});
  c.direct = record(direct);
  c.fb_newton = record(figure3_scene(context, {name, "fb_newton"}));
  c.exact = record(figure3_scene(context, {name, "exact"}));
  c.direct_vs_fb_newton = max_difference(c.direct, c.fb_newton);
  c.direct_vs_exact = max_difference(c.direct, c.exact);
  const double h = direct.grid.h;
  c.direct_stats = run_stats(c.direct, h);
  c.fb_newton_stats = run_stats(c.fb_newton, h);
  c.exact_stats = run_stats(c.exact, h);
  return c;
}

double cor_effect_on_force(const ExperimentContext& context, std::string_view method,
                           std::optional<double> h, std::optional<double> u0) {
  return max_difference(record(figure3_scene(context, {"no_cor", method, h, u0})),
                        record(figure3_scene(context, {"cor075", method, h, u0})))
      .N;
}

RestAnalysis figure3_off_grid(const ExperimentContext& context) {
  return analyse_rest(figure3_scene(context, {"no_cor", "direct", kFigure3OffGridH}));
}

toml::table run_figure3(const ExperimentContext& context) {
  toml::table summary;
  summary.insert("no_cor", column_table(figure3_column(context, "no_cor")));
  summary.insert("cor075", column_table(figure3_column(context, "cor075")));
  summary.insert("cor_effect", cor_effect_table(context));
  summary.insert("off_grid", off_grid_table(context));
  summary.insert("h_sweep", energy_sweep(context));
  context.write("labels.gp", [&] { return labels(summary); });
  return summary;
}

const Experiment kFigure3Experiment{
    "figure3", "Figure 3 (Section 5.2): f = 0, without and with COR = 0.75", &run_figure3};

}  // namespace impact::figure3
