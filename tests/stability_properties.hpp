// The property tests of tests/test_stability.cpp: seeded random scenes across the extreme ranges
// (a Catch2 generator) and what a run of one did, step by step (finite, min(u - phi), energy rises
// beyond round-off, complementarity, the impulse identity (4-9)).
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <random>
#include <string>

#include "impact/loop/simulate.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"
#include "impact/steppers/fb_newton.hpp"

namespace impact::stability_properties {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// ---- Random scenes over the extreme ranges ----

struct RandomScene {
  double phi = 0, u0 = 0, v0 = 0, f = 0;
  std::optional<double> cor;
  double h = 0;
  std::int64_t steps = 0;
  double epsilon = 1e-15;  // fb_newton
  double stiffness = 1e6;  // penalty

  Scene scene(const std::string& method) const {
    MethodParams params = find_method(method)->defaults;
    if (auto* fb = std::get_if<FbNewtonParams>(&params)) fb->epsilon = epsilon;
    if (auto* penalty = std::get_if<PenaltyParams>(&params)) penalty->stiffness = stiffness;
    // T = steps h, and exactly `steps` steps (T/h rounds back to steps within 1e-9).
    return make_scene(Model{phi, f, cor}, State{u0, v0}, static_cast<double>(steps) * h, h, params);
  }
};

// The scene's numbers, for a failing check's message (round_trip: they read back exactly).
inline std::ostream& operator<<(std::ostream& out, const RandomScene& r) {
  out << "phi = " << round_trip(r.phi) << ", u0 = " << round_trip(r.u0)
      << ", v0 = " << round_trip(r.v0) << ", f = " << round_trip(r.f)
      << ", cor = " << (r.cor ? round_trip(*r.cor) : std::string("none"))
      << ", h = " << round_trip(r.h) << ", steps = " << r.steps
      << ", epsilon = " << round_trip(r.epsilon) << ", stiffness = " << round_trip(r.stiffness);
  return out;
}

// A Catch2 generator of `count` scenes from a fixed seed (std::mt19937_64 and libstdc++'s
// distributions: the same scenes on every run).
class RandomScenes final : public Catch::Generators::IGenerator<RandomScene> {
 public:
  RandomScenes(std::uint64_t seed, int count) : rng_(seed), left_(count) { draw(); }
  const RandomScene& get() const override { return scene_; }
  bool next() override {
    if (--left_ <= 0) return false;
    draw();
    return true;
  }

 private:
  double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
  double log_uniform(double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * unit()); }
  void draw() {
    RandomScene s;
    const double p = unit();
    s.phi = p < 0.3 ? 0.0 : p < 0.5 ? 1e6 : -1e3 + 2e3 * unit();
    s.u0 = s.phi + (unit() < 0.25 ? 0.0 : log_uniform(-12, 3));
    const double sign = unit() < 0.6 ? -1.0 : 1.0;
    s.v0 = unit() < 0.15 ? 0.0 : sign * log_uniform(-6, 8);
    const double q = unit();
    s.f = q < 0.15 ? 0.0 : q < 0.85 ? -log_uniform(-3, 8) : log_uniform(-3, 8);
    const double c = unit();
    if (c < 0.1)
      s.cor = 0.0;
    else if (c < 0.2)
      s.cor = 1.0;
    else if (c < 0.35)
      s.cor = unit();
    else if (c < 0.5)
      s.cor = 1 - 1e-3 * unit();
    s.h = log_uniform(-9, 0);
    s.steps = static_cast<std::int64_t>(log_uniform(0, 3.3));
    s.epsilon = log_uniform(-15, -2);
    s.stiffness = log_uniform(2, 9);
    scene_ = s;
  }
  std::mt19937_64 rng_;
  int left_;
  RandomScene scene_;
};

inline Catch::Generators::GeneratorWrapper<RandomScene> random_scenes(std::uint64_t seed,
                                                                      int count) {
  return Catch::Generators::GeneratorWrapper<RandomScene>(
      std::unique_ptr<Catch::Generators::IGenerator<RandomScene>>(new RandomScenes(seed, count)));
}

// What a run did, step by step, against the stability properties.
struct Properties {
  bool finite = true;
  double min_gap = std::numeric_limits<double>::infinity();
  double max_v = 0, max_u = 0;
  double worst_energy_excess = -std::numeric_limits<double>::infinity();  // rise - allowance
  double worst_complementarity = 0;  // |N^l (u^{l+1} - phi)| beyond its allowance
  double impulse = 0;                // h sum N^l
  State last;
};

// The allowance on E^{l+1} - E^l beyond which a rise counts, on top of round-off (see
// check_stability: the free-flight terms, and 2/h times one ulp of u on a contact step).
inline double roundoff(const Model& model, double t, double h, const State& before,
                       const State& after, double N, double max_u, double max_v) {
  const double f = std::fabs(model.f);
  const double ulp_u = kEps * std::fmax(std::fabs(before.u), std::fabs(model.phi));
  return 16 * kEps * (max_v * max_v + f * (max_u + t * max_v + t * t * f)) +
         (N > 0 ? 4 * std::fabs(after.v) * ulp_u / h : 0.0);
}

// extra_allowance: a further bound on E^{l+1} - E^l that the caller's theory gives.
inline Properties run_properties(const Scene& scene, double extra_allowance = 0,
                                 bool smoothed = false, double eps = 0) {
  AnyStepper stepper = make_stepper(scene);
  const Model& m = scene.model;
  Properties p;
  State before = scene.initial;
  p.max_u = std::fabs(before.u);
  p.max_v = std::fabs(before.v);
  simulate(stepper, scene.initial, scene.grid,
           [&](std::int64_t l, const State& s, const StepInfo& info) {
             p.finite = p.finite && std::isfinite(s.u) && std::isfinite(s.v) &&
                        std::isfinite(info.contact_force);
             p.min_gap = std::fmin(p.min_gap, s.u - m.phi);
             p.last = s;
             if (l == 0) return;
             p.max_u = std::fmax(p.max_u, std::fabs(s.u));
             p.max_v = std::fmax(p.max_v, std::fabs(s.v));
             const double N = scheme_force(info), gap = s.u - m.phi;
             p.impulse += scene.grid.h * N;
             double allowance =
                 roundoff(m, scene.grid.t(l), scene.grid.h, before, s, N, p.max_u, p.max_v) +
                 extra_allowance;
             if (smoothed) {
               // The root of (5-3) has a N = eps/2; Newton stops at a residual within
               // 1e-15 max(1, a, N) (a + N + sqrt(eps)) of it, or at the double nearest the
               // root, where N = (2/h^2)(a - a_free) is resolved to (2/h^2) ulp(a) (fb_newton.cpp,
               // check_stability).
               const double a = std::fabs(gap), h = scene.grid.h;
               const double residual =
                   1e-15 * std::fmax(1.0, std::fmax(a, N)) * (a + N + std::sqrt(eps)) +
                   2 * kEps * a * (2 * a / (h * h) + N);
               allowance += 0.5 * eps + residual;
               // (4-3) smoothed: 0 <= N^l (u^{l+1} - phi) = a N <= eps/2 + residual, with u
               // rounded to the floor's ulp.
               const double ulp_phi = 2 * kEps * std::fabs(m.phi);
               const double excess = std::fmax(N * gap - (0.5 * eps + residual + N * ulp_phi),
                                               -N * ulp_phi - N * gap);
               p.worst_complementarity = std::fmax(p.worst_complementarity, excess);
             } else {
               p.worst_complementarity = std::fmax(p.worst_complementarity, std::fabs(N * gap));
             }
             const double rise = energy(m, s) - energy(m, before);
             p.worst_energy_excess = std::fmax(p.worst_energy_excess, rise - allowance);
             before = s;
           });
  return p;
}

// h sum N^l = v^n - v^0 - f T (4-9) with the body force: each of the n steps adds round-off of
// order eps (max|v| + |f| T).
inline double impulse_identity_tolerance(const Scene& scene, const Properties& p) {
  const double T = scene.grid.t(scene.grid.steps);
  return 8 * kEps * static_cast<double>(scene.grid.steps + 1) *
         (p.max_v + std::fabs(scene.model.f) * T + 1e-300);
}

}  // namespace impact::stability_properties
