// The curves of experiments/work_precision: on the paper's Figure 3 and Figure 4 scenes (without
// COR and with COR = 0.75), on a scene whose impact lies on no grid point, and on three scenes with
// a time-dependent force (the vibrating table in its period-1 and its chaotic regime, an
// expression force), every method's error against the reference (`exact`, or for an expression
// force `event_driven`: work_precision_reference.hpp) and the CPU time of its solve, over a sweep
// of the step h (direct, fb_newton, moreau_jean, a peer such as Siconos's Moreau-Jean when it is
// built) or of the tolerance (penalty, c_N = 1e4, 1e6, 1e8, an explicit and an implicit GSL
// stepper; an event-driven peer such as Siconos's LSODAR).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/experiment.hpp"
#include "analysis/work_precision.hpp"
#include "impact/run/scene.hpp"

namespace impact {

// The step sweep: h = 0.1, 0.05, 0.02, ..., 1e-5 (4 decades, 13 steps; steps_125).
constexpr double kStepMax = 0.1, kStepMin = 1e-5;

struct WorkPrecisionScene {
  std::string name;
  std::string experiment, file;  // experiments/<experiment>/<file>
  std::string title;
  bool has_cor;
  bool forced = false;  // f depends on t: its reference is reference_method(), not ExactSolution
  // The step sweep's smallest h: larger where a step costs much more (an expression force, whose
  // step mean takes 16 muparser evaluations), to keep the study's run time.
  double step_min = kStepMin;
};
const std::vector<WorkPrecisionScene>& work_precision_scenes();
const WorkPrecisionScene& work_precision_scene(std::string_view name);
Scene load_work_precision_scene(const ExperimentContext& context, const WorkPrecisionScene& s);

const std::vector<double>& swept_steps();
// Penalty's output grid, and the middle of its tolerance sweep (the reference point).
constexpr double kPenaltyGrid = 1e-3, kPenaltyReferenceTolerance = 1e-7;

struct Curve {
  std::string name;        // e.g. "direct", "penalty_rk8pd_cN1e6", "siconos"
  bool step_sweep = true;  // false: a tolerance sweep on a fixed grid
  std::vector<WorkPrecisionPoint> points;
};

// A solver from another package (Siconos when it is built): a time-stepper swept over the steps
// from kStepMax down to step_min, one point per step, or an adaptive solver swept over the
// tolerances of penalty's sweep on the grid kPenaltyGrid.
struct PeerSolver {
  std::string name;     // the curve's name, e.g. "siconos"
  std::string same_as;  // the project's method with the same scheme, e.g. "moreau_jean"; or ""
  double step_min;      // a step sweep's smallest h; 0 for a tolerance sweep
  bool time_dependent_force_only;  // run on the scenes whose f depends on t, and no other
  // One point: the scene (its grid) with this tolerance (a tolerance sweep; 0 for a step sweep).
  WorkPrecisionPoint (*measure)(const Scene& scene, double tolerance,
                                const std::optional<TimingRule>& rule);
};

// What to run; the defaults are the experiment without a peer.
struct WorkPrecisionOptions {
  // How solves are timed; nullopt: errors only (no CPU times, no timing keys in the summary).
  std::optional<TimingRule> timing = TimingRule{};
  std::vector<PeerSolver> peers;
};

// The time-stepper's curve: the scene with the method's default parameters over swept_steps(),
// down to step_min.
std::vector<WorkPrecisionPoint> step_curve(const Scene& scene, std::string_view method,
                                           const std::optional<TimingRule>& rule,
                                           double step_min = kStepMin);

// The recipe of one scene, shared by the experiment and `impact work-precision`: each
// time-stepper with its default parameters over the steps, every point's errors from one run
// against the scene's reference and the CPU time of its solve alone (time_solve, when a rule is
// given); after_point(points done) after each point, for a progress line.
std::vector<Curve> step_curves(const Scene& scene, const std::vector<std::string>& methods,
                               const std::vector<double>& steps,
                               const std::optional<TimingRule>& rule,
                               const std::function<void(std::size_t)>& after_point = {});

// Errors below this are rounding (10^5 steps of a few ulp of 10), not discretisation: they are
// left out of the fitted orders.
constexpr double kErrorFloor = 1e-10;
// The observed order of a measure over a step curve, as the experiment reports it.
OrderFit curve_order(const Curve& c, ErrorMeasure m);
// The scene as penalty with this GSL stepper, c_N and rtol = atol = tolerance, on kPenaltyGrid.
Scene penalty_variant(Scene scene, const std::string& stepper, double c_N, double tolerance);

// Every curve of a scene, in drawing order: moreau_jean, fb_newton, direct (on top where their
// errors coincide), direct_located (paper_notes/error_analysis.md, "Beyond order one"), the
// peers, event_driven over its tolerance (on a harmonic force, where it is not the reference),
// then penalty's (on a scene without COR: penalty has no COR law).
std::vector<Curve> measure_curves(const Scene& scene, const WorkPrecisionScene& spec,
                                  const WorkPrecisionOptions& options);

// `direct` without COR, f = 0, one impact at t* off the grid: with theta the fraction of the step
// before the floor, the rebound is |v| |1 - 2 theta| and the energy lost 2 theta (1 - theta) v^2
// (paper_notes/restitution.md), whatever h.
struct DirectImpactPrediction {
  double theta, effective_cor, energy_loss;
};
DirectImpactPrediction predict_direct_impact(double t_impact, double speed, double h);

// The reference (`exact`, or `event_driven` for an expression force; error 0 by definition, so no
// point on the diagrams): the CPU time of a solve sampled on kPenaltyGrid, and of one impact: for
// a constant force its time and speed from the closed form (averaged over the first 1000 impacts,
// or as many as there are), for f(t) a solve over [0, T] in one grid step over its number of
// impacts; NaN without one.
struct ExactCost {
  std::string method;
  SolveCost solve;
  std::int64_t grid_points = 0;
  double seconds_per_impact = 0;
};
ExactCost exact_cost(Scene scene, const TimingRule& rule);

}  // namespace impact
