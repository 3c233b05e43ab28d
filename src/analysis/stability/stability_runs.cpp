#include "analysis/stability/stability_runs.hpp"

#include <chrono>

#include "impact/format.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/scene.hpp"

namespace impact::stability {

StabilityRun run_stability_check(const Scene& scene, const StabilityOptions& options) {
  StabilityRun run;
  run.T = scene.T;
  run.h = scene.grid.h;
  const auto start = std::chrono::steady_clock::now();
  run.check = check_stability(scene, options);
  run.seconds = seconds_since(start);
  return run;
}

const std::string_view kStabilityRunColumns =
    "h,T,steps,outcome,code,min_gap,energy_rises,max_energy_rise,max_iterations,mean_iterations,"
    "work,error_u,amplitude,error_energy,seconds,message\n";

std::string stability_csv_row(const std::string& prefix, const StabilityRun& run) {
  const StabilityCheck& k = run.check;
  std::string message = k.message;
  for (char& ch : message)
    if (ch == ',' || ch == '\n') ch = ';';
  return prefix + "," + round_trip(run.h) + "," + round_trip(run.T) + "," +
         std::to_string(k.steps) + "," + std::string(outcome_name(k.outcome)) + "," +
         std::to_string(static_cast<int>(k.outcome)) + "," + round_trip(k.min_gap) + "," +
         std::to_string(k.energy_rises) + "," + round_trip(k.max_energy_rise) + "," +
         std::to_string(k.max_iterations) + "," + round_trip(k.mean_iterations) + "," +
         std::to_string(k.work) + "," + round_trip(k.error_u) + "," + round_trip(k.amplitude) +
         "," + round_trip(k.error_energy) + "," + round_trip(run.seconds) + ",\"" + message +
         "\"\n";
}

std::string map_point(const std::vector<int>& indices, Outcome outcome) {
  std::string line;
  for (const int i : indices) line += std::to_string(i) + " ";
  return line + std::to_string(static_cast<int>(outcome)) + "\n";
}

}  // namespace impact::stability
