#include "analysis/spline_contact.hpp"

#include <gsl/gsl_errno.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>

#include "analysis/fit.hpp"
#include "analysis/quadrature.hpp"
#include "analysis/test_functions.hpp"
#include "impact/forces/gsl_errors.hpp"

namespace impact {

namespace {

void check_order(int order, int max_order) {
  if (order < 0 || order > max_order)
    throw std::invalid_argument("derivative order " + std::to_string(order) + " outside 0.." +
                                std::to_string(max_order));
}

void check_gsl(int status, const char* what) {
  if (status != GSL_SUCCESS)
    throw std::runtime_error(std::string(what) + ": " + gsl_strerror(status));
}

}  // namespace

SplineImpact::SplineImpact(double t_star, double eps, SecondPiece second)
    : t_star_(t_star), eps_(eps), second_(second) {
  if (!(eps > 0) || !std::isfinite(eps) || !std::isfinite(t_star) || !(t_star > eps))
    throw std::invalid_argument("SplineImpact needs eps > 0 and t* > eps");
}

double SplineImpact::piece(SplinePiece p, int order, double r) const {
  check_order(order, 3);
  const double e = eps_, e2 = eps_ * eps_;
  switch (p) {
    case SplinePiece::kS3: {
      const double d[] = {-1.5 * r - 1.5 * e, -1.5, 0.0, 0.0};
      return d[order];
    }
    case SplinePiece::kS1: {
      const double s = r + e;  // t - t* + eps, the paper's variable for S_1
      const double d[] = {-1.5 * s + s * s * s / (2 * e2), -1.5 + 1.5 * s * s / e2, 3 * s / e2,
                          3 / e2};
      return d[order];
    }
    case SplinePiece::kS2: {
      // The printed S_2 has (3/2) r^2 where the corrected one has (3/(2 eps)) r^2.
      const double a = second_ == SecondPiece::kCorrected ? 1.5 / e : 1.5;
      const double d[] = {-e + a * r * r - r * r * r / (2 * e2), 2 * a * r - 1.5 * r * r / e2,
                          2 * a - 3 * r / e2, -3 / e2};
      return d[order];
    }
    case SplinePiece::kS4: {
      const double d[] = {1.5 * r - 1.5 * e, 1.5, 0.0, 0.0};
      return d[order];
    }
  }
  throw std::invalid_argument("unknown spline piece");
}

SplinePiece SplineImpact::piece_for(double r) const {
  if (r <= -eps_) return SplinePiece::kS3;
  if (r <= 0) return SplinePiece::kS1;
  if (r < eps_) return SplinePiece::kS2;
  return SplinePiece::kS4;
}

double SplineImpact::knot(int k) const {
  check_order(k, kSplineKnots - 1);
  return (k - 1) * eps_;
}

SplinePiece SplineImpact::left_of_knot(int k) {
  check_order(k, kSplineKnots - 1);
  const SplinePiece left[] = {SplinePiece::kS3, SplinePiece::kS1, SplinePiece::kS2};
  return left[k];
}

SplinePiece SplineImpact::right_of_knot(int k) {
  check_order(k, kSplineKnots - 1);
  const SplinePiece right[] = {SplinePiece::kS1, SplinePiece::kS2, SplinePiece::kS4};
  return right[k];
}

double KnotJumps::max_abs(int max_order) const {
  check_order(max_order, 3);
  double m = 0;
  for (int order = 0; order <= max_order; ++order)
    for (double j : jump[order]) m = std::max(m, std::fabs(j));
  return m;
}

KnotJumps knot_jumps(const SplineImpact& spline) {
  KnotJumps jumps;
  for (int order = 0; order <= 3; ++order)
    for (int k = 0; k < kSplineKnots; ++k) {
      const double r = spline.knot(k);
      jumps.jump[order][k] = spline.piece(SplineImpact::left_of_knot(k), order, r) -
                             spline.piece(SplineImpact::right_of_knot(k), order, r);
    }
  return jumps;
}

NaturalCubicSpline::NaturalCubicSpline(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)) {
  if (x_.size() < 3 || x_.size() != y_.size())
    throw std::invalid_argument("a natural cubic spline needs at least 3 (x, y) pairs");
  for (std::size_t i = 1; i < x_.size(); ++i)
    if (!(x_[i] > x_[i - 1])) throw std::invalid_argument("spline knots must increase strictly");
  const GslErrorsAsStatus errors;
  interp_ = gsl_interp_alloc(gsl_interp_cspline, x_.size());
  if (interp_ == nullptr) throw std::runtime_error("gsl_interp_alloc failed");
  const int status = gsl_interp_init(interp_, x_.data(), y_.data(), x_.size());
  if (status != GSL_SUCCESS) {
    gsl_interp_free(interp_);
    check_gsl(status, "gsl_interp_init");
  }
}

NaturalCubicSpline::NaturalCubicSpline(NaturalCubicSpline&& other) noexcept
    : x_(std::move(other.x_)),
      y_(std::move(other.y_)),
      interp_(std::exchange(other.interp_, nullptr)) {}

NaturalCubicSpline::~NaturalCubicSpline() {
  if (interp_ != nullptr) gsl_interp_free(interp_);
}

double NaturalCubicSpline::eval(int order, double x) const {
  check_order(order, 2);
  // Beyond the end knots S'' = 0, so the natural spline continues as its tangent line there.
  const bool below = x<x_.front(), above = x> x_.back();
  if (below || above) {
    const double x_end = below ? x_.front() : x_.back(), y_end = below ? y_.front() : y_.back();
    const double slope = gsl_interp_eval_deriv(interp_, x_.data(), y_.data(), x_end, nullptr);
    const double d[] = {y_end + slope * (x - x_end), slope, 0.0};
    return d[order];
  }
  switch (order) {
    case 0:
      return gsl_interp_eval(interp_, x_.data(), y_.data(), x, nullptr);
    case 1:
      return gsl_interp_eval_deriv(interp_, x_.data(), y_.data(), x, nullptr);
    default:
      return gsl_interp_eval_deriv2(interp_, x_.data(), y_.data(), x, nullptr);
  }
}

NaturalCubicSpline natural_spline_through_impact(double eps) {
  return NaturalCubicSpline({-eps, 0.0, eps}, {0.0, -eps, 0.0});
}

NaturalCubicSpline natural_spline_whole(const SplineImpact& spline, double t_begin, double t_end) {
  const double eps = spline.eps(), r0 = t_begin - spline.t_star(), r1 = t_end - spline.t_star();
  return NaturalCubicSpline({r0, -eps, 0.0, eps, r1},
                            {spline.at_offset(0, r0), 0.0, -eps, 0.0, spline.at_offset(0, r1)});
}

double max_difference(const SplineImpact& formula, const NaturalCubicSpline& spline, int order,
                      double r_begin, double r_end, int samples) {
  if (samples < 2 || !(r_end > r_begin))
    throw std::invalid_argument("max_difference needs r_begin < r_end and 2 samples or more");
  std::vector<double> points;
  for (int i = 0; i < samples; ++i)
    points.push_back(r_begin + (r_end - r_begin) * i / (samples - 1));
  for (double r : spline.knots())
    if (r >= r_begin && r <= r_end) points.push_back(r);
  double m = 0;
  for (double r : points)
    m = std::max(m, std::fabs(spline.eval(order, r) - formula.at_offset(order, r)));
  return m;
}

Pairing pair_with_second_derivative(const SplineImpact& spline, double weight,
                                    const std::function<double(double)>& psi) {
  // Each piece's integrand is a linear function times a smooth psi over an interval of length
  // eps: the 61-point Gauss-Kronrod rule integrates it to round-off without subdividing.
  const Quadrature::Rule rule{0.0, 1e-12, GSL_INTEG_GAUSS61};
  Quadrature quadrature(64);
  Pairing result;
  const double eps = spline.eps();
  const std::pair<SplinePiece, std::pair<double, double>> pieces[] = {
      {SplinePiece::kS1, {-eps, 0.0}}, {SplinePiece::kS2, {0.0, eps}}};
  for (const auto& [piece, range] : pieces) {
    auto integrand = [&, piece = piece](double r) {
      return weight * spline.piece(piece, 2, r) * psi(spline.t_star() + r);
    };
    double abserr = 0;
    (piece == SplinePiece::kS1 ? result.left : result.right) = quadrature.integrate(
        integrand, range.first, range.second, {}, rule, "Lemma 5 pairing <w S'', psi>", &abserr);
    result.abserr += abserr;
  }
  return result;
}

std::vector<TestFunction> lemma5_test_functions(double t_star) {
  const double c = t_star + 0.3, w = 0.5;  // Gaussian centre and width
  const double b = t_star + 0.2;           // bump centre
  const double p = t_star - 1;             // the cubic's expansion point
  auto gaussian = [c, w](double t) { return std::exp(-(t - c) * (t - c) / (2 * w * w)); };
  const Bump bump{b, 1.0};
  return {
      {"gaussian", gaussian,
       [=](double t) { return ((t - c) * (t - c) / (w * w * w * w) - 1 / (w * w)) * gaussian(t); }},
      {"cos", [](double t) { return std::cos(t); }, [](double t) { return -std::cos(t); }},
      {"cubic", [p](double t) { return 1 + (t - p) * (t - p) + (t - p) * (t - p) * (t - p); },
       [p](double t) { return 2 + 6 * (t - p); }},
      {"exp", [](double t) { return std::exp(-t); }, [](double t) { return std::exp(-t); }},
      {"bump", [bump](double t) { return bump.value(t); },
       [bump](double t) { return bump.second(t); }},
  };
}

std::vector<double> lemma5_eps_values() {
  const double decades[] = {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  std::vector<double> eps;
  for (std::size_t k = 0; k < std::size(decades); ++k) {
    if (k > 0) eps.push_back(decades[k] * std::sqrt(10.0));
    eps.push_back(decades[k]);
  }
  return eps;
}

Lemma5Convergence lemma5_convergence(const TestFunction& psi, double t_star,
                                     const std::vector<double>& eps) {
  Lemma5Convergence c;
  c.psi_at_t_star = psi.value(t_star);
  c.predicted_coefficient = psi.second_derivative(t_star) / (24 * c.psi_at_t_star);
  std::vector<double> deviations;
  for (double e : eps) {
    const SplineImpact s(t_star, e);
    const Pairing lemma5 = pair_with_second_derivative(s, 1.0 / 6, psi.value);
    const Pairing delta = pair_with_second_derivative(s, 1.0 / 3, psi.value);
    const double p = c.psi_at_t_star;
    c.points.push_back({e, lemma5.total() / p, delta.total() / p, lemma5.left / p, lemma5.right / p,
                        c.predicted_coefficient * e * e});
    deviations.push_back(std::fabs(c.points.back().ratio - 0.5));
  }
  c.fitted_slope = fit_order(eps, deviations).order;
  return c;
}

}  // namespace impact
