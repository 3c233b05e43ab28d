// Work against precision: the error of a solver against the exact solution and the CPU
// time of its solve, for a sweep of the step h (the time-steppers) or of the tolerance (penalty),
// as DifferentialEquations.jl's work-precision sets do it: the solve alone is timed (the stepper is
// built before the clock starts, output is off), after a warm-up, repeated; the minimum and the
// median over the repetitions are kept.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/fit.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/model/model.hpp"
#include "impact/run/error_norms.hpp"
#include "impact/run/scene.hpp"
#include "impact/run/step_events.hpp"

namespace impact {

// CPU time of this process (user + system), in seconds: what a solve costs, whatever else the
// machine runs at the same time.
double cpu_seconds();

struct SolveCost {
  double min = 0;     // CPU seconds of one solve: the fastest repetition
  double median = 0;  // and the median one
  int repetitions = 0;
  int batch = 1;  // solves per timed repetition (short solves are timed in batches)
};

// How long to time: a warm-up, then at least min_repetitions, and more (up to max_repetitions)
// while their total stays under budget_seconds. A solve shorter than min_sample_seconds is
// repeated `batch` times inside one timed repetition, so that the clock's resolution and cost do
// not dominate.
struct TimingRule {
  int min_repetitions = 3;
  int max_repetitions = 9;
  double budget_seconds = 0.05;
  double min_sample_seconds = 2e-4;
};

// Times solve(stepper) on freshly built steppers: make() builds one (not timed).
template <class Make>
SolveCost time_solve(Make&& make, const State& initial, const Grid& grid, const TimingRule& rule);

// The four error measures of the study, as measure_errors() computes them.
enum class ErrorMeasure { sup_u, l1_v, energy_end, first_impact };
inline constexpr ErrorMeasure kErrorMeasures[] = {
    ErrorMeasure::sup_u, ErrorMeasure::l1_v, ErrorMeasure::energy_end, ErrorMeasure::first_impact};
// One row per measure (work_precision.cpp's table): its name, as the CSV columns and the report's
// keys say it, and its axis label with its unit (plot.gp's mlabel(), without enhanced text).
struct MeasureInfo {
  ErrorMeasure measure;
  std::string_view name;
  std::string_view axis_label;
};
const MeasureInfo& measure_info(ErrorMeasure m);
inline std::string_view measure_name(ErrorMeasure m) {
  return measure_info(m).name;
}
// The measure as a non-negative number (|first impact time error|; NaN when there is none).
double error_of(const ErrorNorms& e, ErrorMeasure m);

// One point of a work-precision diagram.
struct WorkPrecisionPoint {
  double h = 0;
  double tolerance = 0;  // the rtol of an adaptive solver (penalty), 0 for a time-stepper
  std::int64_t steps = 0;
  ErrorNorms errors;  // against the exact solution, from one run
  SolveCost cost;
  double reference_seconds = 0;  // wall time of the reference's work in that run (ErrorObserver)
};

// Errors from one run of a stepper built by make() against the model's reference (measure_errors:
// the closed form, or for f(t) the event-driven solution), cost from time_solve() when a rule is
// given.
template <class Make>
WorkPrecisionPoint measure_point(Make&& make, const Model& model, const State& initial,
                                 const Grid& grid, const std::optional<TimingRule>& rule) {
  WorkPrecisionPoint p;
  p.h = grid.h;
  p.steps = grid.steps;
  auto stepper = make();
  ErrorObserver observer(model, initial, grid);  // measure_errors(), with the reference's time
  // A method that dates its own impacts (event_driven) is measured by its first impact event, not
  // by the floor crossing estimated from its grid states, which is the grid's error, not its own.
  std::optional<double> own_first_impact;
  const EventSink first_impact = [&own_first_impact](const Event& e) {
    if (e.kind == EventKind::impact && !own_first_impact) own_first_impact = e.t;
  };
  if constexpr (requires { attach_event_sink(stepper, first_impact); })
    attach_event_sink(stepper, first_impact);
  p.errors = observer.result(simulate(stepper, initial, grid, observer));
  if (const auto t1 = observer.reference_first_impact(); own_first_impact && t1)
    p.errors.first_impact = *own_first_impact - *t1;
  p.reference_seconds = observer.reference_seconds();
  if (rule) p.cost = time_solve(make, initial, grid, *rule);
  return p;
}

// One point for the scene as it stands (its method, h and [method] keys): errors always, the cost
// only when a timing rule is given (the tests measure errors only).
WorkPrecisionPoint measure_scene(const Scene& scene, const std::optional<TimingRule>& rule);

// A curve: the scene (its method) on the grid of each step h covering its [0, T]; after_point()
// after each point.
std::vector<WorkPrecisionPoint> sweep_steps(Scene scene, const std::vector<double>& steps,
                                            const std::optional<TimingRule>& rule,
                                            const std::function<void()>& after_point = {});

// The observed order of a measure over a curve: the least-squares slope of log error against
// log h (fit.hpp's fit_order) over the points whose error is above `floor` (below it the
// error is rounding, not discretisation).
OrderFit observed_order(const std::vector<WorkPrecisionPoint>& points, ErrorMeasure m,
                        double floor = 1e-13);

// The least cost (min over repetitions) among the points whose error is at most `target`.
std::optional<double> cost_to_reach(const std::vector<WorkPrecisionPoint>& points, ErrorMeasure m,
                                    double target);

// Step sizes 1, 2 and 5 times the powers of ten from h_max down to h_min (e.g. 0.1, 0.05, 0.02,
// 0.01, ...), the doubles nearest those decimals: T / h is a whole number for the paper's T = 10
// and the impact at t = 5 of Figure 3 lies on every grid.
std::vector<double> steps_125(double h_max, double h_min);

// --- implementation of the templates ---

template <class Make>
SolveCost time_solve(Make&& make, const State& initial, const Grid& grid, const TimingRule& rule) {
  const auto no_output = [](std::int64_t, const State&, const StepInfo&) {};
  // One timed repetition: `batch` solves on steppers built before the clock starts.
  const auto repetition = [&](int batch) {
    std::vector<decltype(make())> steppers;
    steppers.reserve(static_cast<std::size_t>(batch));
    for (int i = 0; i < batch; ++i) steppers.push_back(make());
    const double start = cpu_seconds();
    for (auto& stepper : steppers) simulate(stepper, initial, grid, no_output);
    return cpu_seconds() - start;
  };
  SolveCost cost;
  // A first, untimed solve warms up (page faults, caches, lazy binding). Then the batch is doubled
  // until a repetition takes min_sample_seconds, judged by the faster of two: one repetition
  // slowed by an interruption (a cold start, another process) would leave a microsecond solve
  // unbatched, timed at the clock's resolution.
  repetition(1);
  while (std::min(repetition(cost.batch), repetition(cost.batch)) < rule.min_sample_seconds &&
         cost.batch < (1 << 20))
    cost.batch *= 2;
  std::vector<double> times;
  double total = 0;
  while (static_cast<int>(times.size()) < rule.min_repetitions ||
         (static_cast<int>(times.size()) < rule.max_repetitions && total < rule.budget_seconds)) {
    times.push_back(repetition(cost.batch) / cost.batch);
    total += times.back() * cost.batch;
  }
  std::sort(times.begin(), times.end());
  cost.repetitions = static_cast<int>(times.size());
  cost.min = times.front();
  const std::size_t n = times.size();
  cost.median = n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
  return cost;
}

}  // namespace impact
