// GSL's adaptive Gauss-Kronrod quadrature, the one wrapper every study uses: QAG on the pieces
// between breakpoints (where the integrand has kinks or jumps, e.g. the impact times), so that
// each piece is smooth, and QAGIU for a tail to infinity. QAG on each piece rather than QAGP on
// the whole: QAGP's extrapolation misreads the crowd of tiny jumps before a Zeno point as a
// divergence.
#pragma once

#include <gsl/gsl_integration.h>

#include <cstddef>
#include <span>
#include <string_view>

namespace impact {

class Quadrature {
 public:
  struct Rule {
    double absolute = 0;      // epsabs
    double relative = 1e-12;  // epsrel
    int key = GSL_INTEG_GAUSS21;
  };
  // Throws std::bad_alloc when GSL cannot allocate the workspace of `limit` subintervals.
  explicit Quadrature(std::size_t limit = 2000);
  Quadrature(const Quadrature&) = delete;
  Quadrature& operator=(const Quadrature&) = delete;
  ~Quadrature();

  // The integral of f over [a, b], split at the breakpoints inside (a, b) (any order); `abserr`,
  // when given, receives the sum of GSL's error estimates. GSL_EROUND (round-off stopped the
  // refinement: the result is as good as double precision allows) is accepted; any other failure
  // throws std::runtime_error naming `what` and GSL's reason.
  template <class F>
  double integrate(F&& f, double a, double b, std::span<const double> breakpoints, const Rule& rule,
                   std::string_view what, double* abserr = nullptr) {
    return integrate_function(as_gsl(f), a, b, breakpoints, rule, what, abserr);
  }
  // The integral of f over [a, inf) (QAGIU; rule.key is not used).
  template <class F>
  double integrate_to_infinity(F&& f, double a, const Rule& rule, std::string_view what,
                               double* abserr = nullptr) {
    return integrate_tail(as_gsl(f), a, rule, what, abserr);
  }

 private:
  template <class F>
  static gsl_function as_gsl(F& f) {
    gsl_function fn;
    fn.function = [](double t, void* p) { return (*static_cast<F*>(p))(t); };
    fn.params = &f;
    return fn;
  }
  double integrate_function(gsl_function fn, double a, double b,
                            std::span<const double> breakpoints, const Rule& rule,
                            std::string_view what, double* abserr);
  double integrate_tail(gsl_function fn, double a, const Rule& rule, std::string_view what,
                        double* abserr);

  std::size_t limit_;
  gsl_integration_workspace* workspace_;
};

}  // namespace impact
