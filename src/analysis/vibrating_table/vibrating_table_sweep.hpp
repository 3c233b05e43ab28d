// Continuation sweeps of the vibrating table over Gamma (the bifurcation diagrams), and the
// thresholds read from them: each run starts where the previous one ended (same time, the table's
// phase carried on), as when the amplitude of a real shaker is turned slowly up or down, so that a
// sweep follows one attractor as long as it exists and shows where it ends.
#pragma once

#include <string>
#include <vector>

#include "analysis/vibrating_table/vibrating_table_runs.hpp"

namespace impact::vibrating_table {

struct SweepPoint {
  double gamma = 0.0;
  TableClassification classification;
  std::vector<TableEvent> events;  // after the transient
  TableScene end;                  // where the run ended: the next run's start
  // The message of a run that stopped with a numerical failure (regime failed); the sweep then
  // continues from where the previous run ended.
  std::string failure;
};

struct SweepSettings {
  int periods = 140;             // table periods per value of Gamma
  int transient = 100;           // of which the first are not kept
  double tolerance = 1e-6;       // of the classification (classify_table_run)
  std::size_t max_events = 256;  // kept per value of Gamma (a chatter has dozens of impacts)
  // Each run starts with the velocity it continues from scaled by 1 + kick, so that an orbit that
  // has lost its stability is left within the run instead of being followed on its rounding
  // errors alone (a real shaker is never free of noise). 0 in the diagrams.
  double kick = 0.0;
};

// Runs `method` at step h over `gammas` in the order given, from `start` (its gamma is replaced by
// each value in turn). A run that fails numerically is recorded as such (failed_points counts them)
// rather than ending the sweep.
std::vector<SweepPoint> sweep_table(const TableScene& start, const MethodParams& method, double h,
                                    const std::vector<double>& gammas,
                                    const SweepSettings& settings);

std::size_t failed_points(const std::vector<SweepPoint>& sweep);

// from, from + step, ..., up to `to` (inclusive up to rounding), or downward for step < 0.
std::vector<double> gamma_grid(double from, double to, double step);

// The period-doubling threshold read from a sweep: the points right above the last one (in
// increasing Gamma) with a split below s_lo, up to the first with a split above s_hi (g / omega),
// fitted by least squares as Gamma = Gamma_pd + c1 split^2 (+ c2 split^4 from four points on): the
// normal form of a supercritical flip, split^2 ~ Gamma - Gamma_pd. NaN when fewer than two points
// qualify. `used` receives how many did.
double fit_period_doubling(const std::vector<SweepPoint>& sweep, double s_lo, double s_hi,
                           int* used = nullptr);

// The Gamma where the split first reaches `level` in increasing Gamma (linear in split^2 between
// the two points around it): where the period-2 branch has grown to a given amplitude, a reading of
// the period doubling that a time-stepper's grid jitter, smaller than `level`, does not move. NaN
// when the split never crosses it from below.
double split_crossing(const std::vector<SweepPoint>& sweep, double level);

// The lowest Gamma of the period-1 block that a downward sweep enters first (failed points
// skipped); NaN when it has none or never leaves it. `keeps` receives that point's position in the
// sweep, `leaves` the position of the next point that is not period 1.
double lowest_period_one(const std::vector<SweepPoint>& sweep, std::size_t* keeps = nullptr,
                         std::size_t* leaves = nullptr);

// Refines the end of a period-1 branch by bisection on Gamma between `keeps` (where the orbit was
// followed; its `end` is the start of every trial) and `leaves` (where it was lost), `iterations`
// times; a trial keeps the orbit when its run is classified period_one with the settings'
// tolerance. A trial that fails numerically ends the bisection there, with its message in
// `failure`.
double bisect_period_one_end(const SweepPoint& keeps, double leaves, const MethodParams& method,
                             double h, const SweepSettings& settings, int iterations,
                             std::string* failure = nullptr);

}  // namespace impact::vibrating_table
