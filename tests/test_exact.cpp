// The exact reference solution (exact.hpp) against values derived by hand, against long-double
// evaluations of the same closed forms, and against the identities it must satisfy: energy (3-1)
// and the impulse identity (4-9). Tolerances are stated as a few ulp of the magnitudes involved,
// with the reason next to each.
// The starts on the floor, far floors, continuity, drift and extreme or invalid data are in
// test_exact_edges.cpp.
#include "exact_support.hpp"

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
