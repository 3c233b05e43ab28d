// The model of the paper, Section 2: u'' = N + f(t) (2-1), 0 <= u - phi ⟂ N >= 0 (2-2),
// with an optional coefficient of restitution (Section 5.2). The body force f(t) is a constant,
// a constant plus a harmonic term, or a muparser expression of t, or of t and the state u, v
// (force.hpp evaluates it).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "impact/model/bonding.hpp"
#include "impact/model/expression.hpp"

namespace impact {

// Position and velocity of the particle at one grid time t_l = l h.
struct State {
  double u = 0.0;
  double v = 0.0;
};

// The physical data every solver needs. An absent body force is f = 0. What an absent COR means
// for each family of methods (no restitution law for the paper's scheme, elastic for the
// event-driven readings) is the contact law's table, contact_law.hpp, through which every solver
// reads the COR.
// The time-dependent part of the body force, amplitude sin(omega t + phase): in the frame of a
// table that vibrates as y = a sin(omega t), amplitude = a omega^2 (vibrating_table).
struct Harmonic {
  double amplitude = 0.0;
  double omega = 0.0;  // rad per unit time, > 0
  double phase = 0.0;  // rad
  // Spelled out rather than defaulted: the Siconos peer includes this header as C++17.
  bool operator==(const Harmonic& other) const {
    return amplitude == other.amplitude && omega == other.omega && phase == other.phase;
  }
};

// The linear part of a force of the state, -k (u - u_eq) - c v (the impact oscillator's spring and
// damper): beside it the constant part f and the harmonic part of the force, so that the whole
// force is f - k (u - u_eq) - c v + amplitude sin(omega t + phase). The method exact follows it in
// closed form (linear_flight.hpp), the others as the force of the state it is (force.hpp).
struct LinearSpring {
  double k = 0.0;     // spring constant (per unit time squared); < 0: an inverted spring
  double c = 0.0;     // damping (per unit time)
  double u_eq = 0.0;  // the spring's rest position
};

// An internal variable z of the system, z' = g(t, u, v, z) (a damage, a bond fraction, a memory
// of the motion): its name, as the force expression, the rates and the output read it, its value
// at t = 0 and its rate g, a muparser expression of t, u, v and the internal variables. It is
// continuous across impacts (an impact changes v alone) and goes on evolving at rest.
struct InternalVariable {
  std::string name;
  double initial = 0.0;
  Expression rate;  // compiled by the scene reader (expression.hpp)
  bool operator==(const InternalVariable&) const = default;
};

// The most internal variables a model may have: kMaxInternal (expression.hpp).

// The body force of (2-1): f(t) = f + amplitude sin(omega t + phase) + expression(t), each part
// optional (the scene reader lets a scene give either the harmonic part or an expression).
struct Model {
  double phi = 0.0;                    // floor position (2-2)
  double f = 0.0;                      // the constant part of the body force (2-1)
  std::optional<double> cor{};         // COR = -v_after / v_before, in [0, 1]
  std::optional<Harmonic> harmonic{};  // the harmonic part of the body force, if any
  Expression expression{};             // muparser, of t (and u, v, z) added to it; empty: none
  // -k (u - u_eq) - c v added to it (LinearSpring); not with an expression
  std::optional<LinearSpring> linear{};
  std::vector<InternalVariable> internal{};  // at most kMaxInternal; empty for the paper's model
  // The bonding field (bonding.hpp) as the scene gives it; it acts where bonded() says so.
  std::optional<Bonding> bonding{};
};

// Whether the model has a bonding field that acts (gamma beta0^2 != 0): where it does not, every
// method runs the paper's model, bit for bit as without [bonding].
inline bool bonded(const Model& model) {
  return model.bonding && bonds_act(*model.bonding);
}

// Where a bonded model's state keeps beta and D (the energy spent on bonds): z[0] and z[1] of
// StateWithInternal (a bonding field and [[internal]] variables are not taken together).
inline constexpr std::size_t kBondFraction = 0, kBondEnergy = 1;

// f(t) = f: the case of the paper's Section 5 and of every closed form in this package.
inline bool constant_force(const Model& model) {
  return !model.harmonic && model.expression.empty() && !model.linear;
}

// The particle's state with the model's internal variables z_1..z_m (m = model.internal.size(),
// the rest of the array zero): the state of a stepper that follows them (StateOf, stepper.hpp).
// A constant or harmonic force without internal variables is stepped with State alone; the
// general force kind (force.hpp) and event_driven step this state with or without them.
struct StateWithInternal : State {
  std::array<double, kMaxInternal> z{};
  bool finite() const {
    for (double x : z)
      if (!std::isfinite(x)) return false;
    return std::isfinite(u) && std::isfinite(v);
  }
};
std::string describe(const StateWithInternal& s);

// The initial state of a model's internal variables beside the particle's.
inline StateWithInternal with_internal(const Model& model, const State& s) {
  StateWithInternal full{s, {}};
  if (bonded(model)) full.z[kBondFraction] = model.bonding->beta0;  // D(0) = 0
  for (std::size_t i = 0; i < model.internal.size() && i < kMaxInternal; ++i)
    full.z[i] = model.internal[i].initial;
  return full;
}

// Energy (3-1)/(4-5): E = v^2/2 - f u, for a constant force.
inline double energy(const Model& model, const State& s) {
  return 0.5 * s.v * s.v - model.f * s.u;
}

// The same with the bonds' energy gamma beta^2 Phi(u - phi) (bonding.hpp), beta = z[kBondFraction],
// for a bonded model; energy(model, s) for any other.
inline double energy(const Model& model, const StateWithInternal& s) {
  const double plain = energy(model, static_cast<const State&>(s));
  if (!bonded(model)) return plain;
  return plain + adhesive_energy(*model.bonding, s.z[kBondFraction], s.u - model.phi);
}

// What one step from t_l to t_{l+1} reports besides the new state.
struct StepInfo {
  // The contact impulse delivered in (t_l, t_{l+1}] divided by h, for every method, so that
  // h * sum = v^n - v^0 - int f (the impulse identity (4-9) with a body force): the N channel.
  // Where Newton's law acts (a COR), the impulse of the step in which it acts.
  double contact_force = 0.0;
  int iterations = 0;     // Newton iterations (fb_newton) or ODE steps (penalty); 0 otherwise
  bool converged = true;  // false when an iterative solve hit its cap without meeting its rule
  // Newton's law replaced the velocity of the scheme's own solve of (4-3) on this step (direct and
  // fb_newton with a COR, restitution.hpp): scheme_force is then N^l as (4-3) gave it, whose
  // impulse h N^l is not the floor's (it is 2|v| where the velocity jumps by (1 + COR)|v|).
  bool restituted = false;
  double scheme_force = 0.0;
};

// N^l of the method's own contact solve: (4-3)'s for the paper's scheme (before Newton's law
// replaces the velocity), the impulse / h for every other method. What decides a contact step
// (contact.hpp) and what the claims about (4-3) read; the N channel is contact_force.
inline double scheme_force(const StepInfo& info) {
  return info.restituted ? info.scheme_force : info.contact_force;
}

// The time grid: t_l = l h exactly (never accumulated), l = 0..steps.
struct Grid {
  double h = 0.0;
  std::int64_t steps = 0;
  double t(std::int64_t l) const { return static_cast<double>(l) * h; }

  // The grid of step h on [0, T]: steps = T/h when T/h is a whole number up to the rounding of
  // the division (4 eps relative: T and h each carry half an ulp of their decimal values and the
  // quotient another half, so T = 10, h = 0.001 gives 10000 steps although 10 / 0.001 rounds to
  // 9999.999999999998), else floor(T/h): the grid never passes T, and ends short of it by less
  // than h when h does not divide T. T/h must be at most 2^53 (the scene reader checks it).
  static Grid covering(double T, double h) {
    const double ratio = T / h, nearest = std::round(ratio);
    const bool whole = std::fabs(ratio - nearest) <= 4 * 2.220446049250313e-16 * nearest;
    return {h, static_cast<std::int64_t>(whole ? nearest : std::floor(ratio))};
  }
  // The last grid time, t_steps <= T.
  double end() const { return t(steps); }
};

}  // namespace impact
