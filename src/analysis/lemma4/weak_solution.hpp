// The weak formulation of (2-1)-(2-4) that the limit of Section 4's existence proof satisfies,
// checked on an exact solution: u >= phi, N >= 0 as a measure, int (u - phi) dN = 0, and
// int u psi'' = int psi dN + f int psi for smooth test functions psi (GSL quadrature). Lemma 4
// asks whether it has one solution only.
#pragma once

#include "impact/model/model.hpp"
#include "impact/references/exact.hpp"

namespace impact::lemma4 {

// The check on [0, T].
struct WeakSolutionCheck {
  double min_gap = 0;           // min of u - phi over a fine sampling and the impact times
  double min_cell_impulse = 0;  // min over a partition of the impulse of a cell: N >= 0
  double total_impulse = 0;     // N([0, T]) = impulse(0, T)
  double complementarity = 0;   // int_(0,T] (u - phi) dN, by Stieltjes integration by parts
  // max over the test functions of |int u psi'' - int psi dN - f int psi|
  double max_weak_residual = 0;
  double max_weak_scale = 0;  // max over the test functions of |int u psi''|, the residual's scale
  int test_functions = 0;
};
WeakSolutionCheck check_weak_solution(const ExactSolution& x, const Model& model, double T);

}  // namespace impact::lemma4
