#include "analysis/impact_oscillator/oscillator_law.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "impact/registry.hpp"
#include "impact/run_scene.hpp"
#include "impact/scene.hpp"

namespace impact::impact_oscillator {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

Model rest_model(const LinearForce& f, double phi) {
  Model m;
  m.phi = phi;
  m.f = f.f0 - f.k * (phi - f.u_eq);
  if (f.amplitude != 0.0) m.harmonic = Harmonic{f.amplitude, f.omega, f.phase};
  return m;
}

}  // namespace

LinearLaw::LinearLaw(const LinearForce& force, double phi)
    : force_(force), phi_(phi), rest_law_(rest_model(force, phi)) {}

void LinearLaw::start(double t, double gap, double v, bool at_crossing) {
  flight_ = LinearFlight(force_, t, phi_ + gap, v);
  gap_ = gap;
  certified_ = checked_ = t;
  if (gap != 0.0 || v != 0.0) return;
  // A zero-speed departure: g'' = f_rest(t) and g''' = -c f_rest(t) + f_rest'(t) there; the
  // first stretch is certified by the next-order bounds, as flight_search.hpp's
  // zero_speed_departure does for a harmonic force.
  const double f = at_crossing ? 0.0 : force(t), rate = -force_.c * f + rest_law_.rate(t);
  const DepartureBounds bounds = flight_.departure_bounds(t);
  double stretch = 0.0;
  if (f > 0.0) stretch = bounds.C > 0.0 ? 1.5 * f / bounds.C : kInfinity;
  if (f >= 0.0 && rate > 0.0)
    stretch = std::fmax(stretch, bounds.D > 0 ? 2 * rate / bounds.D : kInfinity);
  certified_ += std::fmin(stretch, bounds.until - t);
}

std::optional<double> LinearLaw::chatter_window(double t, double V, double e) const {
  const double g = -force(t);
  if (!(g > 0.0)) return std::nullopt;
  const double W0 = chatter_trial_window(e, V, g);
  const double drift = std::fabs(force_.amplitude) * force_.omega * W0 + std::fabs(force_.c) * V;
  const double g_low = g - drift;
  if (!(g_low > 0.0)) return std::nullopt;
  const double spring = std::fabs(force_.k) * V * V / (2 * g_low);
  return chatter_window_within(e, V, W0, g_low - spring, g + drift + spring);
}

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
