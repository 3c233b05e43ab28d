// The methods' parameters as plain data: what a scene's [method] table says, one struct per method,
// apart from the steppers that take them (any_stepper.hpp builds a stepper from them). A header
// that names or holds a method (the scene, the capability table) includes this, and no stepper.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

namespace impact {

// How a scheme evaluates its free flight: `closed_form` from the last contact (free_flight.hpp), or
// `paper`, (5-1) evaluated term by term as printed at every step, u^{l+1} = h (h (N^l + f)/2 + v^l)
// + u^l, with v^{l+1} = (2/h)(u^{l+1} - u^l) - v^l from (4-2). Both are the same discrete solution
// in exact arithmetic; in floating point they differ by rounding, which decides, e.g., when Figure
// 4's particle comes to rest (paper_notes/figure4.md).
enum class FreeFlightForm { closed_form, paper };

struct DirectParams {
  FreeFlightForm free_flight = FreeFlightForm::closed_form;
  bool operator==(const DirectParams&) const = default;
};

struct FbNewtonParams {
  double epsilon = 1e-15;    // smoothing parameter (paper: 1e-15)
  double tolerance = 1e-15;  // relative residual, see FbNewton::do_step (paper: 1e-15)
  int max_iterations = 50;
  FreeFlightForm free_flight = FreeFlightForm::closed_form;
  bool operator==(const FbNewtonParams&) const = default;
};

struct MoreauJeanParams {
  double theta = 0.5;
  bool operator==(const MoreauJeanParams&) const = default;
};

struct PenaltyParams {
  double stiffness = 1e6;         // c_N
  std::string stepper = "rk8pd";  // GSL odeiv2 stepper name
  double rtol = 1e-10;
  double atol = 1e-12;
  // The ODE steps the whole run may take (a stiff contact with an implicit stepper can need 1e5
  // per grid step, minutes for T = 1); 0: automatic, 1e6 plus 1000 per grid step done.
  std::int64_t max_ode_steps = 0;

  bool operator==(const PenaltyParams&) const = default;
};

// The names PenaltyParams::stepper accepts: every GSL odeiv2 stepper (penalty.cpp).
std::span<const std::string_view> penalty_stepper_names();

struct ExactParams {
  // The events a run with a harmonic force may pass (ClosedFormMarch), then a numerical failure
  // that says so; 0: automatic, 1e6 plus 1000 per grid step done (run_budget(), exact_march.hpp). A
  // constant force costs O(1) per sample whatever its number of impacts: no bound.
  std::int64_t max_events = 0;
  bool operator==(const ExactParams&) const = default;
};

struct EventDrivenParams {
  double rtol = 1e-12;     // relative tolerance of rk8pd's error control, in (0, 1e-3]
  double atol = 1e-14;     // absolute tolerance, in (0, 1e-3]
  double max_step = 0.01;  // longest ODE step, > 0: caps the spacing of the force samples
  // The events (impacts, sticks, lifts) and the ODE steps the whole run may take, then a numerical
  // failure that says so; 0: automatic, 1e6 plus 1000 per grid step done (run_budget()).
  std::int64_t max_events = 0;
  std::int64_t max_ode_steps = 0;
  bool operator==(const EventDrivenParams&) const = default;
};

struct DirectLocatedParams {
  bool operator==(const DirectLocatedParams&) const = default;
};

// One method and its parameters: what a scene's [method] table says.
using MethodParams = std::variant<DirectParams, FbNewtonParams, MoreauJeanParams, PenaltyParams,
                                  ExactParams, EventDrivenParams, DirectLocatedParams>;

namespace detail {
template <class P, class Variant>
struct AlternativeIndex;
template <class P, class... Alternatives>
struct AlternativeIndex<P, std::variant<Alternatives...>> {
  static constexpr std::size_t value = [] {
    constexpr bool is[] = {std::is_same_v<P, Alternatives>...};
    for (std::size_t i = 0; i < sizeof...(Alternatives); ++i)
      if (is[i]) return i;
    return std::variant_npos;
  }();
  static_assert(value != std::variant_npos, "not a method's parameters");
};
}  // namespace detail

// P's index in MethodParams, which is its method's row in the method table (methods(),
// capabilities.hpp; a test holds the two in step): a constant, so that a table can name a method
// without spelling its name.
template <class P>
inline constexpr std::size_t method_index = detail::AlternativeIndex<P, MethodParams>::value;

}  // namespace impact
