// Work-precision study: for every method on the paper's Figure 3 and Figure 4 scenes
// (no COR and COR = 0.75) and on a scene whose impact lies on no grid point, the error against
// `exact` and the CPU time of the solve, over a sweep of the step h (direct, fb_newton,
// moreau_jean, Siconos when it was built) or of the tolerance (penalty, several c_N, an explicit
// and an implicit GSL stepper). Writes to RESULTS_DIR:
//   points.csv                       every point: errors, cost (min, median), repetitions
//   curves/<scene>.<curve>.csv       the same per curve, for gnuplot
//   curves.gp                        the scene and curve names, for plot.gp
//   mechanism.csv                    direct without COR on the off-grid scene: theta, effective
//                                    COR, the predicted energy loss 2 theta (1 - theta) v^2 and
//                                    the measured energy error
//   orders.md                        the table of observed orders and costs to reach an error
//   summary.toml                     the key numbers (reference.toml keys)
// Usage: exp_work_precision RESULTS_DIR
#include "impact/work_precision.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "impact/exact.hpp"
#include "impact/output.hpp"
#include "impact/registry.hpp"
#include "impact/scene.hpp"
#ifdef IMPACT_HAVE_SICONOS
#include "siconos_ball.hpp"
#endif

namespace {

using namespace impact;

struct SceneSpec {
  std::string name, file, title;
  bool has_cor;
};

const std::vector<SceneSpec> kScenes = {
    {"figure3_no_cor", "experiments/figure3/no_cor.toml", "Figure 3: f = 0, no COR", false},
    {"figure3_cor075", "experiments/figure3/cor075.toml", "Figure 3: f = 0, COR = 0.75", true},
    {"figure4_no_cor", "experiments/figure4/no_cor.toml", "Figure 4: f = -9.80665, no COR", false},
    {"figure4_cor075", "experiments/figure4/cor075.toml", "Figure 4: f = -9.80665, COR = 0.75",
     true},
    {"offgrid_no_cor", "experiments/work_precision/offgrid.toml",
     "off-grid: f = 0, no COR, impact at t = pi", false},
};

// The sweeps: h from 0.1 to 1e-5 (4 decades, 13 steps) for the project's time-steppers; Siconos
// costs about a microsecond per step, so it stops at 1e-4 to keep `make all` short.
constexpr double kStepMax = 0.1, kStepMin = 1e-5, kSiconosStepMin = 1e-4;
// Normal compliance: output grid h = 1e-3, tolerances rtol = atol over 8 decades.
constexpr double kPenaltyGrid = 1e-3;
const std::vector<double> kTolerances = {1e-3, 1e-5, 1e-7, 1e-9, 1e-11};
const std::vector<double> kStiffnesses = {1e4, 1e6, 1e8};
const std::vector<std::string> kOdeSteppers = {"rk8pd", "msbdf"};
// Errors below this are rounding (10^5 steps of a few ulp of 10), not discretisation: they are
// left out of the fitted orders.
constexpr double kErrorFloor = 1e-10;
const std::vector<double> kTargets = {1e-3, 1e-6};

std::string short_num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

std::string scene_path(const SceneSpec& s) {
  return std::string(IMPACT_SOURCE_DIR) + "/" + s.file;
}

struct Curve {
  std::string name;        // e.g. "direct", "penalty_rk8pd_cN1e6"
  std::string method;      // the registry's name, or "siconos"
  bool step_sweep = true;  // false: a tolerance sweep at a fixed grid
  std::vector<WorkPrecisionPoint> points;
};

void write_curve(const std::filesystem::path& dir, const std::string& scene, const Curve& c) {
  std::ofstream out(dir / "curves" / (scene + "." + c.name + ".csv"));
  out << "h,tolerance,cost_min,cost_median,sup_u,l1_v,energy_end,first_impact\n";
  for (const auto& p : c.points) {
    out << impact::round_trip(p.h) << "," << impact::round_trip(p.tolerance) << ","
        << impact::round_trip(p.cost.min) << "," << impact::round_trip(p.cost.median);
    for (const ErrorMeasure m : kErrorMeasures)
      out << "," << impact::round_trip(error_of(p.errors, m));
    out << "\n";
  }
}

// A fit is steady when no point lies more than a factor 3 off the fitted line.
bool steady(const OrderFit& fit) {
  return fit.max_log_deviation < std::log(3.0);
}

// How a curve reaches an error: measured (the cheapest point at or below it); along the fitted
// line when the curve falls steadily (cost ~ 1/h from its smallest step); beyond the sweep when it
// falls but erratically; not at all when it stalls.
std::string reach(const Curve& c, ErrorMeasure m, double target, const OrderFit& fit) {
  if (const auto cost = cost_to_reach(c.points, m, target)) return short_num(*cost) + " s";
  if (!c.step_sweep) return "not reachable (c_N floor)";
  const auto& last = *std::min_element(c.points.begin(), c.points.end(),
                                       [](const auto& a, const auto& b) { return a.h < b.h; });
  if (fit.points >= 3 && fit.order > 0.5 && steady(fit)) {
    const double h_target = std::exp((std::log(target) - fit.log_constant) / fit.order);
    // Appended, not "~" + ...: GCC 12 gives a false -Wrestrict on a literal + std::string.
    std::string estimate = "~";
    estimate += short_num(last.cost.min * last.h / h_target);
    return estimate + " s (extrapolated)";
  }
  if (fit.points >= 3 && fit.order > 0.5) return "below h = " + short_num(last.h) + " (erratic)";
  return "not reachable (stalls)";
}

// The observed order for the table: the slope with its range, or the level where it stalls.
std::string describe(const OrderFit& fit, const Curve& c, ErrorMeasure m) {
  if (fit.points < 2) return "rounding only";
  if (std::fabs(fit.order) < 0.2) {
    double lowest = INFINITY;
    for (const auto& p : c.points) lowest = std::fmin(lowest, error_of(p.errors, m));
    return "0: stalls (min " + short_num(lowest) + ")";
  }
  return short_num(fit.order) + " (h " + short_num(fit.h_min) + ".." + short_num(fit.h_max) +
         (steady(fit) ? ")" : ", erratic)");
}

// Direct without COR, f = 0, one impact at t* = (u0 - phi) / |v0| off the grid: with theta the
// fraction of the step before the floor, the rebound is |v| |1 - 2 theta| and the energy lost
// 2 theta (1 - theta) v^2 (paper_notes/restitution.md), whatever h.
struct DirectImpactPrediction {
  double theta, effective_cor, energy_loss;
};
DirectImpactPrediction predict_direct_impact(double t_impact, double speed, double h) {
  const double steps = t_impact / h;
  const double theta = steps - std::floor(steps);
  return {theta, std::fabs(1 - 2 * theta), 2 * theta * (1 - theta) * speed * speed};
}

// exact, the reference: the CPU time of one impact, the time and the speed of impact k from the
// closed form (exact.hpp), averaged over the first K impacts (K = 1000, or as many as there are).
double exact_seconds_per_impact(const ExactSolution& exact) {
  std::int64_t impacts = 0;
  while (impacts < 1000 && exact.impact_time(impacts + 1)) ++impacts;
  if (impacts == 0) return std::nan("");
  double sum = 0, seconds = 0;
  std::int64_t evaluated = 0;
  const double start = cpu_seconds();
  // At least 1000 impacts between two readings of the clock, which costs more than an impact.
  const std::int64_t rounds = (1000 + impacts - 1) / impacts;
  while ((seconds = cpu_seconds() - start) < 1e-3) {
    for (std::int64_t r = 0; r < rounds; ++r)
      for (std::int64_t k = 1; k <= impacts; ++k)
        sum += *exact.impact_time(k) + *exact.impact_speed(k);
    evaluated += rounds * impacts;
  }
  if (!std::isfinite(sum)) return std::nan("");
  return seconds / static_cast<double>(evaluated);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s RESULTS_DIR\n", argv[0]);
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir / "curves");
  const double started = cpu_seconds();
  const TimingRule rule;
  const std::vector<double> steps = steps_125(kStepMax, kStepMin);
  const std::vector<double> siconos_steps = steps_125(kStepMax, kSiconosStepMin);

  std::ofstream points_csv(dir / "points.csv");
  points_csv << "scene,curve,h,tolerance,steps,sup_u,l1_v,energy_end,first_impact,cost_min,"
                "cost_median,repetitions,batch\n";
  std::ofstream curves_gp(dir / "curves.gp");
  std::ostringstream scene_names;
  toml::table summary;
  std::ostringstream table;
  table << "| scene | method | order sup u | order L1 v | order E(T) | order t1 | cost to "
           "sup u <= 1e-3 | cost to sup u <= 1e-6 |\n"
        << "| --- | --- | --- | --- | --- | --- | --- | --- |\n";

  for (const SceneSpec& spec : kScenes) {
    scene_names << (scene_names.tellp() > 0 ? " " : "") << spec.name;
    const std::string path = scene_path(spec);
    std::vector<Curve> curves;
    // Drawn in this order: direct last, on top of moreau_jean where their errors coincide.
    for (const char* method : {"moreau_jean", "fb_newton", "direct"})
      curves.push_back({method, method, true,
                        sweep_steps(path, {std::string("method.name=") + method}, steps, rule)});
#ifdef IMPACT_HAVE_SICONOS
    {
      Curve siconos{"siconos", "siconos", true, {}};
      for (const double h : siconos_steps) {
        const Scene scene =
            load_scene(path, {"method.name=moreau_jean", "time.h=" + impact::round_trip(h)});
        siconos.points.push_back(measure_point(
            [&] { return SiconosBall(scene.model, scene.initial, h, scene.grid.steps); },
            scene.model, scene.initial, scene.grid, rule));
      }
      curves.push_back(std::move(siconos));
    }
#endif
    if (!spec.has_cor) {
      for (const std::string& ode : kOdeSteppers)
        for (const double c_N : kStiffnesses) {
          Curve c{"penalty_" + ode + "_cN1e" + std::to_string(std::lround(std::log10(c_N))),
                  "penalty",
                  false,
                  {}};
          for (const double tol : kTolerances)
            c.points.push_back(
                measure_scene(load_scene(path, {"method.name=penalty", "method.stepper=" + ode,
                                                "method.stiffness=" + impact::round_trip(c_N),
                                                "method.rtol=" + impact::round_trip(tol),
                                                "method.atol=" + impact::round_trip(tol),
                                                "time.h=" + impact::round_trip(kPenaltyGrid)}),
                              rule));
          curves.push_back(std::move(c));
        }
    }

    std::string curve_names;
    toml::table scene_summary;
    for (const Curve& c : curves) {
      write_curve(dir, spec.name, c);
      curve_names += (curve_names.empty() ? "" : " ") + c.name;
      for (const auto& p : c.points) {
        points_csv << spec.name << "," << c.name << "," << impact::round_trip(p.h) << ","
                   << impact::round_trip(p.tolerance) << "," << p.steps;
        for (const ErrorMeasure m : kErrorMeasures)
          points_csv << "," << impact::round_trip(error_of(p.errors, m));
        points_csv << "," << impact::round_trip(p.cost.min) << ","
                   << impact::round_trip(p.cost.median) << "," << p.cost.repetitions << ","
                   << p.cost.batch << "\n";
      }
      toml::table entry;
      if (c.step_sweep) {
        table << "| " << spec.name << " | " << c.name;
        for (const ErrorMeasure m : kErrorMeasures) {
          const OrderFit fit = observed_order(c.points, m, kErrorFloor);
          const std::string key(measure_name(m));
          if (fit.points >= 2) {
            entry.insert(key + "_order", fit.order);
            entry.insert(key + "_order_deviation", fit.max_log_deviation);
          }
          table << " | " << describe(fit, c, m);
        }
        const OrderFit sup = observed_order(c.points, ErrorMeasure::sup_u, kErrorFloor);
        for (const double target : kTargets) {
          const std::string r = reach(c, ErrorMeasure::sup_u, target, sup);
          table << " | " << r;
          entry.insert("cost_to_sup_u_" + short_num(target), r);
        }
        table << " |\n";
      } else {
        // A tolerance sweep: its error floor is the compliance model's (c_N), not a rate in h.
        double floor = INFINITY;
        for (const auto& p : c.points) floor = std::fmin(floor, p.errors.sup_u);
        entry.insert("sup_u_floor", floor);
        table << "| " << spec.name << " | " << c.name << " | sup u floor " << short_num(floor)
              << " (tolerance 1e-3..1e-11) | | | | " << reach(c, ErrorMeasure::sup_u, 1e-3, {})
              << " | " << reach(c, ErrorMeasure::sup_u, 1e-6, {}) << " |\n";
      }
      // Regression numbers (deterministic): the errors at h = 1e-3 (a step sweep) or at the
      // middle tolerance 1e-7 (penalty).
      for (const auto& p : c.points)
        if ((c.step_sweep && p.h == 1e-3) || (!c.step_sweep && p.tolerance == 1e-7))
          for (const ErrorMeasure m : kErrorMeasures)
            if (std::isfinite(error_of(p.errors, m)))
              entry.insert(std::string(measure_name(m)) + "_at_reference_point",
                           error_of(p.errors, m));
      scene_summary.insert(c.name, entry);
    }
    curves_gp << "curves_" << spec.name << " = \"" << curve_names << "\"\n"
              << "title_" << spec.name << " = \"" << spec.title << "\"\n";

#ifdef IMPACT_HAVE_SICONOS
    // Siconos against moreau_jean at the same h: the same scheme, so the same error; the ratio of
    // costs is the ratio at equal error.
    {
      const Curve& mj = *std::find_if(curves.begin(), curves.end(),
                                      [](const Curve& c) { return c.name == "moreau_jean"; });
      const Curve& sic = *std::find_if(curves.begin(), curves.end(),
                                       [](const Curve& c) { return c.name == "siconos"; });
      double max_difference = 0, ratio_min = INFINITY, ratio_max = 0;
      std::vector<double> ratios;
      for (const auto& s : sic.points)
        for (const auto& m : mj.points)
          if (m.h == s.h) {
            max_difference = std::fmax(max_difference, std::fabs(s.errors.sup_u - m.errors.sup_u));
            const double r = s.cost.min / m.cost.min;
            ratios.push_back(r);
            ratio_min = std::fmin(ratio_min, r);
            ratio_max = std::fmax(ratio_max, r);
          }
      std::sort(ratios.begin(), ratios.end());
      toml::table s{{"cost_ratio_min", ratio_min},
                    {"cost_ratio_median", ratios[ratios.size() / 2]},
                    {"cost_ratio_max", ratio_max},
                    {"max_sup_u_difference", max_difference}};
      scene_summary.insert("siconos_vs_moreau_jean", s);
    }
#endif
    summary.insert(spec.name, scene_summary);
  }
  curves_gp << "scenes = \"" << scene_names.str() << "\"\n";

  // The reference itself: its error is 0 by definition, so it has no point on the diagrams.
  table << "\n| scene | exact: CPU time of a solve sampled at h = 1e-3 | per grid point | per "
           "impact |\n| --- | --- | --- | --- |\n";
  for (const SceneSpec& spec : kScenes) {
    const Scene scene = load_scene(
        scene_path(spec), {"method.name=exact", "time.h=" + impact::round_trip(kPenaltyGrid)});
    const SolveCost cost =
        time_solve([&] { return make_stepper(scene); }, scene.initial, scene.grid, rule);
    const double per_impact = exact_seconds_per_impact(ExactSolution(scene.model, scene.initial));
    table << "| " << spec.name << " | " << short_num(cost.min) << " s | "
          << short_num(cost.min / static_cast<double>(scene.grid.steps) * 1e9) << " ns | "
          << short_num(per_impact * 1e9) << " ns |\n";
    toml::table* entry = summary[spec.name].as_table();
    entry->insert("exact", toml::table{{"solve_seconds", cost.min},
                                       {"ns_per_grid_point",
                                        cost.min / static_cast<double>(scene.grid.steps) * 1e9},
                                       {"ns_per_impact", per_impact * 1e9}});
  }

  // The mechanism of direct's non-convergence without COR: its energy error on the off-grid scene
  // against the prediction, at the swept steps.
  {
    const SceneSpec& off = kScenes.back();
    const Scene scene = load_scene(scene_path(off));
    const ExactSolution exact(scene.model, scene.initial);
    const double t_impact = *exact.impact_time(1), speed = *exact.impact_speed(1);
    std::ofstream out(dir / "mechanism.csv");
    out << "h,theta,effective_cor,predicted_energy_loss,measured_energy_error\n";
    const std::vector<WorkPrecisionPoint> direct =
        sweep_steps(scene_path(off), {"method.name=direct"}, steps, std::nullopt);
    double max_mismatch = 0;
    for (const auto& p : direct) {
      const auto pred = predict_direct_impact(t_impact, speed, p.h);
      out << impact::round_trip(p.h) << "," << impact::round_trip(pred.theta) << ","
          << impact::round_trip(pred.effective_cor) << "," << impact::round_trip(pred.energy_loss)
          << "," << impact::round_trip(p.errors.energy_end) << "\n";
      max_mismatch = std::fmax(max_mismatch, std::fabs(pred.energy_loss - p.errors.energy_end));
    }
    const auto at_min = predict_direct_impact(t_impact, speed, kStepMin);
    summary.insert("direct_offgrid_mechanism",
                   toml::table{{"max_prediction_mismatch", max_mismatch},
                               {"theta_at_h_min", at_min.theta},
                               {"energy_error_at_h_min", direct.back().errors.energy_end},
                               {"sup_u_error_at_h_min", direct.back().errors.sup_u}});
  }

  summary.insert("sweep_cpu_seconds", cpu_seconds() - started);
#ifdef IMPACT_HAVE_SICONOS
  summary.insert("siconos", true);
#else
  summary.insert("siconos", false);
  std::fprintf(stderr,
               "work_precision: Siconos was not found when the project was configured, so its "
               "curves are left out.\n  To include them: apt-get install libsiconos-kernel-dev, "
               "then rerun make work_precision.\n");
#endif
  std::ofstream(dir / "summary.toml") << summary << "\n";
  std::ofstream(dir / "orders.md") << table.str();
  std::fprintf(stderr, "work_precision: %.1f s of CPU time\n", cpu_seconds() - started);
  return 0;
}
