#include "analysis/convergence/convergence_study.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <variant>

#include "analysis/order_table.hpp"
#include "analysis/path_distance.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/output/csv.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/scene.hpp"

namespace impact::convergence {

const Experiment kConvergenceExperiment{
    "convergence",
    "Section 4: convergence of u_h as h -> 0, effective COR, the identities (4-9) and (4-10)",
    &run_convergence};

namespace {

constexpr double kGravity = 9.80665;  // Section 5.2: f = -9.80665
constexpr double kCor = 0.75;         // the paper's COR
constexpr double kOnGrid = 1e-6;      // theta within this of 0 or 1: the impact is on the grid
constexpr std::int64_t kPathM = 250;  // the paths of the subsequence figure, h ~ 0.02 s

struct SubsequenceSpec {
  const char* name;
  double theta;
};
constexpr SubsequenceSpec kSubsequences[] = {
    {"theta_0_25", 0.25}, {"theta_0_5", 0.5}, {"theta_0_75", 0.75}};

template <class Of>
std::vector<double> column(const std::vector<ConvergencePoint>& points, Of of) {
  std::vector<double> out;
  for (const ConvergencePoint& p : points) out.push_back(of(p));
  return out;
}

double abs_max(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::fmax(m, std::fabs(x));
  return m;
}

// max_i sup_i / h_i: the constant of a first-order bound sup <= C h.
double max_over_h(const std::vector<double>& sup, const std::vector<double>& h) {
  double bound = 0;
  for (std::size_t i = 0; i < h.size(); ++i) bound = std::fmax(bound, sup[i] / h[i]);
  return bound;
}

std::string series_csv(const SeriesRun& run, const Model& model) {
  std::ostringstream csv;
  csv << "h,theta,sup_u,effective_cor,impulse,res49_printed,res49_corrected,compl410,energy_drop,"
         "energy_loss\n";
  for (const ConvergencePoint& p : run.points)
    csv << round_trip(p.h) << ',' << round_trip(p.first_theta()) << ','
        << round_trip(p.errors.sup_u) << ',' << round_trip(p.first_cor()) << ','
        << round_trip(p.tallies.impulse) << ',' << round_trip(p.impulse_residual_printed()) << ','
        << round_trip(p.impulse_residual_corrected()) << ','
        << round_trip(p.tallies.complementarity) << ',' << round_trip(p.tallies.energy_drop) << ','
        << round_trip(p.energy_loss(model)) << '\n';
  return csv.str();
}

// Without COR, (4-6) makes the energy lost equal sum N^l (u^l - phi) step by step, and the first
// impact's effective COR |1 - 2 theta| (exact for f = 0, up to O(h f / V) otherwise).
void insert_direct_without_cor(toml::table& t, const ConvergenceSeries& s, const SeriesRun& run) {
  double drop_gap = 0, cor_gap = 0;
  for (const ConvergencePoint& p : run.points) {
    drop_gap = std::fmax(drop_gap, std::fabs(p.tallies.energy_drop - p.energy_loss(s.model)));
    cor_gap = std::fmax(cor_gap, std::fabs(p.first_cor() - std::fabs(1 - 2 * p.first_theta())));
  }
  const std::vector<double> cor = column(run.points, [](const auto& p) { return p.first_cor(); });
  t.insert("energy_drop_minus_loss_max", drop_gap);
  t.insert("effective_cor_minus_prediction_max", cor_gap);
  t.insert("effective_cor_min", *std::min_element(cor.begin(), cor.end()));
  t.insert("effective_cor_max", *std::max_element(cor.begin(), cor.end()));
}

toml::table series_table(const ConvergenceSeries& s, const SeriesRun& run) {
  const auto& points = run.points;
  const auto h = column(points, [](const auto& p) { return p.h; });
  const auto sup = column(points, [](const auto& p) { return p.errors.sup_u; });
  const auto loss = column(points, [&](const auto& p) { return p.energy_loss(s.model); });
  toml::table t{
      {"label", s.label},
      {"h", toml_array(h)},
      {"sup_u", toml_array(sup)},
      {"theta", toml_array(column(points, [](const auto& p) { return p.first_theta(); }))},
      {"effective_cor", toml_array(column(points, [](const auto& p) { return p.first_cor(); }))},
      {"fit", order_fit_table(run.fit)},
      {"on_grid_points_left_out", static_cast<std::int64_t>(run.on_grid_left_out)},
      {"sup_min", *std::min_element(sup.begin(), sup.end())},
      {"sup_max", *std::max_element(sup.begin(), sup.end())},
      {"sup_over_h_max", max_over_h(sup, h)},
      {"res49_printed_max",
       abs_max(column(points, [](const auto& p) { return p.impulse_residual_printed(); }))},
      {"res49_corrected_max",
       abs_max(column(points, [](const auto& p) { return p.impulse_residual_corrected(); }))},
      {"compl410_max",
       abs_max(column(points, [](const auto& p) { return p.tallies.complementarity; }))},
      {"energy_loss_min", *std::min_element(loss.begin(), loss.end())},
      {"energy_loss_max", *std::max_element(loss.begin(), loss.end())}};
  if (std::holds_alternative<DirectParams>(s.method) && !s.model.cor)
    insert_direct_without_cor(t, s, run);
  return t;
}

std::string subsequence_csv(const SubsequenceRun& run) {
  std::ostringstream csv;
  csv << "m,h,theta,effective_cor,sup_u\n";
  for (std::size_t i = 0; i < run.points.size(); ++i) {
    const ConvergencePoint& p = run.points[i];
    csv << run.m[i] << ',' << round_trip(p.h) << ',' << round_trip(p.first_theta()) << ','
        << round_trip(p.first_cor()) << ',' << round_trip(p.errors.sup_u) << '\n';
  }
  return csv.str();
}

toml::table subsequence_table(const SubsequenceRun& run) {
  const auto h = column(run.points, [](const auto& p) { return p.h; });
  const auto sup = column(run.points, [](const auto& p) { return p.errors.sup_u; });
  return toml::table{{"theta", run.theta},
                     {"limit_cor", run.limit_cor},
                     {"h", toml_array(h)},
                     {"sup_u", toml_array(sup)},
                     {"effective_cor",
                      toml_array(column(run.points, [](const auto& p) { return p.first_cor(); }))},
                     {"fit", order_fit_table(run.fit)},
                     {"sup_max", *std::max_element(sup.begin(), sup.end())},
                     {"sup_over_h_max", max_over_h(sup, h)},
                     {"limit_distance_to_elastic", run.limit_distance_to_elastic}};
}

// u_h at m = 250 for one theta (theta = 0 is taken as theta = 1: the impact at the end of step
// m, on the grid) and the exact solution with COR |1 - 2 theta| on the same grid, for panel (b)
// of the subsequence figure.
std::string path_csv(double theta) {
  const State initial{kOffGridU0, -1.0};
  const double h = step_with_fraction(kOffGridU0, kPathM, theta == 0 ? 1.0 : theta);
  const Scene scene = make_scene(Model{}, initial, kConvergenceT, h, DirectParams{});
  const ExactSolution limit(Model{.cor = std::fabs(1 - 2 * theta)}, initial);
  AnyStepper direct = make_stepper(scene);
  std::ostringstream csv;
  csv << "t,u_h,u_exact\n";
  simulate(direct, scene.initial, scene.grid, [&](std::int64_t l, const State& s, const StepInfo&) {
    const double t = scene.grid.t(l);
    csv << round_trip(t) << ',' << round_trip(s.u) << ',' << round_trip(limit.at(t).u) << '\n';
  });
  return csv.str();
}

}  // namespace

std::vector<ConvergenceSeries> convergence_series(const ConvergenceOptions& options) {
  // u0 = 5, v0 = -1, f = 0 meets the floor at t* = 5.
  const std::vector<double> free_h = at_least(options.free.steps(), options.h_floor);
  const std::vector<double> aligned_h =
      at_least(aligned_steps(options.free.steps(), 5.0), options.h_floor);
  const std::vector<double> gravity_h = at_least(options.gravity.steps(), options.h_floor);
  const State paper{5.0, -1.0}, off_grid{kOffGridU0, -1.0};
  const Model no_force{}, no_force_cor{.cor = kCor};
  const Model gravity{.f = -kGravity, .cor = std::nullopt},
      gravity_cor{.f = -kGravity, .cor = kCor};
  const DirectParams direct;
  const MoreauJeanParams mj;
  return {
      {"f0_direct_aligned", "direct, no COR, u0 = 5, h = 5/m (impact on the grid)", direct,
       no_force, paper, aligned_h},
      {"f0_direct", "direct, no COR, u0 = 5.0123", direct, no_force, off_grid, free_h},
      {"f0_direct_cor", "direct, COR = 0.75, u0 = 5.0123", direct, no_force_cor, off_grid, free_h},
      {"f0_mj", "moreau_jean, e = 1, u0 = 5.0123", mj, no_force, off_grid, free_h},
      {"f0_mj_cor", "moreau_jean, COR = 0.75, u0 = 5.0123", mj, no_force_cor, off_grid, free_h},
      {"g_direct", "direct, no COR, f = -9.80665", direct, gravity, paper, gravity_h},
      {"g_direct_cor", "direct, COR = 0.75, f = -9.80665", direct, gravity_cor, paper, gravity_h},
      {"g_mj", "moreau_jean, e = 1, f = -9.80665", mj, gravity, paper, gravity_h},
      {"g_mj_cor", "moreau_jean, COR = 0.75, f = -9.80665", mj, gravity_cor, paper, gravity_h},
  };
}

SeriesRun run_series(const ConvergenceSeries& s) {
  SeriesRun run;
  std::vector<double> fit_h, fit_sup;
  for (double h : s.h) {
    const ConvergencePoint& p = run.points.emplace_back(
        measure_convergence(make_scene(s.model, s.initial, kConvergenceT, h, s.method)));
    const double theta = p.first_theta();
    const bool on_grid = std::fmin(theta, std::fabs(1 - theta)) < kOnGrid;
    if (s.initial.u == kOffGridU0 && on_grid) {
      ++run.on_grid_left_out;
    } else {
      fit_h.push_back(p.h);
      fit_sup.push_back(p.errors.sup_u);
    }
  }
  run.fit = fit_order(fit_h, fit_sup);
  return run;
}

SubsequenceRun run_subsequence(double theta, const std::vector<std::int64_t>& m) {
  SubsequenceRun run;
  run.theta = theta;
  run.limit_cor = std::fabs(1 - 2 * theta);
  run.m = m;
  const State initial{kOffGridU0, -1.0};
  const Model limit{.cor = run.limit_cor};
  std::vector<double> hs, sup;
  for (std::int64_t k : m) {
    const double h = step_with_fraction(kOffGridU0, k, theta);
    const ConvergencePoint& p = run.points.emplace_back(
        measure_convergence(make_scene(Model{}, initial, kConvergenceT, h, DirectParams{}), limit));
    hs.push_back(p.h);
    sup.push_back(p.errors.sup_u);
  }
  run.fit = fit_order(hs, sup);
  const ExactSolution limit_solution(limit, initial), elastic(Model{.cor = 1.0}, initial);
  run.limit_distance_to_elastic = sup_distance(limit_solution, elastic, kConvergenceT);
  return run;
}

toml::table run_convergence(const ExperimentContext& context, const ConvergenceOptions& options) {
  toml::table series;
  for (const ConvergenceSeries& s : convergence_series(options)) {
    const SeriesRun run = run_series(s);
    context.write("series_" + s.name + ".csv", [&] { return series_csv(run, s.model); });
    series.insert(s.name, series_table(s, run));
  }
  toml::table subsequences;
  for (const SubsequenceSpec& spec : kSubsequences) {
    std::vector<std::int64_t> m;
    for (std::int64_t k : options.subsequence_m)
      if (step_with_fraction(kOffGridU0, k, spec.theta) >= options.h_floor) m.push_back(k);
    const SubsequenceRun run = run_subsequence(spec.theta, m);
    context.write(std::string("subsequence_") + spec.name + ".csv",
                  [&] { return subsequence_csv(run); });
    subsequences.insert(spec.name, subsequence_table(run));
  }
  const double path_thetas[] = {0.0, 0.25, 0.5, 0.75};
  for (int k = 0; k < 4; ++k)
    context.write("path_theta_" + std::to_string(k) + ".csv",
                  [&] { return path_csv(path_thetas[k]); });
  return toml::table{{"series", series}, {"subsequences", subsequences}};
}

toml::table run_convergence(const ExperimentContext& context) {
  return run_convergence(context, ConvergenceOptions{});
}

}  // namespace impact::convergence
