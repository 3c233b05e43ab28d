#include "impact/forces/scheme_flight.hpp"

#include <cmath>
#include <memory>

namespace impact {

GridPhasor::GridPhasor(const Harmonic& w, double h) : omega_(w.omega), h_(h) {
  phase_ = {std::cos(w.phase), std::sin(w.phase)};
  auto table = std::make_unique<std::array<Pair, kLevels * kBase>>();
  for (int k = 0; k < kLevels; ++k)
    for (int d = 0; d < kBase; ++d) {
      const double a = angle(k, d);
      (*table)[static_cast<std::size_t>(k * kBase + d)] = {std::cos(a), std::sin(a)};
    }
  table_ = HeapValue(std::move(table));
  seek(0);
}

double GridPhasor::angle(int k, int d) const {
  return omega_ * (static_cast<double>(static_cast<std::int64_t>(d) << (kDigitBits * k)) * h_);
}

SchemeForce::SchemeForce(const Model& model, double h)
    : phi_(model.phi), h_(h), has_phasor_(model.harmonic.has_value()) {
  if (bonded(model)) bonds_ = model.bonding;
  if (has_phasor_) {
    const Harmonic& w = *model.harmonic;
    phasor_ = GridPhasor(w, h);
    amplitude_over_omega_ = w.amplitude / w.omega;
    slow_ = w.omega * h < kSlowPhase;
    if (slow_) {
      const double half = w.omega * h / 2;  // < 1.6e-7: sinc(half) = 1 - half^2/6 to rounding
      slow_impulse_ = w.amplitude * h * (1 - half * half / 6);
      cos_half_ = std::cos(half);
      sin_half_ = std::sin(half);
    }
  }
  if (!model.expression.empty()) {
    Model expression_part;
    expression_part.expression = model.expression;
    expression_part.internal = model.internal;
    expression_ = HeapValue(std::make_unique<ForceFunction>(expression_part));
  }
}

double SchemeForce::expression_integral(const ForceFunction& expression, std::int64_t l, double h,
                                        double phi, State at) {
  const double t0 = static_cast<double>(l) * h, t1 = static_cast<double>(l + 1) * h;
  if (!expression.state_dependent()) return expression.integral(t0, t1);
  return expression.integral(t0, t1, {phi + at.u, at.v});
}

SchemeFlight::SchemeFlight(const Model& model, double h) : f_(model.f), h_(h), force_(model, h) {
  if (force_.slow()) {
    amplitude_ = model.harmonic->amplitude;
    omega_ = model.harmonic->omega;
    h2_over_12_ = h * h / 12;
  } else if (model.harmonic && model.harmonic->omega * h <= kMaxClosedFormPhase) {
    closed_form_ = true;
    const double trapezoid = h / 2 / std::tan(model.harmonic->omega * h / 2);
    k_trapezoid_ = force_.amplitude_over_omega() * trapezoid;
  }
  stepped_part_ = !model.expression.empty() || bonded(model) ||
                  (model.harmonic && !closed_form_ && !force_.slow());
}

}  // namespace impact
