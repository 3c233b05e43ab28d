// The paper's particle in Siconos, behind the project's stepper interface (stepper.hpp:
// initialize, do_step), so that the error measures and the timing of work_precision.hpp run it
// like the project's own solvers: a LagrangianLinearTIDS of mass 1, the relation y = u - phi >= 0,
// Newton's impact law v+ = -e v- with e = COR, and e = 1 without one (as `exact` and `moreau_jean`
// do). The body force f(t) of (2-1) is the project's own ForceFunction, evaluated by Siconos
// wherever it asks for the external force (an override of LagrangianDS::computeFExt(time)), so a
// constant, harmonic or expression force is the same function for both.
// Two of Siconos's integrators:
//  - time-stepping: MoreauJeanOSI(theta = 1/2) with a one-contact LCP solved by Lemke's method,
//    the same scheme as the project's `moreau_jean`; the force enters its step as
//    h ((1 - theta) f(t_l) + theta f(t_{l+1})), the trapezoidal rule;
//  - event-driven: EventDriven with LsodarOSI (ODEPACK's LSODAR: Adams or BDF with automatic
//    switching, and root finding on y between its steps). Between events it integrates the
//    smooth dynamics, LSODAR's root finder stops it where y reaches 0, an LCP at velocity level
//    applies Newton's law there and one at acceleration level decides whether the particle stays
//    on the floor. Its accuracy is LSODAR's tolerance (rtol = atol), which is what its
//    work-precision curve sweeps; the grid h only sets where it reports the state. It is not a
//    closed form: a grazing impact that LSODAR's root finder steps over (the sign of y does not
//    change at its step ends) is missed, and a Zeno accumulation of impacts is not passed.
//
// This header has no Siconos type in it: siconos_ball.cpp is compiled as C++17 (Boost 1.74's
// uBLAS, which Siconos uses, does not compile as C++20) and the driver as C++20.
#pragma once

#include <cstdint>
#include <memory>

#include "impact/model/model.hpp"

namespace impact {

enum class SiconosIntegrator { moreau_jean, lsodar };

class SiconosBall {
 public:
  // A simulation on [0, steps h] with output step h from `initial`. `tolerance` is LSODAR's
  // rtol = atol (event-driven only).
  SiconosBall(const Model& model, const State& initial, double h, std::int64_t steps,
              SiconosIntegrator integrator, double tolerance = 1e-10);

  // Siconos keeps its own state from `initial`: a simulation starts at l = 0 only, and s is
  // output only (std::logic_error for any other start).
  void initialize(const State& s, std::int64_t l);
  // Advances Siconos's simulation to t_{l+1} and writes its state to s. N^l is the contact
  // impulse of the step over h: Siconos's own impulse for Moreau-Jean, and for the event-driven
  // integrator the impulse identity (4-9), v^{l+1} - v^l minus the integral of f over the step,
  // on a step where Siconos processed an impact or the particle is in contact (0 on a free step).
  StepInfo do_step(State& s, std::int64_t l);

 private:
  struct Impl;
  std::shared_ptr<Impl> impl_;  // shared, so that the stepper moves and copies as simulate() needs
};

}  // namespace impact
