#include "analysis/impact_oscillator/oscillator_law.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "impact/run/any_stepper.hpp"
#include "impact/run/run_scene.hpp"
#include "impact/run/scene.hpp"

namespace impact::impact_oscillator {

LinearTrack oscillator_track(const Oscillator& o, const State& initial, double t0) {
  return LinearTrack(LinearLaw(oscillator_force(o.omega), o.phi()), oscillator_model(o), initial,
                     t0);
}

TrackRun run_track(const Oscillator& o, const State& initial, double T, double t0,
                   std::size_t max_events) {
  TrackRun run;
  LinearTrack track = oscillator_track(o, initial, t0);
  track.set_event_limit(static_cast<std::int64_t>(max_events));
  track.set_event_sink([&run](const Event& e) { run.events.push_back(e); });
  double impulse = 0.0;
  run.final_state = track.advance(T, impulse);
  run.converged = track.converged();
  return run;
}

std::optional<Impact> impact_map(const Oscillator& o, const Impact& from, double horizon) {
  const LinearFlight flight(oscillator_force(o.omega), from.t, o.phi(), o.r * from.V);
  double certified = from.t, checked = from.t;
  long budget = 1'000'000;
  const auto contact =
      search_linear_contact(flight, 0.0, certified, checked, from.t + horizon, budget);
  if (!contact) return std::nullopt;
  return Impact{contact->t - contact->late, -contact->v};
}

bool orbit_is_admissible(const Oscillator& o, const PeriodOneOrbit& orbit) {
  const auto next = impact_map(o, {orbit.t0, orbit.V}, 2 * orbit.T);
  return next && std::fabs(next->t - (orbit.t0 + orbit.T)) <= 1e-9 * (1 + orbit.T);
}

std::vector<Event> event_driven_events(const Oscillator& o, const State& initial, double T,
                                       double h) {
  Model model = oscillator_model(o);
  model.expression = oscillator_expression(o.omega);
  const Scene scene = make_scene(model, initial, T, h, EventDrivenParams{});
  AnyStepper stepper = make_stepper(scene);
  std::vector<Event> events;
  RunOutputs outputs;
  outputs.events = [&events](const Event& e) { events.push_back(e); };
  run_scene(scene, stepper, outputs);
  return events;
}

double impact_phase(double t, double omega) {
  const double period = 2 * std::numbers::pi / omega;
  double phase = std::fmod(t, period);
  if (phase < 0) phase += period;
  return phase;
}

}  // namespace impact::impact_oscillator
