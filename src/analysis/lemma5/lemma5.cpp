#include "analysis/lemma5/lemma5.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "analysis/spline_contact.hpp"
#include "impact/output/csv.hpp"

namespace impact::lemma5 {
namespace {

constexpr double kTStar = 5.0;        // Figure 2's impact time
constexpr double kFigure2Eps = 1e-3;  // where the mass of N_eps is reported

std::string pairing_csv(const Lemma5Convergence& c) {
  std::ostringstream csv;
  csv << "eps,ratio_lemma5,ratio_s2_over_3,deviation,predicted_deviation,left_ratio,"
         "right_ratio\n";
  for (const Lemma5Point& p : c.points) {
    const char* separator = "";
    for (double x : {p.eps, p.ratio, p.delta_ratio, p.ratio - 0.5, p.predicted_deviation,
                     p.left_ratio, p.right_ratio}) {
      csv << separator << round_trip(x);
      separator = ",";
    }
    csv << '\n';
  }
  return csv.str();
}

toml::table summarize(const Lemma5Convergence& c) {
  toml::table entry{{"psi_at_t_star", c.psi_at_t_star},
                    {"predicted_coefficient", c.predicted_coefficient},
                    {"fitted_slope", c.fitted_slope}};
  for (const Lemma5Point& p : c.points) {
    const double k = -std::log10(p.eps);
    if (std::fabs(k - std::round(k)) > 1e-9) continue;  // decades only
    entry.insert("pairing_ratio_eps_1e-" + std::to_string(std::lround(k)), p.ratio);
    if (p.eps == kFigure2Eps)
      entry.insert("measured_coefficient", (p.ratio - 0.5) / (p.eps * p.eps));
  }
  const Lemma5Point& last = c.points.back();
  entry.insert("s2_over_3_ratio_eps_1e-6", last.delta_ratio);
  entry.insert("left_piece_ratio_eps_1e-6", last.left_ratio);
  entry.insert("right_piece_ratio_eps_1e-6", last.right_ratio);
  return entry;
}

}  // namespace

toml::table run_lemma5(const ExperimentContext& context) {
  const std::vector<double> eps = lemma5_eps_values();
  const SplineImpact at_figure2(kTStar, kFigure2Eps);
  const auto one = [](double) { return 1.0; };
  toml::table summary{
      {"t_star", kTStar},
      {"eps_max", eps.front()},
      {"eps_min", eps.back()},
      {"eps_count", static_cast<std::int64_t>(eps.size())},
      {"mass_lemma5_force", pair_with_second_derivative(at_figure2, 1.0 / 6, one).total()},
      {"mass_s2_over_3", pair_with_second_derivative(at_figure2, 1.0 / 3, one).total()}};
  double slope_min = std::numeric_limits<double>::infinity(), slope_max = -slope_min;
  double worst_deviation = 0;
  for (const TestFunction& psi : lemma5_test_functions(kTStar)) {
    const Lemma5Convergence c = lemma5_convergence(psi, kTStar, eps);
    context.write("pairing_" + psi.name + ".csv", [&] { return pairing_csv(c); });
    slope_min = std::min(slope_min, c.fitted_slope);
    slope_max = std::max(slope_max, c.fitted_slope);
    worst_deviation = std::max(worst_deviation, std::fabs(c.points.back().ratio - 0.5));
    summary.insert(psi.name, summarize(c));
  }
  summary.insert("fitted_slope_min", slope_min);
  summary.insert("fitted_slope_max", slope_max);
  summary.insert("max_abs_deviation_eps_1e-6", worst_deviation);
  return toml::table{{"lemma5", std::move(summary)}};
}

const Experiment kLemma5Experiment{
    "lemma5", "Lemma 5 (Section 5.1): the spline contact force N_eps = S''/6 against delta",
    &run_lemma5};

}  // namespace impact::lemma5
