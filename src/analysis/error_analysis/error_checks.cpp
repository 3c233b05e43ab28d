// Statements 1, 2 and 4 of paper_notes/error_analysis.md checked on one scene's runs.
#include "analysis/error_analysis/error_checks.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/error_analysis/error_bounds.hpp"
#include "impact/forces/scheme_flight.hpp"
#include "impact/model/contact.hpp"
#include "impact/model/contact_law.hpp"
#include "impact/steppers/direct_located.hpp"

namespace impact::error_analysis {
namespace {

constexpr double kUnit = 0x1p-53;  // unit roundoff

}  // namespace

double Rounding::time(double speed) const {
  return position / speed;
}

Rounding rounding_of(const Scene& scene, const Trace& exact) {
  double U = 0, V = 0;
  for (const State& s : exact.s) {
    U = std::fmax(U, std::fabs(s.u - scene.model.phi));
    V = std::fmax(V, std::fabs(s.v));
  }
  const Model& m = scene.model;
  const double a = m.harmonic ? std::fabs(m.harmonic->amplitude) : 0.0;
  const double w = m.harmonic ? m.harmonic->omega : 1.0;
  const double F = std::fabs(m.f) + a, T = scene.T, n = static_cast<double>(scene.grid.steps);
  const double phi_ulp = std::nextafter(std::fabs(m.phi), INFINITY) - std::fabs(m.phi);
  // Each closed-form value is a handful of operations on terms bounded by U + T V + F T^2, each
  // rounding by at most kUnit of them; 32 covers them with room. The harmonic terms carry the
  // phasor's error (SchemeFlight::kHarmonicTermError).
  const double harmonic = 4 * SchemeFlight::kHarmonicTermError * (a / w) * (T + 2 / w + 1);
  Rounding r;
  r.position = 32 * kUnit * (U + T * V + F * T * T) + 4 * phi_ulp + harmonic;
  r.velocity = 32 * kUnit * (V + F * T) + harmonic;
  // One rounding of u (of v) per step, each at most kUnit (U + h V) (kUnit (V + h F)), and the
  // velocity's acting for up to T.
  const double per_step_v = 4 * kUnit * n * (V + scene.grid.h * F);
  r.stepped_velocity = r.velocity + per_step_v;
  r.stepped_position = r.position + 4 * kUnit * n * (U + scene.grid.h * V) + T * per_step_v;
  r.rebound = r.velocity + 2 * r.position / scene.grid.h;
  return r;
}

double SceneRuns::cor() const {
  return newton_e(contact_law(scene.scene.model, kElasticReading));
}

double SceneRuns::gap(const Trace& t, std::size_t l) const {
  return t.s[l].u - scene.scene.model.phi;
}

std::optional<std::size_t> SceneRuns::first_contact(const Trace& t) const {
  for (std::size_t l = 0; l + 1 < t.s.size(); ++l)
    if (is_contact_step(scene.scene.model, t.s[l + 1], t.N[l + 1])) return l;
  return std::nullopt;
}

bool SceneRuns::contact_step(const Trace& t, std::size_t l, bool smoothing) const {
  // The step ends on the floor with a contact force: exactly for direct (u^{l+1} = phi), within
  // h sqrt(eps) / 2 for fb_newton (Lemma 2.1 (d)). (is_contact_step's N^l > u^{l+1} - phi compares
  // a force with a length, which misjudges fb_newton's steps when h is far from 1 s.)
  const double h = scene.scene.grid.h;
  const double ceiling = (smoothing ? h * std::sqrt(eps) / 2 : 0.0) + rounding.position;
  return t.N[l + 1] > 0 && gap(t, l + 1) <= ceiling;
}

bool SceneRuns::impact_step(const Trace& t, std::size_t l, bool smoothing) const {
  const Model& m = scene.scene.model;
  const double h = scene.scene.grid.h;
  if (!contact_step(t, l, smoothing)) return false;
  // ... and its flight from t_l reaches the floor within it, to the run's resolution of positions
  // (a gap of a few ulp of a floor at 1e6 puts the crossing just past t_{l+1}).
  const FloorArrival a = floor_arrival({gap(t, l), t.s[l].v}, m.f);
  return a.found && (a.tau - h) * a.speed <= rounding.position;
}

std::optional<std::size_t> SceneRuns::first_impact_step(const Trace& t, bool smoothing) const {
  for (std::size_t l = 0; l + 1 < t.s.size(); ++l)
    if (impact_step(t, l, smoothing)) return l;
  return std::nullopt;
}

Check make_check(const SceneRuns& r, std::string name, double measured, double bound,
                 double allowance, double x, bool lower) {
  Check c;
  c.name = std::move(name);
  c.scene = r.index;
  c.h = r.scene.scene.grid.h;
  c.measured = measured;
  c.bound = bound;
  c.allowance = allowance;
  c.lower = lower;
  c.x = x;
  return c;
}

double kick(const SceneRuns& r, std::size_t l) {
  const Scene& scene = r.scene.scene;
  const double h = scene.grid.h, t = static_cast<double>(l + 1) * h;
  const Model& m = scene.model;
  // fb_newton's flight lies above the exact one (its kicks only push up): the exact gap, less the
  // free flight's own error under f(t) (Lemma 1.2), bounds its free gap from below.
  const double flight_error =
      m.harmonic ? harmonic_flight_bound(m.harmonic->amplitude, m.harmonic->omega, h, t) : 0.0;
  return smoothing_kick(r.eps, h, std::fmax(0.0, r.gap(r.exact, l + 1) - flight_error));
}

KickSum kicks_before(const SceneRuns& r, std::size_t end) {
  const double h = r.scene.scene.grid.h, t_end = static_cast<double>(end) * h;
  KickSum sum;
  for (std::size_t j = 0; j < end; ++j) {
    const double k = kick(r, j);
    sum.velocity += k;
    sum.position += k * (t_end - static_cast<double>(j) * h);
  }
  return sum;
}

// Statement 1: every scheme from the common initial state up to its first contact step and the
// exact first impact. Constant f: exact (Lemma 1.1); f(t): Lemma 1.2; fb_newton: plus Lemma 1.3.
void check_flight(const SceneRuns& r, std::vector<Check>& out) {
  const Scene& scene = r.scene.scene;
  const double h = scene.grid.h;
  const Model& m = scene.model;
  const auto impact_index = [&]() -> std::size_t {
    const double t1 = r.exact.first_impact;
    return t1 < scene.grid.end() ? static_cast<std::size_t>(std::floor(t1 / h))
                                 : static_cast<std::size_t>(scene.grid.steps);
  }();
  struct Scheme {
    const char* name;
    const Trace& trace;
    bool stepped, smoothing;
  };
  for (const Scheme& s :
       {Scheme{"direct", r.direct, false, false}, Scheme{"fb_newton", r.fb_newton, false, true},
        Scheme{"moreau_jean", r.moreau_jean, true, false},
        Scheme{"direct_located", r.located, false, false}}) {
    if (s.trace.failed) continue;
    const std::size_t end = std::min(impact_index, r.first_contact(s.trace).value_or(SIZE_MAX));
    const double allow_u = s.stepped ? r.rounding.stepped_position : r.rounding.position;
    const double allow_v = s.stepped ? r.rounding.stepped_velocity : r.rounding.velocity;
    // The worst grid time, by measured / (bound + allowance).
    double worst = -1, du = 0, bu = 0, dv = 0, bv = 0, wu = 0, wv = 0;
    double kicks = 0, kicks_times = 0;    // sum of the kicks before t_l, and of kick * t_j
    double round_v = 0, round_times = 0;  // the same for the kicks' rounding
    for (std::size_t l = 0; l <= end; ++l) {
      const double t = static_cast<double>(l) * h;
      double bound_u =
          m.harmonic ? harmonic_flight_bound(m.harmonic->amplitude, m.harmonic->omega, h, t) : 0.0;
      double bound_v = 0;
      if (s.smoothing && l < end) {  // Lemma 1.3: a kick at step j moves u by <= kick (t_l - t_j)
        const double k = kick(r, l);
        kicks += k;
        kicks_times += k * t;
        round_v += (kKickRounding - 1) * k;
        round_times += (kKickRounding - 1) * k * t;
      }
      const double eu = std::fabs(s.trace.s[l].u - r.exact.s[l].u);
      const double ev = std::fabs(s.trace.s[l].v - r.exact.s[l].v);
      const double au = allow_u + t * round_v - round_times, av = allow_v + round_v;
      bound_u += t * kicks - kicks_times;
      bound_v += kicks;
      const double score = std::fmax(eu / (bound_u + au), ev / (bound_v + av));
      if (score > worst) {
        worst = score;
        du = eu, bu = bound_u, dv = ev, bv = bound_v, wu = au, wv = av;
      }
    }
    const std::string prefix = std::string("s1.") + s.name;
    const char* kind = m.harmonic ? ".forced" : ".constant";
    out.push_back(make_check(r, prefix + kind + "_u", du, bu, wu));
    out.push_back(make_check(r, prefix + kind + "_v", dv, bv, wv));
  }
}

}  // namespace impact::error_analysis
