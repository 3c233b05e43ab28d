// The exact reference solution (exact.hpp) at its edges: starts on the floor (an impact at 0+,
// resting, lifting, grazing), a far floor and tiny offsets, continuity across impacts, impact
// times that do not drift, extreme data and invalid data.
#include "exact_support.hpp"

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
