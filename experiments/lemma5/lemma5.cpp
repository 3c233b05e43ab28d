// Lemma 5 (Section 5.1): pairs N_eps = S''/6 (the proof's contact force) and S''/3 with smooth test
// functions psi for eps = 1e-1 ... 1e-6 (half decades) by GSL quadrature over the two cubic pieces,
// and compares with psi(t*), the limit the lemma claims. Writes to the directory given as argument:
//   pairing_<psi>.csv  eps, <N_eps, psi>/psi(t*), <S''/3, psi>/psi(t*), the deviation from 1/2,
//                      its leading term psi''(t*) eps^2 / (24 psi(t*)), and each piece's share;
//   summary.toml       the ratios at each decade of eps, the fitted convergence slope per psi.
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "impact/output.hpp"
#include "analysis/spline_contact.hpp"

namespace {

constexpr double kTStar = 5.0;        // Figure 2's impact time
constexpr double kFigure2Eps = 1e-3;  // where the mass of N_eps is reported

void write_csv(const std::string& path, const impact::Lemma5Convergence& c) {
  impact::AtomicFile csv(path);
  std::fprintf(csv.stream(),
               "eps,ratio_lemma5,ratio_s2_over_3,deviation,predicted_deviation,left_ratio,"
               "right_ratio\n");
  for (const impact::Lemma5Point& p : c.points)
    std::fprintf(csv.stream(), "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", p.eps, p.ratio,
                 p.delta_ratio, p.ratio - 0.5, p.predicted_deviation, p.left_ratio, p.right_ratio);
  csv.commit();
}

toml::table summarize(const impact::Lemma5Convergence& c) {
  toml::table entry{{"psi_at_t_star", c.psi_at_t_star},
                    {"predicted_coefficient", c.predicted_coefficient},
                    {"fitted_slope", c.fitted_slope}};
  for (const impact::Lemma5Point& p : c.points) {
    const double k = -std::log10(p.eps);
    if (std::fabs(k - std::round(k)) > 1e-9) continue;  // decades only
    entry.insert("pairing_ratio_eps_1e-" + std::to_string(std::lround(k)), p.ratio);
    if (p.eps == kFigure2Eps)
      entry.insert("measured_coefficient", (p.ratio - 0.5) / (p.eps * p.eps));
  }
  const impact::Lemma5Point& last = c.points.back();
  entry.insert("s2_over_3_ratio_eps_1e-6", last.delta_ratio);
  entry.insert("left_piece_ratio_eps_1e-6", last.left_ratio);
  entry.insert("right_piece_ratio_eps_1e-6", last.right_ratio);
  return entry;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_DIR\n", argv[0]);
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    const std::vector<double> eps = impact::lemma5_eps_values();
    const impact::SplineImpact at_figure2(kTStar, kFigure2Eps);
    const auto one = [](double) { return 1.0; };
    toml::table summary{
        {"t_star", kTStar},
        {"eps_max", eps.front()},
        {"eps_min", eps.back()},
        {"eps_count", static_cast<std::int64_t>(eps.size())},
        {"mass_lemma5_force",
         impact::pair_with_second_derivative(at_figure2, 1.0 / 6, one).total()},
        {"mass_s2_over_3", impact::pair_with_second_derivative(at_figure2, 1.0 / 3, one).total()}};
    double slope_min = std::numeric_limits<double>::infinity(), slope_max = -slope_min;
    double worst_deviation = 0;
    for (const impact::TestFunction& psi : impact::lemma5_test_functions(kTStar)) {
      const impact::Lemma5Convergence c = impact::lemma5_convergence(psi, kTStar, eps);
      write_csv((dir / ("pairing_" + psi.name + ".csv")).string(), c);
      slope_min = std::min(slope_min, c.fitted_slope);
      slope_max = std::max(slope_max, c.fitted_slope);
      worst_deviation = std::max(worst_deviation, std::fabs(c.points.back().ratio - 0.5));
      summary.insert(psi.name, summarize(c));
    }
    summary.insert("fitted_slope_min", slope_min);
    summary.insert("fitted_slope_max", slope_max);
    summary.insert("max_abs_deviation_eps_1e-6", worst_deviation);
    impact::AtomicFile out((dir / "summary.toml").string());
    std::ostringstream text;
    text << toml::table{{"lemma5", std::move(summary)}} << '\n';
    std::fputs(text.str().c_str(), out.stream());
    out.commit();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exp_lemma5: %s\n", e.what());
    return 1;
  }
  return 0;
}
