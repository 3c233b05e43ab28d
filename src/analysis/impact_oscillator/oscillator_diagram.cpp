#include "analysis/impact_oscillator/oscillator_diagram.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "analysis/impact_oscillator/oscillator_law.hpp"
#include "impact/format.hpp"

namespace impact::impact_oscillator {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Oscillator with(const Oscillator& base, SweepParameter parameter, double value) {
  Oscillator o = base;
  (parameter == SweepParameter::sigma ? o.sigma : o.omega) = value;
  return o;
}

double value_of(const Oscillator& o, SweepParameter parameter) {
  return parameter == SweepParameter::sigma ? o.sigma : o.omega;
}

std::string number(double x) {
  return std::isfinite(x) ? round_trip(x) : std::string("nan");
}

}  // namespace

std::vector<double> parameter_grid(double from, double to, double step) {
  std::vector<double> values;
  const long n = std::lround((to - from) / step);
  for (long i = 0; i <= n; ++i) {
    // Parsed from its decimal (12 digits), so that e.g. sigma = -1 is -1 and not -1 + 1e-16: a
    // wall at phi = 1 - 1e-16 holds a resting particle at every phase but one, where the push
    // phi + cos(omega t) touches 0 from above, an exceptional lift-off the contact search does
    // not pass.
    char text[32];
    std::snprintf(text, sizeof text, "%.12g", from + static_cast<double>(i) * step);
    values.push_back(std::strtod(text, nullptr));
  }
  return values;
}

std::vector<DiagramPoint> sweep(SweepParameter parameter, const Oscillator& base,
                                const std::vector<double>& values, const State& start,
                                const DiagramSettings& settings) {
  std::vector<DiagramPoint> points;
  State s = start;
  for (double value : values) {
    DiagramPoint p;
    p.o = with(base, parameter, value);
    // A particle that the moved wall would hold below it is put on it.
    if (s.u < p.o.phi()) s = {p.o.phi(), std::fmax(s.v, 0.0)};
    const double T = (settings.transient_periods + settings.kept_periods) * p.o.period();
    const double kept_from = settings.transient_periods * p.o.period();
    LinearTrack track = oscillator_track(p.o, s, 0.0);
    track.set_event_sink([&](const Event& e) {
      if (e.t < kept_from) return;
      if (e.kind == EventKind::stick) ++p.sticks;
      if (p.events.size() < settings.max_events) p.events.push_back(e);
    });
    double impulse = 0.0;
    s = track.advance(T, impulse);
    p.converged = track.converged();
    points.push_back(std::move(p));
  }
  return points;
}

std::string diagram_rows(const std::vector<DiagramPoint>& points, const std::string& direction,
                         SweepParameter parameter) {
  std::ostringstream out;
  for (const DiagramPoint& p : points)
    for (const Event& e : p.events)
      out << direction << ',' << round_trip(value_of(p.o, parameter)) << ',' << event_name(e.kind)
          << ',' << round_trip(impact_phase(e.t, p.o.omega)) << ',' << round_trip(-e.v_before)
          << '\n';
  return out.str();
}

std::string branch_rows(SweepParameter parameter, const Oscillator& base,
                        const std::vector<double>& values) {
  std::ostringstream out;
  for (double value : values) {
    const Oscillator o = with(base, parameter, value);
    double stable = kNaN, unstable = kNaN, saddle = kNaN, phase = kNaN, saddle_phase = kNaN;
    if (const auto plus = period_one_orbit(o, 1, 1); plus && orbit_is_admissible(o, *plus)) {
      const bool is_stable = leading_multiplier(orbit_trace(o, plus->V), o.r) < 1.0;
      (is_stable ? stable : unstable) = plus->V;
      phase = plus->t0;
    }
    if (const auto minus = period_one_orbit(o, 1, -1); minus && orbit_is_admissible(o, *minus)) {
      saddle = minus->V;
      saddle_phase = minus->t0;
    }
    out << round_trip(value) << ',' << number(stable) << ',' << number(unstable) << ','
        << number(saddle) << ',' << number(phase) << ',' << number(saddle_phase) << '\n';
  }
  return out.str();
}

}  // namespace impact::impact_oscillator
