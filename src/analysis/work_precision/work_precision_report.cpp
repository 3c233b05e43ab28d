#include "analysis/work_precision/work_precision_report.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/markdown.hpp"

namespace impact::work_precision {
namespace {

const double kTargets[] = {1e-3, 1e-6};

// A fit is steady when no point lies more than a factor 3 off the fitted line.
bool steady(const OrderFit& fit) {
  return fit.max_log_deviation < std::log(3.0);
}

// How a curve reaches an error: measured (the cheapest point at or below it); along the fitted
// line when the curve falls steadily (cost ~ 1/h from its smallest step); beyond the sweep when it
// falls but erratically; not at all when it stalls.
std::string reach(const Curve& c, ErrorMeasure m, double target, const OrderFit& fit) {
  if (const auto cost = cost_to_reach(c.points, m, target)) return short_number(*cost) + " s";
  if (!c.step_sweep) return "not reachable (c_N floor)";
  const auto& last = *std::min_element(c.points.begin(), c.points.end(),
                                       [](const auto& a, const auto& b) { return a.h < b.h; });
  if (fit.points >= 3 && fit.order > 0.5 && steady(fit)) {
    const double h_target = std::exp((std::log(target) - fit.log_constant) / fit.order);
    // Appended, not "~" + ...: GCC 12 gives a false -Wrestrict on a literal + std::string.
    std::string estimate = "~";
    estimate += short_number(last.cost.min * last.h / h_target);
    return estimate + " s (extrapolated)";
  }
  if (fit.points >= 3 && fit.order > 0.5) return "below h = " + short_number(last.h) + " (erratic)";
  return "not reachable (stalls)";
}

// The observed order for the table: the slope with its range, or the level where it stalls.
std::string describe(const OrderFit& fit, const Curve& c, ErrorMeasure m) {
  if (fit.points < 2) return "rounding only";
  if (std::fabs(fit.order) < 0.2) {
    double lowest = INFINITY;
    for (const auto& p : c.points) lowest = std::fmin(lowest, error_of(p.errors, m));
    return "0: stalls (min " + short_number(lowest) + ")";
  }
  return short_number(fit.order) + " (h " + short_number(fit.h_min) + ".." +
         short_number(fit.h_max) + (steady(fit) ? ")" : ", erratic)");
}

// A step sweep: the order of each measure, and the cost of reaching each target.
void report_steps(const Curve& c, bool timed, CurveReport& r) {
  for (const ErrorMeasure m : kErrorMeasures) {
    const OrderFit fit = curve_order(c, m);
    const std::string key(measure_name(m));
    if (fit.points >= 2) {
      r.entry.insert(key + "_order", fit.order);
      r.entry.insert(key + "_order_deviation", fit.max_log_deviation);
    }
    r.row += " | " + describe(fit, c, m);
  }
  const OrderFit sup = curve_order(c, ErrorMeasure::sup_u);
  for (const double target : kTargets) {
    const std::string cost = timed ? reach(c, ErrorMeasure::sup_u, target, sup) : "-";
    r.row += " | " + cost;
    if (timed) r.entry.insert("cost_to_sup_u_" + short_number(target), cost);
  }
  r.row += " |\n";
}

// A tolerance sweep: its error floor is the compliance model's (c_N), not a rate in h.
void report_tolerances(const Curve& c, bool timed, CurveReport& r) {
  double floor = INFINITY;
  for (const auto& p : c.points) floor = std::fmin(floor, p.errors.sup_u);
  r.entry.insert("sup_u_floor", floor);
  r.row += " | sup u floor " + short_number(floor) + " (tolerance 1e-3..1e-11) | | |";
  for (const double target : kTargets)
    r.row += " | " + (timed ? reach(c, ErrorMeasure::sup_u, target, {}) : std::string("-"));
  r.row += " |\n";
}

}  // namespace

CurveReport report_curve(const std::string& scene, const Curve& c, bool timed) {
  CurveReport r;
  r.row = "| " + scene + " | " + c.name;
  if (c.step_sweep)
    report_steps(c, timed, r);
  else
    report_tolerances(c, timed, r);
  // Regression numbers (deterministic): the errors at h = 1e-3 (a step sweep) or at the middle
  // tolerance (penalty).
  for (const auto& p : c.points)
    if ((c.step_sweep && p.h == 1e-3) ||
        (!c.step_sweep && p.tolerance == kPenaltyReferenceTolerance))
      for (const ErrorMeasure m : kErrorMeasures)
        if (std::isfinite(error_of(p.errors, m)))
          r.entry.insert(std::string(measure_name(m)) + "_at_reference_point",
                         error_of(p.errors, m));
  return r;
}

std::string orders_table_head() {
  return "| scene | method | order sup u | order L1 v | order E(T) | order t1 | cost to "
         "sup u <= 1e-3 | cost to sup u <= 1e-6 |\n"
         "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
}

}  // namespace impact::work_precision
