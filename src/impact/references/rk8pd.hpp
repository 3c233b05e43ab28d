// GSL odeiv2's rk8pd for an ODE of dimension n, as the event-driven code drives it
// (ode_flight.hpp, internal_floor.hpp): an evolve object with its error control for the accepted
// steps, and a second stepper for the dense output (one step from an accepted step's start). A
// right-hand side that fails (an expression that is not finite) keeps its exception here and
// returns GSL_EBADFUNC; rethrow() passes it on after GSL returns, rather than throwing through
// GSL's C frames. Not installed: the core's implementation.
#pragma once

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cstddef>
#include <exception>
#include <utility>

namespace impact {

struct Rk8pd {
  using Rhs = int (*)(double t, const double y[], double dydt[], void* params);

  // params: what rhs receives (the owner, on the heap, since GSL keeps the pointer).
  Rk8pd(std::size_t n, double atol, double rtol, Rhs rhs, void* params)
      : sys{rhs, nullptr, n, params},
        step(gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, n)),
        dense(gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, n)),
        control(gsl_odeiv2_control_y_new(atol, rtol)),
        evolve(gsl_odeiv2_evolve_alloc(n)) {}
  Rk8pd(const Rk8pd&) = delete;
  Rk8pd& operator=(const Rk8pd&) = delete;
  ~Rk8pd() {
    gsl_odeiv2_evolve_free(evolve);
    gsl_odeiv2_control_free(control);
    gsl_odeiv2_step_free(dense);
    gsl_odeiv2_step_free(step);
  }

  // For a right-hand side's catch (...): keeps the exception, returns GSL's failure status.
  int failed() {
    error = std::current_exception();
    return GSL_EBADFUNC;
  }
  void rethrow() {
    if (error) std::rethrow_exception(std::exchange(error, nullptr));
  }

  gsl_odeiv2_system sys;
  gsl_odeiv2_step* step;
  gsl_odeiv2_step* dense;
  gsl_odeiv2_control* control;
  gsl_odeiv2_evolve* evolve;
  std::exception_ptr error;
  double h_next = 0;  // the step the error control proposes next
};

}  // namespace impact
