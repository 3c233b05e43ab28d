#include "impact/run_scene.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "impact/event_log.hpp"
#include "impact/output.hpp"
#include "impact/work_energy.hpp"

namespace impact {

RunReport run_scene(const Scene& scene, AnyStepper& stepper, const RunOutputs& outputs) {
  const auto start = std::chrono::steady_clock::now();
  const auto& channels = scene.output.channels;
  const auto has = [&](Channel c) { return std::ranges::count(channels, c) > 0; };
  const bool energy = has(Channel::E);
  // E with a time-dependent force needs the work of f over every step, not only the written ones.
  std::optional<WorkEnergy> work;
  if (energy && !constant_force(scene.model))
    work.emplace(scene.model, scene.initial, scene.grid.h);
  std::optional<EventLog> log;
  if (outputs.events && !attach_event_sink(stepper, outputs.events))
    log.emplace(scene.model, scene.grid.h, outputs.events);
  std::optional<ErrorObserver> errors;
  if (outputs.against_exact) errors.emplace(scene.model, scene.initial, scene.grid);

  RowStream stream(
      scene.output.every, scene.grid,
      [&](const OutputRow& r) {
        if (!outputs.rows) return;
        OutputRow row = r;
        if (energy) {
          row.energy = work ? work->energy(row.state) : impact::energy(scene.model, row.state);
          if (!std::isfinite(row.energy)) [[unlikely]]
            throw NumericalError("at t = " + round_trip(scene.grid.t(row.l)) +
                                 (work ? ": the energy v^2/2 - f(0) u(0) - W(t) overflows"
                                       : ": the energy v^2/2 - f u (3-1) overflows") +
                                 " (u and v are finite)");
        }
        outputs.rows(row);
      },
      outputs.check_every, outputs.check);
  StepWatch watch;
  if (errors || work || log)
    watch = [&](std::int64_t l, const State& s, const StepInfo& info) {
      if (errors) (*errors)(l, s, info);
      if (work && l > 0) work->step(l, s);
      if (log) (*log)(l, s, info);
    };
  RunReport report;
  const bool sums = has(Channel::N) || has(Channel::iterations);
  report.summary = simulate_rows(stepper, scene.initial, scene.grid, stream, sums, watch);
  const double total = seconds_since(start);
  if (errors) {
    report.errors = errors->result(report.summary);
    report.reference_seconds = errors->reference_seconds();
  }
  report.seconds = std::max(0.0, total - report.reference_seconds);
  return report;
}

}  // namespace impact
