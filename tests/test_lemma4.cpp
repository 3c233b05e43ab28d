// Lemma 4 (uniqueness) and its proof (4-11)-(4-13): solution paths under COR = 1, weak solutions
// of (2-1)-(2-4) that differ when COR is not fixed, the identity (4-12) on pairs of exact
// solutions, and the numbers of experiments/lemma4/reference.toml. The runs go through the
// experiment's own functions (src/analysis/lemma4/lemma4.hpp): the cheap run is the experiment with
// the path scenes cut to h >= 1e-4, the dense runs sweep h >= 1e-4 finely enough to fit an order.
#include <toml++/toml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/fit.hpp"
#include "analysis/lemma4/energy_identity.hpp"
#include "analysis/lemma4/lemma4.hpp"
#include "analysis/lemma4/weak_solution.hpp"
#include "analysis/path_distance.hpp"
#include "analysis/reference.hpp"
#include "analysis/test_functions.hpp"

using namespace impact;
using namespace impact::lemma4;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kGravity = 9.80665;
constexpr double kT = kLemma4T;

// The experiment with the path scenes cut to their first rows, h >= 1e-4.
const Lemma4Options kCheap{.h_floor = 1e-4};
// h from 2e-2 to 1e-4: 400 values with f = 0 and 100 under gravity (see the order claim).
const Lemma4Options kDense{.free = {2e-2, 1e-4, 400}, .gravity = {2e-2, 1e-4, 100}};

PathScene path_scene(const Lemma4Options& options, const std::string& name) {
  for (PathScene& s : path_scenes(options))
    if (s.name == name) return s;
  throw std::logic_error("no path scene " + name);
}

const SolutionPair& pair_named(const std::string& name) {
  static const std::vector<SolutionPair> pairs = solution_pairs();
  for (const SolutionPair& p : pairs)
    if (p.name == name) return p;
  throw std::logic_error("no pair " + name);
}

// The cheap run reproduces the paths' first rows, not the fits and extremes over their whole
// range (every key of paths.<scene> but the arrays), and everything else.
ReferenceRule cheap_rule(const toml::table& reference) {
  ReferenceRule rule;
  rule.measured_prefix = true;
  for (auto&& [scene, node] : *reference["paths"].as_table())
    for (auto&& [key, value] : *node.as_table())
      if (!value.is_array())
        rule.skip.push_back("paths." + std::string(scene.str()) + "." + std::string(key.str()));
  return rule;
}

// The weak formulation holds when: u >= phi and every cell impulse >= 0 exactly (closed forms
// that never go below the floor), int (u - phi) dN = 0 and int u psi'' = int psi dN + f int psi
// to the quadrature's accuracy: GSL QAG at 1e-12 relative on each of ~10 pieces of 3 integrals
// of magnitude <= the scale, so 1e-10 of the scale with a margin.
void check_weak(const WeakSolutionCheck& c) {
  CHECK(c.min_gap >= 0.0);
  CHECK(c.min_cell_impulse >= 0.0);
  CHECK(std::fabs(c.complementarity) <= 1e-10 * std::fmax(1.0, c.total_impulse));
  CHECK(c.max_weak_residual <= 1e-10 * std::fmax(1.0, c.max_weak_scale));
  CHECK(c.test_functions >= 90);
}

}  // namespace

TEST_CASE("lemma4: the experiment, with the paths' first rows (h >= 1e-4), matches reference.toml",
          "[lemma4][regression]") {
  const toml::table measured = run_lemma4(ExperimentContext{IMPACT_SOURCE_DIR, ""}, kCheap);
  const toml::table reference = read_reference(IMPACT_SOURCE_DIR, "lemma4");
  for (auto&& [scene, node] : *measured["paths"].as_table()) {
    INFO(scene.str());
    CHECK((*node.as_table())["h"].as_array()->size() >= 6);
  }
  for (const std::string& difference :
       compare_with_reference(measured, reference, cheap_rule(reference)))
    FAIL_CHECK(difference);
}

TEST_CASE(
    "C26: Lemma 4 with COR = 1: direct and moreau_jean and the exact solution approach one "
    "trajectory at first order",
    "[claim][lemma4]") {
  // f = 0, impact on the grid (h = 5/m): both schemes hold the particle on the floor for one
  // step, so each is the exact solution delayed by h, sup error h |v0|, and they coincide.
  // Tolerance: rounding of a position (a few ulp of 5 m) passed through (4-2)'s 2/h into a
  // velocity and acting over T = 10 s, 1e-13 / h (as in test_convergence.cpp).
  const PathScene aligned = path_scene(kCheap, "f0");
  const PathRun on_grid = run_paths(aligned);
  for (std::size_t i = 0; i < aligned.h.size(); ++i) {
    const double h = aligned.h[i], tol = 1e-13 / h + 1e-12;
    INFO("h = " << h);
    CHECK(on_grid.direct_exact.sup[i] == Approx(h).margin(tol));
    CHECK(on_grid.mj_exact.sup[i] == Approx(h).margin(tol));
    CHECK(on_grid.direct_mj.sup[i] <= tol);
  }
  // Off the grid and under gravity with COR = 1 given, the distances scatter about C h with the
  // position theta of each impact in its step (f = 0: e |v0| (1 - theta) h for direct), which
  // jumps erratically with h: a fitted order has a standard error. On 400 (f = 0) and 100
  // (gravity) values of h in [1e-4, 2e-2] it is at most 0.05 (checked), and first order is
  // |order - 1| <= 0.1, two standard errors. Between the two schemes, under gravity.
  const PathRun off_grid = run_paths(path_scene(kDense, "f0_cor_1"));
  const PathRun gravity = run_paths(path_scene(kDense, "gravity"));
  for (const PathDistance* d : {&off_grid.direct_exact, &off_grid.mj_exact, &gravity.direct_exact,
                                &gravity.mj_exact, &gravity.direct_mj}) {
    INFO("order " << d->fit.order << " +- " << d->fit.order_standard_error);
    CHECK(d->fit.order_standard_error <= 0.05);
    CHECK(std::fabs(d->fit.order - 1) <= 0.1);
  }
}

TEST_CASE(
    "C26: the grid-aligned first order needs direct's closed form from the last contact: (5-1) "
    "stepped as printed drifts off the grid by rounding and misses by 10528 h at h = 1e-6",
    "[claim][lemma4]") {
  // f = 0, u0 = 5, v0 = -1, no COR, h = 5/m: the closed form is off by h exactly (the case above).
  // Stepped as printed, each step rounds u, and (4-2) passes that into v times 2 / h: the impact
  // that h puts on the grid lands a fraction theta off it, and the rebound loses 2 theta of its
  // speed (Lemma 2.2), which over the 5 s after it is 10 theta m. Measured: 1.3 h at h = 1.4e-5,
  // 3.0 h at 1e-5, 10528 h at 1e-6 (fitted order 0.26 over the experiment's 16 steps, 2e-2 ..
  // 1e-6). Checked: not first order with the closed form's constant 1, more than 100 h off at 1e-6.
  PathScene aligned = path_scene(kCheap, "f0");
  aligned.h = {5.0 / 5e6};
  const PathDistance printed = run_paths_as_printed(aligned);
  INFO("sup / h: " << printed.sup[0] / aligned.h[0] << " at h = 1e-6");
  CHECK(printed.sup[0] >= 100 * aligned.h[0]);
}

TEST_CASE("C26: Lemma 4 with COR = 1: exact solutions depend Lipschitz-continuously on the data",
          "[claim][lemma4]") {
  const PerturbationRun run = run_perturbation();
  REQUIRE(run.delta.size() == 8);
  for (std::size_t i = 0; i < run.delta.size(); ++i) {
    const double d = run.delta[i];
    INFO("delta = " << d);
    // f = 0: u0 + delta shifts the whole path by delta before the impact and by -delta after
    // it, sup = delta; v0 + delta changes the slope, sup = T delta at t = T. Positions of a few
    // m and velocities of 1 m/s: a few ulp of 10.
    CHECK(run.f0_u0[i] == Approx(d).margin(64 * kEps * 10));
    CHECK(run.f0_v0[i] == Approx(kT * d).margin(64 * kEps * 10));
    // Gravity: a bounded ratio sup / delta (9.0 for u0, 0.91 for v0 in the experiment).
    CHECK(run.g_u0[i] <= 10.0 * d);
    CHECK(run.g_v0[i] <= 10.0 * d);
  }
  // And first order in delta over seven decades: the ratio sup / delta settles to the derivative
  // of the path with respect to the data, so the fitted order is 1 to within 0.01.
  CHECK(fit_order(run.delta, run.g_u0).order == Approx(1.0).margin(0.01));
  CHECK(fit_order(run.delta, run.g_v0).order == Approx(1.0).margin(0.01));
}

TEST_CASE(
    "C29: as the paper says, uniqueness needs an impact law: the exact solutions with COR 1 and "
    "1/2 both satisfy (2-1)-(2-4) weakly from the same data and end 2.5 m apart",
    "[claim][lemma4]") {
  const SolutionPair& pair = pair_named("cor");
  const ExactSolution u(pair.model_u, pair.u0), w(pair.model_w, pair.w0);
  check_weak(check_weak_solution(u, pair.model_u, kT));
  check_weak(check_weak_solution(w, pair.model_w, kT));
  CHECK(u.at(0).u == w.at(0).u);
  CHECK(u.at(0).v == w.at(0).v);
  // After the impact at t* = 5 they rebound with 1 and 1/2 m/s: 2.5 m apart at T.
  CHECK(sup_distance(u, w, kT) == Approx(2.5).epsilon(4 * kEps));
  // The same for the limits of the direct scheme (test_convergence.cpp): COR 1/2 and 0.
  const Model plastic{.cor = 0.0};
  check_weak(check_weak_solution(ExactSolution(plastic, pair.u0), plastic, kT));
  // And with gravity, through a Zeno point and a rest phase (COR 0.75).
  const Model gravity{.f = -kGravity, .cor = 0.75};
  check_weak(check_weak_solution(ExactSolution(gravity, pair.u0), gravity, kT));
}

TEST_CASE(
    "C27: error in the paper: (4-13) does not follow from (4-12) when COR = 1: the two elastic "
    "solutions from u0 = 5 and u0 = 5.5 satisfy (4-12) with z_t(0) = 0 yet z_t = 2 for 5 < t < 5.5",
    "[claim][lemma4]") {
  const SolutionPair& pair = pair_named("elastic");
  const ExactSolution u(pair.model_u, pair.u0), w(pair.model_w, pair.w0);
  for (double t : {1.0, 5.2, 5.4, 8.0}) {
    INFO("t = " << t);
    const EnergyIdentity412 r = energy_identity_412(u, w, pair.model_u, t);
    // (4-12) holds: the dropped terms int N u_t vanish for elastic solutions (energy (3-1) is
    // conserved), and f = 0.
    CHECK(r.lhs == Approx(r.paper_rhs).margin(8 * kEps));
    CHECK(r.dropped_n1_u == Approx(0.0).margin(8 * kEps));
    CHECK(r.dropped_n2_w == Approx(0.0).margin(8 * kEps));
  }
  // z_t(0) = 0, but between the two impacts u moves up and w down: z_t^2 = 4, not 0 (4-13).
  const EnergyIdentity412 r = energy_identity_412(u, w, pair.model_u, 5.2);
  CHECK(r.paper_413 == Approx(4.0).epsilon(8 * kEps));
  CHECK(r.lhs == Approx(2.0).epsilon(8 * kEps));  // the factor 1/2 of (1/2) int d/dt z_t^2
  // For elastic solutions (4-12) reads z_t^2(t)/2 = v0^2 - u_t(t) w_t(t): an identity for any
  // pair with |u_t| = |w_t| = |v0|, which says nothing about z_t. The paths are 0.5 m apart
  // (the initial offset, mirrored after the impacts).
  CHECK(sup_distance(u, w, pair.T) == Approx(0.5).epsilon(1e-12));
}

TEST_CASE(
    "C27: the terms (4-12) drops: int N2 w_t is the energy lost by w (COR 1/2: -3/8) and with f != "
    "0 the force terms f (u + w)|_0^t",
    "[claim][lemma4]") {
  const SolutionPair& cor = pair_named("cor");
  const ExactSolution u(cor.model_u, cor.u0), w(cor.model_w, cor.w0);
  const EnergyIdentity412 r = energy_identity_412(u, w, cor.model_u, 8.0);
  // z_t jumps from 0 to 1/2 at t* = 5: left side (1/4 - 0)/2 = 1/8; the paper's right side
  // -1 * 1/2 + (-1)(-1) = 1/2; the difference is int N2 w_t = -(1 - e^2) v0^2 / 2 = -3/8.
  CHECK(r.lhs == Approx(0.125).epsilon(8 * kEps));
  CHECK(r.paper_rhs == Approx(0.5).epsilon(8 * kEps));
  CHECK(r.dropped_n2_w == Approx(-0.375).epsilon(8 * kEps));
  // Under gravity (the pair of the first-condition test at t = 1.5 t1, COR 1 and sqrt(2) - 1):
  // f (u + w)|_0^t = 53.2 m^2/s^2 is missing from (4-12) as printed, besides int N2 w_t.
  const SolutionPair& c1 = pair_named("condition1");
  const ExactSolution ug(c1.model_u, c1.u0), wg(c1.model_w, c1.w0);
  const double t1 = std::sqrt(2 * c1.u0.u / kGravity);
  const EnergyIdentity412 rg = energy_identity_412(ug, wg, c1.model_u, 1.5 * t1);
  CHECK(rg.force_terms > 50.0);
  CHECK(std::fabs(rg.lhs - rg.paper_rhs) > 10.0);
  // lhs = -u_t w_t|_0^t + f (u + w)|_0^t + int N1 u_t + int N2 w_t holds for every pair at every
  // time the experiment keeps; terms up to 100 m^2/s^2, so a few ulp of 100.
  for (const SolutionPair& pair : solution_pairs())
    for (const EnergyIdentity412& x : identities_at(pair)) {
      INFO(pair.name);
      CHECK(x.lhs ==
            Approx(x.paper_rhs + x.force_terms + x.dropped_n1_u + x.dropped_n2_w).margin(1e-12));
    }
}

TEST_CASE(
    "C28: error in the paper: Lemma 4's condition u_t^0 = 0 and u_t(t) = w_t(t) = 0 for some t is "
    "not enough: COR 1 and sqrt(2) - 1 from u0 = 5 and v0 = 0 under gravity",
    "[claim][lemma4]") {
  const SolutionPair& pair = pair_named("condition1");
  const ExactSolution u(pair.model_u, pair.u0), w(pair.model_w, pair.w0);
  const double e = *pair.model_w.cor, t1 = std::sqrt(2 * pair.u0.u / kGravity);
  CHECK(e == Approx(std::sqrt(2.0) - 1).epsilon(4 * kEps));
  check_weak(check_weak_solution(u, pair.model_u, pair.T));
  check_weak(check_weak_solution(w, pair.model_w, pair.T));
  // Both start at rest (u_t^0 = 0, and so "u_t(t) = w_t(t) = 0 for some t" already at t = 0) and
  // both are at an apex at t = 2 t1: u after one elastic flight of 2 t1, w after two flights of
  // 2 e t1 and 2 e^2 t1 with (1 + e)^2 = 2. Velocities are V1 ~ 10 m/s in magnitude: a few ulp.
  CHECK(u.at(2 * t1).v == Approx(0.0).margin(64 * kEps * 10));
  CHECK(w.at(2 * t1).v == Approx(0.0).margin(64 * kEps * 10));
  // Yet u (back at 5 m) and w (at 5 e^4 m) differ, so the lemma's conclusion u = w fails.
  CHECK(u.at(2 * t1).u == Approx(5.0).epsilon(1e-12));
  CHECK(w.at(2 * t1).u == Approx(5.0 * std::pow(e, 4)).epsilon(1e-12));
  // How far apart they get depends on the window. On the pair's [0, 3] s (and on [0, 2.5] s) the
  // largest distance is u's apex 5 m against w's 5 e^4 at 2 t1, 5 (1 - e^4) = 4.853 m. w comes to
  // rest at its Zeno time t1 + 2 e V1 / (g (1 - e)) = 2.438 s, and u is back at 5 m at 4 t1 =
  // 4.04 s: on [0, 10] s the distance is 5 m. The closed forms to a few ulp of 5 m.
  CHECK(pair.T == 3.0);
  CHECK(sup_distance(u, w, pair.T) == Approx(5 * (1 - std::pow(e, 4))).margin(64 * kEps * 5));
  CHECK(sup_distance(u, w, 2.5) == Approx(5 * (1 - std::pow(e, 4))).margin(64 * kEps * 5));
  const double V1 = kGravity * t1, zeno = t1 + 2 * e * V1 / (kGravity * (1 - e));
  CHECK(zeno == Approx(2.438).margin(5e-4));
  CHECK(w.at(zeno + 0.1).u == 0.0);
  CHECK(sup_distance(u, w, 10.0) == Approx(5.0).margin(64 * kEps * 5));
  // At that t, (4-13) holds (z_t(t) = z_t(0) = 0) but says nothing about z_t elsewhere.
  const EnergyIdentity412 r = energy_identity_412(u, w, pair.model_u, 2 * t1);
  CHECK(r.paper_413 == Approx(0.0).margin(1e-12));
  CHECK(energy_identity_412(u, w, pair.model_u, 1.5 * t1).paper_413 > 30.0);
}

TEST_CASE("lemma4: Bump is a smooth test function with the derivatives it claims", "[lemma4]") {
  const Bump psi{2.0, 0.5};
  CHECK(psi.value(1.4) == 0.0);
  CHECK(psi.value(2.6) == 0.0);
  CHECK(psi.value(2.0) == Approx(std::exp(-1.0)).epsilon(4 * kEps));
  for (double t : {1.7, 1.95, 2.2, 2.4}) {
    INFO("t = " << t);
    const double d = 1e-5;  // central differences: error d^2 |psi'''| / 6, about 1e-8 here
    CHECK(psi.first(t) == Approx((psi.value(t + d) - psi.value(t - d)) / (2 * d)).margin(1e-7));
    CHECK(psi.second(t) == Approx((psi.first(t + d) - psi.first(t - d)) / (2 * d)).margin(1e-6));
  }
}
