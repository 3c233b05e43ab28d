#include "analysis/figure2/figure2.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <sstream>
#include <string>
#include <utility>

#include "analysis/spline_contact.hpp"
#include "impact/output/csv.hpp"

namespace impact::figure2 {
namespace {

constexpr double kTStar = 5.0;  // Figure 2's caption: t* = 5
constexpr double kEps = 1e-3;   // and eps = 0.001
constexpr double kTEnd = 10.0;  // panels (d)-(f) show [0, 10]
constexpr int kOuterSamples = 1001;
constexpr int kCubicSamples = 401;
constexpr int kCompareSamples = 20001;

int piece_number(SplinePiece p) {
  switch (p) {
    case SplinePiece::kS3:
      return 3;
    case SplinePiece::kS1:
      return 1;
    case SplinePiece::kS2:
      return 2;
    case SplinePiece::kS4:
      return 4;
  }
  return 0;
}

void csv_row(std::ostringstream& out, std::initializer_list<double> values) {
  const char* separator = "";
  for (double x : values) {
    out << separator << round_trip(x);
    separator = ",";
  }
  out << '\n';
}

// Each piece on its own closed interval, so that the knots appear once per piece and a plot
// that draws the pieces separately has no gap.
std::string pieces_csv(const SplineImpact& s, const NaturalCubicSpline& gsl3,
                       const NaturalCubicSpline& gsl5) {
  std::ostringstream out;
  out << "t,piece,u,v,N,u_gsl3,v_gsl3,N_gsl3,u_gsl5,v_gsl5,N_gsl5\n";
  const double e = s.eps(), t0 = -s.t_star(), t1 = kTEnd - s.t_star();
  const std::pair<SplinePiece, std::pair<double, double>> pieces[] = {{SplinePiece::kS3, {t0, -e}},
                                                                      {SplinePiece::kS1, {-e, 0.0}},
                                                                      {SplinePiece::kS2, {0.0, e}},
                                                                      {SplinePiece::kS4, {e, t1}}};
  for (const auto& [piece, range] : pieces) {
    const bool cubic = piece == SplinePiece::kS1 || piece == SplinePiece::kS2;
    const int n = cubic ? kCubicSamples : kOuterSamples;
    for (int i = 0; i < n; ++i) {
      const double r = range.first + (range.second - range.first) * i / (n - 1);
      csv_row(out, {s.t_star() + r, static_cast<double>(piece_number(piece)), s.piece(piece, 0, r),
                    s.piece(piece, 1, r), s.piece(piece, 2, r), gsl3.eval(0, r), gsl3.eval(1, r),
                    gsl3.eval(2, r), gsl5.eval(0, r), gsl5.eval(1, r), gsl5.eval(2, r)});
    }
  }
  return out.str();
}

std::string printed_s2_csv(const SplineImpact& printed) {
  std::ostringstream out;
  out << "t,u,v,N\n";
  for (int i = 0; i < kCubicSamples; ++i) {
    const double r = printed.eps() * i / (kCubicSamples - 1);
    csv_row(out, {printed.t_star() + r, printed.piece(SplinePiece::kS2, 0, r),
                  printed.piece(SplinePiece::kS2, 1, r), printed.piece(SplinePiece::kS2, 2, r)});
  }
  return out.str();
}

// max over orders 0..2 of the difference scaled by the size of that derivative on the contact
// interval (eps, 3/2, 3/eps), over [r0, r1] and, densely, over the contact interval.
double max_relative_difference(const SplineImpact& s, const NaturalCubicSpline& gsl, double r0,
                               double r1) {
  const double e = s.eps(), scale[] = {e, 1.5, 3 / e};
  double m = 0;
  for (int order = 0; order <= 2; ++order) {
    const double d = std::max(max_difference(s, gsl, order, r0, r1, kCompareSamples),
                              max_difference(s, gsl, order, -e, e, kCompareSamples));
    m = std::max(m, d / scale[order]);
  }
  return m;
}

toml::table summarize(const SplineImpact& s, const SplineImpact& printed,
                      const NaturalCubicSpline& gsl3, const NaturalCubicSpline& gsl5) {
  const double e = s.eps();
  const KnotJumps jp = knot_jumps(printed), jc = knot_jumps(s);
  double max_diff_printed = 0;  // GSL spline against S_eps with the printed S_2, on [t*, t* + eps]
  for (int i = 0; i < kCompareSamples; ++i) {
    const double r = e * i / (kCompareSamples - 1);
    max_diff_printed = std::max(max_diff_printed,
                                std::fabs(gsl3.eval(0, r) - printed.piece(SplinePiece::kS2, 0, r)));
  }
  double min_u = 0;
  for (int i = 0; i < kCompareSamples; ++i)
    min_u = std::min(min_u, s.at_offset(0, -e + 2 * e * i / (kCompareSamples - 1)));
  return toml::table{
      {"t_star", s.t_star()},
      {"eps", e},
      {"s2_jump_at_t_plus_eps_printed", jp.jump[0][2]},
      {"s2_velocity_jump_at_t_plus_eps_printed", jp.jump[1][2]},
      {"s2_second_derivative_jump_at_t_star_printed", jp.jump[2][1]},
      {"s2_second_derivative_jump_at_t_plus_eps_printed", jp.jump[2][2]},
      {"corrected_max_jump_c2", jc.max_abs(2)},
      {"corrected_third_derivative_jump_at_t_star", jc.jump[3][1]},
      {"natural_spline_slope_at_t_minus_eps", gsl3.eval(1, -e)},
      {"natural_spline_slope_at_t_plus_eps", gsl3.eval(1, e)},
      {"natural_spline_second_derivative_at_t_star", gsl3.eval(2, 0.0)},
      {"max_diff_gsl_vs_formula", max_relative_difference(s, gsl3, -e, e)},
      {"max_diff_gsl_vs_formula_u", max_difference(s, gsl3, 0, -e, e, kCompareSamples)},
      {"max_diff_gsl_vs_formula_v", max_difference(s, gsl3, 1, -e, e, kCompareSamples)},
      {"max_diff_gsl_vs_formula_N", max_difference(s, gsl3, 2, -e, e, kCompareSamples)},
      {"max_diff_gsl_whole_vs_formula",
       max_relative_difference(s, gsl5, -s.t_star(), kTEnd - s.t_star())},
      {"max_diff_gsl_vs_printed_u", max_diff_printed},
      {"penetration_depth", -min_u},
      {"velocity_jump", s.at_offset(1, e) - s.at_offset(1, -e)},
  };
}

}  // namespace

toml::table run_figure2(const ExperimentContext& context) {
  const SplineImpact corrected(kTStar, kEps, SecondPiece::kCorrected);
  const SplineImpact printed(kTStar, kEps, SecondPiece::kPrinted);
  const NaturalCubicSpline gsl3 = natural_spline_through_impact(kEps);
  const NaturalCubicSpline gsl5 = natural_spline_whole(corrected, 0.0, kTEnd);
  context.write("pieces.csv", [&] { return pieces_csv(corrected, gsl3, gsl5); });
  context.write("s2_printed.csv", [&] { return printed_s2_csv(printed); });
  return toml::table{{"figure2", summarize(corrected, printed, gsl3, gsl5)}};
}

const Experiment kFigure2Experiment{
    "figure2", "Figure 2 (Section 5.1): the spline approximation S_eps of an impact", &run_figure2};

}  // namespace impact::figure2
