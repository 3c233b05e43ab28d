// The exact reference solution (exact.hpp) against values derived by hand, against long-double
// evaluations of the same closed forms, and against the identities it must satisfy: energy (3-1)
// and the impulse identity (4-9). Tolerances are stated as a few ulp of the magnitudes involved,
// with the reason next to each.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "impact/exact.hpp"

using impact::energy;
using impact::ExactSolution;
using impact::ExactStepper;
using impact::Model;
using impact::State;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kG = 9.80665;  // standard gravity: f = -kG
constexpr std::int64_t kZenoCount = std::numeric_limits<std::int64_t>::max() / 2;

Model model_of(double f, std::optional<double> cor = std::nullopt, double phi = 0.0) {
  Model m;
  m.phi = phi;
  m.f = f;
  m.cor = cor;
  return m;
}

double ulp(double x) {
  return std::nextafter(std::fabs(x), std::numeric_limits<double>::infinity()) - std::fabs(x);
}
double before(double t) {
  return std::nextafter(t, -std::numeric_limits<double>::infinity());
}

}  // namespace

// |a - b| <= tol, printing all three with full precision on failure.
#define CHECK_NEAR(a, b, tol)                                                                   \
  do {                                                                                          \
    const double a_ = (a), b_ = (b), tol_ = (tol);                                              \
    INFO(std::setprecision(17) << #a " = " << a_ << ", " #b " = " << b_ << ", tol = " << tol_); \
    CHECK(std::fabs(a_ - b_) <= tol_);                                                          \
  } while (0)

TEST_CASE("exact: without a force the first impact is at d / |v0|", "[exact]") {
  // Paper, Section 5.2: u0 = 5, v0 = -1, f = 0. u = 5 - t reaches phi = 0 at t = 5 with speed 1;
  // every value below is exact in binary floating point, so the checks are exact.
  const State init{5.0, -1.0};
  SECTION("elastic") {
    const ExactSolution x(model_of(0.0), init);
    REQUIRE(x.impact_time(1));
    CHECK(*x.impact_time(1) == 5.0);
    CHECK(*x.impact_speed(1) == 1.0);
    CHECK_FALSE(x.impact_time(2));  // no force: it never comes back
    CHECK_FALSE(x.rest_time());
    CHECK(x.impacts_until(before(5.0)) == 0);
    CHECK(x.impacts_until(5.0) == 1);
    CHECK(x.impacts_until(1e4) == 1);
    CHECK(x.at(3.0).u == 2.0);
    CHECK(x.at(3.0).v == -1.0);
    CHECK(x.at(5.0).u == 0.0);
    CHECK(x.at(5.0).v == 1.0);  // right-continuous: the post-impact velocity
    CHECK(x.at(7.0).u == 2.0);
    CHECK(x.at(7.0).v == 1.0);
    CHECK(x.impulse(0.0, 10.0) == 2.0);
    CHECK(x.impulse(4.0, 5.0) == 2.0);  // (4, 5] holds t1 = 5
    CHECK(x.impulse(5.0, 10.0) == 0.0);
    CHECK(x.impulse(0.0, 4.9) == 0.0);
  }
  SECTION("COR = 0.75") {
    const ExactSolution x(model_of(0.0, 0.75), init);
    CHECK(x.at(7.0).u == 1.5);
    CHECK(x.at(7.0).v == 0.75);
    CHECK(x.impulse(0.0, 10.0) == 1.75);
    CHECK_FALSE(x.rest_time());
  }
  SECTION("plastic: COR = 0") {
    const ExactSolution x(model_of(0.0, 0.0), init);
    REQUIRE(x.rest_time());
    CHECK(*x.rest_time() == 5.0);
    CHECK(x.at(7.0).u == 0.0);
    CHECK(x.at(7.0).v == 0.0);
    CHECK(x.impulse(0.0, 10.0) == 1.0);  // no force: resting costs no impulse
  }
}

TEST_CASE("exact: first impact under gravity matches the hand-derived root", "[exact]") {
  // u0 = 5, v0 = -1, f = -9.80665: 5 - t - 9.80665 t^2 / 2 = 0. By hand (40 digits, mpmath):
  // V1 = sqrt(v0^2 + 2 * 9.80665 * 5) = sqrt(99.0665) = 9.953215560812495534826930...,
  // t1 = (v0 + V1) / 9.80665 = 8.953215560812495534... / 9.80665 = 0.912973906564677594777720...
  const double V1 = 9.9532155608124955348;
  const double t1 = 0.91297390656467759478;
  const ExactSolution x(model_of(-kG), State{5.0, -1.0});
  REQUIRE(x.impact_time(1));
  // The code's t1 = 2 d / (V1 - v0) is fma, sqrt, subtract, multiply, divide: each within half an
  // ulp, so a few ulp in all; the literal itself is within half an ulp.
  CHECK_NEAR(*x.impact_time(1), t1, 4 * kEps * t1);
  CHECK_NEAR(*x.impact_speed(1), V1, 2 * kEps * V1);  // fma + sqrt: within an ulp
  // Elastic: the second impact is one flight 2 V1 / g later.
  CHECK_NEAR(*x.impact_time(2), t1 + 2 * V1 / kG, 8 * kEps * (t1 + 2 * V1 / kG));
  CHECK(x.impacts_until(before(*x.impact_time(1))) == 0);
  CHECK(x.impacts_until(*x.impact_time(1)) == 1);
  // At the impact the particle is on the floor, moving up with V1.
  CHECK(x.at(*x.impact_time(1)).u == 0.0);
  CHECK(x.at(*x.impact_time(1)).v == *x.impact_speed(1));
  CHECK_NEAR(x.at(before(*x.impact_time(1))).v, -V1, 4 * kEps * V1);
  CHECK_FALSE(x.rest_time());  // elastic: bounces forever
}

TEST_CASE("exact: apex after impact k is (e^k V1)^2 / (2 |f|) above phi", "[exact]") {
  const double phi = 2.0, e = 0.75;
  const ExactSolution x(model_of(-kG, e, phi), State{phi + 5.0, -1.0});
  // By hand: V1^2 = 1 + 2 * 9.80665 * 5 = 99.0665, so the first apex is
  // 0.75^2 * 99.0665 / (2 * 9.80665) = 2.841179518490004372...
  const double t1 = *x.impact_time(1);
  CHECK_NEAR(x.at(t1 + e * *x.impact_speed(1) / kG).u - phi, 2.8411795184900043720,
             8 * kEps * (phi + 2.85));
  const double V1 = *x.impact_speed(1);
  for (std::int64_t k = 1; k <= 30; ++k) {
    const double w = std::pow(e, static_cast<double>(k)) * V1;  // leaves impact k with e^k V1
    const double t_apex = *x.impact_time(k) + w / kG;
    const State s = x.at(t_apex);
    INFO("k = " << k);
    // At the apex u is stationary in t, so the rounding of t_apex (an ulp of t) enters only to
    // second order; what is left is a few roundings of the gap and of phi + gap.
    CHECK_NEAR(s.u - phi, w * w / (2 * kG), 8 * kEps * (phi + w * w / (2 * kG)));
    // v = w - g tau moves at rate g: an error of a few ulp of t in tau, plus roundings of w.
    CHECK_NEAR(s.v, 0.0, 4 * kG * ulp(t_apex) + 4 * kEps * w);
  }
}

TEST_CASE("exact: Zeno time and resting state for COR = 0.75", "[exact]") {
  const double e = 0.75;
  const ExactSolution x(model_of(-kG, e), State{5.0, -1.0});
  // By hand (mpmath, 40 digits) with t1 and V1 of the gravity test above:
  // t_inf = t1 + 2 e V1 / (g (1 - e)) = 0.91297390656467759 + 6 * 9.95321556081249553 / 9.80665
  //       = 7.002647073739500109...
  const double t_inf = 7.0026470737395001090;
  REQUIRE(x.rest_time());
  // t1 + (2 V1 / g) (e / (1 - e)): a handful of roundings on terms of the size of t_inf.
  CHECK_NEAR(*x.rest_time(), t_inf, 8 * kEps * t_inf);
  const double tz = *x.rest_time();
  const double V1 = *x.impact_speed(1);

  // The impact times accumulate at t_inf from below.
  CHECK(*x.impact_time(2) < *x.impact_time(3));
  CHECK(*x.impact_time(200) <= tz);
  CHECK_NEAR(*x.impact_time(200), tz, 4 * ulp(tz));  // 0.75^199 of the span: below an ulp
  // Impact speeds e^(k-1) V1.
  CHECK_NEAR(*x.impact_speed(6), std::pow(e, 5.0) * V1, 4 * kEps * V1);

  // Before t_inf the count is finite; from t_inf on, the documented cap.
  CHECK(x.impacts_until(before(tz)) > 50);
  CHECK(x.impacts_until(before(tz)) < 1000);
  CHECK(x.impacts_until(tz) == kZenoCount);
  CHECK(x.impacts_until(tz + 100.0) == kZenoCount);

  // At rest on the floor: u = phi, v = 0, N = -f.
  for (const double t : {tz, tz + 1e-9, tz + 1.0, tz + 1e4}) {
    CHECK(x.at(t).u == 0.0);
    CHECK(x.at(t).v == 0.0);
  }
  // -f (b - a) is one multiplication: half an ulp of the result.
  CHECK_NEAR(x.impulse(tz + 1.0, tz + 3.0), 2.0 * kG, kEps * 2.0 * kG);
  CHECK_NEAR(x.impulse(tz, tz + 0.5), 0.5 * kG, kEps * 0.5 * kG);
  // An interval over t_inf: the infinitely many impacts after the 5th form the geometric tail
  // sum_{k>=6} (1 + e) e^(k-1) V1 = (1 + e) e^5 V1 / (1 - e), plus the rest after t_inf.
  const double tail = (1 + e) * std::pow(e, 5.0) * V1 / (1 - e);
  CHECK_NEAR(x.impulse(*x.impact_time(5), tz + 1.0), tail + kG * 1.0,
             16 * kEps * (tail + kG + kG * tz));
  // Everything: the total of all impacts is (1 + e) V1 / (1 - e).
  CHECK_NEAR(x.impulse(0.0, tz), (1 + e) * V1 / (1 - e), 16 * kEps * (1 + e) * V1 / (1 - e));

  SECTION("plastic: COR = 0 rests from the first impact") {
    const ExactSolution p(model_of(-kG, 0.0), State{5.0, -1.0});
    REQUIRE(p.rest_time());
    CHECK(*p.rest_time() == *p.impact_time(1));
    CHECK_FALSE(p.impact_time(2));
    CHECK(p.impacts_until(100.0) == 1);
    CHECK(p.at(*p.rest_time()).u == 0.0);
    CHECK(p.at(*p.rest_time()).v == 0.0);
  }
}

TEST_CASE("exact: elastic energy is conserved, also after 1e4 bounces", "[exact]") {
  for (const double phi : {0.0, 3.0}) {
    const Model m = model_of(-kG, std::nullopt, phi);
    const ExactSolution x(m, State{phi + 5.0, -1.0});
    const double E0 = energy(m, State{phi + 5.0, -1.0});
    const double T = *x.impact_time(10001) + 0.3;  // 1e4 bounces and then some
    const int n = 100003;                          // prime: the samples hit every phase
    double worst = 0.0;
    for (int j = 0; j <= n; ++j) {
      const double t = T * j / n;
      worst = std::max(worst, std::fabs(energy(m, x.at(t)) - E0) / std::fabs(E0));
    }
    // In a flight u and v come from one tau and lie on the level V1^2/2 - f phi whatever the
    // rounding of tau; all terms of E are positive here, so the error is a few roundings: a few
    // ulp of E0, far below the required 1e-12.
    INFO("phi = " << phi << ", worst relative energy error = " << worst);
    CHECK(worst <= 16 * kEps);
    CHECK(worst <= 1e-12);
  }
}

TEST_CASE("exact: energy strictly decreases across impacts when COR < 1", "[exact]") {
  for (const double e : {0.75, 0.99}) {
    const Model m = model_of(-kG, e);
    const ExactSolution x(m, State{5.0, -1.0});
    // Energy (3-1) in the flight after impact k, sampled at its midpoint; flight 0 is the drop.
    const auto flight_energy = [&](std::int64_t k) {
      const double a = k == 0 ? 0.0 : *x.impact_time(k);
      return energy(m, x.at(0.5 * (a + *x.impact_time(k + 1))));
    };
    double E_prev = flight_energy(0);
    for (std::int64_t k = 1; k <= 40; ++k) {
      const double E = flight_energy(k);
      INFO("e = " << e << ", k = " << k);
      CHECK(E < E_prev);
      // With phi = 0, E = v^2 / 2 - f u is all kinetic at the floor: each impact scales it by e^2.
      CHECK_NEAR(E / E_prev, e * e, 16 * kEps);
      E_prev = E;
    }
  }
}

TEST_CASE("exact: impulse identity impulse(0, T) = v(T) - v(0) - f T", "[exact]") {
  struct Case {
    const char* name;
    Model model;
    State init;
  };
  const std::vector<Case> cases = {
      {"elastic, gravity", model_of(-kG), {5.0, -1.0}},
      {"COR 0.75, gravity", model_of(-kG, 0.75), {5.0, -1.0}},
      {"COR 0.99, gravity, thrown up", model_of(-kG, 0.99), {1.0, 3.0}},
      {"COR 0, gravity", model_of(-kG, 0.0), {5.0, -1.0}},
      {"no force", model_of(0.0, 0.5), {5.0, -1.0}},
      {"upward force, reaches the floor", model_of(1.0, 0.5), {1.0, -3.0}},
      {"upward force, turns back", model_of(1.0), {1.0, -1.0}},
      {"on the floor, moving down", model_of(-kG, 0.75, 1.0), {1.0, -2.0}},
      {"on the floor, at rest", model_of(-kG, std::nullopt, 1.0), {1.0, 0.0}},
      {"far floor", model_of(-kG, 0.9, 1e6), {1e6 + 1e-3, -1e-2}},
  };
  for (const auto& c : cases) {
    const ExactSolution x(c.model, c.init);
    const double f = c.model.f;
    for (const double T : {0.1, 0.5, 1.0, 2.5, 5.0, 7.0, 10.0, 30.0, 100.0}) {
      const State s = x.at(T);
      const double J = x.impulse(0.0, T);
      // Both sides are a few rounded terms: J is a closed form of a handful of operations, the
      // right side three terms; so a few ulp of the largest magnitude involved.
      const double scale = std::fabs(s.v) + std::fabs(c.init.v) + std::fabs(f) * T + J;
      INFO(c.name << ", T = " << T);
      CHECK_NEAR(J, s.v - c.init.v - f * T, 16 * kEps * scale);
      CHECK(J >= 0.0);  // N >= 0 (2-2)
    }
  }
  SECTION("exactly zero in flight") {
    const ExactSolution x(model_of(-kG), State{5.0, -1.0});
    for (std::int64_t k = 1; k < 1000; k += 37) {
      const double a = *x.impact_time(k), b = *x.impact_time(k + 1);
      CHECK(x.impulse(a, before(b)) == 0.0);  // (t_k, t_{k+1}) holds no impact
      CHECK(x.impulse(a + 0.1, a + 0.2) == 0.0);
      CHECK(x.impulse(before(b), b) == 2.0 * *x.impact_speed(k + 1));
    }
    CHECK(x.impulse(0.0, before(*x.impact_time(1))) == 0.0);
    CHECK(x.impulse(3.0, 3.0) == 0.0);  // empty interval
    CHECK(x.impulse(3.0, 2.0) == 0.0);
  }
  SECTION("the stepper's N^l add up to the identity (4-9)") {
    // The paper's run (Section 5.2): T = 10, h = 0.001, here with gravity and COR = 0.75.
    const Model m = model_of(-kG, 0.75);
    const State init{5.0, -1.0};
    const double h = 0.001;
    const std::int64_t n = 10000;
    ExactStepper stepper(m, h, impact::ExactParams{});
    State s = init;
    stepper.initialize(s, 0);
    double sum = 0.0;
    for (std::int64_t l = 0; l < n; ++l) sum += h * stepper.do_step(s, l).contact_force;
    // 1e4 additions, each rounding within an ulp of the running sum (and N^l h rounded twice).
    const double T = static_cast<double>(n) * h;
    CHECK_NEAR(sum, s.v - init.v - m.f * T, 2.0 * n * kEps * (1.0 + kG * T));
  }
}

TEST_CASE("exact: a particle starting on the floor with v0 < 0 impacts at 0+", "[exact]") {
  const double phi = 1.0, h = 1e-3;
  const ExactSolution x(model_of(-kG, std::nullopt, phi), State{phi, -2.0});
  REQUIRE(x.impact_time(1));
  CHECK(*x.impact_time(1) == 0.0);   // 2 d / (V1 - v0) with d = 0
  CHECK(*x.impact_speed(1) == 2.0);  // sqrt(v0^2) = |v0| exactly
  // at(0) is the initial state; the impact counts in (0, t] for every t > 0.
  CHECK(x.at(0.0).u == phi);
  CHECK(x.at(0.0).v == -2.0);
  CHECK(x.impacts_until(0.0) == 0);
  CHECK(x.impacts_until(1e-300) == 1);
  CHECK(x.impulse(0.0, h) == 4.0);  // (1 + e) V1 in the first step, nothing more
  CHECK(x.impulse(h, 2 * h) == 0.0);
  CHECK_NEAR(x.at(h).v, 2.0 - kG * h, 2 * kEps * 2.0);
  CHECK_NEAR(x.at(h).u, phi + h * (2.0 - 0.5 * kG * h), 2 * kEps * phi);
  // The next impact after one flight 2 V1 / g = 4 / 9.80665 = 0.40788648519117129703 (by hand).
  CHECK_NEAR(*x.impact_time(2), 0.40788648519117129703, 2 * kEps);

  SECTION("no force") {
    const ExactSolution y(model_of(0.0, std::nullopt, phi), State{phi, -2.0});
    CHECK(*y.impact_time(1) == 0.0);
    CHECK(y.at(1.0).u == phi + 2.0);
    CHECK(y.at(1.0).v == 2.0);
  }
  SECTION("upward force, plastic: it lifts off from rest") {
    const ExactSolution y(model_of(1.0, 0.0, phi), State{phi, -2.0});
    CHECK(*y.impact_time(1) == 0.0);
    CHECK_FALSE(y.rest_time());
    CHECK(y.at(2.0).u == phi + 2.0);  // f t^2 / 2
    CHECK(y.at(2.0).v == 2.0);
    CHECK(y.impulse(0.0, 1.0) == 2.0);
  }
}

TEST_CASE("exact: resting, lifting and grazing starts", "[exact]") {
  const double phi = -3.0;
  SECTION("on the floor at rest under gravity: resting from t = 0") {
    const ExactSolution x(model_of(-kG, 0.75, phi), State{phi, 0.0});
    REQUIRE(x.rest_time());
    CHECK(*x.rest_time() == 0.0);
    CHECK_FALSE(x.impact_time(1));
    CHECK(x.impacts_until(10.0) == 0);
    CHECK(x.at(1.0).u == phi);
    CHECK(x.at(1.0).v == 0.0);
    CHECK(x.impulse(0.0, 2.0) == kG * 2.0);  // N = -f over (0, 2]
    CHECK(x.impulse(-1.0, 0.0) == 0.0);
  }
  SECTION("on the floor at rest, no force") {
    const ExactSolution x(model_of(0.0, std::nullopt, phi), State{phi, 0.0});
    CHECK(x.at(5.0).u == phi);
    CHECK(x.at(5.0).v == 0.0);
    CHECK(x.impulse(0.0, 5.0) == 0.0);
  }
  SECTION("leaving the floor: no impact unless a downward force brings it back") {
    const ExactSolution free(model_of(0.0, std::nullopt, phi), State{phi, 1.0});
    CHECK_FALSE(free.impact_time(1));
    CHECK(free.at(2.0).u == phi + 2.0);
    const ExactSolution pushed(model_of(1.0, std::nullopt, phi), State{phi, 0.0});
    CHECK_FALSE(pushed.impact_time(1));
    CHECK(pushed.at(2.0).u == phi + 2.0);
    CHECK(pushed.at(2.0).v == 2.0);
    const ExactSolution thrown(model_of(-kG, std::nullopt, phi), State{phi, 1.0});
    // (v0 + V1) / g with V1 = v0: 2 / 9.80665 = 0.20394324259558564851 (by hand).
    CHECK_NEAR(*thrown.impact_time(1), 0.20394324259558564851, 2 * kEps * 0.2);
    CHECK(*thrown.impact_speed(1) == 1.0);
  }
  SECTION("grazing: reaching the floor with zero speed is no impact") {
    // f = 1, v0 = -2, d = 2: v0^2 = 2 f d, so u - phi = (t - 2)^2 / 2 touches 0 at t = 2.
    const ExactSolution x(model_of(1.0, std::nullopt, phi), State{phi + 2.0, -2.0});
    CHECK_FALSE(x.impact_time(1));
    CHECK(x.at(2.0).u == phi);
    CHECK(x.at(2.0).v == 0.0);
    CHECK(x.at(4.0).u == phi + 2.0);
    CHECK(x.impulse(0.0, 10.0) == 0.0);
  }
}

TEST_CASE("exact: a far floor and tiny offsets do not cancel", "[exact]") {
  // Reference: the same closed forms in long double (64-bit significand, 11 more bits), from the
  // same double data; the gap d = u0 - phi is exact in both (Sterbenz). A double result within a
  // few ulp of it has lost nothing to cancellation; the textbook root (v0 + sqrt(v0^2 + 2 g d)) / g
  // with v0 = -1 and d = 2^-30 would lose about 30 bits.
  using LD = long double;
  const double phi = 1e6, d = std::ldexp(1.0, -30);  // ulp(1e6) = 2^-33: u0 = phi + d is exact
  struct Case {
    double f, v0;
  };
  for (const Case c : {Case{-kG, -1.0}, Case{-kG, -1e-7}, Case{-kG, 1e-7}, Case{-kG, -1e-300},
                       Case{0.0, -1e-7}, Case{1.0, -1e-4}, Case{1e8, -1.0}}) {
    const ExactSolution x(model_of(c.f, std::nullopt, phi), State{phi + d, c.v0});
    const LD ld = static_cast<LD>(phi + d) - static_cast<LD>(phi), v0 = c.v0, f = c.f;
    const LD V = std::sqrt(v0 * v0 - 2 * f * ld);
    const LD t1 = (f < 0 && v0 >= 0) ? (v0 + V) / -f : 2 * ld / (V - v0);
    INFO("f = " << c.f << ", v0 = " << c.v0);
    REQUIRE(x.impact_time(1));
    CHECK_NEAR(*x.impact_time(1), static_cast<double>(t1), 4 * kEps * static_cast<double>(t1));
    CHECK_NEAR(*x.impact_speed(1), static_cast<double>(V), 2 * kEps * static_cast<double>(V));
    // Halfway down the gap is exact to a few ulp of itself; u = phi + gap adds one rounding of
    // u, half an ulp of phi.
    const double th = 0.5 * *x.impact_time(1);
    const LD gap = ld + th * (v0 + 0.5L * f * th);
    CHECK_NEAR(x.at(th).u, static_cast<double>(phi + gap), ulp(phi));
    CHECK(x.at(th).u >= phi);
  }
  SECTION("tiny gap and tiny speed near underflow") {
    const double dt = 1e-300, v0 = -1e-200;  // v0^2 underflows; fma keeps it exactly
    const ExactSolution x(model_of(-kG), State{dt, v0});
    const LD V = std::sqrt(static_cast<LD>(v0) * v0 + 2 * static_cast<LD>(kG) * dt);
    const LD t1 = 2 * static_cast<LD>(dt) / (V - v0);
    CHECK_NEAR(*x.impact_speed(1), static_cast<double>(V), 2 * kEps * static_cast<double>(V));
    CHECK_NEAR(*x.impact_time(1), static_cast<double>(t1), 4 * kEps * static_cast<double>(t1));
  }
}

TEST_CASE("exact: u is continuous across impacts", "[exact]") {
  const double phi = 3.0;
  for (const std::optional<double> cor : {std::optional<double>{}, std::optional<double>{0.75}}) {
    const ExactSolution x(model_of(-kG, cor, phi), State{phi + 5.0, -1.0});
    const double e = cor.value_or(1.0);
    const std::vector<std::int64_t> ks =
        cor ? std::vector<std::int64_t>{1, 2, 3, 10, 20, 40}
            : std::vector<std::int64_t>{1, 2, 3, 10, 100, 1000, 10000};
    for (const std::int64_t k : ks) {
      const double tk = *x.impact_time(k), Vk = *x.impact_speed(k);
      const State l = x.at(before(tk)), r = x.at(tk);
      INFO("COR = " << e << ", k = " << k);
      CHECK(r.u == phi);
      CHECK(r.v == e * Vk);
      // Left of t_k the flight that ends there has tau with the roundings of t_{k-1} and t_k (an
      // ulp of t_k each), at speed V_k; and w - g tau / 2 cancels to O(eps w) there, times
      // tau = 2 w / g: a few eps of the apex height. Plus the rounding of phi + gap.
      const double apex = Vk * Vk / (2 * kG);
      CHECK_NEAR(l.u, r.u, 4 * Vk * ulp(tk) + 8 * kEps * (apex + phi));
      CHECK_NEAR(l.v, -Vk, 4 * kG * ulp(tk) + 4 * kEps * Vk);
    }
  }
}

TEST_CASE("exact: impact times do not drift and at(), impacts_until() agree", "[exact]") {
  SECTION("elastic: t_k = t1 + (k - 1) 2 V1 / g after 1e4 bounces") {
    const ExactSolution x(model_of(-kG), State{5.0, -1.0});
    using LD = long double;
    const LD t1 = *x.impact_time(1), P = 2 * static_cast<LD>(*x.impact_speed(1)) / kG;
    for (const std::int64_t k : {2, 10, 1000, 10001, 1000000}) {
      const double tk = *x.impact_time(k);
      // One multiplication and one addition from t1 and the period: an ulp or so of t_k; an
      // accumulated sum of flight times would be off by about k ulp.
      CHECK_NEAR(tk, static_cast<double>(t1 + (k - 1) * P), 2 * ulp(tk));
      CHECK(x.impacts_until(tk) == k);
      CHECK(x.impacts_until(before(tk)) == k - 1);
      CHECK(x.at(tk).u == 0.0);
    }
  }
  SECTION("COR 0.75: counting matches the closed-form times up to t_inf") {
    const ExactSolution x(model_of(-kG, 0.75), State{5.0, -1.0});
    for (std::int64_t k = 1; k <= 120; ++k) {
      const double tk = *x.impact_time(k);
      if (k > 1 && tk == *x.impact_time(k - 1)) break;  // indistinguishable in double from here
      INFO("k = " << k);
      CHECK(x.impacts_until(tk) >= k);
      CHECK(x.impacts_until(before(tk)) < k);
    }
  }
  SECTION("COR close to 1: expm1 / log1p keep the closed forms accurate") {
    const double e = 1.0 - 1e-9;
    const ExactSolution x(model_of(-kG, e), State{5.0, -1.0});
    using LD = long double;
    const LD t1 = *x.impact_time(1), V1 = *x.impact_speed(1), g = kG, E = e;
    const LD zeno = t1 + 2 * V1 * E / (g * (1 - E));
    REQUIRE(x.rest_time());
    // (1 - e) is exact (Sterbenz), so t_inf carries a few roundings: a few ulp.
    CHECK_NEAR(*x.rest_time(), static_cast<double>(zeno), 8 * ulp(*x.rest_time()));
    for (const std::int64_t k : {2, 3, 10, 1000, 1000000, 1000000000}) {
      const LD m = k - 1;
      const LD tk = t1 + (2 * V1 / g) * E * -std::expm1(m * std::log1p(E - 1)) / (1 - E);
      // The exponent (k - 1) log e is rounded to an ulp of itself, at most k |log e| eps <= 1e-16
      // here: a few ulp of t_k in all.
      INFO("k = " << k);
      CHECK_NEAR(*x.impact_time(k), static_cast<double>(tk), 8 * ulp(*x.impact_time(k)));
      CHECK(x.impacts_until(*x.impact_time(k)) == k);
    }
    // Two impacts: (1 + e) V1 (1 + e); the naive e^0 - e^2 over 1 - e would lose 9 digits.
    const double J = x.impulse(0.0, *x.impact_time(2));
    CHECK_NEAR(J, (1 + e) * *x.impact_speed(1) * (1 + e), 8 * kEps * J);
  }
}

TEST_CASE("exact: extreme data give finite, feasible values", "[exact]") {
  const std::vector<std::optional<double>> cors = {std::nullopt, 0.0, 0.5, 0.75, 1.0 - 1e-12};
  for (const double v0 : {-1e8, -1.0, 0.0, 1e-3, 1e8})
    for (const double f : {-1e8, -kG, 0.0, 1.0, 1e8})
      for (const double phi : {-1e6, 0.0, 1e6})
        for (const double d : {0.0, 1e-12, 1.0, 1e6})
          for (const auto& cor : cors) {
            const ExactSolution x(model_of(f, cor, phi), State{phi + d, v0});
            std::vector<double> ts = {0.0, 1e-9, 1.0, 1e3};
            for (const std::int64_t k : {1, 2, 3, 100, 10001}) {
              if (const auto tk = x.impact_time(k)) {
                ts.push_back(*tk);
                ts.push_back(before(*tk));
                ts.push_back(*tk * 1.5 + 1e-3);
              }
            }
            if (x.rest_time()) {
              ts.push_back(*x.rest_time());
              ts.push_back(before(*x.rest_time()));
              ts.push_back(*x.rest_time() * 2.0 + 1.0);
            }
            for (const double t : ts) {
              const State s = x.at(t);
              const double J = x.impulse(0.0, t);
              if (!(std::isfinite(s.u) && std::isfinite(s.v) && std::isfinite(J) && s.u >= phi &&
                    J >= 0.0)) {
                INFO(std::setprecision(17)
                     << "v0 = " << v0 << ", f = " << f << ", phi = " << phi << ", d = " << d
                     << ", cor = " << cor.value_or(-1) << ", t = " << t << ": u = " << s.u
                     << ", v = " << s.v << ", J = " << J);
                FAIL_CHECK("non-finite or infeasible value");
              }
            }
          }
}

TEST_CASE("exact: invalid data is rejected", "[exact]") {
  CHECK_THROWS_AS(ExactSolution(model_of(-kG), State{-1.0, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(ExactSolution(model_of(-kG, 1.5), State{1.0, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(ExactSolution(model_of(-kG, -0.1), State{1.0, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(ExactSolution(model_of(std::nan("")), State{1.0, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(ExactSolution(model_of(-kG), State{1.0, INFINITY}), std::invalid_argument);
}
