// GSL odeiv2's rk8pd for an ODE of dimension n, as the event-driven code drives it
// (ode_flight.hpp, internal_floor.hpp): an evolve object with its error control for the accepted
// steps, and a second stepper for the dense output (one step from an accepted step's start). A
// right-hand side that fails (an expression that is not finite) keeps its exception here and
// returns GSL_EBADFUNC; rethrow() passes it on after GSL returns, rather than throwing through
// GSL's C frames. OdeSystem (below) holds one with its right-hand side as a copyable value.
#pragma once

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cstddef>
#include <exception>
#include <memory>
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

// An rk8pd integrator and the right-hand side it calls, held together on the heap (GSL keeps a
// pointer to the right-hand side) and copied as one value: a copy holds a copy of the right-hand
// side and GSL objects of its own, with the step the error control proposed carried over, so the
// classes that hold one copy and move by default. Rhs is copyable and has
// int operator()(double t, const double y[], double dydt[]) const, which may throw: the exception
// is kept and rethrow() passes it on.
template <class Rhs>
class OdeSystem {
 public:
  OdeSystem(std::size_t n, double atol, double rtol, Rhs rhs)
      : held_(std::make_unique<Held>(n, atol, rtol, std::move(rhs))) {}
  OdeSystem(const OdeSystem& other)
      : held_(std::make_unique<Held>(other.held_->rk.sys.dimension, other.held_->atol,
                                     other.held_->rtol, other.held_->rhs)) {
    held_->rk.h_next = other.held_->rk.h_next;
  }
  OdeSystem& operator=(const OdeSystem& other) {
    if (this != &other) *this = OdeSystem(other);
    return *this;
  }
  OdeSystem(OdeSystem&&) noexcept = default;
  OdeSystem& operator=(OdeSystem&&) noexcept = default;
  ~OdeSystem() = default;

  // Like a pointer's, constness does not reach the integrator, which a const query steps.
  Rk8pd& rk() const { return held_->rk; }
  const Rhs& rhs() const { return held_->rhs; }
  // The right-hand side at (t, y), through GSL's entry (an exception kept for rethrow()).
  int evaluate(double t, const double y[], double dydt[]) const {
    return Held::call(t, y, dydt, held_.get());
  }

 private:
  struct Held {
    Held(std::size_t n, double a, double r, Rhs f)
        : rhs(std::move(f)), rk(n, a, r, &Held::call, this), atol(a), rtol(r) {}
    static int call(double t, const double y[], double dydt[], void* self) {
      auto* held = static_cast<Held*>(self);
      try {
        return held->rhs(t, y, dydt);
      } catch (...) {
        return held->rk.failed();
      }
    }
    Rhs rhs;
    Rk8pd rk;
    double atol, rtol;
  };
  std::unique_ptr<Held> held_;
};

}  // namespace impact
