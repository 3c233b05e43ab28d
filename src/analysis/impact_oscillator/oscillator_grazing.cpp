#include "analysis/impact_oscillator/oscillator_grazing.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "analysis/impact_oscillator/oscillator_law.hpp"

namespace impact::impact_oscillator {

namespace {

constexpr double kPi = std::numbers::pi;

// The first impact of the grazing pass, from (0, |gamma|, 0) onto the floor with the gap
// gap_a at the start, within one forcing period.
double first_impact_speed(double omega, double g, double gap_a) {
  const LinearFlight flight(oscillator_force(omega), 0.0, g, 0.0);
  double certified = 0.0, checked = 0.0;
  long budget = 1'000'000;
  const auto contact =
      search_linear_contact(flight, gap_a, certified, checked, 2 * kPi / omega, budget);
  if (!contact) throw std::runtime_error("grazing_law: the pass found no impact");
  return -contact->v;
}

}  // namespace

GrazingLaw grazing_law(double omega, double r, double log_min, int decades, int per_decade,
                       bool with_event_driven) {
  GrazingLaw law;
  const double g = grazing_sigma(omega);
  law.sqrt_2a = std::sqrt(2 * grazing_curvature(omega));
  std::vector<double> deltas, speeds, ed_speeds, orbit_speeds;
  for (int k = 0; k <= decades * per_decade; ++k) {
    const double nominal = std::pow(10.0, log_min + static_cast<double>(k) / per_decade);
    // The gap at the start, 2|gamma| - delta, and the delta it stands for: 2|gamma| minus it is
    // exact (the two are within a factor 2), so delta is the one the search sees.
    const double gap_a = 2 * g - nominal;
    GrazingPoint p;
    p.delta = 2 * g - gap_a;
    p.V = first_impact_speed(omega, g, gap_a);
    p.exact = grazing_first_speed(omega, p.delta);
    law.max_relative_deviation =
        std::fmax(law.max_relative_deviation, std::fabs(p.V / p.exact - 1));
    const Oscillator at_orbit{omega, r, g - p.delta};
    if (const auto orbit = period_one_orbit(at_orbit)) p.orbit_V = orbit->V;
    if (with_event_driven) {
      const Oscillator o{omega, r, g - p.delta};
      for (const Event& e : event_driven_events(o, {g, 0.0}, 1.1 * kPi / omega, 0.1))
        if (e.kind == EventKind::impact) {
          p.event_driven = -e.v_before;
          break;
        }
      ed_speeds.push_back(p.event_driven);
    }
    deltas.push_back(p.delta);
    speeds.push_back(p.V);
    orbit_speeds.push_back(p.orbit_V);
    law.points.push_back(p);
  }
  law.reference = fit_order(deltas, speeds);
  law.orbit = fit_order(deltas, orbit_speeds);
  if (with_event_driven) law.event_driven = fit_order(deltas, ed_speeds);
  return law;
}

ChatterPoint chatter_accumulation(const Oscillator& o, double t0, double v0) {
  ChatterPoint p;
  p.t0 = t0;
  p.v0 = v0;
  p.a0 = o.phi() + std::cos(o.omega * t0);
  p.a1 = -o.omega * std::sin(o.omega * t0);
  Impact x{t0, v0 / o.r};  // a take-off speed v0 = r V
  while (o.r * x.V >= 1e-7 * v0) {
    const auto next = impact_map(o, x, 1.0);
    if (!next) throw std::runtime_error("chatter_accumulation: a bounce found no impact");
    x = *next;
    ++p.impacts;
  }
  p.t_inf = x.t + accumulation_time(o.r * x.V, o.phi() + std::cos(o.omega * x.t), o.r);
  p.prediction = t0 + accumulation_time(v0, p.a0, o.r);
  p.prediction_first_order = t0 + accumulation_time_first_order(v0, p.a0, p.a1, o.r);
  return p;
}

StickingRun sticking_run(const Oscillator& o, double v0, double T) {
  StickingRun run;
  const State initial{o.phi(), v0};
  run.reference = run_track(o, initial, T).events;
  run.event_driven = event_driven_events(o, initial, T, T / 1024);
  run.t_inf = chatter_accumulation(o, 0.0, v0).t_inf;
  const double period = o.period(), first = lift_off_angle(o.phi()) / o.omega;
  run.lift_off = first + std::ceil((run.t_inf - first) / period) * period;
  return run;
}

}  // namespace impact::impact_oscillator
