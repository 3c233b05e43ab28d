// One run of a scene as a value: impact::run(scene, options) returns the final state, the step
// counts, and what the options ask for (the rows, kept or streamed; the events, kept or streamed;
// the PointSummary; the errors against the exact reference) with the run's wall time. It is
// run_scene() (run_scene.hpp) with the stepper made here, so that its rows and events are, bit
// for bit, those `impact run` writes for the same scene.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "impact/loop/simulate.hpp"
#include "impact/model/event.hpp"
#include "impact/model/model.hpp"
#include "impact/run/error_norms.hpp"
#include "impact/run/row_stream.hpp"
#include "impact/run/scene.hpp"
#include "impact/run/summary.hpp"

namespace impact {

struct RunOptions {
  // The rows of the scene's output (output.every, output.channels; E filled in where the channels
  // have it): kept in RunResult::rows, and/or handed to on_row as the run makes them.
  bool keep_rows = false;
  std::function<void(const OutputRow&)> on_row;
  // The events (impacts, sticks, releases): kept in RunResult::events, and/or handed to on_event.
  bool keep_events = false;
  EventSink on_event;
  bool summary = false;            // RunResult::summary, the run's PointSummary in O(1) memory
  bool against_reference = false;  // RunResult::errors against the exact solution (exact.hpp)
  StepWatch watch;                 // the caller's own observer of every step (out of line)
  // Called every check_every steps (progress, a full disk, a request to stop); 0: never.
  std::int64_t check_every = 0;
  std::function<void(std::int64_t l)> check;
  // Set by another thread to stop the run: read every check_every steps, it throws Interrupted.
  const std::atomic<bool>* stop = nullptr;
};

struct RunResult {
  StateWithInternal final;  // u, v and the internal variables at the grid's last time, T
  RunSummary steps;         // steps, contact steps, iterations
  std::optional<PointSummary> summary;  // with RunOptions::summary
  std::vector<OutputRow> rows;          // with keep_rows
  std::vector<Event> events;            // with keep_events
  std::optional<ErrorNorms> errors;     // with against_reference
  double seconds = 0.0;                 // wall time of the run without the reference's work
  double reference_seconds = 0.0;       // wall time of the reference (against_reference)
};

// Runs the scene's method over its grid. Throws std::invalid_argument for a method the scene's
// problem refuses (make_stepper), NumericalError for a step that gives a non-finite value or does
// not converge, Interrupted when `stop` is set, and what on_row, on_event, watch and check throw.
RunResult run(const Scene& scene, const RunOptions& options = {});

// run() of the scene with a summary (and the errors against the reference when against_exact):
// one point of `impact sweep`; `stop`, when given, read every check_every steps.
PointOutcome summarize(const Scene& scene, bool against_exact,
                       const std::atomic<bool>* stop = nullptr, std::int64_t check_every = 0);

}  // namespace impact
