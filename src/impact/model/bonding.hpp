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
// Plain data and closed forms only; C++17, since model.hpp includes it (the Siconos peer).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact {

struct Bonding {
  double gamma = 0.0;  // adhesion stiffness, per unit time squared (>= 0)
  // bond length: the pull saturates at gap L (> 0); infinity: never
  double L = std::numeric_limits<double>::infinity();
  double eps_a = 0.0;  // energy density below which bonds do not break (>= 0)
  double beta0 = 1.0;  // the fraction of active bonds at t = 0, in [0, 1]
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

// beta from the logarithm ln(beta / beta0) that an ODE carries (exactly beta0 while it is 0, i.e.
// while no bond broke), and back.
inline double bond_fraction(const Bonding& b, double log_ratio) {
  return b.beta0 * std::exp(log_ratio);
}
inline double bond_log_ratio(const Bonding& b, double beta) {
  return std::log(beta / b.beta0);
}

// (gamma R^2 - eps_a)_+: (ln beta)' = -damage_excess in the product form.
inline double damage_excess(const Bonding& b, double gap) {
  const double r = bond_reach(b, gap);
  return std::max(b.gamma * r * r - b.eps_a, 0.0);
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
inline void bond_step(const Bonding& b, double h, double gap_next, double& beta, double& spent) {
  const double before = beta;
  beta = before / (1.0 + h * damage_excess(b, gap_next));
  spent += b.gamma * ((before - beta) * (before + beta)) * bond_potential(b, gap_next);
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
