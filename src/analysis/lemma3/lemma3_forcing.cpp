#include "analysis/lemma3/lemma3_forcing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "analysis/quadrature.hpp"
#include "impact/forces/force.hpp"
#include "impact/loop/simulate.hpp"

namespace impact::lemma3 {

std::string_view reading_name(ForceReading reading) {
  switch (reading) {
    case ForceReading::sup:
      return "sup";
    case ForceReading::mean:
      return "mean";
    case ForceReading::rms:
      return "rms";
    case ForceReading::sup_f0:
      return "sup_f0";
    case ForceReading::mean_f0:
      return "mean_f0";
    case ForceReading::rms_f0:
      return "rms_f0";
    case ForceReading::constant:
      return "constant";
    case ForceReading::frozen:
      return "frozen";
  }
  throw std::logic_error("reading_name: unknown reading");
}

namespace {

// The times in (0, T) where omega t + phase = base + k period, in increasing order.
void phase_times(const Harmonic& h, double base, double period, double T,
                 std::vector<double>& times) {
  const double first = std::ceil((h.phase - base) / period);
  for (double k = first;; ++k) {
    const double t = (base + k * period - h.phase) / h.omega;
    if (t >= T) break;
    if (t > 0) times.push_back(t);
  }
}

}  // namespace

ForceNorms force_norms(const Model& model, double T) {
  const ForceFunction force(model);
  ForceNorms n;
  if (!model.harmonic) {
    n.sup = n.rms = std::fabs(model.f);
    n.integral = std::fabs(model.f) * T;
    return n;
  }
  const Harmonic& h = *model.harmonic;
  constexpr double pi = std::numbers::pi;
  // |f| is largest at an end or at a crest of the sine inside (0, T).
  std::vector<double> crests;
  phase_times(h, pi / 2, pi, T, crests);
  n.sup = std::fmax(std::fabs(force.at(0)), std::fabs(force.at(T)));
  for (double t : crests) n.sup = std::fmax(n.sup, std::fabs(force.at(t)));
  // int |f| = sum over the pieces between the zeros of f of |int f|, each in closed form.
  std::vector<double> cuts{0.0, T};
  if (h.amplitude != 0 && std::fabs(model.f / h.amplitude) <= 1) {
    const double root = std::asin(-model.f / h.amplitude);
    phase_times(h, root, 2 * pi, T, cuts);
    phase_times(h, pi - root, 2 * pi, T, cuts);
  }
  std::sort(cuts.begin(), cuts.end());
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    n.integral += std::fabs(force.integral(cuts[i], cuts[i + 1]));
  Quadrature quadrature;
  const double square = quadrature.integrate([&](double t) { return force.at(t) * force.at(t); },
                                             0.0, T, crests, {}, "int_0^T f^2");
  n.rms = std::sqrt(square / T);
  return n;
}

Model ForcingCase::model() const {
  Model m;
  m.f = f;
  if (amplitude != 0) m.harmonic = Harmonic{amplitude, omega, phase};
  return m;
}

namespace {

ForcingRatios ratios(double max_u, double max_v, const Lemma3Bounds& b) {
  return {max_v / b.velocity, max_u / b.displacement, max_u / b.displacement_corrected};
}

// The scalar |f| of a reading that is one number over [0, T].
double scalar_force(ForceReading reading, const ForceNorms& n, const Model& model, double T) {
  switch (reading) {
    case ForceReading::sup:
    case ForceReading::sup_f0:
      return n.sup;
    case ForceReading::mean:
    case ForceReading::mean_f0:
      return n.integral / T;
    case ForceReading::rms:
    case ForceReading::rms_f0:
      return n.rms;
    case ForceReading::constant:
      return std::fabs(model.f);
    case ForceReading::frozen:
      break;
  }
  throw std::logic_error("scalar_force: the frozen reading has one force per step");
}

// The force of E^0 in a reading with one F (the header).
double energy_force(ForceReading reading, double F, const Model& model, double f0) {
  switch (reading) {
    case ForceReading::sup_f0:
    case ForceReading::mean_f0:
    case ForceReading::rms_f0:
      return f0;
    case ForceReading::constant:
      return model.f;
    default:
      return f0 < 0 ? -F : F;
  }
}

}  // namespace

ForcingRun run_forcing_case(const ForcingCase& c) {
  const Model model = c.model();
  const ForceFunction force(model);
  const State initial{c.u0, c.v0};
  const Grid grid = Grid::covering(kForcingT, c.h);
  const MethodInfo* method = find_method(c.method);
  if (!method) throw std::invalid_argument("run_forcing_case: unknown method");
  AnyStepper stepper = make_stepper(model, grid.h, method->defaults);
  ForcingRun run;
  run.c = c;
  run.T = grid.end();
  ForcedEnergyMonitor energy(model, grid.h, initial);
  ForcingRatios frozen;
  simulate(stepper, initial, grid, [&](std::int64_t l, const State& s, const StepInfo& info) {
    run.max_u = std::fmax(run.max_u, std::fabs(s.u));
    run.max_v = std::fmax(run.max_v, std::fabs(s.v));
    const double f_now = force.at(grid.t(l));
    const ForcingRatios now = ratios(std::fabs(s.u), std::fabs(s.v),
                                     lemma3_bounds(std::fabs(f_now), f_now, initial, run.T));
    frozen = {std::fmax(frozen.velocity, now.velocity),
              std::fmax(frozen.displacement, now.displacement),
              std::fmax(frozen.displacement_full, now.displacement_full)};
    if (l > 0) energy.observe(l, s, scheme_force(info));
  });
  run.norms = force_norms(model, run.T);
  for (std::size_t i = 0; i < kForceReadings.size(); ++i) {
    const ForceReading reading = kForceReadings[i];
    if (reading == ForceReading::frozen) {
      run.readings[i] = frozen;
      continue;
    }
    const double F = scalar_force(reading, run.norms, model, run.T);
    const double f_energy = energy_force(reading, F, model, force.at(0));
    run.readings[i] = ratios(run.max_u, run.max_v, lemma3_bounds(F, f_energy, initial, run.T));
  }
  const double P = std::fabs(c.v0) + run.norms.integral;
  run.proof_velocity = run.max_v / P;
  run.proof_displacement = run.max_u / (std::fabs(c.u0) + run.T * P);
  run.energy = energy.finish(run.norms.sup, run.T, run.max_u, run.max_v);
  return run;
}

ForcingSweep full_forcing_sweep() {
  return {{-9.80665, -1.0, 0.0, 1.0},
          {0.1, 1.0, 5.0, 30.0},
          {1.0, 10.0, 100.0},
          {0.0, std::numbers::pi / 2},
          {0.0, 5.0},
          {-3.0, 2.0},
          {1e-2, 1e-3}};
}

ForcingSweep reduced_forcing_sweep() {
  return {{-9.80665, -1.0, 0.0, 1.0},
          {0.1, 1.0, 5.0, 30.0},
          {1.0, 100.0},
          {0.0, std::numbers::pi / 2},
          {0.0, 5.0},
          {-3.0, 2.0},
          {1e-2}};
}

std::vector<ForcingRun> run_forcing_sweep(const ForcingSweep& sweep) {
  std::vector<ForcingRun> runs;
  for (std::string_view method : {"direct", "fb_newton"})
    for (double f : sweep.f)
      for (double amplitude : sweep.amplitude)
        for (double omega : sweep.omega)
          for (double phase : sweep.phase)
            for (double u0 : sweep.u0)
              for (double v0 : sweep.v0)
                for (double h : sweep.h)
                  runs.push_back(run_forcing_case({f, amplitude, omega, phase, u0, v0, h, method}));
  return runs;
}

namespace {

template <class Ratio>
ForcingStats stats(const std::vector<const ForcingRun*>& runs, Ratio ratio) {
  ForcingStats s;
  s.runs = static_cast<int>(runs.size());
  if (runs.empty()) return s;
  std::vector<double> values;
  for (const ForcingRun* r : runs) {
    const double x = ratio(*r);
    values.push_back(x);
    s.violations += x > 1 + kForcingSlack;
    s.zero_bound += std::isinf(x);
    if (x > s.max && !std::isinf(x)) {
      s.max = x;
      s.worst = r->c;
    }
  }
  std::sort(values.begin(), values.end());
  const std::size_t m = values.size() / 2;
  s.median = values.size() % 2 ? values[m] : (values[m - 1] + values[m]) / 2;
  return s;
}

}  // namespace

ForcingSummary summarize_forcing(const std::vector<ForcingRun>& runs, std::string_view method) {
  std::vector<const ForcingRun*> chosen;
  for (const ForcingRun& r : runs)
    if (method.empty() || r.c.method == method) chosen.push_back(&r);
  ForcingSummary s;
  s.runs = static_cast<int>(chosen.size());
  for (std::size_t i = 0; i < kForceReadings.size(); ++i) {
    s.velocity[i] = stats(chosen, [i](const ForcingRun& r) { return r.readings[i].velocity; });
    s.displacement[i] =
        stats(chosen, [i](const ForcingRun& r) { return r.readings[i].displacement; });
    s.displacement_full[i] =
        stats(chosen, [i](const ForcingRun& r) { return r.readings[i].displacement_full; });
  }
  s.proof_velocity = stats(chosen, [](const ForcingRun& r) { return r.proof_velocity; });
  s.proof_displacement = stats(chosen, [](const ForcingRun& r) { return r.proof_displacement; });
  for (const ForcingRun* r : chosen) accumulate(s.energy, r->energy);
  return s;
}

}  // namespace impact::lemma3
