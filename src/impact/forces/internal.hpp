// The internal variables of a model (model.hpp): z' = g(t, u, v, z), each rate a muparser
// expression of t, the particle's state and the internal variables by name, and the variables the
// force expression and the rates read. A model without internal variables never builds these.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "impact/model/model.hpp"

namespace impact {

// "t, u and v", or "t, u, v and the internal variables beta, D", for messages.
std::string variables_named(const Model& model);

// Throws std::invalid_argument naming the variable for more than kMaxInternal internal variables,
// a name that is not an identifier ([A-Za-z_][A-Za-z0-9_]*), a name that is taken (t, u, v, pi,
// muparser's constants _pi and _e and its functions; a channel's or an event column's name, which
// the CSV headers would then show twice or mislabel: N, E, iterations, N_scheme, kind, v_before,
// v_after), a name given twice, or a non-finite initial value.
void check_internal_variables(const Model& model);

// The rates g_i of the model's internal variables, evaluated at (t, state, z).
class InternalRates {
 public:
  // Throws std::invalid_argument (check_internal_variables, or a rate that is empty, assigns with
  // '=', does not parse, uses an unknown name or has several comma-separated values). A rate that
  // is not finite where the run evaluates it is reported there (evaluate); the scene reader
  // evaluates every rate at the initial state.
  explicit InternalRates(const Model& model);

  std::size_t size() const { return count_; }
  // The model with its rates compiled (what the scene reader keeps).
  const Model& model() const { return model_; }
  // rate[i] = g_i(t, s.u, s.v, s.z) for i < size(); std::runtime_error naming the variable and t
  // where a rate fails or is not finite.
  void evaluate(double t, const StateWithInternal& s, std::array<double, kMaxInternal>& rate) const;
  // The same for an ODE's right-hand side: the particle's state s and z[0..size()) from arrays,
  // rate[0..size()) written; returns z as the array of a state (the rest 0).
  std::array<double, kMaxInternal> evaluate(double t, const State& s, const double* z,
                                            double* rate) const;

 private:
  Model model_;  // its rates compiled, evaluated through this copy's own parsers
  std::size_t count_ = 0;
};

}  // namespace impact
