// One run of a scene with the outputs it asks for, as `impact run` and `impact sweep` make it and
// as a program using the library can: the decimated rows (row_stream.hpp) with the scene's
// channels, a summary, the events, the errors against the reference, and the method's own time
// apart from the reference's.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>

#include "impact/loop/simulate.hpp"
#include "impact/model/event.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/error_norms.hpp"
#include "impact/run/row_stream.hpp"
#include "impact/run/scene.hpp"
#include "impact/run/summary.hpp"

namespace impact {

struct RunOutputs {
  // Each row (the scene's output.every) with its energy filled in when the scene's channels have E.
  RowStream::RowSink rows;
  EventSink events;  // empty: no events
  bool against_exact = false;
  bool summary = false;  // the run's PointSummary in O(1) memory (a sweep's row, summary.hpp)
  StepWatch watch;       // a caller's own observer of every step (out of line); empty: none
  // Called every check_every steps (a full disk, progress, a Ctrl-C seen by the Python module),
  // with rows or without; 0: never.
  std::int64_t check_every = 0;
  RowStream::Check check;
  // Set by another thread to stop the run: read every check_every steps (every 1024 where the
  // summary alone steps, a sweep's point, without a call in the step loop), it throws Interrupted.
  const std::atomic<bool>* stop = nullptr;
};

struct RunReport {
  RunSummary summary;
  std::optional<PointSummary> point;  // with summary
  std::optional<ErrorNorms> errors;   // with against_exact
  double seconds = 0.0;               // wall time of the run without the reference's work
  double reference_seconds = 0.0;     // wall time of the reference (against_exact)
};

// Runs `stepper` (made for the scene, not yet initialized) over the scene's grid, with every
// observer a run needs assembled here and only here: rows, summary, events, errors, the work of
// f(t), the caller's watch. Throws NumericalError as simulate() does, also when the energy of a
// row overflows.
RunReport run_scene(const Scene& scene, AnyStepper& stepper, const RunOutputs& outputs);

}  // namespace impact
