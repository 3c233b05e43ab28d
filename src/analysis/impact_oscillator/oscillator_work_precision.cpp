#include "analysis/impact_oscillator/oscillator_work_precision.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "analysis/impact_oscillator/oscillator_law.hpp"
#include "impact/format.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/run/any_stepper.hpp"

namespace impact::impact_oscillator {

std::vector<std::string_view> state_force_methods() {
  return methods_with(&Capabilities::state_force);
}

std::vector<std::string_view> refusing_methods() {
  std::vector<std::string_view> out;
  for (const MethodInfo& m : methods())
    if (!m.can.state_force) out.push_back(m.name);
  return out;
}

Oscillator oscillator_of(const Scene& scene) {
  const std::string& e = scene.model.expression.text();
  const std::string head = "-u - cos(", tail = "*t)";
  const auto bad = [&] {
    return std::runtime_error(
        "the scene's force is not the impact oscillator's: force.expression "
        "= '" +
        e + "', expected '-u - cos(omega*t)' with a number omega");
  };
  if (e.rfind(head, 0) != 0 || e.size() <= head.size() + tail.size() ||
      e.compare(e.size() - tail.size(), tail.size(), tail) != 0)
    throw bad();
  const std::string number = e.substr(head.size(), e.size() - head.size() - tail.size());
  char* end = nullptr;
  const double omega = std::strtod(number.c_str(), &end);
  if (end != number.c_str() + number.size() || !(omega > 0)) throw bad();
  if (!scene.model.cor || scene.model.harmonic || scene.model.f != 0.0)
    throw std::runtime_error("the impact oscillator's scene needs floor.cor and no other force");
  return {omega, *scene.model.cor, -scene.model.phi};
}

OscillatorPoint measure(const Scene& scene, const MethodParams& params, double h,
                        const std::optional<TimingRule>& rule) {
  const Oscillator o = oscillator_of(scene);
  const Grid grid = Grid::covering(scene.T, h);
  const auto make = [&] { return make_stepper(scene.model, h, params); };
  OscillatorPoint p;
  p.h = h;
  if (const auto* ed = std::get_if<EventDrivenParams>(&params)) p.tolerance = ed->rtol;
  LinearTrack reference = oscillator_track(o, scene.initial, 0.0);
  AnyStepper stepper = make();
  simulate(stepper, scene.initial, grid, [&](std::int64_t l, const State& s, const StepInfo&) {
    double impulse = 0.0;
    const State r = reference.advance(grid.t(l), impulse);
    p.sup_u = std::fmax(p.sup_u, std::fabs(s.u - r.u));
    p.sup_v = std::fmax(p.sup_v, std::fabs(s.v - r.v));
  });
  if (!reference.converged())
    throw std::runtime_error("the oscillator's reference did not converge");
  if (rule) p.cost = time_solve(make, scene.initial, grid, *rule);
  return p;
}

std::vector<OscillatorCurve> oscillator_curves(const Scene& scene, const std::vector<double>& steps,
                                               const std::vector<double>& tolerances,
                                               double tolerance_grid,
                                               const std::optional<TimingRule>& rule) {
  std::vector<OscillatorCurve> curves;
  for (std::string_view name : state_force_methods()) {
    const MethodInfo& info = *find_method(name);
    OscillatorCurve c;
    c.method = name;
    c.step_sweep = !info.can.reference;
    if (c.step_sweep) {
      std::vector<double> hs, errors;
      for (double h : steps) {
        c.points.push_back(measure(scene, info.defaults, h, rule));
        hs.push_back(h);
        errors.push_back(c.points.back().sup_u);
      }
      c.order = fit_order(hs, errors);
    } else {
      for (double tolerance : tolerances) {
        EventDrivenParams params = std::get<EventDrivenParams>(info.defaults);
        params.rtol = params.atol = tolerance;
        c.points.push_back(measure(scene, params, tolerance_grid, rule));
      }
    }
    curves.push_back(std::move(c));
  }
  return curves;
}

std::string curve_rows(const std::string& scene, const std::vector<OscillatorCurve>& curves) {
  std::ostringstream out;
  for (const OscillatorCurve& c : curves)
    for (const OscillatorPoint& p : c.points)
      out << scene << ',' << c.method << ',' << round_trip(p.h) << ',' << round_trip(p.tolerance)
          << ',' << round_trip(p.sup_u) << ',' << round_trip(p.sup_v) << ','
          << round_trip(p.cost.min) << ',' << round_trip(p.cost.median) << '\n';
  return out.str();
}

}  // namespace impact::impact_oscillator
