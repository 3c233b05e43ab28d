#include "scene/method_keys.hpp"

#include <string_view>
#include <vector>

#include "scene/scene_error.hpp"
#include "scene/toml_text.hpp"

namespace impact {
namespace {

template <class Params>
Params& params(Scene& s) {
  return std::get<Params>(s.method);
}
template <class Params>
const Params& params(const Scene& s) {
  return std::get<Params>(s.method);
}

std::span<const std::string_view> free_flight_forms() {
  static constexpr std::string_view kForms[] = {"closed_form", "paper"};
  return kForms;
}
template <class Params>
KeyValue get_free_flight(const Scene& s) {
  return std::string(params<Params>(s).free_flight == FreeFlightForm::paper ? "paper"
                                                                            : "closed_form");
}
template <class Params>
void set_free_flight(Scene& s, const KeyValue& v) {
  params<Params>(s).free_flight =
      std::get<std::string>(v) == "paper" ? FreeFlightForm::paper : FreeFlightForm::closed_form;
}
template <class Params, double Params::*member>
KeyValue get_number(const Scene& s) {
  return params<Params>(s).*member;
}
template <class Params, double Params::*member>
void set_number(Scene& s, const KeyValue& v) {
  params<Params>(s).*member = std::get<double>(v);
}

template <class Params, std::int64_t Params::*member>
KeyValue get_integer(const Scene& s) {
  return params<Params>(s).*member;
}
template <class Params, std::int64_t Params::*member>
void set_integer(Scene& s, const KeyValue& v) {
  params<Params>(s).*member = std::get<std::int64_t>(v);
}

constexpr std::string_view kMaxEvents =
    "events (impacts, sticks, lifts) the whole run may pass, then a numerical failure (0: "
    "automatic, 1e6 plus 1000 per grid step)";

constexpr std::string_view kFreeFlight =
    "free flight between contacts: in closed form from the last contact, or (5-1) term by term at "
    "every step, as printed";

// Every method's keys, in the order --help lists them.
const KeySpec kMethodKeys[] = {
    {.table = "method",
     .key = "free_flight",
     .params = method_index<DirectParams>,
     .type = KeyType::name,
     .choices = free_flight_forms,
     .meaning = kFreeFlight,
     .get = get_free_flight<DirectParams>,
     .set = set_free_flight<DirectParams>},
    {.table = "method",
     .key = "epsilon",
     .params = method_index<FbNewtonParams>,
     .type = KeyType::number,
     .range = {.lo = 0.0, .hi = 1.0, .lo_open = true},
     .meaning = "smoothing parameter of (5-3)",
     .get = [](const Scene& s) -> KeyValue { return params<FbNewtonParams>(s).epsilon; },
     .set = [](Scene& s,
               const KeyValue& v) { params<FbNewtonParams>(s).epsilon = std::get<double>(v); }},
    {.table = "method",
     .key = "tolerance",
     .params = method_index<FbNewtonParams>,
     .type = KeyType::number,
     .range = {.lo = 0.0, .hi = 0.1, .lo_open = true},
     .meaning = "Newton's stopping rule, relative residual",
     .get = [](const Scene& s) -> KeyValue { return params<FbNewtonParams>(s).tolerance; },
     .set = [](Scene& s,
               const KeyValue& v) { params<FbNewtonParams>(s).tolerance = std::get<double>(v); }},
    {.table = "method",
     .key = "max_iterations",
     .params = method_index<FbNewtonParams>,
     .type = KeyType::integer,
     .range = {.lo = 1.0, .hi = 10000.0},
     .meaning = "Newton iterations per step before a numerical failure",
     .get = [](const Scene& s) -> KeyValue {
       return std::int64_t{params<FbNewtonParams>(s).max_iterations};
     },
     .set =
         [](Scene& s, const KeyValue& v) {
           params<FbNewtonParams>(s).max_iterations = static_cast<int>(std::get<std::int64_t>(v));
         }},
    {.table = "method",
     .key = "free_flight",
     .params = method_index<FbNewtonParams>,
     .type = KeyType::name,
     .choices = free_flight_forms,
     .meaning = kFreeFlight,
     .get = get_free_flight<FbNewtonParams>,
     .set = set_free_flight<FbNewtonParams>},
    {.table = "method",
     .key = "theta",
     .params = method_index<MoreauJeanParams>,
     .type = KeyType::number,
     .range = {.lo = 0.0, .hi = 1.0},
     .meaning = "the theta of the scheme",
     .get = [](const Scene& s) -> KeyValue { return params<MoreauJeanParams>(s).theta; },
     .set = [](Scene& s,
               const KeyValue& v) { params<MoreauJeanParams>(s).theta = std::get<double>(v); }},
    {.table = "method",
     .key = "stiffness",
     .params = method_index<PenaltyParams>,
     .type = KeyType::number,
     .range = {.lo = 0.0, .hi = 1e15, .lo_open = true},
     .meaning = "c_N of the compliance N = c_N max(phi - u, 0)",
     .get = [](const Scene& s) -> KeyValue { return params<PenaltyParams>(s).stiffness; },
     .set = [](Scene& s,
               const KeyValue& v) { params<PenaltyParams>(s).stiffness = std::get<double>(v); }},
    {.table = "method",
     .key = "stepper",
     .params = method_index<PenaltyParams>,
     .type = KeyType::name,
     .choices = penalty_stepper_names,
     .meaning = "GSL odeiv2 stepper",
     .get = [](const Scene& s) -> KeyValue { return params<PenaltyParams>(s).stepper; },
     .set = [](Scene& s,
               const KeyValue& v) { params<PenaltyParams>(s).stepper = std::get<std::string>(v); }},
    {.table = "method",
     .key = "rtol",
     .params = method_index<PenaltyParams>,
     .type = KeyType::number,
     .range = {.lo = 0.0, .hi = 1.0, .lo_open = true},
     .meaning = "relative error tolerance of the ODE driver",
     .get = [](const Scene& s) -> KeyValue { return params<PenaltyParams>(s).rtol; },
     .set = [](Scene& s,
               const KeyValue& v) { params<PenaltyParams>(s).rtol = std::get<double>(v); }},
    {.table = "method",
     .key = "atol",
     .params = method_index<PenaltyParams>,
     .type = KeyType::number,
     .range = {.lo = 0.0, .hi = 1.0, .lo_open = true},
     .meaning = "absolute error tolerance of the ODE driver",
     .get = [](const Scene& s) -> KeyValue { return params<PenaltyParams>(s).atol; },
     .set = [](Scene& s,
               const KeyValue& v) { params<PenaltyParams>(s).atol = std::get<double>(v); }},
    {.table = "method",
     .key = "max_ode_steps",
     .params = method_index<PenaltyParams>,
     .type = KeyType::integer,
     .range = {.lo = 0.0, .hi = 999999999999.0},
     .meaning = "ODE steps the whole run may take, then a numerical failure (0: automatic, 1e6 "
                "plus 1000 per grid step)",
     .get = [](const Scene& s) -> KeyValue { return params<PenaltyParams>(s).max_ode_steps; },
     .set =
         [](Scene& s, const KeyValue& v) {
           params<PenaltyParams>(s).max_ode_steps = std::get<std::int64_t>(v);
         }},
    {.table = "method",
     .key = "rtol",
     .params = method_index<EventDrivenParams>,
     .type = KeyType::number,
     .range = {.lo = 0.0, .hi = 1e-3, .lo_open = true},
     .meaning = "relative error tolerance of rk8pd between impacts",
     .get = get_number<EventDrivenParams, &EventDrivenParams::rtol>,
     .set = set_number<EventDrivenParams, &EventDrivenParams::rtol>},
    {.table = "method",
     .key = "atol",
     .params = method_index<EventDrivenParams>,
     .type = KeyType::number,
     .range = {.lo = 0.0, .hi = 1e-3, .lo_open = true},
     .meaning = "absolute error tolerance of rk8pd between impacts",
     .get = get_number<EventDrivenParams, &EventDrivenParams::atol>,
     .set = set_number<EventDrivenParams, &EventDrivenParams::atol>},
    {.table = "method",
     .key = "max_step",
     .params = method_index<EventDrivenParams>,
     .type = KeyType::number,
     .range = {.lo = 0.0, .hi = 1e6, .lo_open = true},
     .meaning = "longest ODE step; f is sampled 9 times per step to bound it for the impact search",
     .get = get_number<EventDrivenParams, &EventDrivenParams::max_step>,
     .set = set_number<EventDrivenParams, &EventDrivenParams::max_step>},
    {.table = "method",
     .key = "max_events",
     .params = method_index<EventDrivenParams>,
     .type = KeyType::integer,
     .range = {.lo = 0.0, .hi = 999999999999.0},
     .meaning = kMaxEvents,
     .get = get_integer<EventDrivenParams, &EventDrivenParams::max_events>,
     .set = set_integer<EventDrivenParams, &EventDrivenParams::max_events>},
    {.table = "method",
     .key = "max_ode_steps",
     .params = method_index<EventDrivenParams>,
     .type = KeyType::integer,
     .range = {.lo = 0.0, .hi = 999999999999.0},
     .meaning = "ODE steps the whole run may take, then a numerical failure (0: automatic, 1e6 "
                "plus 1000 per grid step)",
     .get = get_integer<EventDrivenParams, &EventDrivenParams::max_ode_steps>,
     .set = set_integer<EventDrivenParams, &EventDrivenParams::max_ode_steps>},
    {.table = "method",
     .key = "max_events",
     .params = method_index<ExactParams>,
     .type = KeyType::integer,
     .range = {.lo = 0.0, .hi = 999999999999.0},
     .meaning = "with a harmonic force, events (impacts, sticks, lifts) the whole run may pass, "
                "then a numerical failure (0: automatic, 1e6 plus 1000 per grid step)",
     .get = get_integer<ExactParams, &ExactParams::max_events>,
     .set = set_integer<ExactParams, &ExactParams::max_events>},
};

}  // namespace

std::span<const KeySpec> method_keys() {
  return kMethodKeys;
}

void read_method_keys(const KeyReader& r, const toml::table& method, Scene& scene) {
  const std::string_view name = method_name(scene.method);
  for (const KeySpec& spec : kMethodKeys)
    if (spec.params == scene.method.index())
      if (const toml::node* node = method.get(spec.key)) spec.set(scene, r.value(spec, *node));
  r.only(method, "method", key_names("method", name),
         "unknown key for method '" + std::string(name) + "'");
}

}  // namespace impact
