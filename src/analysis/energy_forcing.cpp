#include "analysis/energy_forcing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "analysis/laplace.hpp"
#include "analysis/tolerances.hpp"
#include "impact/forces/work_energy.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/run/any_stepper.hpp"

namespace impact {

ForcedEnergyMonitor::ForcedEnergyMonitor(const Model& model, double h, const State& initial)
    : force_(model), h_(h), phi_(model.phi), previous_(initial) {}

void ForcedEnergyMonitor::observe(std::int64_t l, const State& s, double contact_force) {
  const double t0 = static_cast<double>(l - 1) * h_, t1 = static_cast<double>(l) * h_;
  const double kinetic = 0.5 * (s.v * s.v - previous_.v * previous_.v);
  const double work = kinetic - force_.step_mean(t0, h_) * (s.u - previous_.u);
  const double energy = kinetic - force_.at(t1) * s.u + force_.at(t0) * previous_.u;
  increments_.push_back(
      {work, energy, rebound_energy_roundoff(phi_, h_, previous_.u, s.v, contact_force)});
  previous_ = s;
}

ForcedEnergyCounts ForcedEnergyMonitor::finish(double sup_force, double T, double max_u,
                                               double max_v) const {
  ForcedEnergyCounts c;
  c.steps = static_cast<std::int64_t>(increments_.size());
  const double roundoff = energy_evaluation_roundoff(sup_force, T, max_u, max_v) +
                          phasor_energy_roundoff(force_.model(), sup_force, T, max_v);
  for (const Increment& i : increments_) {
    const double tolerance = roundoff + i.rebound_roundoff;
    c.work_rises += i.work > tolerance;
    c.max_work_rise_over_tolerance = std::fmax(c.max_work_rise_over_tolerance, i.work / tolerance);
    c.energy_rises += i.energy > tolerance;
    c.max_energy_rise = std::fmax(c.max_energy_rise, i.energy);
  }
  return c;
}

double phasor_energy_roundoff(const Model& model, double sup_force, double T, double max_v) {
  if (!model.harmonic) return 0.0;
  const Harmonic& w = *model.harmonic;
  const double drift = SchemeFlight::kHarmonicTermError;
  const double scale = std::fabs(w.amplitude) / w.omega * drift;
  return 2 * scale * (max_v + sup_force * (T + 2 / w.omega));
}

void accumulate(ForcedEnergySummary& summary, const ForcedEnergyCounts& counts) {
  ++summary.runs;
  summary.steps += counts.steps;
  summary.work_rises += counts.work_rises;
  summary.energy_rises += counts.energy_rises;
  summary.energy_rise_runs += counts.energy_rises > 0;
  summary.max_work_rise_over_tolerance =
      std::fmax(summary.max_work_rise_over_tolerance, counts.max_work_rise_over_tolerance);
  summary.max_energy_rise = std::fmax(summary.max_energy_rise, counts.max_energy_rise);
}

namespace {

// The largest |relative deviation| of s (L X)(s) from X(0) over s_values. The samples say nothing
// after T; the part left out is taken as bounded by their largest |value|, which is not proven
// here for W (its work term may grow), but enters only as e^{-s T} of it (e^{-44} for s = 1.1,
// T = 40).
double max_laplace_deviation(const std::vector<double>& samples, double h,
                             std::span<const double> s_values) {
  double tail_sup = 0, worst = 0;
  for (double x : samples) tail_sup = std::fmax(tail_sup, std::fabs(x));
  for (double s : s_values)
    worst = std::fmax(
        worst, std::fabs(lemma1_samples(samples, h, Interpolation::linear, s, tail_sup).deviation));
  return worst;
}

double relative_change(const std::vector<double>& x) {
  return (x.back() - x.front()) / std::fabs(x.front());
}

double largest_rise(const std::vector<double>& x) {
  double rise = 0;
  for (std::size_t l = 0; l + 1 < x.size(); ++l) rise = std::fmax(rise, x[l + 1] - x[l]);
  return rise / std::fabs(x.front());
}

}  // namespace

Lemma1Forcing lemma1_forcing(double amplitude, double omega, double cor, const MethodParams& method,
                             std::span<const double> s_values, double T) {
  Model model;
  model.f = -9.80665;
  model.cor = cor;
  if (amplitude != 0) model.harmonic = Harmonic{amplitude, omega, 0.0};
  const ForceFunction force(model);
  const State initial{1.0, 0.0};
  const Grid grid = Grid::covering(T, kLemma1ForcingH);
  AnyStepper stepper = make_stepper(model, grid.h, method);
  std::vector<double> energy, energy_constant, work;
  WorkEnergy work_energy(model, initial, grid.h);
  simulate(stepper, initial, grid, [&](std::int64_t l, const State& s, const StepInfo&) {
    if (l > 0) work_energy.step(l, s);
    energy.push_back(0.5 * s.v * s.v - force.at(grid.t(l)) * s.u);
    energy_constant.push_back(impact::energy(model, s));
    work.push_back(work_energy.energy(s));
  });
  Lemma1Forcing r;
  r.amplitude = amplitude;
  r.omega = omega;
  r.energy = max_laplace_deviation(energy, grid.h, s_values);
  r.energy_constant = max_laplace_deviation(energy_constant, grid.h, s_values);
  r.work = max_laplace_deviation(work, grid.h, s_values);
  r.work_final_change = relative_change(work);
  r.energy_final_change = relative_change(energy);
  r.work_max_rise = largest_rise(work);
  r.energy_max_rise = largest_rise(energy);
  return r;
}

}  // namespace impact
