#include "impact/scheme_flight.hpp"

#include <cmath>

#include "impact/free_flight.hpp"

namespace impact {

GridPhasor::GridPhasor(const Harmonic& w, double h)
    : omega_(w.omega),
      phase_(w.phase),
      h_(h),
      rot_c_(std::cos(w.omega * h)),
      rot_s_(std::sin(w.omega * h)) {
  seek(0);
}

void GridPhasor::anchor() {
  const double theta = omega_ * (static_cast<double>(l_) * h_) + phase_;
  c_ = std::cos(theta);
  s_ = std::sin(theta);
  countdown_ = kReanchorSteps;
}

void GridPhasor::seek(std::int64_t l) {
  l_ = l - l % kReanchorSteps;
  anchor();
  while (l_ < l) advance();
}

SchemeForce::SchemeForce(const Model& model, double h) : h_(h) {
  if (model.harmonic) {
    phasor_.emplace(*model.harmonic, h);
    amplitude_over_omega_ = model.harmonic->amplitude / model.harmonic->omega;
  }
  if (!model.expression.empty()) {
    Model expression_part;
    expression_part.expression = model.expression;
    expression_.emplace(expression_part);
  }
}

SchemeForce::Impulse SchemeForce::advance(std::int64_t l) {
  Impulse impulse;
  if (phasor_) {
    seek(l);
    const double c0 = phasor_->cos();
    phasor_->advance();
    // (a/w)(cos theta_l - cos theta_{l+1}); the difference cancels for short steps, to an absolute
    // error of a few ulp of a/w, the scale of the harmonic part of the velocity.
    impulse.harmonic = amplitude_over_omega_ * (c0 - phasor_->cos());
  }
  if (expression_)
    impulse.expression =
        expression_->integral(static_cast<double>(l) * h_, static_cast<double>(l + 1) * h_);
  return impulse;
}

SchemeFlight::SchemeFlight(const Model& model, double h) : f_(model.f), h_(h), force_(model, h) {
  if (model.harmonic && model.harmonic->omega * h <= kMaxClosedFormPhase) {
    closed_form_ = true;
    trapezoid_ = h / 2 / std::tan(model.harmonic->omega * h / 2);
  }
}

void SchemeFlight::start(std::int64_t l, const State& s) {
  anchor_l_ = l;
  anchor_ = s;
  stepped_ = {};
  force_.seek(l);
  if (closed_form_) {
    anchor_cos_ = force_.phasor()->cos();
    anchor_sin_ = force_.phasor()->sin();
  }
}

State SchemeFlight::step(std::int64_t l) {
  State next;
  free_flight(anchor_.u, anchor_.v, static_cast<double>(l + 1 - anchor_l_) * h_, f_, next.u,
              next.v);
  step_force_ = f_;
  if (force_.constant()) return next;
  const SchemeForce::Impulse impulse = force_.advance(l);
  const double stepped = closed_form_ ? impulse.expression : impulse.harmonic + impulse.expression;
  // (4-1)-(4-2) with N^l = 0 for the stepped part: u += h (V + I/2), V += I.
  stepped_.u += h_ * (stepped_.v + stepped / 2);
  stepped_.v += stepped;
  next.u += stepped_.u;
  next.v += stepped_.v;
  if (closed_form_) {
    const GridPhasor& now = *force_.phasor();
    const double k = force_.amplitude_over_omega();
    const double s = static_cast<double>(l + 1 - anchor_l_) * h_;
    next.v += k * (anchor_cos_ - now.cos());
    next.u += k * (s * anchor_cos_ - trapezoid_ * (now.sin() - anchor_sin_));
  }
  step_force_ = f_ + (impulse.harmonic + impulse.expression) / h_;
  return next;
}

}  // namespace impact
