// The controlled integral of step_quadrature.hpp.
#include "impact/forces/step_quadrature.hpp"

#include <gsl/gsl_integration.h>

#include <array>
#include <cmath>
#include <exception>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "impact/forces/gsl_errors.hpp"

namespace impact {

namespace {

constexpr int kNodes = 16, kPairs = kNodes / 2;

// GSL's 16-point table, and the weights that give the Legendre coefficients c_14 and c_15 of the
// polynomial through the rule's samples: c_k = (2k + 1)/2 sum_i w_i P_k(x_i) f_i over the nodes
// +-x_i, P_14 even and P_15 odd.
struct GaussLegendre16 {
  const gsl_integration_glfixed_table* table = nullptr;
  std::array<double, kPairs> even{}, odd{};
};

const GaussLegendre16& gauss_legendre_16() {
  static const GaussLegendre16 rule = [] {
    GaussLegendre16 g;
    g.table = gsl_integration_glfixed_table_alloc(kNodes);
    for (int i = 0; i < kPairs; ++i) {
      const double x = g.table->x[i];
      double previous = 1,
             p = x;  // P_0, P_1, then P_{k+1} = ((2k + 1) x P_k - k P_{k-1}) / (k + 1)
      double p14 = 0;
      for (int k = 1; k < 15; ++k) {
        const double next = ((2 * k + 1) * x * p - k * previous) / (k + 1);
        previous = p;
        p = next;
        if (k + 1 == 14) p14 = p;
      }
      g.even[i] = 29.0 / 2 * g.table->w[i] * p14;
      g.odd[i] = 31.0 / 2 * g.table->w[i] * p;
    }
    return g;
  }();
  return rule;
}

struct Rule {
  double value = 0, tail = 0, largest = 0, at = 0;  // at: where |f| is largest
};

// The 16-point rule over [a, b] as gsl_integration_glfixed sums it, with |c_14| + |c_15| and the
// largest |f| of its samples.
Rule gauss_legendre(const Integrand& f, double a, double b) {
  const GaussLegendre16& g = gauss_legendre_16();
  const double A = 0.5 * (b - a), B = 0.5 * (b + a);
  double sum = 0, even = 0, odd = 0, largest = 0, at = B;
  for (int i = 0; i < kPairs; ++i) {
    const double Ax = A * g.table->x[i];
    const double plus = f.f(B + Ax, f.self), minus = f.f(B - Ax, f.self);
    sum += g.table->w[i] * (plus + minus);
    even += g.even[i] * (plus + minus);
    odd += g.odd[i] * (plus - minus);
    if (std::fabs(plus) > largest) std::tie(largest, at) = std::pair(std::fabs(plus), B + Ax);
    if (std::fabs(minus) > largest) std::tie(largest, at) = std::pair(std::fabs(minus), B - Ax);
  }
  return {A * sum, std::fabs(even) + std::fabs(odd), largest, at};
}

// The integrand for QAG: GSL's C frames must not see an exception, so the first is kept and
// rethrown after GSL returns; where |f| was largest is kept for the message.
struct Watched {
  explicit Watched(const Integrand& integrand) : f(&integrand) {}
  const Integrand* f;
  std::exception_ptr error;
  double largest = 0, at = 0;
  static double eval(double t, void* self) {
    auto* w = static_cast<Watched*>(self);
    if (w->error) return 0;
    try {
      const double value = w->f->f(t, w->f->self);
      if (std::fabs(value) > w->largest) {
        w->largest = std::fabs(value);
        w->at = t;
      }
      return value;
    } catch (...) {
      w->error = std::current_exception();
      return 0;
    }
  }
};

using Workspace =
    std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)>;

gsl_integration_workspace* workspace() {
  thread_local const Workspace w(gsl_integration_workspace_alloc(kMaxSubintervals),
                                 &gsl_integration_workspace_free);
  return w.get();
}

}  // namespace

double controlled_integral(const Integrand& f, double a, double b) {
  const Rule rule = gauss_legendre(f, a, b);
  if (!(rule.tail > kResolvedTail * rule.largest)) return rule.value;
  const double mid = 0.5 * (a + b);
  const Rule left = gauss_legendre(f, a, mid), right = gauss_legendre(f, mid, b);
  Watched watched(f);
  for (const Rule& r : {rule, left, right})
    if (r.largest >= watched.largest)
      std::tie(watched.largest, watched.at) = std::pair(r.largest, r.at);
  const double tolerance = kStepTolerance * (b - a) * watched.largest;
  if (std::fabs(left.value + right.value - rule.value) <= tolerance) return rule.value;

  gsl_function F{&Watched::eval, &watched};
  double result = 0, error = 0;
  int status;
  {
    GslErrorsAsStatus quiet;
    status = gsl_integration_qag(&F, a, b, tolerance, 0.0, kMaxSubintervals, GSL_INTEG_GAUSS61,
                                 workspace(), &result, &error);
  }
  if (watched.error) std::rethrow_exception(watched.error);
  if (status == GSL_SUCCESS && std::isfinite(result)) return result;
  std::ostringstream msg;
  msg.precision(10);
  msg << "the force expression is not resolved over [" << a << ", " << b << "]: its integral "
      << "there (a step's mean force) does not reach " << kStepTolerance
      << " of (b - a) max|f| with " << kMaxSubintervals << " pieces (GSL: " << gsl_strerror(status)
      << "); |f| reaches " << watched.largest << " at t = " << watched.at
      << ": f is unbounded there or varies faster than the step resolves; use a smaller time.h, "
         "or method event_driven";
  throw std::runtime_error(msg.str());
}

}  // namespace impact
