#include "analysis/quadrature.hpp"

#include <algorithm>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "impact/forces/gsl_errors.hpp"

namespace impact {
namespace {

void check(int status, std::string_view what) {
  if (status != GSL_SUCCESS && status != GSL_EROUND)
    throw std::runtime_error(std::string(what) +
                             ": GSL quadrature failed: " + gsl_strerror(status));
}

}  // namespace

Quadrature::Quadrature(std::size_t limit)
    : limit_(limit), workspace_(gsl_integration_workspace_alloc(limit)) {
  if (!workspace_) throw std::bad_alloc();
}

Quadrature::~Quadrature() {
  gsl_integration_workspace_free(workspace_);
}

double Quadrature::integrate_function(gsl_function fn, double a, double b,
                                      std::span<const double> breakpoints, const Rule& rule,
                                      std::string_view what, double* abserr) {
  std::vector<double> points{a};
  for (double t : breakpoints)
    if (t > a && t < b) points.push_back(t);
  points.push_back(b);
  std::sort(points.begin(), points.end());
  const GslErrorsAsStatus errors_as_status;
  double total = 0, error = 0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    if (!(points[i + 1] > points[i])) continue;
    double result = 0, piece_error = 0;
    check(gsl_integration_qag(&fn, points[i], points[i + 1], rule.absolute, rule.relative, limit_,
                              rule.key, workspace_, &result, &piece_error),
          what);
    total += result;
    error += piece_error;
  }
  if (abserr) *abserr = error;
  return total;
}

double Quadrature::integrate_tail(gsl_function fn, double a, const Rule& rule,
                                  std::string_view what, double* abserr) {
  const GslErrorsAsStatus errors_as_status;
  double result = 0, error = 0;
  check(gsl_integration_qagiu(&fn, a, rule.absolute, rule.relative, limit_, workspace_, &result,
                              &error),
        what);
  if (abserr) *abserr = error;
  return result;
}

}  // namespace impact
