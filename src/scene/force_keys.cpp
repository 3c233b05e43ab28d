#include "scene/force_keys.hpp"

#include <stdexcept>
#include <string>

#include "impact/forces/force.hpp"
#include "impact/format.hpp"
#include "impact/methods/capabilities.hpp"
#include "scene/toml_text.hpp"

namespace impact {
namespace {

// The harmonic part of a scene being read: each of its keys creates it, so that the keys can come
// in any order (check_force() then asks for amplitude and omega).
Harmonic& harmonic(Scene& s) {
  if (!s.model.harmonic) s.model.harmonic.emplace();
  return *s.model.harmonic;
}

KeyValue harmonic_value(const Scene& s, double Harmonic::*member) {
  return s.model.harmonic ? KeyValue(*s.model.harmonic.*member) : KeyValue();
}

// The linear part, created by each of its keys as the harmonic part is.
LinearSpring& linear(Scene& s) {
  if (!s.model.linear) s.model.linear.emplace();
  return *s.model.linear;
}

KeyValue linear_value(const Scene& s, double LinearSpring::*member) {
  return s.model.linear ? KeyValue(*s.model.linear.*member) : KeyValue();
}

constexpr std::string_view kLinearAlso = "not with force.expression";

const KeySpec kForceKeys[] = {
    {.table = "force",
     .key = "f",
     .type = KeyType::number,
     .meaning = "the constant part of the body force f(t) of (2-1); 0 without [force] or when "
                "[force] gives only the others",
     .get = [](const Scene& s) -> KeyValue { return s.model.f; },
     .set = [](Scene& s, const KeyValue& v) { s.model.f = std::get<double>(v); }},
    {.table = "force",
     .key = "amplitude",
     .type = KeyType::number,
     .also = "with force.omega",
     .meaning = "adds amplitude sin(omega t + phase) to f",
     .get = [](const Scene& s) { return harmonic_value(s, &Harmonic::amplitude); },
     .set = [](Scene& s, const KeyValue& v) { harmonic(s).amplitude = std::get<double>(v); }},
    {.table = "force",
     .key = "omega",
     .type = KeyType::number,
     .range = {.lo = 0.0, .lo_open = true},
     .also = "with force.amplitude",
     .meaning = "angular frequency of the harmonic part, rad per unit time",
     .get = [](const Scene& s) { return harmonic_value(s, &Harmonic::omega); },
     .set = [](Scene& s, const KeyValue& v) { harmonic(s).omega = std::get<double>(v); }},
    {.table = "force",
     .key = "phase",
     .type = KeyType::number,
     .also = "with force.amplitude",
     .meaning = "phase of the harmonic part, rad (0 when left out)",
     .get = [](const Scene& s) { return harmonic_value(s, &Harmonic::phase); },
     .set = [](Scene& s, const KeyValue& v) { harmonic(s).phase = std::get<double>(v); }},
    {.table = "force",
     .key = "expression",
     .type = KeyType::text,
     .also = "at most 4096 characters, not with f, amplitude, omega, phase or linear, not with "
             "method exact",
     .only_some = "u and v",
     .only_with = &Capabilities::state_force,
     .meaning = "the whole body force as a muparser function of t, e.g. \"-9.80665 + 14.71 * "
                "sin(62.83 * t)\" (pi is defined), or of t, the position u and the velocity v, "
                "f(t, u, v), e.g. \"-400 * (u - 0.05) - 2 * v + 10 * sin(20 * t)\"",
     .get = [](const Scene& s) -> KeyValue {
       return s.model.expression.empty() ? KeyValue() : KeyValue(s.model.expression.text());
     },
     .set = [](Scene& s, const KeyValue& v) { s.model.expression = std::get<std::string>(v); }},
    // force.linear = { k, c, u_eq }: adds -k (u - u_eq) - c v to f and the harmonic part.
    {.table = "force.linear",
     .key = "k",
     .type = KeyType::number,
     .also = kLinearAlso,
     .only_some = "a linear force",
     .only_with = &Capabilities::linear_force,
     .meaning = "spring constant of the linear force -k (u - u_eq) - c v added to f and the "
                "harmonic part (0 when left out; < 0: an inverted spring); exact follows it in "
                "closed form",
     .get = [](const Scene& s) { return linear_value(s, &LinearSpring::k); },
     .set = [](Scene& s, const KeyValue& v) { linear(s).k = std::get<double>(v); }},
    {.table = "force.linear",
     .key = "c",
     .type = KeyType::number,
     .also = kLinearAlso,
     .meaning = "damping of the linear force, per unit time (0 when left out; < 0 feeds energy in)",
     .get = [](const Scene& s) { return linear_value(s, &LinearSpring::c); },
     .set = [](Scene& s, const KeyValue& v) { linear(s).c = std::get<double>(v); }},
    {.table = "force.linear",
     .key = "u_eq",
     .type = KeyType::number,
     .also = kLinearAlso,
     .meaning = "the spring's rest position (0 when left out)",
     .get = [](const Scene& s) { return linear_value(s, &LinearSpring::u_eq); },
     .set = [](Scene& s, const KeyValue& v) { linear(s).u_eq = std::get<double>(v); }},
};

constexpr std::string_view kHarmonicKeys[] = {"amplitude", "omega", "phase"};

// force.linear: a table with at least one key, no expression beside it (the expression is the
// whole force; -k (u - u_eq) - c v belongs inside it). Whether the method takes it is refusal()'s.
void check_linear(const KeyReader& r, const toml::table& force) {
  const toml::node* linear = force.get("linear");
  if (!linear) return;
  if (const toml::table* keys = linear->as_table(); keys && keys->empty())
    r.fail_value("force", "linear", *linear,
                 "the table is empty: give k, c or u_eq (any finite numbers, each 0 when left "
                 "out), or leave force.linear out");
  if (const toml::node* expression = force.get("expression"))
    r.fail_value("force", "expression", *expression,
                 "is exclusive with force.linear = " + show(*linear) +
                     ": the expression gives the whole force f(t, u, v); write -k * (u - u_eq) - "
                     "c * v inside it, or give the linear part with f and the harmonic part "
                     "(with --set, --unset force.expression or --unset force.linear)");
}

}  // namespace

std::span<const KeySpec> force_keys() {
  return kForceKeys;
}

void check_force(const KeyReader& r, const toml::table& root, Scene& scene) {
  const toml::table* force = root.get("force") ? root.get("force")->as_table() : nullptr;
  if (!force) return;
  if (force->empty())
    r.fail_table("force", "[force]",
                 "the table is empty: give f, or amplitude and omega (and phase), or expression, "
                 "or linear; leave [force] out for f = 0");
  const auto node = [&](std::string_view key) { return force->get(key); };
  const toml::node* expression = node("expression");
  check_linear(r, *force);
  // An expression is the whole force: with f beside it, a scene that writes gravity in both
  // (as f = -g above an expression "-g + ...") would double it without a word.
  if (expression && node("f"))
    r.fail_value("force", "expression", *expression,
                 "is exclusive with force.f = " + show(*node("f")) +
                     ": the expression gives the whole force f(t); write the constant part "
                     "inside it (with --set, --unset force.f)");
  for (std::string_view key : kHarmonicKeys) {
    if (!node(key)) continue;
    if (expression)
      r.fail_value("force", "expression", *expression,
                   "is exclusive with force." + std::string(key) + " = " + show(*node(key)) +
                       ": give the harmonic part (amplitude, omega, phase) or an expression, "
                       "not both");
    if (key != "amplitude" && !node("amplitude"))
      r.fail_value("force", key, *node(key),
                   "given without force.amplitude: the harmonic part amplitude sin(omega t + "
                   "phase) needs amplitude (finite) and omega (> 0)");
  }
  if (node("amplitude") && !node("omega"))
    r.fail_value("force", "amplitude", *node("amplitude"),
                 "needs force.omega, the angular frequency in rad per unit time (> 0)");
  if (!expression) return;
  if (scene.model.expression.empty())  // ForceFunction reads an empty expression as none
    r.fail_value("force", "expression", *expression,
                 "the expression is empty; give a function of t, or leave the key out");
  try {
    // Compiled here, once: the solvers' copies share what the parse found.
    scene.model.expression = Expression(scene.model.expression.text(), scene.model.internal);
    // A force of the state where the run starts (z at its initial values), so that one that is
    // not finite there fails with the scene; a force of t alone was evaluated at t = 0 above.
    if (scene.model.expression.reads_state()) {
      const StateWithInternal start = with_internal(scene.model, scene.initial);
      try {
        force_expression_at(scene.model.expression, 0.0, start, start.z.data());
      } catch (const std::runtime_error& e) {
        r.fail_value("force", "expression", *expression,
                     std::string(e.what()) + " (the initial state: " +
                         (scene.model.internal.empty()
                              ? "u = " + round_trip(start.u) + ", v = " + round_trip(start.v)
                              : describe(start)) +
                         ")");
      }
    }
  } catch (const std::invalid_argument& e) {
    r.fail_value("force", "expression", *expression, e.what());
  }
}

}  // namespace impact
