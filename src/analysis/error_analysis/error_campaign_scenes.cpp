// The campaign's scenes and its runs on the grid (error_campaign.hpp).
#include <cmath>
#include <cstdint>
#include <numbers>

#include "analysis/error_analysis/error_campaign.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/error_norms.hpp"

namespace impact::error_analysis {
namespace {

constexpr double kGravity = 9.80665;
// The longest run: T / h <= kMaxSteps keeps a scene's runs to milliseconds.
constexpr double kMaxSteps = 2e4;

// splitmix64: a generator whose numbers do not depend on the standard library.
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : state_(seed) {}
  double uniform(double a = 0, double b = 1) {
    state_ += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return a + (b - a) * static_cast<double>(z >> 11) * 0x1p-53;
  }
  double log_uniform(double lo, double hi) { return std::pow(10.0, uniform(lo, hi)); }
  bool chance(double p) { return uniform() < p; }
  double sign() { return chance(0.5) ? 1.0 : -1.0; }

 private:
  std::uint64_t state_;
};

// Initial data over wide ranges, with the stability map's extremes (experiments/stability): the
// particle on the floor, at rest, thrown at 1e4 m/s, a floor far from the origin.
State draw_initial(Draw& d, double phi) {
  const double gap = d.chance(0.1) ? 0.0 : d.log_uniform(-4, 3);
  double v = d.chance(0.15) ? 0.0 : d.sign() * d.log_uniform(-3, 2);
  if (d.chance(0.03)) v = -d.log_uniform(3, 4);
  return {phi + gap, v};
}

double draw_phi(Draw& d) {
  return d.chance(0.1) ? 1e6 : 0.0;
}

double draw_cor(Draw& d) {
  const double p = d.uniform();
  if (p < 0.12) return 0.0;
  if (p < 0.2) return 1.0;
  if (p < 0.27) return 0.999;
  return d.uniform(0.02, 0.98);
}

// The grid: T / h log-uniform in [30, kMaxSteps].
double draw_step(Draw& d, double T) {
  return T / d.log_uniform(std::log10(30.0), std::log10(kMaxSteps));
}

// A time by which something happens: the first impact (or 1 s without one).
double first_impact(const Model& model, const State& initial) {
  const auto t1 = ExactSolution(model, initial).impact_time(1);
  return t1 && *t1 > 0 ? *t1 : 1.0;
}

Scene zeno_scene(Draw& d) {
  Model model;
  model.phi = draw_phi(d);
  model.f = -(d.chance(0.05) ? d.log_uniform(3, 8) : d.log_uniform(-1, 2) * kGravity / 10);
  model.cor = draw_cor(d);
  const State initial = draw_initial(d, model.phi);
  const ExactSolution exact(model, initial);
  const double t1 = first_impact(model, initial);
  double T;
  if (const auto rest = exact.rest_time(); rest && *model.cor < 1)
    T = std::fmax(*rest * d.uniform(0.3, 1.6), 1.01 * t1);
  else  // e = 1: a few bounces of 2 V_1 / g
    T = t1 + d.uniform(0.5, 8) * 2 * exact.impact_speed(1).value_or(1.0) / -model.f;
  return make_scene(model, initial, T, draw_step(d, T), DirectParams{});
}

Scene single_scene(Draw& d) {
  Model model;
  model.phi = draw_phi(d);
  model.f = d.chance(0.3) ? 0.0 : d.log_uniform(-2, 2);
  model.cor = draw_cor(d);
  State initial = draw_initial(d, model.phi);
  initial.v = -std::fabs(initial.v == 0 ? 1.0 : initial.v);  // towards the floor
  const double T = first_impact(model, initial) * d.uniform(1.2, 4);
  return make_scene(model, initial, T, draw_step(d, T), DirectParams{});
}

Scene no_cor_scene(Draw& d) {
  Model model;
  model.phi = draw_phi(d);
  model.f = d.chance(0.4) ? 0.0 : -d.log_uniform(-1, 2) * kGravity / 10;
  State initial = draw_initial(d, model.phi);
  if (model.f == 0) initial.v = -std::fabs(initial.v == 0 ? 1.0 : initial.v);
  const double T = first_impact(model, initial) * d.uniform(1.3, 5);
  return make_scene(model, initial, T, draw_step(d, T), DirectParams{});
}

Scene forced_scene(Draw& d) {
  Model model;
  const double p = d.uniform();
  model.f = p < 0.4 ? -kGravity : p < 0.6 ? 0.0 : d.uniform(-50, 50);
  model.harmonic = Harmonic{d.sign() * d.log_uniform(-1, 2), d.log_uniform(-1, 2),
                            d.uniform(0, 2 * std::numbers::pi)};
  if (d.chance(0.7)) model.cor = draw_cor(d);
  State initial{d.log_uniform(-2, 1), d.chance(0.2) ? 0.0 : d.sign() * d.log_uniform(-2, 1)};
  const double T = d.uniform(0.5, 4);
  // The step resolves the force: omega h <= 1, where the schemes sum its flight in closed form.
  const double h = std::fmin(draw_step(d, T), d.uniform(0.05, 1) / model.harmonic->omega);
  return make_scene(model, initial, T, std::fmax(h, T / kMaxSteps), DirectParams{});
}

}  // namespace

std::string_view kind_name(CampaignKind kind) {
  switch (kind) {
    case CampaignKind::zeno:
      return "zeno";
    case CampaignKind::single:
      return "single";
    case CampaignKind::no_cor:
      return "no_cor";
    case CampaignKind::forced:
      break;
  }
  return "forced";
}

std::vector<CampaignScene> campaign_scenes(std::size_t count, std::uint64_t seed) {
  Draw d(seed);
  std::vector<CampaignScene> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    // Of every 12 scenes: 4 zeno, 2 single, 3 no_cor, 3 forced.
    const std::size_t slot = i % 12;
    const CampaignKind kind = slot < 4   ? CampaignKind::zeno
                              : slot < 6 ? CampaignKind::single
                              : slot < 9 ? CampaignKind::no_cor
                                         : CampaignKind::forced;
    switch (kind) {
      case CampaignKind::zeno:
        out.push_back({kind, zeno_scene(d)});
        break;
      case CampaignKind::single:
        out.push_back({kind, single_scene(d)});
        break;
      case CampaignKind::no_cor:
        out.push_back({kind, no_cor_scene(d)});
        break;
      case CampaignKind::forced:
        out.push_back({kind, forced_scene(d)});
        break;
    }
  }
  return out;
}

Trace run_trace(const Scene& scene) {
  Trace trace;
  const auto n = static_cast<std::size_t>(scene.grid.steps) + 1;
  trace.s.reserve(n);
  trace.N.reserve(n);
  AnyStepper stepper = make_stepper(scene);
  try {
    simulate(stepper, scene.initial, scene.grid,
             [&](std::int64_t, const State& s, const StepInfo& info) {
               trace.s.push_back(s);
               trace.N.push_back(scheme_force(info));
             });
  } catch (const NumericalError&) {
    trace = Trace{};
    trace.failed = true;
  }
  return trace;
}

Trace reference_trace(const Scene& scene) {
  Trace trace;
  ReferenceSolution exact(scene.model, scene.initial, scene.grid.end());
  const auto n = static_cast<std::size_t>(scene.grid.steps) + 1;
  trace.s.reserve(n);
  for (std::int64_t l = 0; l <= scene.grid.steps; ++l) trace.s.push_back(exact.at(scene.grid.t(l)));
  trace.first_impact = exact.first_impact().value_or(INFINITY);
  return trace;
}

}  // namespace impact::error_analysis
