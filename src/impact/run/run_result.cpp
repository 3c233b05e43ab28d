#include "impact/run/run_result.hpp"

#include <algorithm>
#include <utility>

#include "impact/run/run_scene.hpp"

namespace impact {
namespace {

StateWithInternal with_internal(const State& s, const std::array<double, kMaxInternal>& z) {
  StateWithInternal full;
  static_cast<State&>(full) = s;
  full.z = z;
  return full;
}

}  // namespace

RunResult run(const Scene& scene, const RunOptions& options) {
  AnyStepper stepper = make_stepper(scene);
  RunResult result;
  RunOutputs outputs;
  // The final state comes from what the run observes anyway, so that asking for it adds no work to
  // a step: the last row (the row stream always writes the last step), else the summary's final
  // state; a run that asks for neither streams the scene's grid with one row at its end and no
  // channels, the cheapest observer there is.
  const bool rows = options.keep_rows || static_cast<bool>(options.on_row);
  OutputRow last;
  if (rows)
    outputs.rows = [&](const OutputRow& row) {
      if (options.on_row) options.on_row(row);
      if (options.keep_rows) result.rows.push_back(row);
      last = row;
    };
  if (options.keep_events || options.on_event)
    outputs.events = [&](const Event& e) {
      if (options.on_event) options.on_event(e);
      if (options.keep_events) result.events.push_back(e);
    };
  outputs.against_exact = options.against_reference;
  outputs.summary = options.summary;
  outputs.watch = options.watch;
  outputs.check_every = options.check_every;
  outputs.check = options.check;
  outputs.stop = options.stop;

  RunReport report;
  if (rows || options.summary) {
    report = run_scene(scene, stepper, outputs);
  } else {
    Scene final_only = scene;
    final_only.output = Output{{}, std::max<std::int64_t>(scene.grid.steps, 1)};
    outputs.rows = [&](const OutputRow& row) { last = row; };
    report = run_scene(final_only, stepper, outputs);
  }
  if (report.point)
    result.final = with_internal(report.point->final, report.point->internal_final);
  else
    result.final = with_internal(last.state, last.internal);
  result.steps = report.summary;
  result.summary = std::move(report.point);
  result.errors = report.errors;
  result.seconds = report.seconds;
  result.reference_seconds = report.reference_seconds;
  return result;
}

PointOutcome summarize(const Scene& scene, bool against_exact, const std::atomic<bool>* stop,
                       std::int64_t check_every) {
  RunOptions options;
  options.summary = true;
  options.against_reference = against_exact;
  options.stop = stop;
  options.check_every = check_every;
  RunResult result = impact::run(scene, options);
  return {*result.summary, result.errors, result.reference_seconds};
}

}  // namespace impact
