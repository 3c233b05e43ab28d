#include "analysis/stability/stability_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "analysis/stability/stability_cases.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/scene.hpp"
#include "impact/steppers/fb_newton.hpp"

namespace impact::stability {
namespace {

constexpr int kLogEpsMin = -15, kLogEpsMax = -2;

// The bounce has COR = 1, so that its scheme is accurate as h -> 0 and the map shows where the
// smoothing spoils it; without COR the scheme's impact loses energy whatever eps (README).
struct SmoothingScene {
  double gap0, v0, T;
  std::optional<double> cor;
};
const SmoothingScene kScenes[] = {{1, 0, 2, 1.0}, {0, 0, 1, std::nullopt}};

StabilityRun run_smoothing(const SmoothingScene& s, double eps, double h) {
  FbNewtonParams params;
  params.epsilon = eps;
  const double T = std::fmin(s.T, kMaxSteps * h);
  return run_stability_check(
      make_scene(Model{0, kGravity, s.cor}, State{s.gap0, s.v0}, T, h, params));
}

}  // namespace

const std::vector<std::string>& smoothing_scene_names() {
  static const std::vector<std::string> names = {"bounce", "rest"};
  return names;
}

SmoothingMap SmoothingMap::run() {
  SmoothingMap map;
  for (std::size_t s = 0; s < std::size(kScenes); ++s)
    for (int log_eps = kLogEpsMin; log_eps <= kLogEpsMax; ++log_eps)
      for (int log_h = kLogHMin; log_h <= kLogHMax; ++log_h) {
        const StabilityRun run =
            run_smoothing(kScenes[s], std::pow(10.0, log_eps), std::pow(10.0, log_h));
        const StabilityCheck& k = run.check;
        map.failures += k.outcome == Outcome::failure || k.outcome == Outcome::non_finite;
        map.energy_violations += k.outcome == Outcome::energy_grows;
        map.max_iterations = std::max(map.max_iterations, k.max_iterations);
        map.max_mean_iterations = std::fmax(map.max_mean_iterations, k.mean_iterations);
        map.runs.push_back({s, log_eps, log_h, run});
      }
  return map;
}

std::string SmoothingMap::csv() const {
  std::string text = "scene,epsilon," + std::string(kStabilityRunColumns);
  for (const SmoothingRun& r : runs)
    text += stability_csv_row(
        smoothing_scene_names()[r.scene] + "," + round_trip(std::pow(10.0, r.log_eps)), r.run);
  return text;
}

std::string SmoothingMap::dat() const {
  std::string text = "# scene_index log10_eps log10_h code\n";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const SmoothingRun& r = runs[i];
    text += map_point({static_cast<int>(r.scene), r.log_eps, r.log_h}, r.run.check.outcome);
    if (i + 1 == runs.size() || runs[i + 1].scene != r.scene) text += "\n\n";
  }
  return text;
}

}  // namespace impact::stability
