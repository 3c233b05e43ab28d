#include "scene/sweep_quantities.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "impact/model/model.hpp"
#include "impact/run/step_events.hpp"
#include "scene/scene_error.hpp"

namespace impact {
namespace {

struct QuantityInfo {
  Quantity quantity;
  std::string_view name, help;
};

constexpr QuantityInfo kQuantities[] = {
    {Quantity::u_T, "u_T", "u at the last grid time (T when h divides T)"},
    {Quantity::v_T, "v_T", "v at the last grid time"},
    {Quantity::E_T, "E_T",
     "energy v^2/2 - f u (3-1) at the last grid time (with f(t), the E channel's)"},
    {Quantity::contact_steps, "contact_steps",
     "steps with N^l > u^{l+1} - phi: (4-3)'s force branch"},
    {Quantity::impacts, "impacts", "contact episodes before rest (all of them without rest)"},
    {Quantity::first_impact_time, "first_impact_time",
     "t_l + (u^l - phi)/|v^l| for the first contact step l; nan without one"},
    {Quantity::rest_time, "rest_time",
     "where the particle comes to rest for good: for exact and event_driven the time of their "
     "last stick event (no lift after it), for the time-steppers t_{l+1} for the first step l "
     "of a final contact episode of >= 3 steps; nan without rest"},
    {Quantity::max_u, "max_u", "largest u^l, t = 0 included"},
    {Quantity::iterations, "iterations", "Newton iterations (fb_newton) or ODE steps (penalty)"},
    {Quantity::z1_T, "z1_T",
     "NAME_T: the internal variable NAME ([[internal]]) at the last grid time, one column each; "
     "with [bonding]: beta_T and D_T"},
    {Quantity::z2_T, "z2_T", ""},
    {Quantity::z3_T, "z3_T", ""},
    {Quantity::z4_T, "z4_T", ""},
    {Quantity::debond_time, "debond_time",
     "with [bonding]: when beta first falls to bonding.debond_below (the debond event); nan "
     "without"},
    {Quantity::capture_time, "capture_time",
     "with [bonding]: the top of the first flight that turns back to the floor (the capture "
     "event); nan without"},
    {Quantity::escape_time, "escape_time",
     "with [bonding] and f = 0: the first t_l from which the particle provably never comes "
     "back (the escape event); nan without"},
    {Quantity::wall_s, "wall_s",
     "wall time of the point's method (a share of its group's in the ensemble), the "
     "reference's left out; not in the default"},
    {Quantity::err_u_sup, "err_u_sup", "max_l |u^l - u(t_l)|, with --against exact"},
    {Quantity::err_v_l1, "err_v_l1", "h sum_l |v^l - v(t_l)|, with --against exact"},
    {Quantity::err_E_T, "err_E_T",
     "|E^n - E(T)|, E as the channel E defines it, with --against exact"},
    {Quantity::err_internal_sup, "err_internal_sup",
     "max over l and the internal variables of |z^l - z(t_l)| (with [bonding]: beta and D), "
     "with --against exact"},
    {Quantity::err_first_impact, "err_first_impact",
     "first impact time (first step with N^l > 0) minus the exact one, with --against exact"},
    {Quantity::reference_s, "reference_s",
     "wall time of the point's reference, with --against exact; not in the default"},
};

bool is_error_measure(Quantity q) {
  return q >= Quantity::err_u_sup;
}

// The internal variable a quantity is (z1_T..z4_T), if it is one.
std::optional<std::size_t> internal_quantity(Quantity q) {
  if (q < Quantity::z1_T || q > Quantity::z4_T) return std::nullopt;
  return static_cast<std::size_t>(q) - static_cast<std::size_t>(Quantity::z1_T);
}

// Whether a quantity has a column for this model: NAME_T for its internal variables only (a bonded
// model's beta and D: event_variables, step_events.hpp).
bool exists_for(Quantity q, const Model& model) {
  if (const auto i = internal_quantity(q)) return *i < event_variables(model).size();
  if (q >= Quantity::debond_time && q <= Quantity::escape_time) return bonded(model);
  return q != Quantity::err_internal_sup || !model.internal.empty() || bonded(model);
}

}  // namespace

std::string quantities_help() {
  std::string text;
  for (const auto& q : kQuantities) {
    if (q.help.empty()) continue;  // z2_T..z4_T: NAME_T says it for all
    const std::string name = q.quantity == Quantity::z1_T ? "NAME_T" : std::string(q.name);
    text += "  " + name + std::string(19 - name.size(), ' ') + std::string(q.help) + "\n";
  }
  return text;
}

std::string quantity_name(Quantity q, const Model& model) {
  if (const auto i = internal_quantity(q)) {
    const std::vector<std::string> names = event_variables(model);
    if (*i < names.size()) return names[*i] + "_T";
  }
  return std::string(kQuantities[static_cast<int>(q)].name);
}

bool is_quantity_name(std::string_view name) {
  return std::any_of(std::begin(kQuantities), std::end(kQuantities),
                     [&](const QuantityInfo& q) { return q.name == name; });
}

std::vector<Quantity> parse_summary(const std::string& list, bool against_exact,
                                    const Model& model) {
  std::vector<Quantity> quantities;
  if (list.empty()) {
    for (const auto& q : kQuantities)
      if (q.quantity != Quantity::wall_s && q.quantity != Quantity::reference_s &&
          (against_exact || !is_error_measure(q.quantity)) && exists_for(q.quantity, model))
        quantities.push_back(q.quantity);
    return quantities;
  }
  std::vector<std::string> names;
  std::vector<Quantity> named;
  for (const auto& q : kQuantities)
    if (exists_for(q.quantity, model)) {
      names.push_back(quantity_name(q.quantity, model));
      named.push_back(q.quantity);
    }
  for (std::size_t start = 0; start <= list.size();) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, comma - start);
    start = comma + 1;
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
      std::string allowed;
      for (const auto& n : names) allowed += (allowed.empty() ? "" : ", ") + n;
      throw SceneError("--summary " + list + ": unknown quantity '" + name +
                       "' (allowed: " + allowed + ")");
    }
    const Quantity q = named[static_cast<std::size_t>(it - names.begin())];
    if (std::find(quantities.begin(), quantities.end(), q) != quantities.end())
      throw SceneError("--summary " + list + ": '" + name + "' is listed twice");
    if (is_error_measure(q) && !against_exact)
      throw SceneError("--summary " + list + ": '" + name + "' needs --against exact");
    quantities.push_back(q);
  }
  // The reference would be run at every point and nothing written from it: refused, as an error
  // measure without --against is.
  if (against_exact && std::none_of(quantities.begin(), quantities.end(), is_error_measure)) {
    std::string measures;
    for (std::size_t i = 0; i < names.size(); ++i)
      if (is_error_measure(named[i])) measures += (measures.empty() ? "" : ", ") + names[i];
    throw SceneError("--against exact: --summary " + list + " names no error measure (" + measures +
                     "), so the reference would run at every point for nothing; add "
                     "one to --summary, or leave --against out");
  }
  return quantities;
}

}  // namespace impact
