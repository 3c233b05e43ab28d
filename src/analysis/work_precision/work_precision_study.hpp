// experiments/work_precision: every method's error against `exact` and the CPU time of its
// solve, over a sweep of h (or of the tolerance), on the paper's scenes and an off-grid one
// (work_precision_curves.hpp), with the observed orders (work_precision_report.hpp) and why
// `direct` without COR does not converge off the grid.
#pragma once

#include <toml++/toml.h>

#include "analysis/experiment.hpp"
#include "analysis/reference.hpp"
#include "analysis/work_precision_curves.hpp"

namespace impact::work_precision {

// Writes to the context's results directory: points.csv (every point: errors, cost, repetitions),
// curves/<scene>.<curve>.csv and curves.gp (for plot.gp), mechanism.csv (direct without COR on
// the off-grid scene: theta, effective COR, predicted and measured energy error), orders.md (the
// observed orders and costs). Returns the summary: errors and orders (deterministic) and, when
// the solves are timed, CPU times and costs (this machine's).
toml::table run_work_precision(const ExperimentContext& context);
toml::table run_work_precision(const ExperimentContext& context,
                               const WorkPrecisionOptions& options);

extern const Experiment kWorkPrecisionExperiment;

// How a summary compares with reference.toml: without what depends on this machine's timing
// (CPU times, costs, sweep_cpu_seconds) and on the build (the Siconos peer's curves).
ReferenceRule work_precision_reference_rule();

}  // namespace impact::work_precision
