#include "analysis/work_precision.hpp"

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <ctime>
#include <iterator>
#include <stdexcept>
#include <string>

#include "impact/run/any_stepper.hpp"

namespace impact {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

namespace {

// In ErrorMeasure's order, so that measure_info() indexes by it.
constexpr MeasureInfo kMeasures[] = {
    {ErrorMeasure::sup_u, "sup_u", "max_l |u^l - u(t_l)| [m]"},
    {ErrorMeasure::l1_v, "l1_v", "h sum_l |v^l - v(t_l)| [m]"},
    {ErrorMeasure::energy_end, "energy_end", "|E^n - E(T)| [m^2/s^2]"},
    {ErrorMeasure::first_impact, "first_impact", "|t_1,h - t_1| [s]"},
};
static_assert(std::size(kMeasures) == std::size(kErrorMeasures) && [] {
  for (std::size_t i = 0; i < std::size(kMeasures); ++i)
    if (kMeasures[i].measure != kErrorMeasures[i] ||
        static_cast<std::size_t>(kErrorMeasures[i]) != i)
      return false;
  return true;
}());

}  // namespace

const MeasureInfo& measure_info(ErrorMeasure m) {
  return kMeasures[static_cast<std::size_t>(m)];
}

double error_of(const ErrorNorms& e, ErrorMeasure m) {
  switch (m) {
    case ErrorMeasure::sup_u:
      return e.sup_u;
    case ErrorMeasure::l1_v:
      return e.l1_v;
    case ErrorMeasure::energy_end:
      return e.energy_end;
    case ErrorMeasure::first_impact:
      return std::fabs(e.first_impact);
  }
  return std::nan("");
}

WorkPrecisionPoint measure_scene(const Scene& scene, const std::optional<TimingRule>& rule) {
  WorkPrecisionPoint p = measure_point([&] { return make_stepper(scene); }, scene.model,
                                       scene.initial, scene.grid, rule);
  if (const auto* penalty = std::get_if<PenaltyParams>(&scene.method)) p.tolerance = penalty->rtol;
  return p;
}

std::vector<WorkPrecisionPoint> sweep_steps(Scene scene, const std::vector<double>& steps,
                                            const std::optional<TimingRule>& rule,
                                            const std::function<void()>& after_point) {
  std::vector<WorkPrecisionPoint> points;
  for (const double h : steps) {
    scene.grid = Grid::covering(scene.T, h);
    points.push_back(measure_scene(scene, rule));
    if (after_point) after_point();
  }
  return points;
}

OrderFit observed_order(const std::vector<WorkPrecisionPoint>& points, ErrorMeasure m,
                        double floor) {
  std::vector<double> h, err;
  for (const auto& p : points) {
    const double e = error_of(p.errors, m);
    if (e > floor) {
      h.push_back(p.h);
      err.push_back(e);
    }
  }
  return fit_order(h, err);
}

std::optional<double> cost_to_reach(const std::vector<WorkPrecisionPoint>& points, ErrorMeasure m,
                                    double target) {
  std::optional<double> best;
  for (const auto& p : points)
    if (error_of(p.errors, m) <= target && (!best || p.cost.min < *best)) best = p.cost.min;
  return best;
}

std::vector<double> steps_125(double h_max, double h_min) {
  if (!(h_max >= h_min && h_min > 0))
    throw std::invalid_argument("steps_125: need h_max >= h_min > 0");
  std::vector<double> steps;
  for (int exponent = static_cast<int>(std::ceil(std::log10(h_max))) + 1;; --exponent) {
    for (const char* mantissa : {"5", "2", "1"}) {
      // Parsed from the decimal, so that e.g. 2e-5 is the double nearest 2e-5 and not 2 * 1e-5.
      const double h =
          std::strtod((std::string(mantissa) + "e" + std::to_string(exponent)).c_str(), nullptr);
      if (h < h_min * (1 - 1e-12)) return steps;
      if (h <= h_max * (1 + 1e-12)) steps.push_back(h);
    }
  }
}

}  // namespace impact
