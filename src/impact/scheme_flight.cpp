#include "impact/scheme_flight.hpp"

#include <cmath>

namespace impact {

GridPhasor::GridPhasor(const Harmonic& w, double h)
    : omega_(w.omega), h_(h), table_(static_cast<std::size_t>(kLevels * kBase)) {
  phase_ = {std::cos(w.phase), std::sin(w.phase)};
  for (int k = 0; k < kLevels; ++k)
    for (int d = 0; d < kBase; ++d) {
      const double a = angle(k, d);
      table_[static_cast<std::size_t>(k * kBase + d)] = {std::cos(a), std::sin(a)};
    }
  seek(0);
}

double GridPhasor::angle(int k, int d) const {
  return omega_ * (static_cast<double>(static_cast<std::int64_t>(d) << (kDigitBits * k)) * h_);
}

SchemeForce::SchemeForce(const Model& model, double h)
    : phi_(model.phi), h_(h), has_phasor_(model.harmonic.has_value()) {
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
    expression_ = std::make_unique<ForceFunction>(expression_part);
  }
}

SchemeForce::SchemeForce(const SchemeForce& other)
    : phi_(other.phi_),
      h_(other.h_),
      has_phasor_(other.has_phasor_),
      slow_(other.slow_),
      phasor_(other.phasor_),
      amplitude_over_omega_(other.amplitude_over_omega_),
      slow_impulse_(other.slow_impulse_),
      cos_half_(other.cos_half_),
      sin_half_(other.sin_half_) {
  if (other.expression_) expression_ = std::make_unique<ForceFunction>(*other.expression_);
}

SchemeForce& SchemeForce::operator=(const SchemeForce& other) {
  if (this != &other) *this = SchemeForce(other);
  return *this;
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
  stepped_part_ = !model.expression.empty() || (model.harmonic && !closed_form_ && !force_.slow());
}

}  // namespace impact
