// The ball on a vibrating table y = a sin(omega t + phase) as a scene of the package (the model of
// vibrating_table_theory.hpp in SI units: f(t) = -g + Gamma g sin(omega t + phase), phi = 0,
// COR = e) and what one run of any method says about it: its impacts and its rests on the table.
// The events are those `impact run --events` reports (step_events.hpp): the methods that know them
// exactly (exact) report them through set_event_sink; a time-stepper's are read off its steps by
// StepEvents (an impact dated where the step's flight under its mean force crosses the floor, a
// rest from two contact steps in a row ending at rest).
#pragma once

#include <cstdint>
#include <numbers>
#include <string_view>
#include <vector>

#include "impact/methods/capabilities.hpp"
#include "impact/model/event.hpp"
#include "impact/model/model.hpp"

namespace impact::vibrating_table {

inline constexpr double kTableGravity = 9.80665;                  // g, m/s^2
inline constexpr double kTableOmega = 2 * std::numbers::pi * 10;  // rad/s: a 10 Hz table

struct TableScene {
  double gamma = 1.0;  // a omega^2 / g
  double e = 0.5;      // restitution on the relative velocity
  double phase = 0.0;  // the table's phase at t = 0, rad
  State initial{};     // relative to the table, SI
  double omega = kTableOmega;
  double g = kTableGravity;

  double period() const { return 2 * std::numbers::pi / omega; }
  double speed_unit() const { return g / omega; }  // the theory's unit of speed
};

Model table_model(const TableScene& scene);

// A scene started just after an impact of the period-1 orbit of period n (closed form,
// vibrating_table_theory.hpp): u = 0, v = w* g / omega, with the table's phase at t = 0 set to the
// orbit's impact phase. Throws std::invalid_argument below the existence threshold.
TableScene table_scene_on_orbit(double gamma, double e, int n = 1);

// One event of a run as the diagrams use it: phase = omega t + phase mod 2 pi; for an impact the
// relative take-off speed (for a time-stepper the velocity at the end of the contact step), in
// units of g / omega.
struct TableEvent {
  double t = 0.0;
  EventKind kind = EventKind::impact;
  double phase = 0.0;
  double speed = 0.0;
};

struct TableRun {
  std::vector<TableEvent> events;  // those at t >= the transient, in increasing t
  State final_state{};             // at the last grid time
  std::int64_t impacts = 0;        // over the whole run
  std::int64_t steps = 0;
};

// Runs `method` with step h over `periods` table periods and keeps the events after the first
// `transient` periods (at most max_events of them; the rest are counted in impacts only).
TableRun run_table(const TableScene& scene, const MethodParams& method, double h, int periods,
                   int transient, std::size_t max_events = 4096);

// The state relative to the table at every grid time of `periods` table periods.
struct TableSample {
  double t = 0.0;
  State state{};
};
std::vector<TableSample> sample_table(const TableScene& scene, const MethodParams& method, double h,
                                      int periods);

// What the kept events say about the attractor.
// failed: the run stopped with a numerical failure (see SweepPoint::failure).
enum class TableRegime { period_one, periodic, aperiodic, sticking, resting, failed };

struct TableClassification {
  TableRegime regime = TableRegime::aperiodic;
  int period = 0;  // impacts per repetition, for period_one (1) and periodic
  // The median of |w_k - w_{k-1}| over the kept impacts (g / omega): the amplitude of a period-2
  // orbit, robust to the odd step of a time-stepper's impact that moves to the next grid time.
  double split = 0.0;
  double spread = 0.0;  // largest |w_k - w_{k-period}| (0 for an exact period)
};

// period_one: no rest, every flight within `tolerance` (phase units) of 2 pi n for one n and the
// speeds within `tolerance` of each other; periodic: the sequence repeats after p <= 16 impacts to
// `tolerance`; sticking: a rest among the kept events; resting: no event at all.
TableClassification classify_table_run(const TableRun& run, const TableScene& scene,
                                       double tolerance);

std::string_view regime_name(TableRegime regime);

}  // namespace impact::vibrating_table
