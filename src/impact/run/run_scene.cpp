#include "impact/run/run_scene.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "impact/forces/work_energy.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/bond_events.hpp"
#include "impact/run/row_stream.hpp"
#include "impact/run/scene.hpp"
#include "impact/run/step_events.hpp"

namespace impact {
namespace {

[[noreturn, gnu::cold, gnu::noinline]] void throw_interrupted() {
  throw Interrupted{};
}

// The summary with a caller's stop flag read every 1024 steps, stepped locally as the summary
// alone, with no call on the loop's path (throw_interrupted does not return). The atomic load
// still makes GCC 12 keep the summary's values in memory: a rest replayed (repeats.hpp) costs
// 4.3 instead of 1.2 ns a step (the Python module's sweeps only; a flight or a force of t, no
// measurable change).
struct StoppableSummary {
  static constexpr bool kStepsLocally = true;
  static constexpr std::int64_t kEvery = 1024;
  SummaryObserver summary;
  const std::atomic<bool>* stop;
  template <class St>
  void operator()(std::int64_t l, const St& s, const StepInfo& info) {
    summary(l, s, info);
    if ((l & (kEvery - 1)) == 0) [[unlikely]]
      if (stop->load(std::memory_order_relaxed)) throw_interrupted();
  }
};

}  // namespace

RunReport run_scene(const Scene& scene, AnyStepper& stepper, const RunOutputs& outputs) {
  const auto start = std::chrono::steady_clock::now();
  const auto& channels = scene.output.channels;
  const auto has = [&](Channel c) { return std::ranges::count(channels, c) > 0; };
  const bool energy = outputs.rows && has(Channel::E);
  const bool own_events = method_info(scene.method).can.exact_events;
  // E with a time-dependent force needs the work of f over every step, not only the written ones;
  // so do a summary's E_T and the energy error against the reference. A method that follows the
  // motion between its events gives the work of each flight from its events (work_energy.hpp).
  std::optional<WorkEnergy> work;
  if ((energy || outputs.summary || outputs.against_exact) && !constant_force(scene.model))
    work.emplace(scene.model, scene.initial, scene.grid.h, own_events);
  // A method that knows its events dates the rest by them (its final stick), not on the grid.
  std::optional<double> rest_from_events;
  const bool rest_by_events = outputs.summary && own_events;
  std::optional<StepEvents> log;
  // A bonded model's events (bond_events.hpp) for the events and the summary's fates: the
  // method's events pass through it, to be merged with the bonds' in time.
  std::optional<BondEvents> bonds;
  const EventSink sink = [&](const Event& e) {
    if (work) work->event(e);
    if (e.kind == EventKind::stick)
      rest_from_events = e.t;
    else if (e.kind == EventKind::impact || e.kind == EventKind::lift)
      rest_from_events.reset();
    if (outputs.events) outputs.events(e);
  };
  if (bonded(scene.model) && (outputs.events || outputs.summary))
    bonds.emplace(scene.model, scene.grid.h, sink);
  if (outputs.events || (work && work->follows_motion()) || rest_by_events) {
    const EventSink held = [&](const Event& e) { bonds->hold(e); };
    if (!attach_event_sink(stepper, bonds ? held : sink) && outputs.events)
      log.emplace(scene.model, scene.grid.h, bonds ? held : outputs.events);
  }
  std::optional<ErrorObserver> errors;
  // What the reference does not follow is refused, never measured wrong.
  if (outputs.against_exact)
    if (const auto r = reference_refusal(scene.model))
      throw std::invalid_argument("the errors against the exact solution: " + r->message);
  if (outputs.against_exact) errors.emplace(scene.model, scene.initial, scene.grid);
  SummaryObserver summary(scene.model, scene.grid);

  // What must see every step runs out of line, on copies, so that a run without any keeps the
  // plain loop of its rows or of its summary. The summary steps in the loop itself when it is the
  // run's only output (the sweep), else it joins the out-of-line watch.
  const bool summary_inline = outputs.summary && !outputs.rows;
  // The caller's check and stop flag: in the rows' stream, or in the watch; the flag alone, where
  // the summary steps alone, beside it.
  const std::int64_t check_every =
      (outputs.check || outputs.stop) && outputs.check_every > 0 ? outputs.check_every : 0;
  const auto periodic = [&](std::int64_t l) {
    if (outputs.stop && outputs.stop->load(std::memory_order_relaxed)) throw_interrupted();
    if (outputs.check) outputs.check(l);
  };
  const bool stoppable_summary = summary_inline && check_every > 0 && !outputs.check;
  StepWatch watch;
  if (errors || work || log || bonds || outputs.watch || (outputs.summary && !summary_inline) ||
      (check_every > 0 && !outputs.rows && !stoppable_summary))
    watch = [&](std::int64_t l, const StateWithInternal& s, const StepInfo& info) {
      if (errors) (*errors)(l, s, info);
      // The step's events, all of them, before the work of the steps after them (work_energy.hpp).
      if (log && bonds) (*log)(l, s, info);
      if (bonds) (*bonds)(l, s);
      if (work && l > 0) work->step(l, s);
      if (log && !bonds) (*log)(l, s, info);
      if (outputs.summary && !summary_inline) {
        if (scene.model.internal.empty())
          summary(l, static_cast<const State&>(s), info);
        else
          summary(l, s, info);
      }
      if (outputs.watch) outputs.watch(l, s, info);
      if (check_every > 0 && !outputs.rows && l > 0 && l % check_every == 0) periodic(l);
    };

  RunReport report;
  if (outputs.rows) {
    RowStream stream(
        scene.output.every, scene.grid,
        [&](const OutputRow& r) {
          OutputRow row = r;
          if (energy) {
            const StateWithInternal at{row.state, row.internal};
            row.energy = work ? work->energy(at) : impact::energy(scene.model, at);
            if (!std::isfinite(row.energy)) [[unlikely]]
              throw NumericalError("at t = " + round_trip(scene.grid.t(row.l)) +
                                   (work ? ": the energy v^2/2 - f(0) u(0) - W(t) overflows"
                                         : ": the energy v^2/2 - f u (3-1) overflows") +
                                   " (u and v are finite)");
          }
          outputs.rows(row);
        },
        check_every, periodic);
    const bool sums = has(Channel::N) || has(Channel::iterations);
    report.summary = simulate_rows(stepper, scene.initial, scene.grid, stream, sums, watch,
                                   has(Channel::N_scheme));
  } else if (summary_inline && !watch && stoppable_summary) {
    StoppableSummary stoppable{summary, outputs.stop};
    report.summary = simulate(stepper, scene.initial, scene.grid, stoppable);
    summary = stoppable.summary;
  } else if (summary_inline && !watch) {
    report.summary = simulate(stepper, scene.initial, scene.grid, summary);
  } else if (summary_inline) {
    report.summary = simulate(stepper, scene.initial, scene.grid,
                              [&](std::int64_t l, const auto& s, const StepInfo& info) {
                                summary(l, s, info);
                                watch_step(watch, l, s, info);
                              });
  } else {
    report.summary = simulate(stepper, scene.initial, scene.grid,
                              [&](std::int64_t l, const auto& s, const StepInfo& info) {
                                if (watch) watch_step(watch, l, s, info);
                              });
  }
  const double total = seconds_since(start);
  if (outputs.summary) {
    report.point = summary.result(report.summary);
    // With f(t), E^n is the E channel's, v^2/2 - f(0) u(0) - W, summed over the same steps, so
    // that a sweep's E_T is impact run's last E bit for bit (with the bonds' energy and D from the
    // final internal state, as the rows take them).
    if (work)
      report.point->energy_final =
          work->energy(StateWithInternal{report.point->final, report.point->internal_final});
    // A bonded model's E^n holds the bonds' energy, beta from the final internal state (model.hpp).
    if (bonded(scene.model) && !work)
      report.point->energy_final = impact::energy(
          scene.model, StateWithInternal{report.point->final, report.point->internal_final});
    if (rest_by_events) report.point->rest_time = rest_from_events;
    if (bonds) report.point->bonds = bonds->fates();
  }
  if (errors) {
    // The energy error compares the E channel's E^n with the reference's E(T), as it defines E.
    report.errors = work ? errors->result(report.summary, work->energy(errors->final_state()))
                         : errors->result(report.summary);
    report.reference_seconds = errors->reference_seconds();
  }
  report.seconds = std::max(0.0, total - report.reference_seconds);
  return report;
}

}  // namespace impact
