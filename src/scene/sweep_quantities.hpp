// What a sweep reports per point: the summary quantities a user can ask for (impact sweep
// --summary, impact.sweep's summary), their names and what one point gave. The CSV of
// `impact sweep` and the columns of impact::sweep() both read a point's values through
// visit_quantity(), so that the two agree to the bit.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "impact/model/model.hpp"
#include "impact/run/summary.hpp"

namespace impact {

// The quantities, in the order of the default --summary (which leaves out the times wall_s and
// reference_s, so that the default output is the same bytes on every run, and the errors unless
// --against exact).
enum class Quantity {
  u_T,
  v_T,
  E_T,
  contact_steps,
  impacts,
  first_impact_time,
  rest_time,
  max_u,
  iterations,
  z1_T,  // the internal variables at the last grid time, named after them (NAME_T)
  z2_T,
  z3_T,
  z4_T,
  debond_time,  // a bonded model's first bond events (bond_events.hpp)
  capture_time,
  escape_time,
  wall_s,
  err_u_sup,
  err_v_l1,
  err_E_T,
  err_internal_sup,
  err_first_impact,
  reference_s,
};

// "name  what it is" lines for --help.
std::string quantities_help();
// Parses "rest_time,E_T"; empty text gives the default (with the model's internal variables,
// NAME_T for each, and err_internal_sup with --against exact). Throws SceneError for an unknown
// name, a name listed twice, or an error measure without --against exact.
std::vector<Quantity> parse_summary(const std::string& list, bool against_exact,
                                    const Model& model = {});
// A name, as in the header: NAME_T for an internal variable of `model`.
std::string quantity_name(Quantity q, const Model& model = {});
// Whether `name` is a quantity's name (NAME_T as z1_T..z4_T).
bool is_quantity_name(std::string_view name);

// What one point gave: its summary, or why it failed (a NumericalError's message).
struct PointResult {
  std::optional<PointOutcome> outcome;
  std::string failure;
  double wall_s = 0;
};

// Calls `use` with quantity q of a point's outcome: a double, or a std::int64_t for the counts
// (contact_steps, impacts, iterations); NaN for a time that does not exist.
template <class Use>
decltype(auto) visit_quantity(Quantity q, const PointOutcome& o, double wall_s, Use&& use) {
  const PointSummary& s = o.summary;
  switch (q) {
    case Quantity::u_T:
      return use(s.final.u);
    case Quantity::v_T:
      return use(s.final.v);
    case Quantity::E_T:
      return use(s.energy_final);
    case Quantity::contact_steps:
      return use(std::int64_t{s.contact_steps});
    case Quantity::impacts:
      return use(std::int64_t{s.impacts});
    case Quantity::first_impact_time:
      return use(s.first_impact_time);
    case Quantity::rest_time:
      return use(s.rest_time.value_or(std::numeric_limits<double>::quiet_NaN()));
    case Quantity::max_u:
      return use(s.max_u);
    case Quantity::iterations:
      return use(std::int64_t{s.iterations});
    case Quantity::z1_T:
    case Quantity::z2_T:
    case Quantity::z3_T:
    case Quantity::z4_T:
      return use(
          s.internal_final[static_cast<std::size_t>(q) - static_cast<std::size_t>(Quantity::z1_T)]);
    case Quantity::debond_time:
      return use(s.bonds.debond);
    case Quantity::capture_time:
      return use(s.bonds.capture);
    case Quantity::escape_time:
      return use(s.bonds.escape);
    case Quantity::wall_s:
      return use(wall_s);
    case Quantity::err_u_sup:
      return use(o.errors->sup_u);
    case Quantity::err_v_l1:
      return use(o.errors->l1_v);
    case Quantity::err_E_T:
      return use(o.errors->energy_end);
    case Quantity::err_internal_sup:
      return use(o.errors->sup_internal);
    case Quantity::err_first_impact:
      return use(o.errors->first_impact);
    case Quantity::reference_s:
      break;
  }
  return use(o.reference_seconds);
}

}  // namespace impact
