#include "analysis/error_analysis/error_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <thread>

#include "impact/references/exact.hpp"

namespace impact::error_analysis {
namespace {

Scene with_method(Scene scene, const MethodParams& method) {
  scene.method = method;
  return scene;
}

double median(std::vector<double> x) {
  if (x.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
  std::nth_element(x.begin(), mid, x.end());
  return *mid;
}

}  // namespace

SceneRuns run_scene_runs(const CampaignScene& scene, std::size_t index) {
  const Scene& s = scene.scene;
  SceneRuns r{scene, index, reference_trace(s), std::nullopt, {}, {}, {}, {}, {}, 0};
  if (constant_force(s.model)) r.V1 = ExactSolution(s.model, s.initial).impact_speed(1);
  r.direct = run_trace(with_method(s, DirectParams{}));
  r.fb_newton = run_trace(with_method(s, FbNewtonParams{}));
  r.moreau_jean = run_trace(with_method(s, MoreauJeanParams{}));
  r.located = run_trace(with_method(s, DirectLocatedParams{}));
  r.rounding = rounding_of(s, r.exact);
  r.eps = FbNewtonParams{}.epsilon;
  return r;
}

void check_scene(const CampaignScene& scene, std::size_t index, std::vector<Check>& out) {
  const SceneRuns r = run_scene_runs(scene, index);
  check_flight(r, out);
  check_impact(r, out);
  check_zeno(r, out);
  check_no_cor(r, out);
  check_located(r, out);
  // A failed run is a check of its own: the schemes never fail on these scenes (C34).
  for (const Trace* t : {&r.direct, &r.fb_newton, &r.moreau_jean, &r.located})
    out.push_back(make_check(r, "run.failed", t->failed ? 1.0 : 0.0, 0, 0));
}

CampaignResult run_campaign(const CampaignOptions& options) {
  const std::vector<CampaignScene> scenes = campaign_scenes(options.scenes, options.seed);
  // Two threads, each on every other scene; the checks are put back in scene order.
  constexpr std::size_t kThreads = 2;
  std::vector<std::vector<std::vector<Check>>> parts(kThreads);
  std::vector<std::thread> workers;
  for (std::size_t w = 0; w < kThreads; ++w)
    workers.emplace_back([&, w] {
      for (std::size_t i = w; i < scenes.size(); i += kThreads) {
        parts[w].emplace_back();
        check_scene(scenes[i], i, parts[w].back());
      }
    });
  for (std::thread& t : workers) t.join();
  CampaignResult result;
  result.scenes = scenes.size();
  for (std::size_t i = 0; i < scenes.size(); ++i)
    for (const Check& c : parts[i % kThreads][i / kThreads]) result.checks.push_back(c);
  std::map<std::string, std::size_t> order;
  std::map<std::string, std::vector<double>> ratios;
  for (const Check& c : result.checks) {
    if (c.name == "run.failed") {
      ++result.runs;
      result.failed_runs += c.measured > 0;
    }
    if (!order.contains(c.name)) {
      order.emplace(c.name, result.summaries.size());
      CheckSummary s;
      s.name = c.name;
      s.conjecture = is_conjecture(c.name);
      s.identity = true;
      result.summaries.push_back(s);
    }
    CheckSummary& s = result.summaries[order.at(c.name)];
    ++s.runs;
    s.violations += c.violated();
    s.identity = s.identity && c.bound == 0 && !c.lower;
    const double q = c.ratio();
    if (std::isfinite(q)) {
      ratios[c.name].push_back(q);
      s.worst_ratio = std::fmax(s.worst_ratio, q);
    }
  }
  for (CheckSummary& s : result.summaries) s.median_ratio = median(ratios[s.name]);
  std::sort(result.summaries.begin(), result.summaries.end(),
            [](const CheckSummary& a, const CheckSummary& b) { return a.name < b.name; });
  return result;
}

}  // namespace impact::error_analysis
