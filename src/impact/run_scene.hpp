// One run of a scene with the outputs it asks for, as `impact run` makes it and as a program using
// the library can: the decimated rows (row_stream.hpp) with the scene's channels, the events, the
// errors against the reference, and the method's own time apart from the reference's.
#pragma once

#include <cstdint>
#include <optional>

#include "impact/error_norms.hpp"
#include "impact/events.hpp"
#include "impact/registry.hpp"
#include "impact/row_stream.hpp"
#include "impact/run.hpp"
#include "impact/scene.hpp"

namespace impact {

struct RunOutputs {
  // Each row (the scene's output.every) with its energy filled in when the scene's channels have E.
  RowStream::RowSink rows;
  EventSink events;  // empty: no events
  bool against_exact = false;
  // Called every check_every steps (a full disk, progress); 0: never.
  std::int64_t check_every = 0;
  RowStream::Check check;
};

struct RunReport {
  RunSummary summary;
  std::optional<ErrorNorms> errors;  // with against_exact
  double seconds = 0.0;              // wall time of the run without the reference's work
  double reference_seconds = 0.0;    // wall time of the reference (against_exact)
};

// Runs `stepper` (made for the scene, not yet initialized) over the scene's grid. Throws
// NumericalError as simulate() does, also when the energy of a row overflows.
RunReport run_scene(const Scene& scene, AnyStepper& stepper, const RunOutputs& outputs);

}  // namespace impact
