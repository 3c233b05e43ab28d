// Lemma 4's proof, (4-11)-(4-13), evaluated on a pair of exact solutions: the two sides of (4-12)
// and the terms the proof drops on the way.
#pragma once

#include "impact/model/model.hpp"
#include "impact/references/exact.hpp"

namespace impact::lemma4 {

// The terms of (4-12) at time t for two solutions u, w of (2-1) with the same constant f.
struct EnergyIdentity412 {
  double lhs = 0;           // (1/2) int_0^t d/dtau z_tau^2 = (z_t^2(t) - z_t^2(0)) / 2
  double paper_rhs = 0;     // -u_t(t) w_t(t) + u_t(0) w_t(0), (4-12)'s last line
  double force_terms = 0;   // f (u(t) - u(0) + w(t) - w(0)), dropped by (4-12) when f != 0
  double dropped_n1_u = 0;  // int_0^t N1 u_tau = E_u(t) - E_u(0), set to 0 by the proof
  double dropped_n2_w = 0;  // int_0^t N2 w_tau = E_w(t) - E_w(0), set to 0 by the proof
  double paper_413 = 0;     // z_t^2(t) - z_t^2(0), which (4-13) claims is 0
  // lhs = paper_rhs + force_terms + dropped_n1_u + dropped_n2_w holds for every pair.
};
EnergyIdentity412 energy_identity_412(const ExactSolution& u, const ExactSolution& w,
                                      const Model& model, double t);

}  // namespace impact::lemma4
