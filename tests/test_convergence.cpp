// Section 4 (existence proof): convergence of u_h of (4-1)-(4-3) as h -> 0, the effective COR of
// an impact, the identities (4-9) and (4-10), and the numbers of
// experiments/convergence/reference.toml. Every run goes through the experiment's own functions
// (src/analysis/convergence/convergence_study.hpp): the cheap run is the experiment's first rows (h
// >= 1e-4, at most 1e5 steps per run), the dense runs sweep h >= 1e-4 finely enough to fit an
// order.
#include <toml++/toml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/convergence/convergence_study.hpp"
#include "analysis/convergence/proof_tallies.hpp"
#include "analysis/fit.hpp"
#include "analysis/reference.hpp"
#include "impact/steppers/direct.hpp"

using namespace impact;
using namespace impact::convergence;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kGravity = 9.80665;
constexpr double kT = kConvergenceT;

// run_series of the series of `options`, each run once for all the test cases.
struct SeriesRuns {
  ConvergenceOptions options;
  std::map<std::string, SeriesRun> runs;

  const SeriesRun& operator()(const std::string& name) {
    if (!runs.contains(name))
      for (const ConvergenceSeries& s : convergence_series(options))
        if (s.name == name) runs.emplace(name, run_series(s));
    return runs.at(name);
  }
};
// The experiment's first rows: every series and subsequence with h >= 1e-4.
SeriesRuns cheap{{.h_floor = 1e-4}, {}};
// h from 2e-2 to 1e-4, 400 values with f = 0 and 100 under gravity: enough points that a fitted
// order has a standard error of at most 0.05 (the errors scatter with theta, see check_order).
SeriesRuns dense{{.free = {2e-2, 1e-4, 400}, .gravity = {2e-2, 1e-4, 100}}, {}};

// Rounding of a position (a few ulp of |u| <= 5 m) enters the rebound velocity through (4-2),
// v^{l+1} = 2 (phi - u^l) / h - v^l, multiplied by 2 / h, and then acts over T = 10 s: 2 * 5e-15
// * 10 / h = 1e-13 / h [m]. The same bound, without the factor T, covers theta and the effective
// COR (dimensionless, 1e-14 / h), and 1e-12 covers what does not pass through 2 / h.
double rounding_tolerance(double h) {
  return 1e-13 / h + 1e-12;
}

// A fitted order is as precise as the errors lie on a power law. With f = 0 and a COR the error
// is e |v0| (1 - theta) h (the bound of the next test case is its largest value), theta the
// position of the impact in its step, which jumps erratically with h; under gravity each impact
// adds such a term. So the order of a series has
// a standard error, and a claimed order p is checked as |order - p| <= 0.1 on a grid where that
// standard error is at most 0.05: 0.1 is two standard errors, and orders 0 and 1 stay more than
// 18 of them apart.
void check_order(const OrderFit& fit, double p) {
  INFO("order " << fit.order << " +- " << fit.order_standard_error << " over " << fit.points
                << " points, h in [" << fit.h_min << ", " << fit.h_max << "]");
  CHECK(fit.order_standard_error <= 0.05);
  CHECK(std::fabs(fit.order - p) <= 0.1);
}

// The cheap run gives the experiment's first rows, not what sums up its whole range of h: the
// fits and extremes of each series and subsequence (every key but the arrays and the data that
// do not depend on h) are left out.
ReferenceRule cheap_rule(const toml::table& reference) {
  ReferenceRule rule;
  rule.measured_prefix = true;
  for (const char* group : {"series", "subsequences"})
    for (auto&& [name, node] : *reference[group].as_table())
      for (auto&& [key, value] : *node.as_table()) {
        const std::string_view k = key.str();
        if (!value.is_array() && k != "label" && k != "theta" && k != "limit_cor" &&
            k != "limit_distance_to_elastic")
          rule.skip.push_back(std::string(group) + "." + std::string(name.str()) + "." +
                              std::string(k));
      }
  return rule;
}

}  // namespace

TEST_CASE("convergence: the experiment's first rows (h >= 1e-4) match reference.toml",
          "[convergence][regression]") {
  const toml::table measured =
      run_convergence(ExperimentContext{IMPACT_SOURCE_DIR, ""}, cheap.options);
  const toml::table reference = read_reference(IMPACT_SOURCE_DIR, "convergence");
  for (const char* group : {"series", "subsequences"})
    for (auto&& [name, node] : *measured[group].as_table()) {
      INFO(name.str());
      CHECK((*node.as_table())["h"].as_array()->size() >= 7);
    }
  for (const std::string& difference :
       compare_with_reference(measured, reference, cheap_rule(reference)))
    FAIL_CHECK(difference);
}

TEST_CASE("C25: with a COR the direct scheme converges at first order with sup error <= COR |v0| h",
          "[claim][convergence]") {
  // f = 0, COR = 0.75, impact at t* in (t_m, t_{m+1}]: the exact particle leaves the floor at t*
  // with e |v0| and is e |v0| (t_{m+1} - t*) <= e |v0| h above it at t_{m+1}, where the scheme
  // is at phi with the same velocity e |v0| (Section 5.2's reset). From then on both fly alike.
  for (const ConvergencePoint& p : cheap("f0_direct_cor").points) {
    INFO("h = " << p.h);
    CHECK(p.errors.sup_u <= 0.75 * 1.0 * p.h + rounding_tolerance(p.h));
    CHECK(p.first_cor() == Approx(0.75).margin(rounding_tolerance(p.h)));
  }
  for (const char* name :
       {"f0_direct_cor", "g_direct_cor", "f0_mj_cor", "g_mj_cor", "f0_mj", "g_mj"}) {
    INFO(name);
    check_order(dense(name).fit, 1.0);
  }
  // On the grid (u0 = 5, h = 5/m) the error is h itself (below), up to the rounding of 1e-13 / h:
  // relative 1e-5 at h = 1e-4, so the order is 1 to 1e-5 over two decades.
  CHECK(cheap("f0_direct_aligned").fit.order == Approx(1.0).margin(1e-5));
}

TEST_CASE(
    "C24: without COR the direct scheme's impact has COR |1 - 2 theta| and u_h does not converge "
    "to the elastic solution off the grid",
    "[claim][convergence]") {
  const Model model;  // f = 0, no COR
  double largest = 0;
  for (const ConvergencePoint& p : cheap("f0_direct").points) {
    INFO("h = " << p.h);
    const double theta = p.first_theta(), e = p.first_cor();
    // f = 0: v^{l+1} = 2 (phi - u^l)/h - v^l = |v0| (1 - 2 theta) (4-2), and when that is < 0
    // the next step reflects it: the rebound speed is |1 - 2 theta| |v0|.
    CHECK(e == Approx(std::fabs(1 - 2 * theta)).margin(rounding_tolerance(p.h)));
    // The exact particle rebounds with |v0| = 1 m/s, u_h with e |v0|, both from about t*: at T
    // they are (1 - e)(T - t*) apart, up to the step shifts (at most 2 h |v0|).
    CHECK(p.errors.sup_u >= (1 - e) * (kT - kOffGridU0) - 2 * p.h);
    // (4-6): the energy lost is N^l (u^l - phi) = 2 theta (1 - theta) v^2 on the impact step.
    CHECK(p.energy_loss(model) == Approx(p.tallies.energy_drop).margin(rounding_tolerance(p.h)));
    largest = std::fmax(largest, p.errors.sup_u);
  }
  CHECK(largest >= 3.0);  // no decay with h: O(1) errors down to h = 1e-4 (1e-6 in the experiment)
  // No convergence: the fitted order is 0 (check_order explains the tolerance). Over 400 values
  // of h, theta takes values all over [0, 1), so the effective COR takes values all over [0, 1].
  const SeriesRun& off_grid = dense("f0_direct");
  check_order(off_grid.fit, 0.0);
  double cor_min = 1;
  for (const ConvergencePoint& p : off_grid.points) {
    INFO("h = " << p.h);
    CHECK(p.first_cor() == Approx(std::fabs(1 - 2 * p.first_theta())).margin(1e-9));
    cor_min = std::fmin(cor_min, p.first_cor());
  }
  CHECK(cor_min < 0.05);

  // On the grid (u0 = 5, h = 5/m) the rebound is elastic and u_h is the exact solution delayed by
  // one step (the impulse of (4-4) acts at t_{l+1}): sup error = h |v0| exactly, up to rounding.
  // The step that lands on the floor has N^l = 0 and is not a contact step (contact.hpp): the
  // impact's episode starts from the floor, theta = 0.
  for (const ConvergencePoint& p : cheap("f0_direct_aligned").points) {
    INFO("h = " << p.h);
    CHECK(p.errors.sup_u == Approx(p.h).margin(rounding_tolerance(p.h)));
    CHECK(p.first_cor() == Approx(1.0).margin(1e-12));
    CHECK(p.first_theta() == 0.0);
  }
}

TEST_CASE(
    "C23: subsequences h = t*/(m + theta) converge at first order to the exact solution with COR "
    "|1 - 2 theta|: different limits and each a solution of (2-1)-(2-4)",
    "[claim][convergence]") {
  const std::vector<std::int64_t> m = {250, 2500, 25000};
  for (double theta : {0.25, 0.75}) {
    const SubsequenceRun sub = run_subsequence(theta, m);
    CHECK(sub.limit_cor == 0.5);
    for (const ConvergencePoint& p : sub.points) {
      INFO("theta = " << theta << ", h = " << p.h);
      CHECK(p.first_theta() == Approx(theta).margin(rounding_tolerance(p.h)));
      CHECK(p.first_cor() == Approx(0.5).margin(rounding_tolerance(p.h)));
      // The step shift: u_h leaves the floor at t_{m+1} (theta < 1/2) or t_{m+2} (theta > 1/2),
      // the limit at t*, both with speed 1/2: apart by at most 2 h * 1/2 = h.
      CHECK(p.errors.sup_u <= p.h + rounding_tolerance(p.h));
    }
    // Two decades, a constant error ratio: the order is 1 to the rounding of the ratio.
    CHECK(sub.fit.order == Approx(1.0).margin(0.01));
    // The limits are (2-1)-(2-4) solutions that differ: (1 - e)(T - t*) apart from the elastic
    // one (they rebound at t* with 1/2 and 1 m/s).
    CHECK(sub.limit_distance_to_elastic == Approx(0.5 * (kT - kOffGridU0)).epsilon(1e-12));
  }
  // theta = 1/2: a plastic impact, u_h = phi after it, as the limit with COR 0: only rounding.
  const SubsequenceRun plastic = run_subsequence(0.5, m);
  CHECK(plastic.limit_cor == 0.0);
  for (const ConvergencePoint& p : plastic.points) CHECK(p.errors.sup_u <= rounding_tolerance(p.h));
  CHECK(plastic.limit_distance_to_elastic == Approx(kT - kOffGridU0).epsilon(1e-12));
}

TEST_CASE(
    "C20: error in the paper: (4-9) as printed (h sum N^l = v^n - v^0) omits the body force: h sum "
    "N^l = v^n - v^0 - f T holds",
    "[claim][convergence]") {
  for (const char* name : {"g_direct", "g_mj"})
    for (const ConvergencePoint& p : cheap(name).points) {
      INFO(name << " h = " << p.h);
      // Each of the n = T/h terms h N^l carries a rounding of a few eps (max|v| + |f| T).
      const double n = kT / p.h, tol = 4 * kEps * n * (15.0 + kGravity * kT);
      CHECK(std::fabs(p.impulse_residual_corrected()) <= tol);
      CHECK(p.impulse_residual_printed() == Approx(kGravity * p.t_end).margin(tol));
    }
}

TEST_CASE(
    "convergence: with the COR reset (restitution.md), h sum N^l is 2 (1 - theta) |v0|, not "
    "the velocity jump (1 + COR) |v0|: N_h does not converge to u'' - f",
    "[claim][convergence]") {
  for (const ConvergencePoint& p : cheap("f0_direct_cor").points) {
    INFO("h = " << p.h);
    const double theta = p.first_theta();
    // The complementarity solve gives N^l = (2/h^2)(phi - u_free) = 2 (1 - theta) |v0| / h; the
    // velocity is then reset to COR |v0| and no further contact force acts (an impact on a grid
    // point: the step that lands on the floor has N^l = 0 and is not a contact step, contact.hpp;
    // the next one starts on the floor, theta = 0, and carries the whole 2 |v0|).
    CHECK(p.tallies.impulse == Approx(2 * (1 - theta)).margin(rounding_tolerance(p.h)));
    CHECK(p.impulse_residual_corrected() ==
          Approx(2 * (1 - theta) - 1.75).margin(rounding_tolerance(p.h)));
  }
}

TEST_CASE(
    "C22: (4-10) h sum N^l (u^{l+1} - phi) = 0 holds exactly for direct, moreau_jean's sum is "
    "-5.50 at h = 2e-2 under gravity, and without COR the energy lost is sum N^l (u^l - phi) (4-6)",
    "[claim][convergence]") {
  for (const char* name : {"f0_direct", "f0_direct_cor", "g_direct", "g_direct_cor"})
    for (const ConvergencePoint& p : cheap(name).points) {
      INFO(name << " h = " << p.h);
      CHECK(p.tallies.complementarity == 0.0);  // (4-3): u^{l+1} = phi exactly when N^l > 0
    }
  // moreau_jean does not project u onto the floor: at h = 2e-2 under gravity its impulse steps end
  // below phi, and the sum is -5.50 (the ledger's key, compl410_max, is the largest |sum| over h,
  // which is this one). It tends to 0 with h, not monotonically (its sign changes): 0.020 at
  // h = 1.26e-4 (the cheap run's last), 0.0012 at 1e-5 (the experiment's).
  const std::vector<ConvergencePoint>& mj = cheap("g_mj").points;
  REQUIRE(mj.front().h == 0.02);
  CHECK(mj.front().tallies.complementarity == Approx(-5.50).margin(0.005));
  for (const ConvergencePoint& p : mj) {
    INFO("h = " << p.h);
    CHECK(std::fabs(p.tallies.complementarity) <= std::fabs(mj.front().tallies.complementarity));
  }
  CHECK(std::fabs(mj.back().tallies.complementarity) <= 0.01 * 5.50);
  const Model gravity{.f = -kGravity, .cor = std::nullopt};
  for (const ConvergencePoint& p : cheap("g_direct").points) {
    INFO("h = " << p.h);
    // E^{l+1} - E^l = -N^l (u^l - phi) per step; rounding of E is a few eps (E^0 ~ 50).
    CHECK(p.energy_loss(gravity) ==
          Approx(p.tallies.energy_drop).margin(1e-9 + rounding_tolerance(p.h)));
  }
}

TEST_CASE(
    "convergence: under gravity without COR the direct scheme loses all its energy by "
    "T = 10 at every h, so u_h misses the elastic solution by its apex height",
    "[claim][convergence]") {
  const Model gravity{.f = -kGravity, .cor = std::nullopt};
  const double E0 = 0.5 + kGravity * 5.0;  // (3-1) with u0 = 5, v0 = -1
  const SeriesRun& g = cheap("g_direct");
  for (const ConvergencePoint& p : g.points) {
    INFO("h = " << p.h);
    CHECK(p.energy_loss(gravity) >= 0.999 * E0);
    // The elastic solution keeps bouncing to the apex E0 / g = 5.051 m while u_h rests on the
    // floor (u_h >= phi = 0): the error is the apex as the grid samples it, at most g h^2 / 8
    // below it.
    CHECK(p.errors.sup_u <= E0 / kGravity + 1e-12);
    CHECK(p.errors.sup_u >= E0 / kGravity - kGravity * p.h * p.h / 8);
  }
  // So the error does not depend on h: ln sup varies by less than g h^2 / 8 / 5.05 <= 1e-4 over
  // ln h spanning 5.3, and the order is 0 to 1e-4 / 5.3.
  CHECK(std::fabs(g.fit.order) <= 1e-4);
}

TEST_CASE("convergence: fit_order, log_spaced, step_with_fraction and TallyingStepper",
          "[convergence]") {
  const std::vector<double> hs = log_spaced(1e-1, 1e-4, 4);
  REQUIRE(hs.size() == 4);
  CHECK(hs[0] == 1e-1);
  CHECK(hs[3] == Approx(1e-4).epsilon(4 * kEps));
  CHECK(hs[1] == Approx(1e-2).epsilon(4 * kEps));
  std::vector<double> err;
  for (double h : hs) err.push_back(3 * h * h);
  const OrderFit fit = fit_order(hs, err);
  CHECK(fit.order == Approx(2.0).epsilon(1e-12));
  CHECK(std::exp(fit.log_constant) == Approx(3.0).epsilon(1e-10));
  CHECK(fit.points == 4);
  CHECK(fit.max_log_deviation < 1e-12);
  CHECK(fit.order_standard_error < 1e-12);
  CHECK(fit.h_min == Approx(1e-4).epsilon(1e-12));
  CHECK(std::isnan(fit_order(std::vector<double>{1.0}, std::vector<double>{1.0}).order));
  // Errors 1, 1, 1 and 2 at h = 1e-1 .. 1e-4: with x = ln h, S_xx = 5 ln(10)^2, the slope is
  // -0.3 log10(2) and the residuals' sum of squares 0.3 ln(2)^2, so the standard error is
  // sqrt(0.3 ln(2)^2 / 2 / S_xx) = sqrt(0.03) log10(2).
  const OrderFit scattered = fit_order(hs, std::vector<double>{1, 1, 1, 2});
  CHECK(scattered.order == Approx(-0.3 * std::log10(2.0)).epsilon(1e-12));
  CHECK(scattered.order_standard_error == Approx(std::sqrt(0.03) * std::log10(2.0)).epsilon(1e-12));
  CHECK(step_with_fraction(5.0, 4, 1.0) == 1.0);

  // f = 0, u0 = 1, v0 = -1, h = 0.3: the floor is crossed in the fourth step (t = 0.9 .. 1.2) a
  // third of the way in: theta = 1/3, rebound |1 - 2/3| = 1/3, one contact step.
  const Model model;
  Direct direct(model, 0.3, {});
  ProofTallies tallies;
  TallyingStepper tallying(direct, model, 0.3, tallies);
  State s{1.0, -1.0};
  tallying.initialize(s, 0);
  for (std::int64_t l = 0; l < 6; ++l) tallying.do_step(s, l);
  REQUIRE(tallies.episodes.size() == 1);
  CHECK(tallies.episodes[0].t_start == Approx(0.9));
  CHECK(tallies.episodes[0].flight_fraction == Approx(1.0 / 3).epsilon(1e-12));
  CHECK(tallies.episodes[0].effective_cor() == Approx(1.0 / 3).epsilon(1e-12));
  CHECK(tallies.episodes[0].steps == 1);
  CHECK(tallies.impulse == Approx(4.0 / 3).epsilon(1e-12));  // v from -1 to 1/3
  CHECK(tallies.last.v == Approx(1.0 / 3).epsilon(1e-12));
}
