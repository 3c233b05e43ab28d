// Figure 3 (Section 5.2, f = 0): the key numbers of the two columns and an h sweep of the energy
// kept by the one impact. The trajectories themselves are written by `impact run` (experiment.mk).
//
// Usage: exp_figure3 SCENE_DIR RESULTS_DIR
//   reads SCENE_DIR/no_cor.toml and SCENE_DIR/cor075.toml, writes RESULTS_DIR/summary.toml,
//   RESULTS_DIR/labels.gp (the numbers the plot prints) and RESULTS_DIR/h_sweep.csv.
#include <toml++/toml.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "impact/output.hpp"
#include "analysis/rest.hpp"
#include "scene/read_scene.hpp"

namespace {

using namespace impact;

void write_file(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  std::fputs(text.c_str(), file.stream());
  file.commit();
}

// The numbers of one column of Figure 3.
toml::table column(const std::string& scene_path) {
  const Scene direct_scene = load_scene(scene_path, {"method.name=direct"});
  const auto direct = record(direct_scene);
  const auto fb_newton = record(load_scene(scene_path, {"method.name=fb_newton"}));
  const auto exact = record(load_scene(scene_path, {"method.name=exact"}));
  const ChannelDifference between = max_difference(direct, fb_newton);
  const ChannelDifference to_exact = max_difference(direct, exact);
  const double h = direct_scene.grid.h;

  const RunStats direct_stats = run_stats(direct, h), fb_newton_stats = run_stats(fb_newton, h),
                 exact_stats = run_stats(exact, h);

  return toml::table{
      {"max_diff_u", between.u},
      {"max_diff_v", between.v},
      {"max_diff_N", between.N},
      {"max_diff_E", between.E},
      {"max_error_u_direct", to_exact.u},
      {"energy_initial", direct.front().E},
      {"energy_final_direct", direct.back().E},
      {"energy_final_fb_newton", fb_newton.back().E},
      {"energy_final_exact", exact.back().E},
      {"energy_drift_direct", direct_stats.energy_drift},
      {"energy_drift_fb_newton", fb_newton_stats.energy_drift},
      {"peak_N_direct", direct_stats.peak_N},
      {"peak_N_time_direct", direct_stats.peak_t},
      {"peak_N_fb_newton", fb_newton_stats.peak_N},
      {"peak_N_exact", exact_stats.peak_N},
      {"peak_N_time_exact", exact_stats.peak_t},
      {"impulse_direct", direct_stats.impulse},
      {"impulse_exact", exact_stats.impulse},
      {"velocity_change_direct", direct.back().v - direct.front().v},
  };
}

// max_l |N_a - N_b| between the two columns for one method (and extra scene keys): the COR's
// effect on the contact force.
double cor_effect_on_force(const std::string& dir, const std::string& method,
                           std::vector<std::string> overrides = {}) {
  overrides.push_back("method.name=" + method);
  return max_difference(record(load_scene(dir + "/no_cor.toml", overrides)),
                        record(load_scene(dir + "/cor075.toml", overrides)))
      .N;
}

// The left column at step sizes that do not put the impact t* = 5 on the grid: the energy kept is
// (1 - 2 theta)^2 E^0 (paper_notes/restitution.md), theta from the scheme's own last free step.
std::string energy_sweep(const std::string& scene_path, toml::table& summary) {
  std::ostringstream csv;
  csv << "h,theta,energy_ratio_direct,energy_ratio_fb_newton,energy_ratio_predicted\n";
  constexpr int kSteps = 200;  // h = 10^(-4 + 2 i / 200), i = 0..200: 1e-4 .. 1e-2
  double worst_ratio = 1.0, worst_h = 0.0;
  for (int i = 0; i <= kSteps; ++i) {
    const double h = std::pow(10.0, -4.0 + 2.0 * i / kSteps);
    const std::string step = "time.h=" + impact::round_trip(h);
    const RestAnalysis direct = analyse_rest(load_scene(scene_path, {step, "method.name=direct"}));
    const RestAnalysis fb_newton =
        analyse_rest(load_scene(scene_path, {step, "method.name=fb_newton"}));
    const double theta = direct.episodes.front().linear_fraction;
    const double ratio = direct.energy_final / direct.energy_initial;
    csv << impact::round_trip(h) << ',' << impact::round_trip(theta) << ','
        << impact::round_trip(ratio) << ','
        << impact::round_trip(fb_newton.energy_final / fb_newton.energy_initial) << ','
        << impact::round_trip((1 - 2 * theta) * (1 - 2 * theta)) << '\n';
    if (ratio < worst_ratio) {
      worst_ratio = ratio;
      worst_h = h;
    }
  }
  summary.insert("h_sweep", toml::table{{"points", kSteps + 1},
                                        {"h_min", 1e-4},
                                        {"h_max", 1e-2},
                                        {"min_energy_ratio_direct", worst_ratio},
                                        {"h_of_min_energy_ratio", worst_h}});
  return csv.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: exp_figure3 SCENE_DIR RESULTS_DIR\n");
    return 2;
  }
  const std::string dir = argv[1], out = argv[2];
  try {
    toml::table summary;
    summary.insert("no_cor", column(dir + "/no_cor.toml"));
    summary.insert("cor075", column(dir + "/cor075.toml"));
    // At the paper's h the impact t* = 5 is on the grid (theta = 0); u0 one ulp above 5 moves it
    // just after the grid point; h = 6e-4 and 3e-4 put it at theta = 1/3 and 2/3 of a step.
    const std::string u0_up = "initial.u0=" + impact::round_trip(std::nextafter(5.0, 6.0));
    summary.insert(
        "cor_effect",
        toml::table{
            {"max_diff_N_direct", cor_effect_on_force(dir, "direct")},
            {"max_diff_N_fb_newton", cor_effect_on_force(dir, "fb_newton")},
            {"max_diff_N_direct_u0_plus_ulp", cor_effect_on_force(dir, "direct", {u0_up})},
            {"max_diff_N_direct_theta_third", cor_effect_on_force(dir, "direct", {"time.h=6e-4"})},
            {"max_diff_N_direct_theta_two_thirds",
             cor_effect_on_force(dir, "direct", {"time.h=3e-4"})}});
    // One step size that misses the grid: h = 3e-4 puts t* = 5 at 2/3 of step 16666.
    const RestAnalysis off_grid =
        analyse_rest(load_scene(dir + "/no_cor.toml", {"time.h=3e-4", "method.name=direct"}));
    const ContactEpisode& impact = off_grid.episodes.front();
    summary.insert("off_grid",
                   toml::table{
                       {"h", 3e-4},
                       {"theta", impact.linear_fraction},
                       {"energy_loss", impact.energy_before - impact.energy_after},
                       {"energy_loss_predicted", 2 * impact.linear_fraction * (1 - impact.linear_fraction) *
                                                     impact.speed_before * impact.speed_before},
                       {"energy_final", off_grid.energy_final},
                   });
    write_file(out + "/h_sweep.csv", energy_sweep(dir + "/no_cor.toml", summary));

    std::ostringstream toml_text;
    toml_text
        << "# Figure 3 (Section 5.2): measured by exp_figure3; see experiments/figure3/README.md\n"
        << summary << '\n';
    write_file(out + "/summary.toml", toml_text.str());

    // The numbers the plot prints in its titles.
    std::ostringstream labels;
    for (const char* scene : {"no_cor", "cor075"})
      for (const char* channel : {"u", "v", "N", "E"})
        labels << "diff_" << scene << "_" << channel << " = "
               << impact::round_trip(
                      *summary[scene][std::string("max_diff_") + channel].value<double>())
               << '\n';
    write_file(out + "/labels.gp", labels.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exp_figure3: %s\n", e.what());
    return 1;
  }
  return 0;
}
