// Section 5.1 ("infinite-dimensional approach") and Lemma 5: the smooth approximation S_eps of the
// displacement of a particle that meets the floor phi = 0 at t* with f = 0, and the contact force
// built from its second derivative.
//
// In the local time r = t - t* the paper's pieces are
//   S_3 = -(3/2) r - (3/2) eps                          on [0, t* - eps],
//   S_1 = -(3/2)(r + eps) + (r + eps)^3 / (2 eps^2)     on (t* - eps, t*],
//   S_2 = -eps + (3/(2 eps)) r^2 - r^3 / (2 eps^2)      on [t*, t* + eps)   (corrected),
//   S_4 = (3/2) r - (3/2) eps                           on [t* + eps, inf).
// Section 5.1 prints S_2 with (3/2) r^2 instead of (3/(2 eps)) r^2. That S_2 is not continuous
// with S_4 at t* + eps (the jump is -(3/2) eps + (3/2) eps^2) and its second derivative is not
// the S_2'' = 3/eps - 3 r/eps^2 that Lemma 5's proof uses; the corrected one is, and makes S_eps
// C^2 (S''' jumps at the three knots, as for any cubic spline).
// The corrected S_1, S_2 are the natural cubic spline through (t* - eps, 0), (t*, -eps),
// (t* + eps, 0), and S_eps on [a, b] is the natural cubic spline through those three points and
// (a, S_3(a)), (b, S_4(b)): NaturalCubicSpline (GSL's gsl_interp_cspline) rebuilds both.
//
// Lemma 5 takes N_eps = S''/6 on (t* - eps, t* + eps). Since S'' integrates to the velocity jump
// S'(t* + eps) - S'(t* - eps) = 3, N_eps has mass 1/2 and tends to delta(t - t*)/2, not delta;
// S''/3 tends to delta. pair_with_second_derivative() measures <w S'', psi> by GSL quadrature.
#pragma once

#include <gsl/gsl_interp.h>

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace impact {

// Which S_2 the approximation uses: as printed in Section 5.1, or corrected.
enum class SecondPiece { kPrinted, kCorrected };

// The four pieces of S_eps in time order.
enum class SplinePiece { kS3, kS1, kS2, kS4 };

// The knots where the pieces meet, in time order: t* - eps (S_3|S_1), t* (S_1|S_2),
// t* + eps (S_2|S_4).
inline constexpr int kSplineKnots = 3;

class SplineImpact {
 public:
  // Throws std::invalid_argument unless eps > 0 and t* > eps (so S_3 starts at t = 0 as printed).
  SplineImpact(double t_star, double eps, SecondPiece second = SecondPiece::kCorrected);

  double t_star() const { return t_star_; }
  double eps() const { return eps_; }

  // d^order/dr^order (order 0..3) of piece p's formula at local time r = t - t*, for any r
  // (the formula, not S_eps: no switch to another piece).
  double piece(SplinePiece p, int order, double r) const;
  // The piece S_eps uses at local time r: S_3 for r <= -eps, S_1 on (-eps, 0], S_2 on (0, eps),
  // S_4 for r >= eps.
  SplinePiece piece_for(double r) const;
  // S_eps^(order) at local time r, and at time t.
  double at_offset(int order, double r) const { return piece(piece_for(r), order, r); }
  double at(int order, double t) const { return at_offset(order, t - t_star_); }
  // Local time of knot k (0, 1, 2) and the pieces left and right of it.
  double knot(int k) const;
  static SplinePiece left_of_knot(int k);
  static SplinePiece right_of_knot(int k);

 private:
  double t_star_, eps_;
  SecondPiece second_;
};

// Jump (left piece minus right piece) of the derivative `order` (0..3) at each knot:
// jump[order][k]. E.g. jump[0][2] = S_2(t* + eps) - S_4(t* + eps).
struct KnotJumps {
  std::array<std::array<double, kSplineKnots>, 4> jump{};
  // max |jump| over the knots for the derivatives 0..max_order.
  double max_abs(int max_order) const;
};
KnotJumps knot_jumps(const SplineImpact& spline);

// GSL's natural cubic spline (gsl_interp_cspline: S'' = 0 at both end knots) through (x_i, y_i),
// continued linearly beyond the end knots, which keeps it the natural spline on the whole line.
class NaturalCubicSpline {
 public:
  // Throws std::invalid_argument for fewer than 3 points or x not strictly increasing.
  NaturalCubicSpline(std::vector<double> x, std::vector<double> y);
  NaturalCubicSpline(const NaturalCubicSpline&) = delete;
  NaturalCubicSpline& operator=(const NaturalCubicSpline&) = delete;
  NaturalCubicSpline(NaturalCubicSpline&& other) noexcept;
  NaturalCubicSpline& operator=(NaturalCubicSpline&&) = delete;
  ~NaturalCubicSpline();

  // d^order/dx^order (order 0..2) at x.
  double eval(int order, double x) const;
  const std::vector<double>& knots() const { return x_; }

 private:
  std::vector<double> x_, y_;
  gsl_interp* interp_ = nullptr;
};

// The natural spline through the impact data in local time r: (-eps, 0), (0, -eps), (eps, 0).
NaturalCubicSpline natural_spline_through_impact(double eps);
// The natural spline in local time through the impact data and the trajectory's values at the
// ends of [t_begin, t_end]: (t_begin - t*, S_3(t_begin)), ..., (t_end - t*, S_4(t_end)).
NaturalCubicSpline natural_spline_whole(const SplineImpact& spline, double t_begin, double t_end);

// max over `samples` equally spaced local times in [r_begin, r_end] (both included, plus the
// knots inside) of |spline^(order) - S_eps^(order)|.
double max_difference(const SplineImpact& formula, const NaturalCubicSpline& spline, int order,
                      double r_begin, double r_end, int samples);

// <weight S'', psi> = integral over (t* - eps, t* + eps) of weight S''(t) psi(t) dt, computed by
// Quadrature (GSL's QAG) in the local time r on each cubic piece separately (S'' is smooth on
// each).
struct Pairing {
  double left = 0;    // over (t* - eps, t*], the S_1 piece
  double right = 0;   // over [t*, t* + eps), the S_2 piece
  double abserr = 0;  // GSL's error estimate, summed
  double total() const { return left + right; }
};
Pairing pair_with_second_derivative(const SplineImpact& spline, double weight,
                                    const std::function<double(double)>& psi);

// Smooth test functions for Lemma 5, with their second derivatives: for the symmetric kernel
// S''/6 the pairing is psi(t*)/2 + psi''(t*) eps^2/24 + O(eps^4).
struct TestFunction {
  std::string name;
  std::function<double(double)> value;
  std::function<double(double)> second_derivative;
};
// A Gaussian centred at t* + 0.3 (width 0.5), cos t, the cubic 1 + (t - t* + 1)^2 + (t - t* + 1)^3,
// exp(-t) and the C^infinity bump exp(-1/(1 - x^2)), x = t - t* - 0.2, supported in |x| < 1
// (Bump{t* + 0.2, 1}, analysis/test_functions.hpp).
std::vector<TestFunction> lemma5_test_functions(double t_star);

// The Lemma 5 experiment's eps: 1e-1, 10^-1.5, 1e-2, ..., 1e-6 (11 values, half decades; the
// decades are the doubles nearest to 10^-k).
std::vector<double> lemma5_eps_values();

// <S''/6, psi> and <S''/3, psi> divided by psi(t*) at one eps, with each piece's share.
struct Lemma5Point {
  double eps = 0;
  double ratio = 0;        // <N_eps, psi> / psi(t*), N_eps = S''/6: tends to 1/2
  double delta_ratio = 0;  // <S''/3, psi> / psi(t*): tends to 1
  double left_ratio = 0;   // the S_1'' piece's share of ratio: tends to 1/4
  double right_ratio = 0;  // the S_2'' piece's share: tends to 1/4
  // psi''(t*) eps^2 / (24 psi(t*)), the leading term of ratio - 1/2.
  double predicted_deviation = 0;
};
struct Lemma5Convergence {
  double psi_at_t_star = 0;
  double predicted_coefficient = 0;  // psi''(t*) / (24 psi(t*))
  std::vector<Lemma5Point> points;   // one per eps, in the order given
  double fitted_slope = 0;           // fit_order of |ratio - 1/2| against eps, all points
};
Lemma5Convergence lemma5_convergence(const TestFunction& psi, double t_star,
                                     const std::vector<double>& eps);

}  // namespace impact
