// Beyond one particle: two masses joined by a linear spring above the floor of the paper, the
// lower one touching it. With q = (x1, x2) (x1 the lower mass m1, x2 the upper m2):
//   M q'' = -k (x2 - x1 - ell) (-1, 1) + M (g, g) + (N, 0),  0 <= x1 - phi ⟂ N >= 0,
// with Newton's impact law on x1' (COR e, or e = 1 without one) as for the paper's particle
// (2-1)-(2-4), which the lower mass is when k = 0. g is the body force per unit mass (the paper's
// f, constant). Only the lower mass meets the floor: the upper one is assumed to stay above it
// (x2 > x1; the spring is a spring, not a rod: nothing enforces it, a scene must keep it so).
// The state is Eigen's fixed-size vectors (no heap, no aliasing of a std::vector).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <string>

namespace impact {

struct Chain {
  double m1 = 1.0, m2 = 1.0;    // masses, > 0
  double k = 1.0;               // spring stiffness, >= 0 (k = 0: two free particles)
  double ell = 1.0;             // rest length of the spring
  double g = 0.0;               // body force per unit mass (f of (2-1)); < 0 pulls down
  double phi = 0.0;             // floor position (2-2)
  std::optional<double> cor{};  // COR of the lower mass's impacts, in [0, 1]; none: e = 1
};

// Throws std::invalid_argument naming the parameter for non-finite data, m <= 0, k < 0 or a COR
// outside [0, 1].
void check_chain(const Chain& chain);

// Positions and velocities of the two masses at one time.
struct ChainState {
  Eigen::Vector2d q = Eigen::Vector2d::Zero();  // (x1, x2)
  Eigen::Vector2d v = Eigen::Vector2d::Zero();  // (x1', x2')

  bool finite() const { return q.allFinite() && v.allFinite(); }
};

// "x1 = ..., x2 = ..., v1 = ..., v2 = ...", for a failure message (simulate.hpp).
std::string describe(const ChainState& s);

// Throws std::invalid_argument for a non-finite state or a lower mass below the floor.
void check_chain_state(const Chain& chain, const ChainState& s);

// E = (m1 x1'^2 + m2 x2'^2)/2 + k (x2 - x1 - ell)^2/2 - g (m1 x1 + m2 x2): the energy (3-1) of
// both masses plus the spring's, conserved in flight and at an elastic impact.
inline double chain_energy(const Chain& chain, const ChainState& s) {
  const double stretch = s.q(1) - s.q(0) - chain.ell;
  return 0.5 * (chain.m1 * s.v(0) * s.v(0) + chain.m2 * s.v(1) * s.v(1)) +
         0.5 * chain.k * stretch * stretch - chain.g * (chain.m1 * s.q(0) + chain.m2 * s.q(1));
}

}  // namespace impact
