#include "analysis/work_precision/work_precision_study.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "analysis/markdown.hpp"
#include "analysis/work_precision/work_precision_report.hpp"
#include "analysis/work_precision_lyapunov.hpp"
#include "impact/output/csv.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/scene.hpp"

namespace impact::work_precision {
namespace {

// The scene whose `direct` curve shows why direct without COR does not converge.
constexpr std::string_view kMechanismScene = "offgrid_no_cor";
// The chaotic scene, whose horizon T is checked against its Lyapunov time, measured over
// kLyapunovHorizon on the grid kLyapunovStep.
constexpr std::string_view kChaoticScene = "table_chaotic";
constexpr double kLyapunovHorizon = 20.0, kLyapunovStep = 1e-3;

// lyapunov.csv and the summary's [<scene>.lyapunov].
toml::table lyapunov_summary(const ExperimentContext& context, const Scene& scene) {
  const LyapunovEstimate estimate = estimate_lyapunov(scene, kLyapunovHorizon, kLyapunovStep);
  context.write("lyapunov.csv", [&] { return lyapunov_csv(estimate); });
  return toml::table{{"lambda", estimate.lambda},
                     {"lyapunov_time", estimate.lyapunov_time},
                     {"horizon_T", scene.T},
                     {"fitted_until", estimate.fitted_until},
                     {"delta0", estimate.delta0}};
}

std::string point_columns(const WorkPrecisionPoint& p) {
  return round_trip(p.h) + "," + round_trip(p.tolerance);
}

std::string errors_columns(const WorkPrecisionPoint& p) {
  std::string text;
  for (const ErrorMeasure m : kErrorMeasures) {
    text += ',';  // not "," + ...: GCC 12 gives a false -Wrestrict on a literal + std::string
    text += round_trip(error_of(p.errors, m));
  }
  return text;
}

// curves/<scene>.<curve>.csv
std::string curve_csv(const Curve& c) {
  std::string text = "h,tolerance,cost_min,cost_median,sup_u,l1_v,energy_end,first_impact\n";
  for (const auto& p : c.points)
    text += point_columns(p) + "," + round_trip(p.cost.min) + "," + round_trip(p.cost.median) +
            errors_columns(p) + "\n";
  return text;
}

// The rows of points.csv for one curve.
std::string points_rows(const std::string& scene, const Curve& c) {
  std::string text;
  for (const auto& p : c.points)
    text += scene + "," + c.name + "," + point_columns(p) + "," + std::to_string(p.steps) +
            errors_columns(p) + "," + round_trip(p.cost.min) + "," + round_trip(p.cost.median) +
            "," + std::to_string(p.cost.repetitions) + "," + std::to_string(p.cost.batch) + "\n";
  return text;
}

// The peer against the method it implements, at the same h: the same scheme, so the same error;
// the ratio of costs is the ratio at equal error.
toml::table peer_comparison(const std::vector<Curve>& curves, const PeerSolver& peer, bool timed) {
  const auto named = [&](const std::string& name) -> const Curve& {
    return *std::find_if(curves.begin(), curves.end(),
                         [&](const Curve& c) { return c.name == name; });
  };
  double max_difference = 0;
  std::vector<double> ratios;
  for (const auto& s : named(peer.name).points)
    for (const auto& m : named(peer.same_as).points)
      if (m.h == s.h) {
        max_difference = std::fmax(max_difference, std::fabs(s.errors.sup_u - m.errors.sup_u));
        ratios.push_back(s.cost.min / m.cost.min);
      }
  toml::table t{{"max_sup_u_difference", max_difference}};
  if (timed && !ratios.empty()) {
    std::sort(ratios.begin(), ratios.end());
    t.insert("cost_ratio_min", ratios.front());
    t.insert("cost_ratio_median", ratios[ratios.size() / 2]);
    t.insert("cost_ratio_max", ratios.back());
  }
  return t;
}

// `exact`'s own cost: a row of orders.md's second table and the scene's [exact] summary.
std::string exact_row(const WorkPrecisionScene& spec, const ExactCost& cost,
                      toml::table& scene_summary) {
  const double per_point = cost.solve.min / static_cast<double>(cost.grid_points) * 1e9;
  scene_summary.insert("exact", toml::table{{"solve_seconds", cost.solve.min},
                                            {"ns_per_grid_point", per_point},
                                            {"ns_per_impact", cost.seconds_per_impact * 1e9}});
  return "| " + spec.name + " | " + cost.method + " | " + short_number(cost.solve.min) + " s | " +
         short_number(per_point) + " ns | " + short_number(cost.seconds_per_impact * 1e9) +
         " ns |\n";
}

// The mechanism of direct's non-convergence without COR: its energy error on the off-grid scene
// (the `direct` curve) against the prediction, at every swept step.
toml::table direct_mechanism(const ExperimentContext& context, const Scene& scene,
                             const Curve& direct) {
  const ExactSolution exact(scene.model, scene.initial);
  const double t_impact = *exact.impact_time(1), speed = *exact.impact_speed(1);
  std::string csv = "h,theta,effective_cor,predicted_energy_loss,measured_energy_error\n";
  double max_mismatch = 0;
  for (const auto& p : direct.points) {
    const auto pred = predict_direct_impact(t_impact, speed, p.h);
    csv += round_trip(p.h) + "," + round_trip(pred.theta) + "," + round_trip(pred.effective_cor) +
           "," + round_trip(pred.energy_loss) + "," + round_trip(p.errors.energy_end) + "\n";
    max_mismatch = std::fmax(max_mismatch, std::fabs(pred.energy_loss - p.errors.energy_end));
  }
  context.write("mechanism.csv", [&] { return csv; });
  const WorkPrecisionPoint& finest = direct.points.back();
  return toml::table{{"max_prediction_mismatch", max_mismatch},
                     {"theta_at_h_min", predict_direct_impact(t_impact, speed, kStepMin).theta},
                     {"energy_error_at_h_min", finest.errors.energy_end},
                     {"sup_u_error_at_h_min", finest.errors.sup_u}};
}

// The text files of the whole run, filled scene by scene.
struct Outputs {
  std::string points =
      "scene,curve,h,tolerance,steps,sup_u,l1_v,energy_end,first_impact,"
      "cost_min,cost_median,repetitions,batch\n";
  std::string curves_gp, constant_scene_names, forced_scene_names, orders = orders_table_head();
  std::string exact_table =
      "\n| scene | reference | CPU time of a solve sampled at h = 1e-3 | per grid point | per "
      "impact |\n| --- | --- | --- | --- | --- |\n";
};

toml::table run_scene(const ExperimentContext& context, const WorkPrecisionScene& spec,
                      const WorkPrecisionOptions& options, Outputs& out, toml::table& summary) {
  const Scene scene = load_work_precision_scene(context, spec);
  const std::vector<Curve> curves = measure_curves(scene, spec, options);
  toml::table scene_summary;
  std::string names;
  for (const Curve& c : curves) {
    context.write("curves/" + spec.name + "." + c.name + ".csv", [&] { return curve_csv(c); });
    out.points += points_rows(spec.name, c);
    CurveReport report = report_curve(spec.name, c, options.timing.has_value());
    out.orders += report.row;
    scene_summary.insert(c.name, std::move(report.entry));
    names += (names.empty() ? "" : " ") + c.name;
  }
  for (const PeerSolver& peer : options.peers)
    if (!peer.same_as.empty())
      scene_summary.insert(peer.name + "_vs_" + peer.same_as,
                           peer_comparison(curves, peer, options.timing.has_value()));
  if (options.timing) {
    const ExactCost cost = exact_cost(scene, *options.timing);
    out.exact_table += exact_row(spec, cost, scene_summary);
    // For plot.gp's direct_located figure: the reference's cost, sampled on h = 1e-3.
    out.curves_gp += "exact_seconds_" + spec.name + " = " + round_trip(cost.solve.min) + "\n";
  }
  out.curves_gp += "curves_" + spec.name + " = \"" + names + "\"\n" + "title_" + spec.name +
                   " = \"" + spec.title + "\"\n";
  std::string& names_of_kind = spec.forced ? out.forced_scene_names : out.constant_scene_names;
  names_of_kind += (names_of_kind.empty() ? "" : " ") + spec.name;
  if (spec.name == kChaoticScene) {
    toml::table lyapunov = lyapunov_summary(context, scene);
    out.curves_gp += "lyapunov_lambda = " + round_trip(*lyapunov["lambda"].value<double>()) +
                     "\nlyapunov_T = " + round_trip(scene.T) + "\n";
    scene_summary.insert("lyapunov", std::move(lyapunov));
  }
  if (spec.name == kMechanismScene)
    summary.insert("direct_offgrid_mechanism",
                   direct_mechanism(context, scene,
                                    *std::find_if(curves.begin(), curves.end(), [](const Curve& c) {
                                      return c.name == "direct";
                                    })));
  return scene_summary;
}

}  // namespace

toml::table run_work_precision(const ExperimentContext& context) {
  return run_work_precision(context, WorkPrecisionOptions{});
}

toml::table run_work_precision(const ExperimentContext& context,
                               const WorkPrecisionOptions& options) {
  const double started = cpu_seconds();
  if (context.writes()) std::filesystem::create_directories(context.results_dir + "/curves");
  Outputs out;
  toml::table summary;
  for (const WorkPrecisionScene& spec : work_precision_scenes())
    summary.insert(spec.name, run_scene(context, spec, options, out, summary));
  context.write("points.csv", [&] { return out.points; });
  context.write("curves.gp", [&] {
    return out.curves_gp + "constant_scenes = \"" + out.constant_scene_names +
           "\"\nforced_scenes = \"" + out.forced_scene_names +
           "\"\nscenes = constant_scenes.\" \".forced_scenes\n";
  });
  context.write("orders.md",
                [&] { return out.orders + (options.timing ? out.exact_table : std::string()); });
  summary.insert("siconos", !options.peers.empty());
  if (options.timing) summary.insert("sweep_cpu_seconds", cpu_seconds() - started);
  return summary;
}

const Experiment kWorkPrecisionExperiment{
    "work_precision",
    "Work against precision: every method's error against exact and the CPU time of its solve",
    &run_work_precision};

ReferenceRule work_precision_reference_rule() {
  ReferenceRule rule;
  rule.skip = {"sweep_cpu_seconds", "siconos"};
  for (const WorkPrecisionScene& s : work_precision_scenes()) {
    for (const char* table : {".exact", ".siconos", ".siconos_vs_moreau_jean", ".siconos_lsodar"})
      rule.skip.push_back(s.name + table);  // a whole table
    for (const char* curve : {"direct", "fb_newton", "moreau_jean"})
      for (const char* target : {"0.001", "1e-06"})
        rule.skip.push_back(s.name + "." + curve + ".cost_to_sup_u_" + target);
  }
  return rule;
}

}  // namespace impact::work_precision
