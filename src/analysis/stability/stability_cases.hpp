// The extreme cases of experiments/stability: every method over h = 1e-9 .. 1 on 19 scenes that
// push one quantity to its limit (|v0| and |f| up to 1e8, a floor at 1e6, starting on the floor,
// 1.1e4 bounces, COR 0 and 1), each run classified by check_stability.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/stability/stability_runs.hpp"
#include "impact/run/scene.hpp"

namespace impact::stability {

// One extreme case: the scene data and its natural duration T (a run at step h covers
// min(T, max_steps h): the smallest steps see the start of the case only).
struct ExtremeCase {
  std::string name;
  double phi, gap0, v0, f;  // u0 = phi + gap0
  std::optional<double> cor;
  double T;
};

const std::vector<ExtremeCase>& extreme_cases();
// The five methods of the map, in its order.
const std::vector<std::string>& stability_methods();
// The steps of the map: h = 10^log_h for log_h = kLogHMin .. kLogHMax.
constexpr int kLogHMin = -9, kLogHMax = 0;

// One cell of the map: the case run by the method (its default parameters) at h = 10^log_h over
// min(T, 1e5 h) (penalty: min(T, 2e4 h) and at most 2e6 ODE steps, it costs ~1 us per step).
StabilityRun run_extreme_case(const ExtremeCase& c, std::string_view method, int log_h);
// The same, by the case's name (std::out_of_range for an unknown one).
StabilityRun run_extreme_case(std::string_view name, std::string_view method, int log_h);

// The whole map: method x case x h.
class CaseMap {
 public:
  static CaseMap run();
  const StabilityRun& at(const std::string& method, std::string_view name, int log_h) const;
  // The runs of one method on the case of index c, h ascending.
  const std::vector<StabilityRun>& row(const std::string& method, std::size_t c) const;
  // How many of the method's runs had this outcome.
  int count(const std::string& method, Outcome outcome) const;

  std::string csv() const;  // cases.csv: one row per run
  std::string dat() const;  // map_cases.dat: method_index case_index log10_h code, per method

 private:
  std::map<std::string, std::vector<std::vector<StabilityRun>>> runs_;  // [method][case][h]
};

}  // namespace impact::stability
