#include "analysis/lemma3/bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/tolerances.hpp"
#include "impact/loop/simulate.hpp"

namespace impact::lemma3 {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// What measure_lemma3 keeps of each step until the maxima that set the tolerances are known.
struct StepRecord {
  double energy_increase;   // E^{l+1} - E^l
  double rebound_roundoff;  // rebound_energy_roundoff (tolerances.hpp), 0 in free flight
  double printed_4_7_gap;   // |u^{l+1}| - (|u^0| + (1/2) h sum_{k=1..l+1} |v^k|)
};

}  // namespace

Lemma3Bounds lemma3_bounds(const Model& model, const State& initial, double T) {
  return lemma3_bounds(std::fabs(model.f), model.f, initial, T);
}

Lemma3Bounds lemma3_bounds(double F, double f_energy, const State& initial, double T) {
  const double E0 = 0.5 * initial.v * initial.v - f_energy * initial.u;  // (4-5)
  // >= (v^0)^2 when F >= |f_energy|, as for a constant force: the guard is for the other readings.
  const double A = std::fmax(0.0, 2 * E0 + 2 * F * std::fabs(initial.u) + F * T);
  Lemma3Bounds b;
  b.velocity = std::sqrt(A * (1 + F * T * std::exp(F * T)));  // (4-8)
  b.displacement = std::fabs(initial.u) + T / 2 * b.velocity;
  b.displacement_corrected = std::fabs(initial.u) + T * b.velocity;
  b.impulse = b.velocity - initial.v;
  return b;
}

Lemma3Measurement measure_lemma3(AnyStepper& stepper, const Model& model, const State& initial,
                                 const Grid& grid) {
  Lemma3Measurement m;
  std::vector<StepRecord> records;
  records.reserve(static_cast<std::size_t>(grid.steps));
  State previous = initial;
  double half_path = 0;  // (1/2) int_0^{t_l} |v_h|, v_h = v^{k} on (t_{k-1}, t_k]
  simulate(stepper, initial, grid, [&](std::int64_t l, const State& s, const StepInfo& info) {
    m.max_u = std::fmax(m.max_u, std::fabs(s.u));
    m.max_v = std::fmax(m.max_v, std::fabs(s.v));
    if (l == 0) return;
    half_path += 0.5 * grid.h * std::fabs(s.v);
    const double N = scheme_force(info);
    m.impulse += grid.h * N;
    records.push_back({energy(model, s) - energy(model, previous),
                       rebound_energy_roundoff(model.phi, grid.h, previous.u, s.v, N),
                       std::fabs(s.u) - (std::fabs(initial.u) + half_path)});
    previous = s;
  });
  m.steps = grid.steps;
  m.T = grid.t(grid.steps);
  m.velocity_change = previous.v - initial.v;

  const double F = std::fabs(model.f), T = m.T;
  // Round-off of u: the terms of the free flight, as in energy_evaluation_roundoff.
  const double u_roundoff = 16 * kEps * (m.max_u + T * m.max_v + T * T * F);
  const double energy_roundoff = energy_evaluation_roundoff(model.f, T, m.max_u, m.max_v);
  for (const StepRecord& r : records) {
    const double tolerance = energy_roundoff + r.rebound_roundoff;
    m.energy_increases += r.energy_increase > 0;
    m.energy_violations += r.energy_increase > tolerance;
    m.max_energy_increase = std::fmax(m.max_energy_increase, r.energy_increase);
    m.max_energy_increase_over_tolerance =
        std::fmax(m.max_energy_increase_over_tolerance, r.energy_increase / tolerance);
    m.printed_4_7_violations += r.printed_4_7_gap > u_roundoff;
  }
  return m;
}

std::vector<Lemma3Run> lemma3_sweep() {
  std::vector<Lemma3Run> runs;
  for (double f : kLemma3SweepF)
    for (double u0 : kLemma3SweepU0)
      for (double v0 : kLemma3SweepV0)
        for (double h : kLemma3SweepH) {
          Model model;
          model.f = f;
          const State initial{u0, v0};
          // T / h is an integer for every h of the sweep (to within the rounding of 2 / 1e-k).
          const Grid grid{h, std::llround(kLemma3SweepT / h)};
          AnyStepper stepper = Direct(model, h, {});
          Lemma3Run run{h, f, u0, v0, lemma3_bounds(model, initial, grid.t(grid.steps)), {}};
          run.measured = measure_lemma3(stepper, model, initial, grid);
          runs.push_back(run);
        }
  return runs;
}

double bound_ratio(double measured, double bound) {
  if (bound == 0 && measured == 0) return 0;
  return measured / bound;
}

namespace {

RatioStats ratio_stats(std::vector<double> ratios) {
  RatioStats r;
  if (ratios.empty()) return r;
  std::sort(ratios.begin(), ratios.end());
  for (double x : ratios) r.violations += x > 1 + kBoundSlack;
  r.min = ratios.front();
  r.max = ratios.back();
  const std::size_t m = ratios.size() / 2;
  r.median = ratios.size() % 2 ? ratios[m] : (ratios[m - 1] + ratios[m]) / 2;
  return r;
}

}  // namespace

Lemma3Summary summarize_lemma3(const std::vector<Lemma3Run>& runs) {
  Lemma3Summary s;
  s.runs = static_cast<int>(runs.size());
  std::vector<double> velocity, displacement, corrected, impulse;
  for (const Lemma3Run& r : runs) {
    const Lemma3Measurement& m = r.measured;
    velocity.push_back(bound_ratio(m.max_v, r.bounds.velocity));
    displacement.push_back(bound_ratio(m.max_u, r.bounds.displacement));
    corrected.push_back(bound_ratio(m.max_u, r.bounds.displacement_corrected));
    impulse.push_back(bound_ratio(m.impulse, r.bounds.impulse));
    s.identity_printed_max_residual =
        std::fmax(s.identity_printed_max_residual, std::fabs(m.impulse - m.velocity_change));
    s.identity_corrected_max_residual = std::fmax(
        s.identity_corrected_max_residual, std::fabs(m.impulse - (m.velocity_change - r.f * m.T)));
    s.printed_4_7_violation_runs += m.printed_4_7_violations > 0;
    s.energy_steps += m.steps;
    s.energy_increases += m.energy_increases;
    s.energy_violations += m.energy_violations;
    s.energy_max_increase_over_tolerance =
        std::fmax(s.energy_max_increase_over_tolerance, m.max_energy_increase_over_tolerance);
  }
  s.velocity = ratio_stats(velocity);
  s.displacement = ratio_stats(displacement);
  s.displacement_corrected = ratio_stats(corrected);
  s.impulse = ratio_stats(impulse);
  return s;
}

}  // namespace impact::lemma3
