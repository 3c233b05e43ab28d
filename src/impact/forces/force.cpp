#include "impact/forces/force.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string_view>

#include "impact/forces/harmonic_series.hpp"
#include "impact/forces/internal.hpp"
#include "impact/forces/step_quadrature.hpp"
#include "impact/format.hpp"

namespace impact {

ForceFunction::ForceFunction(const Model& model)
    : model_(linear_as_expression(model)), harmonic_(model_.harmonic) {
  if (!model_.expression.empty()) {
    model_.expression = model_.expression.compiled(model_.internal);
    state_dependent_ = model_.expression.reads_state();
  }
  // Until a stepper sets them, the internal variables are at their values at t = 0.
  for (std::size_t i = 0; i < model_.internal.size() && i < kMaxInternal; ++i)
    z_[i] = model_.internal[i].initial;
}

namespace {

// eval() at t, with what fails or is not finite named as a force expression's.
template <class Eval>
double checked(double t, const Eval& eval) {
  double value;
  try {
    value = eval();
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("the force expression fails at t = " + round_trip(t) + ": " +
                             e.what());
  }
  if (!std::isfinite(value))
    throw std::runtime_error("the force expression is " + round_trip(value) + " at t = " +
                             round_trip(t) + "; it must be finite wherever the run evaluates it");
  return value;
}

}  // namespace

double force_expression_at(const Expression& expression, double t, const State& s,
                           const double* z) {
  return checked(t, [&] { return expression(t, s.u, s.v, z); });
}

double ForceFunction::expression_at(double t) const {
  return checked(t, [&] { return model_.expression(t); });
}

double ForceFunction::expression_at(double t, const State& s) const {
  return force_expression_at(model_.expression, t, s, z_.data());
}

double ForceFunction::at(double t) const {
  if (state_dependent_)
    throw std::logic_error("ForceFunction::at(t): the force reads u or v; give the state");
  double value = model_.f;
  if (harmonic_) value += harmonic_->amplitude * std::sin(harmonic_->omega * t + harmonic_->phase);
  if (!model_.expression.empty()) value += expression_at(t);
  return value;
}

double ForceFunction::at(double t, const State& s) const {
  if (!state_dependent_) return at(t);
  // An expression of the state is the whole force (the reader refuses f and a harmonic part
  // beside an expression), so f and the harmonic part are zero here.
  return model_.f + expression_at(t, s);
}

double ForceFunction::integral(double t0, double t1) const {
  if (state_dependent_)
    throw std::logic_error(
        "ForceFunction::integral(t0, t1): the force reads u or v; give the state");
  double value = model_.f * (t1 - t0);
  // cos(a) - cos(b) = 2 sin((a + b)/2) sin((b - a)/2), without cancellation for short steps.
  if (harmonic_) value += harmonic_integral(*harmonic_, t0, t1);
  if (!model_.expression.empty()) {
    const Integrand f{[](double t, void* self) {
                        return static_cast<const ForceFunction*>(self)->expression_at(t);
                      },
                      const_cast<ForceFunction*>(this)};
    value += controlled_integral(f, t0, t1);
  }
  return value;
}

double ForceFunction::integral(double t0, double t1, const State& s) const {
  if (!state_dependent_) return integral(t0, t1);
  struct Frozen {
    const ForceFunction* force;
    State s;
  } frozen{this, s};
  const Integrand f{[](double t, void* self) {
                      const auto* at = static_cast<const Frozen*>(self);
                      return at->force->expression_at(t, at->s);
                    },
                    &frozen};
  return model_.f * (t1 - t0) + controlled_integral(f, t0, t1);
}

double ForceFunction::step_mean(double t0, double h) const {
  if (constant()) return model_.f;
  return integral(t0, t0 + h) / h;
}

double ForceFunction::step_mean(double t0, double h, const State& s) const {
  if (!state_dependent_) return step_mean(t0, h);
  return integral(t0, t0 + h, s) / h;
}

State ForceFunction::flight(const State& s, double t0, double t1) const {
  if (!model_.expression.empty())
    throw std::logic_error("ForceFunction::flight: an expression force has no closed form");
  const double dt = t1 - t0;
  State next{s.u + dt * (s.v + dt * model_.f / 2), s.v + dt * model_.f};
  if (harmonic_) {
    // u'' = a sin(w t + p): v gains (a/w)(cos(w t0 + p) - cos(w t1 + p)) and u gains
    // (a/w) cos(w t0 + p) dt - (a/w^2)(sin(w t1 + p) - sin(w t0 + p)), the differences written
    // as products so that a short flight keeps its digits. Where w dt < 1/2 the u term still
    // cancels (dt - sin(w dt)/w), so the flight is summed as harmonic_series.hpp writes it.
    const Harmonic& w = *harmonic_;
    const double a0 = w.omega * t0 + w.phase, x = w.omega * dt;
    const double k = w.amplitude / w.omega;
    if (std::fabs(x) < 0.5 || !std::isfinite(k / w.omega)) {
      const SlowAngle terms = slow_angle(x);
      const double c = std::cos(a0), s = std::sin(a0), a_dt = w.amplitude * dt;
      next.v += a_dt * (c * terms.c1 + s * terms.s1);
      next.u += a_dt * dt * (c * terms.s2 + s * terms.c2);
      return next;
    }
    const double mid = w.omega * (t0 + t1) / 2 + w.phase, half = w.omega * dt / 2;
    next.v += k * 2 * std::sin(mid) * std::sin(half);
    next.u += k * (std::cos(a0) * dt - 2 * std::cos(mid) * std::sin(half) / w.omega);
  }
  return next;
}

void ForceFunction::set_internal(const std::array<double, kMaxInternal>& z) const {
  z_ = z;
}

Model linear_as_expression(const Model& model) {
  if (!model.linear) return model;
  // A number as the expression reads it back: parenthesized, so that a sign is no operator.
  const auto number = [](double x) {
    std::string text = "(";
    text += round_trip(x);
    text += ')';
    return text;
  };
  const LinearSpring& spring = *model.linear;
  std::string text = number(model.f);
  if (spring.k != 0.0) text += " - " + number(spring.k) + " * (u - " + number(spring.u_eq) + ")";
  if (spring.c != 0.0) text += " - " + number(spring.c) + " * v";
  if (model.harmonic && model.harmonic->amplitude != 0.0) {
    const Harmonic& w = *model.harmonic;
    text += " + " + number(w.amplitude) + " * sin(" + number(w.omega) + " * t + " +
            number(w.phase) + ")";
  }
  // u and v named even where k = c = 0, so that the force stays one of the state for every method.
  if (spring.k == 0.0 && spring.c == 0.0) text += " + 0 * u";
  Model expression = model;
  expression.f = 0.0;
  expression.harmonic.reset();
  expression.linear.reset();
  expression.expression = text;
  return expression;
}

bool state_force(const Model& model) {
  if (model.linear) return true;
  if (model.expression.empty()) return false;
  try {
    return model.expression.compiled(model.internal).reads_state();
  } catch (const std::invalid_argument&) {
    return false;
  }
}

std::optional<double> ForceFunction::bound() const {
  if (!model_.expression.empty()) return std::nullopt;
  return std::fabs(model_.f) + (harmonic_ ? std::fabs(harmonic_->amplitude) : 0.0);
}

}  // namespace impact
