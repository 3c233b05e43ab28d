// The bonding field: adhesion with damage between the particle and the floor, the future work the
// paper announces in its conclusion ("a more realistic contact model ... where we add the effect
// of a bonding field"). In the gap g = u - phi >= 0, the product form of the Shillor-Sofonea-Telega
// school (paper_notes/bonding_field.md: sources, and what of them is confirmed):
//   u'' = N + f - gamma beta^2 R(g),   R(g) = min(g, L),
//   beta' = -(beta (gamma R(g)^2 - eps_a))_+ = -beta (gamma R(g)^2 - eps_a)_+,   beta(0) = beta0,
// beta the fraction of active bonds (never healing), gamma the adhesion stiffness, eps_a the energy
// density below which bonds hold, L the bond length past which the pull saturates. The pull derives
// from the adhesive energy gamma beta^2 Phi(g), Phi' = R, so that with a constant f
//   E = v^2/2 - f u + gamma beta^2 Phi(g),   dE/dt = 2 gamma beta beta' Phi(g) <= 0 in flight,
// and E + D = E(0) with D the energy spent on bonds, int -2 gamma beta beta' Phi (impacts' losses
// (1 - COR^2) V^2 / 2 aside). With gamma = 0 or beta0 = 0 the pull and the damage vanish
// identically: the model is the paper's, and the package runs it as the paper's (bonded()).
//
// The Frémond form (LMGC90's MAC_CZM law; paper_notes/bonding_field.md) puts beta inside the
// bracket, with a viscosity b > 0:
//   b beta' = -(beta gamma R(g)^2 - eps_a)_+,
// the same pull and energy, so the same dE/dt = 2 gamma beta beta' Phi(g) <= 0. Its damage stops
// at beta = eps_a/(gamma R^2) at a fixed opening, where the product form decays to 0.
//
// Plain data and closed forms only; C++17, since model.hpp includes it (the Siconos peer).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact {

// The damage law: the product form beta' = -beta (gamma R^2 - eps_a)_+, or the Frémond form
// b beta' = -(beta gamma R^2 - eps_a)_+.
enum class BondForm { product, fremond };

struct Bonding {
  double gamma = 0.0;  // adhesion stiffness, per unit time squared (>= 0)
  // bond length: the pull saturates at gap L (> 0); infinity: never
  double L = std::numeric_limits<double>::infinity();
  double eps_a = 0.0;                 // energy density below which bonds do not break (>= 0)
  double beta0 = 1.0;                 // the fraction of active bonds at t = 0, in [0, 1]
  BondForm form = BondForm::product;  // where beta stands in the damage law
  // the Frémond form's viscosity (> 0, per unit time); NaN: not given (the product form has none)
  double b = std::numeric_limits<double>::quiet_NaN();
  // the fraction of active bonds at or below which the bond counts as broken: the run's debond
  // event (event.hpp), in [0, 1); beta > 0 at every finite time in both forms, so 0 means "never"
  // except by underflow
  double debond_below = 0.01;
};

// Whether the bonding field acts at all: gamma beta0^2 != 0. Otherwise nothing of it is run.
inline bool bonds_act(const Bonding& b) {
  return b.gamma != 0.0 && b.beta0 != 0.0;
}

// R(g) = min(g, L) for g >= 0; 0 below the floor (a gap that rounding made negative pulls not).
inline double bond_reach(const Bonding& b, double gap) {
  return std::min(std::max(gap, 0.0), b.L);
}

// Phi(g) = int_0^g R: g^2/2 up to L, L g - L^2/2 beyond.
inline double bond_potential(const Bonding& b, double gap) {
  const double g = std::max(gap, 0.0);
  return g <= b.L ? 0.5 * g * g : b.L * g - 0.5 * b.L * b.L;
}

// The adhesive energy gamma beta^2 Phi(g), the bonds' part of E.
inline double adhesive_energy(const Bonding& b, double beta, double gap) {
  return b.gamma * beta * beta * bond_potential(b, gap);
}

// The pull gamma beta^2 R(g) (subtracted from f).
inline double adhesive_pull(const Bonding& b, double beta, double gap) {
  return b.gamma * beta * beta * bond_reach(b, gap);
}

// beta from the variable an ODE carries for it, and back. The product form carries the logarithm
// ln(beta / beta0) (exactly beta0 while it is 0, i.e. while no bond broke; beta > 0 always). The
// Frémond form carries beta itself, read in [0, 1]: its rate is not proportional to beta, so the
// logarithm's rate would blow up as beta -> 0, and an explicit stage may overshoot below 0.
inline double bond_fraction(const Bonding& b, double carried) {
  if (b.form == BondForm::fremond) return std::clamp(carried, 0.0, 1.0);
  return b.beta0 * std::exp(carried);
}
inline double bond_carried(const Bonding& b, double beta) {
  if (b.form == BondForm::fremond) return beta;
  return std::log(beta / b.beta0);
}

// (gamma R^2 - eps_a)_+: (ln beta)' = -damage_excess in the product form.
inline double damage_excess(const Bonding& b, double gap) {
  const double r = bond_reach(b, gap);
  return std::max(b.gamma * r * r - b.eps_a, 0.0);
}

// The Frémond form's beta' = -(beta gamma R^2 - eps_a)_+ / b.
inline double fremond_rate(const Bonding& b, double beta, double gap) {
  const double r = bond_reach(b, gap);
  return -std::max(beta * (b.gamma * (r * r)) - b.eps_a, 0.0) / b.b;
}

// The rates of the carried variable (bond_fraction) and of D, the energy spent on bonds,
// D' = -2 gamma beta beta' Phi(g), at beta and the gap g.
struct BondRates {
  double carried, spent;
};
inline BondRates bond_rates(const Bonding& b, double beta, double gap) {
  if (b.form == BondForm::fremond) {
    const double rate = fremond_rate(b, beta, gap);
    return {rate, -2.0 * b.gamma * beta * rate * bond_potential(b, gap)};
  }
  const double excess = damage_excess(b, gap);
  return {-excess, 2.0 * adhesive_energy(b, beta, gap) * excess};
}

// Keeps an ODE step's carried variable from raising beta above the step's start (and, Frémond,
// from taking it below 0): rk8pd's weights are not all positive.
inline double bond_carried_monotone(const Bonding& b, double carried, double at_start) {
  if (b.form == BondForm::fremond) return std::fmax(std::fmin(carried, at_start), 0.0);
  return std::fmin(carried, at_start);
}

// One step of the bonds in a time-stepper (WithInternal, with_internal.hpp), from (beta_n, D_n)
// to (beta_{n+1}, D_{n+1}) once the particle's step has given the gap g_{n+1} at its end:
//   beta_{n+1} = beta_n / (1 + h (gamma R(g_{n+1})^2 - eps_a)_+),
// implicit Euler's closed form of beta' = -beta (gamma R^2 - eps_a)_+. The rate is read at the
// step's end, g_{n+1}, because implicit Euler takes it there, and because it is known without an
// iteration: the particle's step used beta_n alone (the pull is explicit). The divisor is >= 1,
// so beta_{n+1} is in [0, beta_n] for any h, also in rounding (a quotient by x >= 1 rounds to at
// most beta_n); an explicit Euler step would go negative once h (gamma R^2 - eps_a) > 1 (a stiff
// gamma). D gains the adhesive energy the bonds lost at that gap,
//   D_{n+1} = D_n + gamma (beta_n^2 - beta_{n+1}^2) Phi(g_{n+1}) >= D_n,
// so that the adhesive energy and D move together: E + D changes only by what the particle's
// scheme itself does to E (the plain scheme's energy bookkeeping).
//
// The Frémond form takes MAC_CZM's update (LMGC90, src/Core/shared/mod_tact_behav.f90, updt_CZM),
// implicit Euler of b beta' = -(beta gamma R^2 - eps_a) at g_{n+1}, in the normal direction alone:
//   beta_{n+1} = (h eps_a + beta_n b) / (b + h gamma R(g_{n+1})^2),
// kept only where it does not raise beta and damage is on at beta_n (eps_a <= beta_n gamma R^2;
// the two conditions are the same in exact arithmetic), else beta_{n+1} = beta_n. It lies in
// (0, beta_n] when taken: a weighted mean of beta_n and eps_a/(gamma R^2) <= beta_n.
inline double fremond_update(const Bonding& b, double h, double gap_next, double beta) {
  const double r = bond_reach(b, gap_next);
  const double opening = b.gamma * (r * r);
  const double next = (h * b.eps_a + beta * b.b) / (b.b + h * opening);
  return next <= beta && b.eps_a <= beta * opening ? next : beta;
}
inline void bond_step(const Bonding& b, double h, double gap_next, double& beta, double& spent) {
  const double before = beta;
  if (b.form == BondForm::fremond) {
    beta = fremond_update(b, h, gap_next, before);
  } else {
    const double excess = damage_excess(b, gap_next);
    // No damage in this step: beta / 1 and D + 0 are beta and D bit for bit, and the division,
    // whose latency would chain each step to the next, is skipped (the well with no damage).
    if (excess == 0.0) return;
    beta = before / (1.0 + h * excess);
  }
  spent += b.gamma * ((before - beta) * (before + beta)) * bond_potential(b, gap_next);
}

// Whether a particle at gap g > 0 moving away from the floor at v > 0 under the pull alone (f = 0)
// never comes back: the impulse the pull can still give is at most v. While it rises the gap stays
// >= g, so R >= r = R(g) and beta decays at least at the rate c, beta(t) <= beta e^{-c t}:
// c = gamma r^2 - eps_a in the product form, gamma r^2 / b in the Frémond form with eps_a = 0 (with
// eps_a > 0 Frémond's beta keeps eps_a/(gamma R^2) and a finite L keeps a pull: no bound here).
// The pull gamma beta(t)^2 min(g(t), L) with g(t) <= g + v t then gives at most
//   gamma beta^2 min(L / (2c), g / (2c) + v / (4c^2)),
// and v >= that keeps v(t) >= 0 for ever. Past L (g >= L) the bound is the impulse itself (R = L
// and c are constant there, and v - gamma beta^2 L / (2c) is invariant): the test is exact, the
// particle escapes if and only if it holds; short of L it is sufficient only.
inline bool never_returns(const Bonding& b, double beta, double gap, double v) {
  if (!(v > 0.0) || !(gap > 0.0)) return false;
  const double r = bond_reach(b, gap);
  double c = 0.0;
  if (b.form == BondForm::fremond) {
    if (b.eps_a > 0.0) return false;
    c = b.gamma * (r * r) / b.b;
  } else {
    c = b.gamma * (r * r) - b.eps_a;
  }
  if (!(c > 0.0)) return false;
  const double k = b.gamma * beta * beta;
  return v >= k * std::min(b.L / (2.0 * c), gap / (2.0 * c) + v / (4.0 * c * c));
}

// The highest gap of a flight in the well with no damage, R = g (g <= L) and a constant force
// f = -G: the motion keeps E_w = v^2/2 + G g + k g^2/2, k = gamma beta^2 > 0, and rises to the
// root of G g + k g^2/2 = E_w, (sqrt(G^2 + 2 k E_w) - G)/k, written without cancellation for G > 0.
inline double well_height(double k, double G, double gap, double v) {
  const double energy = 0.5 * v * v + G * gap + 0.5 * k * gap * gap;
  const double root = std::sqrt(G * G + 2.0 * k * energy);
  return G > 0.0 ? 2.0 * energy / (root + G) : (root - G) / k;
}

// The flight time from the floor at speed v0 > 0 back to it in that well, omega = sqrt(k):
// 2 atan2(v0 omega, G)/omega, the arc above the floor of an oscillation about g = -G/omega^2
// (paper_notes/bonding_field.md); it returns at speed -v0.
inline double well_return_time(double k, double G, double v0) {
  const double omega = std::sqrt(k);
  return 2.0 * std::atan2(v0 * omega, G) / omega;
}

}  // namespace impact
