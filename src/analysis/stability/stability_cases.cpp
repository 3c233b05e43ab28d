#include "analysis/stability/stability_cases.hpp"

#include <cmath>
#include <stdexcept>

#include "impact/methods/capabilities.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/scene.hpp"

namespace impact::stability {
namespace {

// The work budget of penalty.
constexpr std::int64_t kMaxOdeSteps = 2'000'000;

std::size_t case_index(std::string_view name) {
  const auto& cases = extreme_cases();
  for (std::size_t c = 0; c < cases.size(); ++c)
    if (cases[c].name == name) return c;
  throw std::out_of_range("no extreme case " + std::string(name));
}

}  // namespace

const std::vector<ExtremeCase>& extreme_cases() {
  // name, phi, u0 - phi, v0, f, COR, T (README.md describes each case)
  static const std::vector<ExtremeCase> cases = {
      {"paper_f0", 0, 5, -1, 0, {}, 10},                // Figure 3 left
      {"paper_gravity", 0, 5, -1, kGravity, {}, 10},    // Figure 4 left
      {"cor0", 0, 5, -1, kGravity, 0.0, 10},            // plastic
      {"cor1", 0, 5, -1, kGravity, 1.0, 10},            // elastic
      {"cor_0.999", 0, 0.01, 0, kGravity, 0.999, 100},  // ~1000 impacts before t_inf = 90.3
      {"bounces_1e4", 0, 1e-4, 0, kGravity, {}, 100},   // 1.1e4 bounces of 9e-3 s
      {"v0_-1e8", 0, 1, -1e8, 0, {}, 1},
      {"v0_-1e8_gravity", 0, 1, -1e8, kGravity, {}, 1},
      {"f_-1e8", 0, 1, 0, -1e8, {}, 1},           // 3500 bounces in T = 1
      {"f_+1e8", 0, 1, -1e8, 1e8, {}, 1},         // pushing away
      {"f_+9.8", 0, 0.01, -1, -kGravity, {}, 1},  // pushing away
      {"f_+9.8_cor1", 0, 0.01, -1, -kGravity, 1.0, 1},
      {"contact_v0<0", 0, 0, -1, kGravity, {}, 1},  // starting on the floor
      {"contact_v0=0", 0, 0, 0, kGravity, {}, 1},   // resting contact
      {"contact_v0>0", 0, 0, 1, kGravity, {}, 1},
      {"contact_f0", 0, 0, 0, 0, {}, 1},
      {"phi_1e6", 1e6, 5, -1, kGravity, {}, 10},  // a far floor
      {"phi_1e6_near", 1e6, 1e-3, -1, kGravity, {}, 1},
      {"phi_1e6_rest", 1e6, 0, 0, kGravity, {}, 1},
  };
  return cases;
}

const std::vector<std::string>& stability_methods() {
  static const std::vector<std::string> methods = {"direct", "fb_newton", "moreau_jean", "exact",
                                                   "penalty"};
  return methods;
}

StabilityRun run_extreme_case(const ExtremeCase& c, std::string_view method, int log_h) {
  const MethodInfo* info = find_method(method);
  if (!info) throw std::out_of_range("no method " + std::string(method));
  const bool penalty = method == "penalty";
  const double h = std::pow(10.0, log_h);
  const double T = std::fmin(c.T, (penalty ? kMaxPenaltySteps : kMaxSteps) * h);
  // u0 = phi + gap0 rounds to the floor's ulp; gap0 = 0 gives u0 = phi exactly.
  const Scene scene =
      make_scene(Model{c.phi, c.f, c.cor}, State{c.phi + c.gap0, c.v0}, T, h, info->defaults);
  return run_stability_check(scene, {penalty ? kMaxOdeSteps : 0, {}});
}

StabilityRun run_extreme_case(std::string_view name, std::string_view method, int log_h) {
  return run_extreme_case(extreme_cases()[case_index(name)], method, log_h);
}

CaseMap CaseMap::run() {
  CaseMap map;
  for (const std::string& method : stability_methods()) {
    auto& by_case = map.runs_[method];
    for (const ExtremeCase& c : extreme_cases()) {
      by_case.emplace_back();
      for (int log_h = kLogHMin; log_h <= kLogHMax; ++log_h)
        by_case.back().push_back(run_extreme_case(c, method, log_h));
    }
  }
  return map;
}

const std::vector<StabilityRun>& CaseMap::row(const std::string& method, std::size_t c) const {
  return runs_.at(method).at(c);
}

const StabilityRun& CaseMap::at(const std::string& method, std::string_view name, int log_h) const {
  return row(method, case_index(name)).at(static_cast<std::size_t>(log_h - kLogHMin));
}

int CaseMap::count(const std::string& method, Outcome outcome) const {
  int n = 0;
  for (const auto& row : runs_.at(method))
    for (const StabilityRun& run : row) n += run.check.outcome == outcome;
  return n;
}

std::string CaseMap::csv() const {
  std::string text = "method,case," + std::string(kStabilityRunColumns);
  const auto& cases = extreme_cases();
  for (const std::string& method : stability_methods())
    for (std::size_t c = 0; c < cases.size(); ++c)
      for (const StabilityRun& run : row(method, c))
        text += stability_csv_row(method + "," + cases[c].name, run);
  return text;
}

std::string CaseMap::dat() const {
  std::string text = "# method_index case_index log10_h code\n";
  const auto& methods = stability_methods();
  for (std::size_t m = 0; m < methods.size(); ++m) {
    for (std::size_t c = 0; c < extreme_cases().size(); ++c)
      for (int log_h = kLogHMin; log_h <= kLogHMax; ++log_h)
        text +=
            map_point({static_cast<int>(m), static_cast<int>(c), log_h},
                      row(methods[m], c)[static_cast<std::size_t>(log_h - kLogHMin)].check.outcome);
    text += "\n\n";
  }
  return text;
}

}  // namespace impact::stability
