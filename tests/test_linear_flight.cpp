// The closed-form flight under a linear force (linear_flight.hpp) against GSL's rk8pd at tight
// tolerances on random scenes of every kind (under-, critically and over-damped, k = 0, an
// inverted spring, resonance and near-resonance), its bound on |u''| against dense samples, and
// the certified contact search on it (a grazing dip that samples miss).
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "check_near.hpp"
#include "impact/references/linear_flight.hpp"

using impact::AccelerationBound;
using impact::FlightMotion;
using impact::LinearFlight;
using impact::LinearForce;

namespace {

int rhs(double t, const double y[], double dydt[], void* params) {
  const auto* f = static_cast<const LinearForce*>(params);
  dydt[0] = y[1];
  dydt[1] = f->at(t, y[0], y[1]);
  return GSL_SUCCESS;
}

// rk8pd from (t_a, u_a, v_a) to each of `times`, tolerances 1e-14.
std::vector<FlightMotion> rk8pd(const LinearForce& force, double t_a, double u_a, double v_a,
                                const std::vector<double>& times) {
  LinearForce f = force;
  gsl_odeiv2_system sys{rhs, nullptr, 2, &f};
  gsl_odeiv2_driver* driver =
      gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-4, 1e-14, 1e-14);
  double t = t_a, y[2] = {u_a, v_a};
  std::vector<FlightMotion> out;
  for (double target : times) {
    REQUIRE(gsl_odeiv2_driver_apply(driver, &t, target, y) == GSL_SUCCESS);
    out.push_back({y[0], y[1], f.at(t, y[0], y[1])});
  }
  gsl_odeiv2_driver_free(driver);
  return out;
}

struct Kind {
  std::string name;
  LinearForce force;
};

// A random scene of each kind (the generator's draws in a fixed order).
std::vector<Kind> random_scenes(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto in = [&](double a, double b) { return a + (b - a) * unit(rng); };
  std::vector<Kind> out;
  for (int i = 0; i < 3; ++i) {
    LinearForce base{in(0.2, 5), 0.0, in(-1, 1), in(-3, 3), in(-2, 2), in(0.3, 4), in(0, 6)};
    const double k = base.k, w = base.omega;
    LinearForce f = base;
    f.c = 2 * std::sqrt(k) * in(0.05, 0.9);
    out.push_back({"under-damped", f});
    f.c = 2 * std::sqrt(k);
    out.push_back({"critically damped", f});
    f.c = 2 * std::sqrt(k) * in(1.2, 3);
    out.push_back({"over-damped", f});
    f.c = 2 * std::sqrt(k) * (1 + 1e-9);
    out.push_back({"nearly critical", f});
    f.c = 0.0;
    out.push_back({"undamped", f});
    f.k = w * w;
    out.push_back({"resonant", f});
    f.k = w * w * (1 + 1e-7);
    out.push_back({"near resonance, undamped", f});
    f.c = 1e-3 * w;
    f.k = w * w * (1 - 1e-4);
    out.push_back({"near resonance, damped", f});
    f = base;
    f.k = 0.0;
    f.c = in(0.05, 1.5);
    out.push_back({"k = 0, damped", f});
    f.c = 0.0;
    out.push_back({"k = 0, undamped", f});
    f = base;
    f.k = -in(0.2, 2);
    f.c = in(0.0, 1.0);
    out.push_back({"inverted spring", f});
    f = base;
    f.c = -in(0.05, 0.3);
    out.push_back({"negative damping", f});
    f = base;
    f.c = in(0.05, 1);
    f.amplitude = 0.0;
    out.push_back({"no harmonic term", f});
  }
  return out;
}

}  // namespace

TEST_CASE("linear flight: the closed form equals rk8pd at tolerance 1e-14 on 39 random scenes",
          "[linear_flight]") {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> times;
  for (const Kind& kind : random_scenes(rng)) {
    const double t_a = 50 * unit(rng), u_a = 2 * unit(rng) - 1, v_a = 4 * unit(rng) - 2;
    const LinearFlight flight(kind.force, t_a, u_a, v_a);
    times.clear();
    // Short times (the Taylor regime) and long ones (the others), up to 5 time units.
    for (double s : {1e-6, 1e-3, 0.05, 0.3, 0.7, 1.3, 2.0, 3.1, 4.2, 5.0}) times.push_back(t_a + s);
    const std::vector<FlightMotion> reference = rk8pd(kind.force, t_a, u_a, v_a, times);
    for (std::size_t i = 0; i < times.size(); ++i) {
      const FlightMotion m = flight.at(times[i]), r = reference[i];
      INFO(kind.name << " (k = " << kind.force.k << ", c = " << kind.force.c
                     << ", omega = " << kind.force.omega << ", Duhamel form: " << flight.duhamel()
                     << "), t - t_a = " << times[i] - t_a);
      // rk8pd's own error over 5 time units at 1e-14 per step, relative to the motion's size.
      const double scale = 1 + std::fabs(r.u) + std::fabs(r.v) + std::fabs(r.a);
      CHECK_NEAR(m.u, r.u, 1e-11 * scale);
      CHECK_NEAR(m.v, r.v, 1e-11 * scale);
      CHECK_NEAR(m.a, r.a, 1e-11 * scale);
    }
  }
}

TEST_CASE("linear flight: at the anchor the flight is its start state, and at resonance it grows",
          "[linear_flight]") {
  const LinearForce resonant{4.0, 0.0, 0.0, 0.0, 1.0, 2.0, 0.0};
  const LinearFlight flight(resonant, 0.0, 0.0, 0.0);
  CHECK(flight.duhamel());
  CHECK(flight.at(0.0).u == 0.0);
  CHECK(flight.at(0.0).v == 0.0);
  // u'' + 4 u = sin 2t from rest: u = sin(2t)/8 - t cos(2t)/4, the secular term.
  for (double t : {0.5, 10.0, 100.0}) {
    const double exact = std::sin(2 * t) / 8 - t * std::cos(2 * t) / 4;
    CHECK_NEAR(flight.at(t).u, exact, 1e-14 * (1 + t));
  }
}

TEST_CASE("linear flight: |u''| stays below its certified bound over each window, 39 scenes",
          "[linear_flight]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const Kind& kind : random_scenes(rng)) {
    const LinearFlight flight(kind.force, 3 * unit(rng), 2 * unit(rng) - 1, 4 * unit(rng) - 2);
    double worst = 0.0;
    // Bounds from 40 points of the flight, each checked over its window (a global one over 20
    // time units) at 400 samples.
    for (int j = 0; j < 40; ++j) {
      const double from = flight.start() + 0.25 * j;
      const AccelerationBound b = flight.acceleration_bound(from);
      const double span = std::isfinite(b.until) ? b.until - from : 20.0;
      for (int i = 0; i <= 400; ++i)
        worst = std::fmax(worst, std::fabs(flight.at(from + span * i / 400).a) / b.B);
    }
    INFO(kind.name << " (k = " << kind.force.k << ", c = " << kind.force.c << ")");
    CHECK(worst <= 1.0);
    CHECK(worst > 0.05);  // and not vacuous
  }
}

TEST_CASE(
    "linear flight: the certified search finds a dip 1e-9 below the floor that sampling "
    "every 0.01 misses",
    "[linear_flight]") {
  // u'' = -u - cos(2.8 t): the free orbit u = gamma cos(2.8 t) (gamma = 1/(2.8^2 - 1)) has its
  // minimum -gamma at t = pi/2.8; a floor 1e-9 above it is touched for 2 sqrt(2e-9/a) ~ 6e-5.
  const double omega = 2.8, gamma = 1 / (omega * omega - 1);
  const LinearForce oscillator{1.0, 0.0, 0.0, 0.0, -1.0, omega, std::numbers::pi / 2};
  const LinearFlight flight(oscillator, 0.0, gamma, 0.0);
  const double phi = -gamma + 1e-9;
  bool sampled = false;
  for (int i = 0; i <= 200; ++i) sampled = sampled || flight.at(0.01 * i).u < phi;
  CHECK_FALSE(sampled);
  double certified = 0.0, checked = 0.0;
  long budget = 100000;
  const auto contact =
      impact::search_linear_contact(flight, gamma - phi, certified, checked, 2.0, budget);
  REQUIRE(contact);
  const double t_min = std::numbers::pi / omega, a = 1 + gamma;  // u'' at the minimum
  CHECK_NEAR(contact->t, t_min - std::sqrt(2e-9 / a), 1e-9);
  CHECK_NEAR(-contact->v, std::sqrt(2 * a * 1e-9), 1e-6 * std::sqrt(2 * a * 1e-9));
  // 1e-9 above the minimum instead: no contact within one forcing period.
  certified = checked = 0.0;
  budget = 100000;
  CHECK_FALSE(impact::search_linear_contact(flight, 2 * gamma + 1e-9, certified, checked,
                                            2 * std::numbers::pi / omega, budget));
  CHECK(budget > 0);
}
