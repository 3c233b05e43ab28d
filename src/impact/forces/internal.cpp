#include "impact/forces/internal.hpp"

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "impact/format.hpp"

namespace impact {

namespace {

bool identifier(const std::string& name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_'))
    return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

}  // namespace

std::string variables_named(const Model& model) {
  return variables_named(variables_of(model.internal).names);
}

void check_internal_variables(const Model& model) {
  if (model.internal.size() > kMaxInternal)
    throw std::invalid_argument("the model has " + std::to_string(model.internal.size()) +
                                " internal variables; at most " + std::to_string(kMaxInternal) +
                                " are allowed");
  const mu::Parser functions;
  for (std::size_t i = 0; i < model.internal.size(); ++i) {
    const InternalVariable& z = model.internal[i];
    const std::string quoted = "internal variable \"" + z.name + "\"";
    if (!identifier(z.name))
      throw std::invalid_argument(quoted +
                                  ": a name is a letter or '_' followed by letters, digits or '_'");
    if (z.name == "t" || z.name == "u" || z.name == "v" || z.name == "pi" ||
        functions.GetFunDef().count(z.name) > 0 || functions.GetConst().count(z.name) > 0)
      throw std::invalid_argument(quoted +
                                  ": the name is taken (t, u, v, pi, muparser's constants _pi "
                                  "and _e and its functions are)");
    // The CSV of the rows writes a column per channel and the events file t, kind, v_before and
    // v_after, each followed by the internal variables' columns.
    for (std::string_view column :
         {"N", "E", "iterations", "N_scheme", "kind", "v_before", "v_after"})
      if (z.name == column)
        throw std::invalid_argument(quoted +
                                    ": the name is taken by a column of the output (the channels "
                                    "u, v, N, E, iterations, N_scheme and the events' t, kind, "
                                    "v_before, v_after); give the variable another name");
    for (std::size_t j = 0; j < i; ++j)
      if (model.internal[j].name == z.name) throw std::invalid_argument(quoted + " is given twice");
    if (!std::isfinite(z.initial))
      throw std::invalid_argument(quoted + ": the initial value " + round_trip(z.initial) +
                                  " must be finite");
  }
}

InternalRates::InternalRates(const Model& model) : model_(model), count_(model.internal.size()) {
  check_internal_variables(model);
  for (InternalVariable& z : model_.internal) z.rate = z.rate.compiled(model_.internal, z.name);
}

void InternalRates::evaluate(double t, const StateWithInternal& s,
                             std::array<double, kMaxInternal>& rate) const {
  for (std::size_t i = 0; i < count_; ++i) {
    const InternalVariable& z = model_.internal[i];
    try {
      rate[i] = z.rate(t, s.u, s.v, s.z.data());
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("the rate of internal variable \"" + z.name +
                               "\" fails at t = " + round_trip(t) + ": " + e.what() +
                               " (the variables are " + variables_named(model_) + ")");
    }
    if (!std::isfinite(rate[i]))
      throw std::runtime_error("the rate of internal variable \"" + z.name + "\" is " +
                               round_trip(rate[i]) + " at t = " + round_trip(t) +
                               "; it must be finite wherever the run evaluates it");
  }
}

std::array<double, kMaxInternal> InternalRates::evaluate(double t, const State& s, const double* z,
                                                         double* rate) const {
  StateWithInternal full{s, {}};
  std::copy(z, z + count_, full.z.begin());
  std::array<double, kMaxInternal> rates{};
  evaluate(t, full, rates);
  std::copy(rates.begin(), rates.begin() + static_cast<std::ptrdiff_t>(count_), rate);
  return full.z;
}

std::string describe(const StateWithInternal& s) {
  std::string text = "u = " + round_trip(s.u) + ", v = " + round_trip(s.v) + ", z = (";
  for (std::size_t i = 0; i < kMaxInternal; ++i) text += (i ? ", " : "") + round_trip(s.z[i]);
  return text + ")";
}

}  // namespace impact
