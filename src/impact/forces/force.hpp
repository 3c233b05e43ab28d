// The body force f(t) of (2-1) as the solvers evaluate it: its value, its integral over a step
// (the discrete force of the schemes, see below) and, for a constant or harmonic force, the free
// flight in closed form. One ForceFunction per solver: an expression force owns a muparser
// parser, which is not safe to share between threads.
//
// A force of the state. An expression may read the position u and the velocity v besides t (the
// impact oscillator f = -k (u - u_eq) - c v + A sin(omega t)); (2-1) becomes u'' = N + f(t, u, v).
// Such a force is evaluated at a state: at(t, s), and its integral over a step with the state
// frozen at the step's start, integral(t0, t1, s), the explicit reading of the discrete force of
// the schemes (scheme_flight.hpp). The forms without a state refuse it (std::logic_error), so that
// no solver reads a force of the state as one of t alone.
//
// A linear force (Model::linear) is a force of the state too: a ForceFunction reads it as the
// expression linear_as_expression() writes, so that every method that takes a force of the state
// takes it (exact alone follows it in closed form, linear_law.hpp).
//
// Internal variables (model.hpp). An expression may also read the model's internal variables by
// their names; that too makes it a force of the state. Their values are the ForceFunction's own,
// set by the stepper that follows them (set_internal) before it evaluates f: a ForceFunction
// belongs to one solver, as its parser does.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "impact/model/model.hpp"

namespace impact {

class ForceFunction {
 public:
  // Throws std::invalid_argument for an expression that is empty, too long, does not parse (the
  // message gives the position), uses a variable other than t, u and v, or is not finite at
  // t = 0, u = v = 0.
  // A model's expression compiled by the scene reader is not parsed again (its copy here parses
  // once more, at its first evaluation: expression.hpp).
  explicit ForceFunction(const Model& model);

  bool constant() const { return !harmonic_ && model_.expression.empty(); }
  // Whether the expression reads u, v or an internal variable: a force of the state.
  bool state_dependent() const { return state_dependent_; }
  // The internal variables the expression reads from now on (z_1..z_m of the model, the rest 0).
  void set_internal(const std::array<double, kMaxInternal>& z) const;

  // f(t). Throws std::runtime_error naming t where an expression is not finite, std::logic_error
  // for a force of the state.
  double at(double t) const;
  // f(t, s.u, s.v), for any force (one of t alone ignores s).
  double at(double t, const State& s) const;
  // The integral of f over [t0, t1]: in closed form, or for an expression by 16-point
  // Gauss-Legendre (GSL), exact for polynomials of degree 31 over the interval, with its error
  // under control (step_quadrature.hpp: checked where the samples do not show a resolved f, then
  // adaptive); std::runtime_error for an interval it cannot resolve (a pole, a force too fast).
  // std::logic_error for a force of the state.
  double integral(double t0, double t1) const;
  // The integral of f(t, s.u, s.v) over [t0, t1] with the state frozen at s, as above.
  double integral(double t0, double t1, const State& s) const;
  // The discrete force of step l of the schemes (4-1)-(4-3): the step's mean (1/h) of the integral
  // of f over [t_l, t_{l+1}], which keeps the impulse identity h sum N^l = v^n - v^0 - integral of
  // f exact (4-9). For a constant force it is f.
  double step_mean(double t0, double h) const;
  // The same with the state frozen at s, the step's start (integral(t0, t0 + h, s) / h).
  double step_mean(double t0, double h, const State& s) const;
  // The exact free flight from (t0, s) to t1 (u'' = f(t), no contact): closed form for a constant
  // or harmonic force; std::logic_error for an expression (its flights are integrated by ODE).
  State flight(const State& s, double t0, double t1) const;
  // sup |f(t)| over all t, |f| + |amplitude|, for a constant or harmonic force (it bounds |u''| in
  // free flight, which brackets impact times rigorously); nullopt for an expression.
  std::optional<double> bound() const;

  const Model& model() const { return model_; }

 private:
  // The expression's value at t (and s), std::runtime_error where it fails or is not finite.
  double expression_at(double t) const;
  double expression_at(double t, const State& s) const;
  Model model_;  // its expression compiled, evaluated through this copy's own parser
  std::optional<Harmonic> harmonic_;
  bool state_dependent_ = false;
  mutable std::array<double, kMaxInternal> z_{};  // set_internal()
};

// A force expression's value at t and the state s with the internal variables z[0..m) (the scene
// reader's probe at the initial state); std::runtime_error naming t where it fails or is not
// finite, as ForceFunction::at.
double force_expression_at(const Expression& expression, double t, const State& s, const double* z);

// The model with its linear part (Model::linear), its constant part f and its harmonic part
// written as the one expression of the state they make, f - k * (u - u_eq) - c * v + amplitude *
// sin(omega * t + phase), each number with the digits that read back to it (a term that is zero
// left out); the model itself when it has no linear part.
Model linear_as_expression(const Model& model);

// Whether a model's force reads u, v or an internal variable: a linear part, or an expression that
// does (false for none, or for one that does not parse: the scene reader refuses that with its own
// message). An expression compiled by the reader is not parsed again.
bool state_force(const Model& model);

// The force-kind policy: what a time-stepper's body force needs, read once from the model by
// make_stepper (any_stepper.cpp). constant: nothing; harmonic: the grid phasor; general: any
// expression (of t or of the state, a linear force written as one), internal variables and/or a
// bonding field that acts (its pull a force of the state, beta and D in z), stepped always with
// StateWithInternal (with_internal.hpp; z zero-sized without [[internal]] or bonds).
// A new force or law is a runtime value inside one of these kinds, never a new stepper type.
enum class ForceKind { constant, harmonic, general };

inline ForceKind force_kind(const Model& model) {
  if (!model.internal.empty() || !model.expression.empty() || model.linear || bonded(model))
    return ForceKind::general;
  return model.harmonic ? ForceKind::harmonic : ForceKind::constant;
}

}  // namespace impact
