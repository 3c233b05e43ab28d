// The exact solution for a linear force; conventions in linear_law.hpp.
#include "impact/references/linear_law.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace impact {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The model of the force on the floor, f_rest(t): a constant and the harmonic term.
Model rest_model(const LinearForce& f, double phi) {
  Model m;
  m.phi = phi;
  m.f = f.f0 - f.k * (phi - f.u_eq);
  if (f.amplitude != 0.0) m.harmonic = Harmonic{f.amplitude, f.omega, f.phase};
  return m;
}

}  // namespace

LinearForce linear_force(const Model& model) {
  LinearForce force;
  if (model.linear) {
    force.k = model.linear->k;
    force.c = model.linear->c;
    force.u_eq = model.linear->u_eq;
  }
  force.f0 = model.f;
  if (model.harmonic && model.harmonic->amplitude != 0.0) {
    force.amplitude = model.harmonic->amplitude;
    force.omega = model.harmonic->omega;
    force.phase = model.harmonic->phase;
  }
  return force;
}

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

LinearTrack linear_track(const Model& model, const State& initial, double t0) {
  if (!model.expression.empty())
    throw std::invalid_argument(
        "exact: a linear force is the whole force of the state; it takes no expression beside it");
  if (!model.internal.empty())
    throw std::invalid_argument("exact: a linear force's closed form has no internal variables");
  if (model.harmonic && model.harmonic->amplitude != 0.0 && !(model.harmonic->omega > 0.0))
    throw std::invalid_argument("exact: the harmonic force needs omega > 0");
  // LinearFlight checks that the data are finite where the track starts its first flight.
  return LinearTrack(LinearLaw(linear_force(model), model.phi), model, initial, t0);
}

}  // namespace impact
