// Lemma 1 (Section 3): (L E)(s) = E(0) / s for s > 1, checked by GSL quadrature on the energy (3-1)
// of the exact solution (transformed to infinity) and of the direct scheme (5-1) on the scenes of
// Figures 3 and 4 (run to T = 40, the rest bounded), at the s of kLemma1S (laplace.hpp).
//
// Usage: exp_lemma1 SOURCE_DIR RESULTS_DIR. Writes to RESULTS_DIR
//   deviation.csv      s and, per case, the relative deviation (s L E(s) - E(0)) / |E(0)| (linear
//                      interpolation of a scheme's samples), its closed form from the jumps of E,
//                      GSL's error estimate and, for a scheme, the deviation with piecewise
//                      constant interpolation
//   energy_<case>.csv  t, E(t) / E(0) on [0, 10]: what is transformed
//   summary.toml       the key numbers (the keys of experiments/lemma1/reference.toml)
#include <toml++/toml.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "impact/exact.hpp"
#include "analysis/laplace.hpp"
#include "impact/output.hpp"
#include "scene/read_scene.hpp"

namespace {

using impact::Lemma1Case;
using impact::Lemma1Point;

constexpr double kPlotT = 10.0;      // the time span of Figures 3 and 4
constexpr double kPlotStep = 0.005;  // sampling of E(t) for the plot

struct CaseResult {
  const Lemma1Case* c;
  std::vector<Lemma1Point> linear, constant;  // constant: scheme cases only
};

void write_deviation(const std::string& path, const std::vector<CaseResult>& results) {
  impact::AtomicFile file(path);
  std::FILE* out = file.stream();
  std::fputs("s", out);
  for (const CaseResult& r : results) {
    const char* n = r.c->name.c_str();
    std::fprintf(out, ",%s,%s_predicted,%s_abserr", n, n, n);
    if (!r.constant.empty()) std::fprintf(out, ",%s_constant", n);
  }
  std::fputs("\n", out);
  for (std::size_t i = 0; i < impact::kLemma1S.size(); ++i) {
    std::fprintf(out, "%.17g", impact::kLemma1S[i]);
    for (const CaseResult& r : results) {
      const Lemma1Point& p = r.linear[i];
      std::fprintf(out, ",%.17g,%.17g,%.17g", p.deviation, p.predicted, p.abserr);
      if (!r.constant.empty()) std::fprintf(out, ",%.17g", r.constant[i].deviation);
    }
    std::fputs("\n", out);
  }
  file.commit();
}

// E(t) / E(0) on [0, kPlotT]: the exact solution sampled every kPlotStep, a scheme's samples
// decimated to the same spacing.
void write_energy(const std::string& path, const Lemma1Case& c, const std::string& source_dir) {
  const std::string scene_path = source_dir + "/experiments/" + c.scene;
  const impact::Scene scene = impact::load_scene(scene_path, c.overrides);
  impact::AtomicFile file(path);
  std::FILE* out = file.stream();
  std::fputs("t,E_over_E0\n", out);
  const double E0 = impact::energy(scene.model, scene.initial);
  if (c.exact) {
    const impact::ExactSolution exact(scene.model, scene.initial);
    const auto rows = static_cast<int>(std::lround(kPlotT / kPlotStep));
    for (int i = 0; i <= rows; ++i) {
      const double t = i * kPlotStep;
      std::fprintf(out, "%.17g,%.17g\n", t, impact::energy(scene.model, exact.at(t)) / E0);
    }
  } else {
    const std::vector<double> E = impact::energy_samples(scene_path, c.overrides);
    const auto every = std::max<std::size_t>(1, std::lround(kPlotStep / scene.grid.h));
    for (std::size_t l = 0; l < E.size() && scene.grid.t(l) <= kPlotT; l += every)
      std::fprintf(out, "%.17g,%.17g\n", scene.grid.t(l), E[l] / E0);
  }
  file.commit();
}

toml::table summarize(const CaseResult& r) {
  double max_abs = 0, max_closed_form = 0, max_interpolation = 0, max_abserr = 0, max_tail = 0;
  for (std::size_t i = 0; i < r.linear.size(); ++i) {
    const Lemma1Point& p = r.linear[i];
    max_abs = std::fmax(max_abs, std::fabs(p.deviation));
    max_abserr = std::fmax(max_abserr, p.abserr);
    max_tail = std::fmax(max_tail, p.tail_bound);
    // A scheme's closed form is that of the piecewise constant interpolant.
    const Lemma1Point& q = r.constant.empty() ? p : r.constant[i];
    max_closed_form = std::fmax(max_closed_form, std::fabs(q.deviation - q.predicted));
    if (!r.constant.empty())
      max_interpolation = std::fmax(max_interpolation, std::fabs(p.deviation - q.deviation));
  }
  toml::table t{{"deviation_at_s_min", r.linear.front().deviation},
                {"deviation_at_s_max", r.linear.back().deviation},
                {"max_abs_deviation", max_abs},
                {"max_quadrature_minus_closed_form", max_closed_form},
                {"max_quadrature_error_estimate", max_abserr},
                {"max_tail_bound", max_tail},
                {"holds_to_quadrature_accuracy", max_abs <= impact::kLemma1HoldsThreshold}};
  if (!r.constant.empty()) t.insert("max_linear_minus_constant_interpolation", max_interpolation);
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s SOURCE_DIR RESULTS_DIR\n", argv[0]);
    return 2;
  }
  try {
    const std::string source_dir = argv[1];
    const std::filesystem::path dir = argv[2];
    const std::vector<Lemma1Case> cases = impact::lemma1_cases();
    std::vector<CaseResult> results;
    toml::array s_values;
    for (double s : impact::kLemma1S) s_values.push_back(s);
    toml::table summary{{"s", s_values},
                        {"scheme_T", impact::kLemma1SchemeT},
                        {"holds_threshold", impact::kLemma1HoldsThreshold}};
    for (const Lemma1Case& c : cases) {
      CaseResult r{&c, impact::lemma1_run(c, source_dir, impact::Interpolation::linear), {}};
      if (!c.exact)
        r.constant = impact::lemma1_run(c, source_dir, impact::Interpolation::piecewise_constant);
      write_energy((dir / ("energy_" + c.name + ".csv")).string(), c, source_dir);
      summary.insert(c.name, summarize(r));
      results.push_back(std::move(r));
    }
    write_deviation((dir / "deviation.csv").string(), results);
    impact::AtomicFile file((dir / "summary.toml").string());
    std::ostringstream text;
    text << toml::table{{"lemma1", summary}} << '\n';
    std::fputs(text.str().c_str(), file.stream());
    file.commit();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exp_lemma1: %s\n", e.what());
    return 1;
  }
  return 0;
}
