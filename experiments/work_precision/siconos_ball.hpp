// Siconos's Moreau-Jean time-stepping (MoreauJeanOSI, theta = 1/2, Newton's impact law, a
// one-contact LCP solved by Lemke's method) on the paper's particle: a LagrangianLinearTIDS of
// mass 1 with the constant force f, the relation y = u - phi. Behind the project's stepper
// interface (registry.hpp: initialize, do_step), so that measure_errors() and the timing of
// work_precision.hpp run it like the project's own solvers. Its impact law uses e = COR, and e = 1
// without one, as `exact` and `moreau_jean` do.
//
// This header has no Siconos type in it: siconos_ball.cpp is compiled as C++17 (Boost 1.74's
// uBLAS, which Siconos uses, does not compile as C++20) and the driver as C++20.
#pragma once

#include <cstdint>
#include <memory>

#include "impact/model.hpp"

namespace impact {

class SiconosBall {
 public:
  // A simulation on [0, steps h] with step h from `initial`.
  SiconosBall(const Model& model, const State& initial, double h, std::int64_t steps);

  // Siconos keeps its own state from `initial`: a simulation starts at l = 0 only, and s is
  // output only (std::logic_error for any other start).
  void initialize(const State& s, std::int64_t l);
  // Advances Siconos's simulation by one step and writes its state to s. N^l is the impulse of
  // the step over h.
  StepInfo do_step(State& s, std::int64_t l);

 private:
  struct Impl;
  std::shared_ptr<Impl> impl_;  // shared, so that the stepper moves and copies as simulate() needs
};

}  // namespace impact
