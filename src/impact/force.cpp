#include "impact/force.hpp"

#include <muParser.h>

#include <array>
#include <cctype>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string_view>

#include "impact/format.hpp"
#include "impact/harmonic_series.hpp"
#include "impact/internal.hpp"
#include "impact/step_quadrature.hpp"

namespace impact {

namespace {

// A token muparser could not read that starts as a number does ("9.8e", "2.5e+").
bool starts_number(const std::string& token) {
  return !token.empty() && (std::isdigit(static_cast<unsigned char>(token[0])) || token[0] == '.');
}

// The number that starts at `position` of the text: digits, '.', an exponent and its sign.
std::string number_at(const std::string& text, std::size_t position) {
  std::size_t end = position;
  while (end < text.size()) {
    const char c = text[end];
    const bool sign =
        (c == '+' || c == '-') && end > position && (text[end - 1] == 'e' || text[end - 1] == 'E');
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || sign)) break;
    ++end;
  }
  return text.substr(position, end - position);
}

// After the first Eval, which parses the expression and records the variables it uses: u, v or
// an internal variable.
bool reads_state(const mu::Parser& parser, const Model& model) {
  const auto& used = parser.GetUsedVar();
  if (used.count("u") > 0 || used.count("v") > 0) return true;
  for (const InternalVariable& z : model.internal)
    if (used.count(z.name) > 0) return true;
  return false;
}

}  // namespace

// The parser binds t, u, v and the internal variables by address, so each ForceFunction owns its
// parser and its variables.
struct ForceFunction::Expression {
  Expression(const std::string& expression, const Model& model) : text(expression) {
    if (text.size() > kMaxExpressionLength)
      throw std::invalid_argument("the expression has " + std::to_string(text.size()) +
                                  " characters; at most " + std::to_string(kMaxExpressionLength) +
                                  " are allowed");
    if (text.find_first_not_of(" \t") == std::string::npos)
      throw std::invalid_argument("the expression is empty; give a function of t (and u, v)");
    refuse_assignment(text, "a force only reads " + variables_named(model));
    try {
      define_variables(parser, t, u, v, model, z.data());
      parser.SetExpr(text);
      t = u = v = 0.0;
      for (std::size_t i = 0; i < model.internal.size() && i < kMaxInternal; ++i)
        z[i] = model.internal[i].initial;
      const double f0 = parser.Eval();
      state =
          reads_state(parser, model);  // muparser records the variables as the first Eval parses
      refuse_value_list(parser);
      // A force of t alone must be finite where every run starts; one of the state is probed at
      // the scene's initial state by the scene reader (check_force), and elsewhere where the run
      // evaluates it.
      if (!std::isfinite(f0) && !state)
        throw std::invalid_argument("the expression is " + round_trip(f0) +
                                    " at t = 0; it must be finite");
    } catch (const mu::Parser::exception_type& e) {
      // Positions are counted from 1 here; muparser's own message counts from 0, so it is left
      // out where the position is all it adds.
      const std::string at = " at position " + std::to_string(e.GetPos() + 1);
      if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN && starts_number(e.GetToken()))
        throw std::invalid_argument("the number \"" + number_at(text, e.GetPos()) + "\"" + at +
                                    " is malformed (a number is digits with an optional fraction "
                                    "and exponent, as 9.8, .5 or 2.5e-3)");
      if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN)
        throw std::invalid_argument("the expression uses \"" + e.GetToken() + "\"" + at +
                                    ", which is no variable or function muparser knows (the "
                                    "variables are " +
                                    variables_named(model) + "; pi is defined)");
      throw std::invalid_argument("the expression does not parse" + at + ": " + e.GetMsg() +
                                  " (the variables are " + variables_named(model) +
                                  "; pi is defined)");
    }
  }
  double operator()(double at) const {
    t = at;
    return evaluate();
  }
  double operator()(double at, const State& s) const {
    t = at;
    u = s.u;
    v = s.v;
    return evaluate();
  }
  double evaluate() const {
    const double at = t;
    double value;
    try {
      value = parser.Eval();
    } catch (const mu::Parser::exception_type& e) {
      throw std::runtime_error("the force expression fails at t = " + round_trip(at) + ": " +
                               e.GetMsg());
    }
    if (!std::isfinite(value))
      throw std::runtime_error("the force expression is " + round_trip(value) +
                               " at t = " + round_trip(at) +
                               "; it must be finite wherever the run evaluates it");
    return value;
  }

  std::string text;
  mutable double t = 0.0, u = 0.0, v = 0.0;
  mutable std::array<double, kMaxInternal> z{};  // the internal variables, set_internal()
  bool state = false;  // the expression reads u, v or an internal variable
  mu::Parser parser;
};

ForceFunction::ForceFunction(const Model& model)
    : model_(linear_as_expression(model)), harmonic_(model_.harmonic) {
  if (!model_.expression.empty()) {
    expression_ = std::make_unique<Expression>(model_.expression, model_);
    state_dependent_ = expression_->state;
  }
}

ForceFunction::ForceFunction(const ForceFunction& other)
    : model_(other.model_), harmonic_(other.harmonic_), state_dependent_(other.state_dependent_) {
  if (other.expression_) {
    expression_ = std::make_unique<Expression>(other.expression_->text, model_);
    expression_->z = other.expression_->z;
  }
}

ForceFunction& ForceFunction::operator=(const ForceFunction& other) {
  if (this != &other) *this = ForceFunction(other);
  return *this;
}

ForceFunction::ForceFunction(ForceFunction&&) noexcept = default;
ForceFunction& ForceFunction::operator=(ForceFunction&&) noexcept = default;
ForceFunction::~ForceFunction() = default;

double ForceFunction::at(double t) const {
  if (state_dependent_)
    throw std::logic_error("ForceFunction::at(t): the force reads u or v; give the state");
  double value = model_.f;
  if (harmonic_) value += harmonic_->amplitude * std::sin(harmonic_->omega * t + harmonic_->phase);
  if (expression_) value += (*expression_)(t);
  return value;
}

double ForceFunction::at(double t, const State& s) const {
  if (!state_dependent_) return at(t);
  // An expression of the state is the whole force (the reader refuses f and a harmonic part
  // beside an expression), so f and the harmonic part are zero here.
  return model_.f + (*expression_)(t, s);
}

double ForceFunction::integral(double t0, double t1) const {
  if (state_dependent_)
    throw std::logic_error(
        "ForceFunction::integral(t0, t1): the force reads u or v; give the state");
  double value = model_.f * (t1 - t0);
  // cos(a) - cos(b) = 2 sin((a + b)/2) sin((b - a)/2), without cancellation for short steps.
  if (harmonic_) value += harmonic_integral(*harmonic_, t0, t1);
  if (expression_) {
    const Integrand f{
        [](double t, void* self) { return (*static_cast<const Expression*>(self))(t); },
        expression_.get()};
    value += controlled_integral(f, t0, t1);
  }
  return value;
}

double ForceFunction::integral(double t0, double t1, const State& s) const {
  if (!state_dependent_) return integral(t0, t1);
  struct Frozen {
    const Expression* expression;
    State s;
  } frozen{expression_.get(), s};
  const Integrand f{[](double t, void* self) {
                      const auto* at = static_cast<const Frozen*>(self);
                      return (*at->expression)(t, at->s);
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
  if (expression_)
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
  if (expression_) expression_->z = z;
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
    mu::Parser parser;
    double t = 0, u = 0, v = 0;
    std::array<double, kMaxInternal> z{};
    define_variables(parser, t, u, v, model, z.data());
    parser.SetExpr(model.expression);
    parser.Eval();
    return reads_state(parser, model);
  } catch (const mu::Parser::exception_type&) {
    return false;
  }
}

std::optional<double> ForceFunction::bound() const {
  if (expression_) return std::nullopt;
  return std::fabs(model_.f) + (harmonic_ ? std::fabs(harmonic_->amplitude) : 0.0);
}

}  // namespace impact
