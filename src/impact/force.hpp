// The body force f(t) of (2-1) as the solvers evaluate it: its value, its integral over a step
// (the discrete force of the schemes, see below) and, for a constant or harmonic force, the free
// flight in closed form. One ForceFunction per solver: an expression force owns a muparser
// parser, which is not safe to share between threads.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "impact/model.hpp"

namespace impact {

// The longest expression a scene may give (characters).
inline constexpr std::size_t kMaxExpressionLength = 4096;

class ForceFunction {
 public:
  // Throws std::invalid_argument for an expression that is empty, too long, does not parse (the
  // message gives the position), uses a variable other than t, or is not finite at t = 0.
  explicit ForceFunction(const Model& model);
  ForceFunction(const ForceFunction& other);
  ForceFunction& operator=(const ForceFunction& other);
  ForceFunction(ForceFunction&&) noexcept;
  ForceFunction& operator=(ForceFunction&&) noexcept;
  ~ForceFunction();

  bool constant() const { return !harmonic_ && !expression_; }
  bool has_expression() const { return expression_ != nullptr; }

  // f(t). Throws std::runtime_error naming t where an expression is not finite.
  double at(double t) const;
  // The integral of f over [t0, t1]: in closed form, or for an expression by 16-point
  // Gauss-Legendre (GSL), exact for polynomials of degree 31 over the interval, with its error
  // under control (step_quadrature.hpp: checked where the samples do not show a resolved f, then
  // adaptive); std::runtime_error for an interval it cannot resolve (a pole, a force too fast).
  double integral(double t0, double t1) const;
  // The discrete force of step l of the schemes (4-1)-(4-3): the step's mean (1/h) of the integral
  // of f over [t_l, t_{l+1}], which keeps the impulse identity h sum N^l = v^n - v^0 - integral of
  // f exact (4-9). For a constant force it is f.
  double step_mean(double t0, double h) const;
  // The exact free flight from (t0, s) to t1 (u'' = f(t), no contact): closed form for a constant
  // or harmonic force; std::logic_error for an expression (its flights are integrated by ODE).
  State flight(const State& s, double t0, double t1) const;
  // sup |f(t)| over all t, |f| + |amplitude|, for a constant or harmonic force (it bounds |u''| in
  // free flight, which brackets impact times rigorously); nullopt for an expression.
  std::optional<double> bound() const;

  const Model& model() const { return model_; }

 private:
  struct Expression;
  Model model_;
  std::optional<Harmonic> harmonic_;
  std::unique_ptr<Expression> expression_;
};

}  // namespace impact
