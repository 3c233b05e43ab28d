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
    : h_(h), has_phasor_(model.harmonic.has_value()) {
  if (has_phasor_) {
    phasor_ = GridPhasor(*model.harmonic, h);
    amplitude_over_omega_ = model.harmonic->amplitude / model.harmonic->omega;
  }
  if (!model.expression.empty()) {
    Model expression_part;
    expression_part.expression = model.expression;
    expression_ = std::make_unique<ForceFunction>(expression_part);
  }
}

SchemeForce::SchemeForce(const SchemeForce& other)
    : h_(other.h_),
      has_phasor_(other.has_phasor_),
      phasor_(other.phasor_),
      amplitude_over_omega_(other.amplitude_over_omega_) {
  if (other.expression_) expression_ = std::make_unique<ForceFunction>(*other.expression_);
}

SchemeForce& SchemeForce::operator=(const SchemeForce& other) {
  if (this != &other) *this = SchemeForce(other);
  return *this;
}

double SchemeForce::expression_integral(const ForceFunction& expression, std::int64_t l, double h) {
  return expression.integral(static_cast<double>(l) * h, static_cast<double>(l + 1) * h);
}

SchemeFlight::SchemeFlight(const Model& model, double h) : f_(model.f), h_(h), force_(model, h) {
  if (model.harmonic && model.harmonic->omega * h <= kMaxClosedFormPhase) {
    closed_form_ = true;
    const double trapezoid = h / 2 / std::tan(model.harmonic->omega * h / 2);
    k_trapezoid_ = force_.amplitude_over_omega() * trapezoid;
  }
  stepped_part_ = !model.expression.empty() || (model.harmonic && !closed_form_);
}

}  // namespace impact
