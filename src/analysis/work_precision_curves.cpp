#include "analysis/work_precision_curves.hpp"

#include <cmath>
#include <stdexcept>

#include "analysis/work_precision_reference.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/any_stepper.hpp"
#include "scene/read_scene.hpp"

namespace impact {
namespace {

const std::vector<double> kTolerances = {1e-3, 1e-5, kPenaltyReferenceTolerance, 1e-9, 1e-11};
const std::vector<double> kStiffnesses = {1e4, 1e6, 1e8};
const std::vector<std::string> kOdeSteppers = {"rk8pd", "msbdf"};

Curve peer_curve(Scene scene, const PeerSolver& peer, double step_min,
                 const std::optional<TimingRule>& rule) {
  Curve c{peer.name, peer.step_min > 0, {}};
  if (!c.step_sweep) {
    scene.grid = Grid::covering(scene.T, kPenaltyGrid);
    for (const double tolerance : kTolerances)
      c.points.push_back(peer.measure(scene, tolerance, rule));
    return c;
  }
  for (const double h : steps_125(kStepMax, std::fmax(peer.step_min, step_min))) {
    scene.grid = Grid::covering(scene.T, h);
    c.points.push_back(peer.measure(scene, 0.0, rule));
  }
  return c;
}

Curve penalty_curve(const Scene& scene, const std::string& stepper, double c_N,
                    const std::optional<TimingRule>& rule) {
  Curve c{"penalty_" + stepper + "_cN1e" + std::to_string(std::lround(std::log10(c_N))), false, {}};
  for (const double tolerance : kTolerances)
    c.points.push_back(measure_scene(penalty_variant(scene, stepper, c_N, tolerance), rule));
  return c;
}

// The method event_driven (GSL rk8pd between impacts) over the tolerances, rtol = atol, on the
// grid kPenaltyGrid: on a harmonic force, where `exact` is the reference it is measured against.
Curve event_driven_curve(const Scene& scene, const std::optional<TimingRule>& rule) {
  Curve c{"event_driven", false, {}};
  for (const double tolerance : kTolerances) {
    Scene variant = scene;
    variant.method = find_method("event_driven")->defaults;
    std::visit(
        [&](auto& params) {
          if constexpr (requires { params.rtol = params.atol = tolerance; })
            params.rtol = params.atol = tolerance;
        },
        variant.method);
    variant.grid = Grid::covering(scene.T, kPenaltyGrid);
    WorkPrecisionPoint p = measure_scene(variant, rule);
    p.tolerance = tolerance;
    c.points.push_back(p);
  }
  return c;
}

}  // namespace

const std::vector<WorkPrecisionScene>& work_precision_scenes() {
  static const std::vector<WorkPrecisionScene> scenes = {
      {"figure3_no_cor", "figure3", "no_cor.toml", "Figure 3: f = 0, no COR", false},
      {"figure3_cor075", "figure3", "cor075.toml", "Figure 3: f = 0, COR = 0.75", true},
      {"figure4_no_cor", "figure4", "no_cor.toml", "Figure 4: f = -9.80665, no COR", false},
      {"figure4_cor075", "figure4", "cor075.toml", "Figure 4: f = -9.80665, COR = 0.75", true},
      {"offgrid_no_cor", "work_precision", "offgrid.toml",
       "off-grid: f = 0, no COR, impact at t = pi", false},
      {"table_period1", "work_precision", "table_period1.toml",
       "vibrating table, period 1: {/Symbol G} = 1.3, e = 0.5", true, true},
      {"table_chaotic", "work_precision", "table_chaotic.toml",
       "vibrating table, chaotic: {/Symbol G} = 5, e = 0.5, T = 1 s", true, true},
      {"expression", "work_precision", "expression.toml", "f = -9.80665 + 4 tanh(5 sin 2t), no COR",
       false, true, 1e-4},
  };
  return scenes;
}

const WorkPrecisionScene& work_precision_scene(std::string_view name) {
  for (const WorkPrecisionScene& s : work_precision_scenes())
    if (s.name == name) return s;
  throw std::out_of_range("no work-precision scene " + std::string(name));
}

Scene load_work_precision_scene(const ExperimentContext& context, const WorkPrecisionScene& s) {
  return load_scene(context.scene_path(s.experiment, s.file));
}

const std::vector<double>& swept_steps() {
  static const std::vector<double> steps = steps_125(kStepMax, kStepMin);
  return steps;
}

namespace {

// The scene with the method's default parameters.
Scene with_method(Scene scene, std::string_view method) {
  const MethodInfo* info = find_method(method);
  if (!info) throw std::out_of_range("no method " + std::string(method));
  scene.method = info->defaults;
  return scene;
}

// The swept steps from kStepMax down to step_min.
std::vector<double> steps_down_to(double step_min) {
  return step_min == kStepMin ? swept_steps() : steps_125(kStepMax, step_min);
}

}  // namespace

std::vector<WorkPrecisionPoint> step_curve(const Scene& scene, std::string_view method,
                                           const std::optional<TimingRule>& rule, double step_min) {
  return sweep_steps(with_method(scene, method), steps_down_to(step_min), rule);
}

std::vector<Curve> step_curves(const Scene& scene, const std::vector<std::string>& methods,
                               const std::vector<double>& steps,
                               const std::optional<TimingRule>& rule,
                               const std::function<void(std::size_t)>& after_point) {
  std::vector<Curve> curves;
  std::size_t done = 0;
  for (const std::string& method : methods)
    curves.push_back({method, true, sweep_steps(with_method(scene, method), steps, rule, [&] {
                        if (after_point) after_point(++done);
                      })});
  return curves;
}

OrderFit curve_order(const Curve& c, ErrorMeasure m) {
  return observed_order(c.points, m, kErrorFloor);
}

Scene penalty_variant(Scene scene, const std::string& stepper, double c_N, double tolerance) {
  PenaltyParams params;
  params.stepper = stepper;
  params.stiffness = c_N;
  params.rtol = params.atol = tolerance;
  scene.method = params;
  scene.grid = Grid::covering(scene.T, kPenaltyGrid);
  return scene;
}

std::vector<Curve> measure_curves(const Scene& scene, const WorkPrecisionScene& spec,
                                  const WorkPrecisionOptions& options) {
  std::vector<Curve> curves =
      step_curves(scene, {"moreau_jean", "fb_newton", "direct", "direct_located"},
                  steps_down_to(spec.step_min), options.timing);
  for (const PeerSolver& peer : options.peers)
    if (!peer.time_dependent_force_only || !constant_force(scene.model))
      curves.push_back(peer_curve(scene, peer, spec.step_min, options.timing));
  if (!constant_force(scene.model) && scene.model.expression.empty() && find_method("event_driven"))
    curves.push_back(event_driven_curve(scene, options.timing));
  if (!spec.has_cor)
    for (const std::string& stepper : kOdeSteppers)
      for (const double c_N : kStiffnesses)
        curves.push_back(penalty_curve(scene, stepper, c_N, options.timing));
  return curves;
}

DirectImpactPrediction predict_direct_impact(double t_impact, double speed, double h) {
  const double steps = t_impact / h;
  const double theta = steps - std::floor(steps);
  return {theta, std::fabs(1 - 2 * theta), 2 * theta * (1 - theta) * speed * speed};
}

namespace {

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

// The reference with f(t) tracking its events alone: one grid step over [0, T], timed, over the
// number of impacts its event log reports (NaN without one, or without an event log).
double event_seconds_per_impact(Scene scene, const TimingRule& rule) {
  scene.grid = Grid{scene.T, 1};
  const std::int64_t impacts = count_impacts(scene);
  if (impacts == 0) return std::nan("");
  const SolveCost solve =
      time_solve([&] { return make_stepper(scene); }, scene.initial, scene.grid, rule);
  return solve.min / static_cast<double>(impacts);
}

}  // namespace

ExactCost exact_cost(Scene scene, const TimingRule& rule) {
  scene.method = find_method(reference_method(scene.model))->defaults;
  scene.grid = Grid::covering(scene.T, kPenaltyGrid);
  ExactCost cost;
  cost.method = method_name(scene.method);
  cost.solve = time_solve([&] { return make_stepper(scene); }, scene.initial, scene.grid, rule);
  cost.grid_points = scene.grid.steps;
  cost.seconds_per_impact =
      constant_force(scene.model)
          ? exact_seconds_per_impact(ExactSolution(scene.model, scene.initial))
          : event_seconds_per_impact(scene, rule);
  return cost;
}

}  // namespace impact
