// A muparser expression of t, u, v and the model's internal variables (force.expression, an
// internal variable's rate), compiled once and copied as a value.
//
// Compiled: Expression(text, internal) parses the text once and keeps what the parse found (the
// text, whether it reads u, v or an internal variable, the variables' names) in facts that every
// copy shares. A text alone (Expression("2 * t"), as code that builds a model writes it) is not
// yet compiled: compiled(internal) compiles it where it is first needed, and returns a copy of a
// compiled expression as it is.
//
// Evaluated: muparser binds the variables by address, so each copy that evaluates builds its own
// parser at its first evaluation (one parse more) and keeps it; a copy starts without one. A copy
// therefore belongs to one thread, as the solver that holds it does; the facts are read-only.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace impact {

// The longest expression a scene may give (characters).
inline constexpr std::size_t kMaxExpressionLength = 4096;

// The most internal variables a model may have (model.hpp): a state carries them in a fixed
// array, so that a step copies no heap memory.
inline constexpr std::size_t kMaxInternal = 4;

// The internal variables as an expression reads them: the names (z[i] of an evaluation is
// names[i]) and the values at t = 0, at which a force is checked when it is compiled.
struct ExpressionVariables {
  std::vector<std::string> names;
  std::vector<double> initial;
};
// The first kMaxInternal of a model's internal variables (anything with .name and .initial).
template <class Internal>
ExpressionVariables variables_of(const Internal& internal) {
  ExpressionVariables variables;
  for (const auto& z : internal) {
    if (variables.names.size() == kMaxInternal) break;
    variables.names.push_back(z.name);
    variables.initial.push_back(z.initial);
  }
  return variables;
}
// "t, u and v", or "t, u, v and the internal variables beta, D", for messages.
std::string variables_named(const std::vector<std::string>& names);

class Expression {
 public:
  Expression();  // none
  // The text, not yet compiled (empty: none).
  Expression(std::string text);  // NOLINT(google-explicit-constructor): a model's force is its text
  Expression(const char* text);  // NOLINT(google-explicit-constructor)
  // Compiles: throws std::invalid_argument for a text that is empty, too long, assigns with '=',
  // does not parse (the message gives the position), uses a name other than t, u, v and the
  // internal variables', gives several comma-separated values, or (a force of t alone) is not
  // finite at t = 0, u = v = 0. `rate_of` names the internal variable whose rate this is (its
  // messages say so, and a rate's value at t = 0 is not checked); empty for a force.
  template <class Internal>
  Expression(std::string text, const Internal& internal, std::string_view rate_of = {})
      : Expression(std::move(text), variables_of(internal), rate_of, Compile{}) {}
  Expression(const Expression& other);
  Expression& operator=(const Expression& other);
  Expression(Expression&&) noexcept;
  Expression& operator=(Expression&&) noexcept;
  ~Expression();

  const std::string& text() const;
  bool empty() const { return !facts_; }  // a text is never empty
  bool is_compiled() const;
  // This expression compiled for these internal variables: a copy of it if it is (no parse),
  // else a new compilation of its text (as the constructor above).
  template <class Internal>
  Expression compiled(const Internal& internal, std::string_view rate_of = {}) const {
    return compiled(variables_of(internal), rate_of, Compile{});
  }
  // Whether the expression reads u, v or an internal variable (compiled; false for none).
  bool reads_state() const;

  // The value at t, u, v and z[0..m) for the m internal variables it was compiled with (u, v, z
  // unchanged by the form of t alone). Throws std::runtime_error with muparser's message where
  // the evaluation fails; the value may be non-finite (the caller names what it is).
  double operator()(double t) const;
  double operator()(double t, double u, double v, const double* z) const;

  bool operator==(const Expression& other) const { return text() == other.text(); }
  bool operator==(const std::string& other) const { return text() == other; }
  bool operator==(const char* other) const { return text() == other; }

 private:
  struct Compile {};
  Expression(std::string text, ExpressionVariables variables, std::string_view rate_of, Compile);
  Expression compiled(const ExpressionVariables& variables, std::string_view rate_of,
                      Compile) const;
  struct Facts;
  struct Parser;
  Parser& parser() const;
  std::shared_ptr<const Facts> facts_;      // shared by the copies
  mutable std::unique_ptr<Parser> parser_;  // this copy's own, made at its first evaluation
};

// How many times an Expression has parsed a text with muparser in this process (a compilation
// or a copy's first evaluation): for the tests that count them.
std::size_t expression_parses();

}  // namespace impact
