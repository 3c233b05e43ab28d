// Section 4 (existence proof): convergence of u_h of (4-1)-(4-3) as h -> 0, the effective COR of
// an impact, the identities (4-9) and (4-10), and the numbers of
// experiments/convergence/reference.toml. The runs here are the cheap ones (h >= 1e-4, at most
// 1e5 steps); the full range down to h = 1e-6 is the experiment's.
#include <toml++/toml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "analysis/fit.hpp"
#include "analysis/proof_tallies.hpp"
#include "impact/registry.hpp"
#include "reference_support.hpp"

using namespace impact;

using namespace impact::testing;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kGravity = 9.80665;
constexpr double kT = 10.0;
constexpr double kOffGridU0 = 5.0123;
constexpr double kCheapH = 1e-4;  // the smallest h a test recomputes

const toml::table& reference() {
  return reference_file("convergence");
}

// The series of the experiment (experiments/convergence/convergence.cpp), by name.
struct SeriesSpec {
  const char* name;
  const char* method;
  Model model;
  State initial;
};
const std::vector<SeriesSpec>& series_specs() {
  static const std::vector<SeriesSpec> specs = {
      {"f0_direct_aligned", "direct", model_of(0, std::nullopt), {5.0, -1.0}},
      {"f0_direct", "direct", model_of(0, std::nullopt), {kOffGridU0, -1.0}},
      {"f0_direct_cor", "direct", model_of(0, 0.75), {kOffGridU0, -1.0}},
      {"f0_mj", "moreau_jean", model_of(0, std::nullopt), {kOffGridU0, -1.0}},
      {"f0_mj_cor", "moreau_jean", model_of(0, 0.75), {kOffGridU0, -1.0}},
      {"g_direct", "direct", model_of(-kGravity, std::nullopt), {5.0, -1.0}},
      {"g_direct_cor", "direct", model_of(-kGravity, 0.75), {5.0, -1.0}},
      {"g_mj", "moreau_jean", model_of(-kGravity, std::nullopt), {5.0, -1.0}},
      {"g_mj_cor", "moreau_jean", model_of(-kGravity, 0.75), {5.0, -1.0}},
  };
  return specs;
}

const SeriesSpec& spec(const std::string& name) {
  for (const SeriesSpec& s : series_specs())
    if (name == s.name) return s;
  throw std::logic_error("no series " + name);
}

// Rounding of a position (a few ulp of |u| <= 5 m) enters the rebound velocity through (4-2),
// v^{l+1} = 2 (phi - u^l) / h - v^l, multiplied by 2 / h, and then acts over T = 10 s: 2 * 5e-15
// * 10 / h = 1e-13 / h [m]. The same bound, without the factor T, covers theta and the effective
// COR (dimensionless, 1e-14 / h), and 1e-12 covers what does not pass through 2 / h.
double rounding_tolerance(double h) {
  return 1e-13 / h + 1e-12;
}

// All the runs of a series with h >= kCheapH, recomputed.
struct Recomputed {
  std::vector<std::size_t> index;  // into the reference arrays
  std::vector<ConvergencePoint> points;
};
Recomputed recompute(const std::string& name) {
  const SeriesSpec& s = spec(name);
  const auto hs = numbers(reference()["series"][name]["h"]);
  Recomputed r;
  for (std::size_t i = 0; i < hs.size(); ++i)
    if (hs[i] >= kCheapH) {
      r.index.push_back(i);
      r.points.push_back(measure_convergence(
          make_scene(s.model, s.initial, kT, hs[i], find_method(s.method)->defaults)));
    }
  return r;
}

double first_theta(const ConvergencePoint& p) {
  return p.tallies.episodes.empty() ? std::nan("") : p.tallies.episodes.front().flight_fraction;
}
double first_cor(const ConvergencePoint& p) {
  return p.tallies.episodes.empty() ? std::nan("") : p.tallies.episodes.front().effective_cor();
}

bool same_or_both_nan(double a, double b, double tol) {
  return (std::isnan(a) && std::isnan(b)) || std::fabs(a - b) <= tol;
}

}  // namespace

TEST_CASE("convergence: the cheap runs of every series match reference.toml",
          "[convergence][regression]") {
  for (const SeriesSpec& s : series_specs()) {
    const Recomputed r = recompute(s.name);
    const auto ref = reference()["series"][s.name];
    const auto sup = numbers(ref["sup_u"]), theta = numbers(ref["theta"]),
               cor = numbers(ref["effective_cor"]), hs = numbers(ref["h"]);
    REQUIRE(r.points.size() >= 8);
    for (std::size_t k = 0; k < r.points.size(); ++k) {
      const std::size_t i = r.index[k];
      const ConvergencePoint& p = r.points[k];
      INFO(s.name << " h = " << hs[i]);
      CHECK(p.h == hs[i]);
      CHECK(std::fabs(p.errors.sup_u - sup[i]) <= rounding_tolerance(hs[i]));
      CHECK(same_or_both_nan(first_theta(p), theta[i], rounding_tolerance(hs[i])));
      CHECK(same_or_both_nan(first_cor(p), cor[i], rounding_tolerance(hs[i])));
    }
    // The fit in reference.toml is fit_order() of the reference arrays (on the off-grid scene,
    // without the grid-aligned points): refitting them gives the same order.
    const auto fit = ref["fit"];
    if (number(fit["points"]) == static_cast<double>(hs.size())) {
      CHECK(fit_order(hs, sup).order == Approx(number(fit["order"])).epsilon(1e-12));
    }
  }
}

TEST_CASE(
    "convergence: with a COR the direct scheme converges at first order, sup error <= "
    "COR |v0| h",
    "[claim][convergence]") {
  // f = 0, COR = 0.75, impact at t* in (t_m, t_{m+1}]: the exact particle leaves the floor at t*
  // with e |v0| and is e |v0| (t_{m+1} - t*) <= e |v0| h above it at t_{m+1}, where the scheme
  // is at phi with the same velocity e |v0| (Section 5.2's reset). From then on both fly alike.
  const Recomputed r = recompute("f0_direct_cor");
  for (const ConvergencePoint& p : r.points) {
    INFO("h = " << p.h);
    CHECK(p.errors.sup_u <= 0.75 * 1.0 * p.h + rounding_tolerance(p.h));
    CHECK(first_cor(p) == Approx(0.75).margin(rounding_tolerance(p.h)));
  }
  // The fitted orders over the experiment's full range (2e-2 .. 1.7e-6 with f = 0, 2e-2 .. 1e-5
  // under gravity): 1 within the scatter that the position theta of the impact in its step
  // causes (the error constant varies with theta, see the bound above).
  for (const char* name : {"f0_direct_cor", "g_direct_cor", "f0_mj_cor", "g_mj_cor", "f0_mj",
                           "g_mj", "f0_direct_aligned"}) {
    INFO(name);
    const double order = number(reference()["series"][name]["fit"]["order"]);
    CHECK(order >= 0.9);
    CHECK(order <= 1.15);
  }
}

TEST_CASE(
    "convergence: without COR the direct scheme's impact has COR |1 - 2 theta| and u_h does "
    "not converge to the elastic solution off the grid",
    "[claim][convergence]") {
  const Recomputed off = recompute("f0_direct");
  double largest = 0;
  for (const ConvergencePoint& p : off.points) {
    INFO("h = " << p.h);
    const double theta = first_theta(p), e = first_cor(p);
    // f = 0: v^{l+1} = 2 (phi - u^l)/h - v^l = |v0| (1 - 2 theta) (4-2), and when that is < 0
    // the next step reflects it: the rebound speed is |1 - 2 theta| |v0|.
    CHECK(e == Approx(std::fabs(1 - 2 * theta)).margin(rounding_tolerance(p.h)));
    // The exact particle rebounds with |v0| = 1 m/s, u_h with e |v0|, both from about t*: at T
    // they are (1 - e)(T - t*) apart, up to the step shifts (at most 2 h |v0|).
    CHECK(p.errors.sup_u >= (1 - e) * (kT - kOffGridU0) - 2 * p.h);
    // (4-6): the energy lost is N^l (u^l - phi) = 2 theta (1 - theta) v^2 on the impact step.
    CHECK(p.energy_loss(spec("f0_direct").model) ==
          Approx(p.tallies.energy_drop).margin(rounding_tolerance(p.h)));
    largest = std::fmax(largest, p.errors.sup_u);
  }
  CHECK(largest >= 3.0);  // no decay with h: O(1) errors down to h = 1e-4 (1e-6 in the experiment)
  const auto ref = reference()["series"]["f0_direct"];
  CHECK(number(ref["fit"]["order"]) == Approx(0.0).margin(0.2));
  CHECK(number(ref["effective_cor_min"]) < 0.05);
  CHECK(number(ref["effective_cor_minus_prediction_max"]) <= 1e-9);

  // On the grid (u0 = 5, h = 5/m) the rebound is elastic and u_h is the exact solution delayed by
  // one step (the impulse of (4-4) acts at t_{l+1}): sup error = h |v0| exactly, up to rounding.
  for (const ConvergencePoint& p : recompute("f0_direct_aligned").points) {
    INFO("h = " << p.h);
    CHECK(p.errors.sup_u == Approx(p.h).margin(rounding_tolerance(p.h)));
    CHECK(first_cor(p) == Approx(1.0).margin(1e-12));
  }
}

TEST_CASE(
    "convergence: subsequences h = t*/(m + theta) converge at first order to the exact "
    "solution with COR |1 - 2 theta|: different limits, each a solution of (2-1)-(2-4)",
    "[claim][convergence]") {
  const Model scheme = model_of(0, std::nullopt);
  const State initial{kOffGridU0, -1.0};
  for (double theta : {0.25, 0.75}) {
    const Model limit = model_of(0, std::fabs(1 - 2 * theta));
    std::vector<double> hs, sups;
    for (std::int64_t m : {250, 2500, 25000}) {
      const double h = step_with_fraction(kOffGridU0, m, theta);
      const ConvergencePoint p = measure_convergence(
          make_scene(scheme, initial, kT, h, find_method("direct")->defaults), limit);
      INFO("theta = " << theta << ", m = " << m);
      CHECK(first_theta(p) == Approx(theta).margin(rounding_tolerance(h)));
      CHECK(first_cor(p) == Approx(0.5).margin(rounding_tolerance(h)));
      // The step shift: u_h leaves the floor at t_{m+1} (theta < 1/2) or t_{m+2} (theta > 1/2),
      // the limit at t*, both with speed 1/2: apart by at most 2 h * 1/2 = h.
      CHECK(p.errors.sup_u <= p.h + rounding_tolerance(h));
      hs.push_back(h);
      sups.push_back(p.errors.sup_u);
    }
    // Two decades, a constant error ratio: the order is 1 to the rounding of the ratio.
    CHECK(fit_order(hs, sups).order == Approx(1.0).margin(0.01));
  }
  // theta = 1/2: a plastic impact, u_h = phi after it, as the limit with COR 0: only rounding.
  for (std::int64_t m : {250, 2500, 25000}) {
    const double h = step_with_fraction(kOffGridU0, m, 0.5);
    const ConvergencePoint p = measure_convergence(
        make_scene(scheme, initial, kT, h, find_method("direct")->defaults), model_of(0, 0.0));
    CHECK(p.errors.sup_u <= rounding_tolerance(h));
  }
  // The limits are (2-1)-(2-4) solutions that differ: (1 - e)(T - t*) apart from the elastic one.
  const auto subs = reference()["subsequences"];
  CHECK(number(subs["theta_0_25"]["limit_distance_to_elastic"]) ==
        Approx(0.5 * (kT - kOffGridU0)).epsilon(1e-12));
  CHECK(number(subs["theta_0_5"]["limit_distance_to_elastic"]) ==
        Approx(kT - kOffGridU0).epsilon(1e-12));
  CHECK(number(subs["theta_0_25"]["fit"]["order"]) == Approx(1.0).margin(0.01));
  CHECK(number(subs["theta_0_75"]["fit"]["order"]) == Approx(1.0).margin(0.01));
}

TEST_CASE(
    "error in the paper: (4-9) as printed, h sum N^l = v^n - v^0, omits the body force: "
    "h sum N^l = v^n - v^0 - f T holds",
    "[claim][convergence]") {
  const Model model = model_of(-kGravity, std::nullopt);
  for (double h : {1e-2, 1e-3, 1e-4}) {
    const ConvergencePoint p =
        measure_convergence(make_scene(model, {5.0, -1.0}, kT, h, find_method("direct")->defaults));
    INFO("h = " << h);
    // Each of the n = T/h terms h N^l carries a rounding of a few eps (max|v| + |f| T).
    const double n = kT / h, tol = 4 * kEps * n * (15.0 + kGravity * kT);
    CHECK(std::fabs(p.impulse_residual_corrected()) <= tol);
    CHECK(p.impulse_residual_printed() == Approx(kGravity * p.t_end).margin(tol));
  }
  // And moreau_jean satisfies the corrected identity too (its N^l is its impulse over h).
  CHECK(number(reference()["series"]["g_mj"]["res49_corrected_max"]) <= 1e-8);
  CHECK(number(reference()["series"]["g_direct"]["res49_printed_max"]) ==
        Approx(kGravity * kT).epsilon(1e-3));
}

TEST_CASE(
    "convergence: with the COR reset (restitution.md), h sum N^l is 2 (1 - theta) |v0|, not "
    "the velocity jump (1 + COR) |v0|: N_h does not converge to u'' - f",
    "[claim][convergence]") {
  for (const ConvergencePoint& p : recompute("f0_direct_cor").points) {
    INFO("h = " << p.h);
    const double theta = first_theta(p);
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
    "convergence: (4-10) h sum N^l (u^{l+1} - phi) = 0 holds exactly for direct, and "
    "without COR the energy lost is sum N^l (u^l - phi) (4-6)",
    "[claim][convergence]") {
  for (const char* name : {"f0_direct", "f0_direct_cor", "g_direct", "g_direct_cor"}) {
    INFO(name);
    CHECK(number(reference()["series"][name]["compl410_max"]) == 0.0);
  }
  for (const ConvergencePoint& p : recompute("g_direct").points) {
    INFO("h = " << p.h);
    CHECK(p.tallies.complementarity == 0.0);  // (4-3): u^{l+1} = phi exactly when N^l > 0
    // E^{l+1} - E^l = -N^l (u^l - phi) per step; rounding of E is a few eps (E^0 ~ 50).
    CHECK(p.energy_loss(spec("g_direct").model) ==
          Approx(p.tallies.energy_drop).margin(1e-9 + rounding_tolerance(p.h)));
  }
}

TEST_CASE(
    "convergence: under gravity without COR the direct scheme loses all its energy by "
    "T = 10 at every h, so u_h misses the elastic solution by its apex height",
    "[claim][convergence]") {
  const double E0 = 0.5 + kGravity * 5.0;  // (3-1) with u0 = 5, v0 = -1
  const auto ref = reference()["series"]["g_direct"];
  CHECK(number(ref["energy_loss_min"]) >= 0.999 * E0);
  // The elastic solution keeps bouncing to the apex E0 / g = 5.051 m while u_h rests on the floor
  // (u_h >= phi = 0): the error is the apex as the grid samples it, at most g h^2 / 8 below it
  // (h <= 2e-2: 4.9e-4 m).
  CHECK(number(ref["sup_max"]) <= E0 / kGravity + 1e-12);
  CHECK(number(ref["sup_min"]) >= E0 / kGravity - kGravity * 2e-2 * 2e-2 / 8);
  for (const ConvergencePoint& p : recompute("g_direct").points) {
    INFO("h = " << p.h);
    CHECK(p.energy_loss(spec("g_direct").model) >= 0.999 * E0);
  }
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
  CHECK(fit.h_min == Approx(1e-4).epsilon(1e-12));
  CHECK(std::isnan(fit_order(std::vector<double>{1.0}, std::vector<double>{1.0}).order));
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
