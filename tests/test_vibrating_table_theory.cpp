// The closed forms of paper_notes/vibrating_table.md (period-1 orbits of the ball on a vibrating
// table, their existence and period-doubling thresholds) against the exact impact map computed
// numerically: the closed-form flight, a bracketed first root refined by GSL, a GSL multiroot
// fixed point and a finite-difference Jacobian.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <optional>

#include "analysis/vibrating_table/vibrating_table_theory.hpp"

using namespace impact;
using namespace impact::vibrating_table;

namespace {

constexpr double kPi = std::numbers::pi;

double trace(const std::array<double, 4>& m) {
  return m[0] + m[3];
}
double det(const std::array<double, 4>& m) {
  return m[0] * m[3] - m[1] * m[2];
}

}  // namespace

TEST_CASE("vibrating table: the thresholds' closed forms at e = 0.5 and 0.8", "[vibrating_table]") {
  CHECK(period_one_existence_threshold(0.5, 1) == Approx(kPi / 3).epsilon(1e-15));
  CHECK(period_one_existence_threshold(0.5, 1) == Approx(1.047198).margin(5e-7));
  CHECK(period_doubling_threshold(0.5, 1) == Approx(1.526824).margin(5e-7));
  CHECK(period_one_existence_threshold(0.8, 1) == Approx(0.349066).margin(5e-7));
  CHECK(period_doubling_threshold(0.8, 1) == Approx(1.070836).margin(5e-7));
  CHECK(period_one_existence_threshold(1.0, 1) == 0.0);
  CHECK_FALSE(period_one_orbit(1.0, 0.5, 1));  // below Gamma_1 = 1.047
  // At Gamma_1 the two branches meet with an eigenvalue 1 (saddle-node); at Gamma_pd the stable
  // one has an eigenvalue -1; the determinant is e^2 everywhere (the impact loses 1 - e^2 of the
  // phase-space area).
  for (double e : {0.5, 0.8})
    for (int n : {1, 2}) {
      const auto at_g1 = period_one_orbit(period_one_existence_threshold(e, n), e, n);
      REQUIRE(at_g1);
      CHECK(std::abs(at_g1->eigenvalues[1] - 1.0) < 1e-12);
      const auto at_pd = period_one_orbit(period_doubling_threshold(e, n), e, n);
      REQUIRE(at_pd);
      CHECK(std::abs(at_pd->eigenvalues[0] + 1.0) < 1e-7);
      CHECK(det(at_pd->jacobian) == Approx(e * e).epsilon(1e-12));
    }
}

TEST_CASE(
    "vibrating table: one step of the exact impact map returns the closed-form period-1 orbit",
    "[vibrating_table]") {
  for (double e : {0.5, 0.8})
    for (int n : {1, 2}) {
      const double g1 = period_one_existence_threshold(e, n), gpd = period_doubling_threshold(e, n);
      for (double x : {0.05, 0.5, 0.95}) {
        const double gamma = g1 + x * (gpd - g1);
        INFO("e = " << e << ", n = " << n << ", Gamma = " << gamma);
        const auto orbit = period_one_orbit(gamma, e, n);
        REQUIRE(orbit);
        const auto step = impact_map(orbit->impact, gamma, e);
        REQUIRE(step);
        // The flight is the first root of u: 2 pi n, not an earlier touch of the table. Brent
        // stops at a few ulp of the root; the take-off speed carries that through u' ~ 1.
        CHECK(step->flight == Approx(2 * kPi * n).epsilon(1e-13));
        CHECK(step->next.phase == Approx(orbit->impact.phase).margin(1e-11));
        CHECK(step->next.speed == Approx(orbit->impact.speed).epsilon(1e-11));
        // The saddle branch is a fixed point too.
        const auto saddle = period_one_orbit(gamma, e, n, false);
        const auto saddle_step = impact_map(saddle->impact, gamma, e);
        REQUIRE(saddle_step);
        CHECK(saddle_step->flight == Approx(2 * kPi * n).epsilon(1e-13));
      }
    }
}

TEST_CASE(
    "vibrating table: the GSL fixed point and the finite-difference Jacobian of the exact map "
    "match "
    "the closed forms",
    "[vibrating_table]") {
  for (double e : {0.5, 0.8})
    for (int n : {1, 2}) {
      const double g1 = period_one_existence_threshold(e, n), gpd = period_doubling_threshold(e, n);
      for (double x : {0.1, 0.5, 0.9, 1.1}) {
        const double gamma = g1 + x * (gpd - g1);
        INFO("e = " << e << ", n = " << n << ", Gamma = " << gamma);
        const auto orbit = period_one_orbit(gamma, e, n);
        REQUIRE(orbit);
        const auto fixed =
            map_fixed_point({orbit->impact.phase + 0.05, orbit->impact.speed * 1.02}, gamma, e, n);
        REQUIRE(fixed);
        // The solver stops at a residual of 1e-13; I - J has no eigenvalue below ~0.05 here.
        CHECK(fixed->phase == Approx(orbit->impact.phase).margin(1e-10));
        CHECK(fixed->speed == Approx(orbit->impact.speed).epsilon(1e-10));
        // Central differences with step 1e-5: truncation ~ 1e-10 x the map's third derivative,
        // rounding ~ 1e-16 / 1e-5; each entry to 1e-7 of the matrix' scale.
        const std::array<double, 4> numeric = map_jacobian(*fixed, gamma, e);
        for (int k = 0; k < 4; ++k) CHECK(numeric[k] == Approx(orbit->jacobian[k]).margin(1e-7));
        CHECK(trace(numeric) == Approx(trace(orbit->jacobian)).margin(1e-7));
        CHECK(det(numeric) == Approx(e * e).margin(1e-7));
      }
    }
}

TEST_CASE("vibrating table: the period-doubling threshold of the numeric map is the closed form",
          "[vibrating_table]") {
  for (double e : {0.5, 0.8}) {
    const double g1 = period_one_existence_threshold(e, 1);
    const double numeric = numeric_period_doubling_threshold(e, 1, g1 + 0.01, 0.05);
    // 1 + trace + det from the finite-difference Jacobian carries ~1e-9; its slope in Gamma is
    // of order 1, so the root is good to ~1e-8.
    CHECK(numeric == Approx(period_doubling_threshold(e, 1)).margin(1e-7));
  }
}
