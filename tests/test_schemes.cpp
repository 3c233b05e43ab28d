// The time-steppers against the exact solution where they must agree, against each other, and the
// discrete invariants of Section 4 on seeded random scenes.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "analysis/tolerances.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"
#include "scene/read_scene.hpp"
#include "trajectory_support.hpp"

using namespace impact;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

using testing::Row;
using testing::trajectory;

std::vector<Row> trajectory(const Scene& scene) {
  AnyStepper stepper = make_stepper(scene);
  return trajectory(stepper, scene.initial, scene.grid);
}

Scene paper_scene(const std::string& file, const std::string& method) {
  return load_scene(std::string(IMPACT_SOURCE_DIR) + "/experiments/" + file,
                    {"method.name=" + method});
}

}  // namespace

TEST_CASE("C30: direct is exact in free flight and delays a grid-aligned impact by one step",
          "[direct][exact][claim]") {
  // Between contacts (4-1)-(4-2) is exact for a constant force, so up to the first contact the
  // scheme equals the exact parabola. With f = 0 and h = 2^-10 every u^l = 5 - l h is exact in
  // binary and the floor is met exactly at t* = 5 = 5120 h. The step ending at t* has
  // u^{l+1} = phi with N^l = 0; the impulse comes in the next step and, as (4-4) places it, acts at
  // t* + h, so the scheme holds the particle on the floor for one step: afterwards it is the exact
  // solution delayed by h, u_h(t_l) = u(t_{l-1}), an O(h) error (h |v|).
  const double h = std::ldexp(1.0, -10);
  Model model;
  const State initial{5.0, -1.0};
  const Grid grid{h, 10 * 1024};
  auto direct = trajectory(Direct(model, h, {}), initial, grid);
  auto exact = trajectory(ExactStepper(model, h, {}), initial, grid);
  const std::size_t impact_row = 5120;
  for (std::size_t l = 0; l < direct.size(); ++l) {
    INFO("l = " << l);
    if (l <= impact_row) {
      CHECK(direct[l].s.u == exact[l].s.u);
      if (l < impact_row) CHECK(direct[l].s.v == exact[l].s.v);
    } else {
      CHECK(direct[l].s.u == exact[l - 1].s.u);
      if (l > impact_row + 1) CHECK(direct[l].s.v == exact[l - 1].s.v);
    }
  }
  CHECK(direct[impact_row].info.contact_force == 0.0);
  CHECK(direct[impact_row + 1].info.contact_force == 2 / h);
  CHECK(exact[impact_row].info.contact_force == 2 / h);
}

TEST_CASE("direct equals the exact parabola before the first impact under gravity",
          "[direct][exact]") {
  Model model;
  model.f = -9.80665;
  const State initial{5.0, -1.0};
  const double h = 1e-3;
  const Grid grid{h, 900};  // the first impact is at t1 = 0.9120...
  auto direct = trajectory(Direct(model, h, {}), initial, grid);
  auto exact = trajectory(ExactStepper(model, h, {}), initial, grid);
  for (std::size_t l = 0; l < direct.size(); ++l) {
    INFO("l = " << l);
    // Both evaluate u0 + v0 t + f t^2/2 in closed form, in different orders of operations.
    CHECK(direct[l].s.u == Approx(exact[l].s.u).epsilon(0).margin(8 * kEps * 10));
    CHECK(direct[l].s.v == Approx(exact[l].s.v).epsilon(0).margin(8 * kEps * 10));
  }
}

TEST_CASE("moreau_jean is first order: it lags the exact bounce by one step", "[moreau_jean]") {
  const double h = std::ldexp(1.0, -10);
  Model model;
  const State initial{5.0, -1.0};
  const Grid grid{h, 10 * 1024};
  auto mj = trajectory(MoreauJean(model, h, {}), initial, grid);
  auto exact = trajectory(ExactStepper(model, h, {}), initial, grid);
  double worst = 0;
  for (std::size_t l = 0; l < mj.size(); ++l)
    worst = std::fmax(worst, std::fabs(mj[l].s.u - exact[l].s.u));
  // The contact becomes active one step late (u^l + h v^l / 2 <= 0 at u^l = 0), so after the
  // bounce u is exactly one step h |v| behind.
  CHECK(worst == Approx(h).margin(1e-12));
  CHECK(mj.back().s.v == 1.0);
}

struct Difference {
  double u = 0, v = 0;
};

Difference max_difference(const std::vector<Row>& a, const std::vector<Row>& b, std::size_t rows) {
  Difference d;
  for (std::size_t l = 0; l < rows; ++l) {
    d.u = std::fmax(d.u, std::fabs(a[l].s.u - b[l].s.u));
    d.v = std::fmax(d.v, std::fabs(a[l].s.v - b[l].s.v));
  }
  return d;
}

TEST_CASE(
    "C6: direct and fb_newton agree step by step on the paper's scenes except where the scheme "
    "without COR amplifies the smoothing by 2/h at each impact",
    "[direct][fb_newton][claim]") {
  const double sqrt_eps = std::sqrt(1e-15);  // the paper's smoothing, the fb_newton default
  SECTION("Figure 3: the grid-aligned impact meets the kink of F_eps") {
    for (std::string file : {"figure3/no_cor.toml", "figure3/cor075.toml"}) {
      auto direct = trajectory(paper_scene(file, "direct"));
      auto fb = trajectory(paper_scene(file, "fb_newton"));
      const Difference d = max_difference(direct, fb, direct.size());
      INFO(file << ": max |du| = " << d.u << ", max |dv| = " << d.v);
      // At t = 5 the free position is exactly phi (a = b = 0), where F_eps = 0 gives
      // a = sqrt(eps / (2k)), N = sqrt(eps k / 2), k = 2/h^2: a velocity kick h N = sqrt(eps) per
      // such step, kept for the remaining 5 time units. Measured: 6.3e-8 and 3.2e-7 without COR,
      // 3.2e-8 and 1.2e-7 with COR (which resets v from v^l after one kick).
      CHECK(d.v <= 2.01 * sqrt_eps);
      CHECK(d.u <= 2.01 * sqrt_eps * 5);
    }
  }
  SECTION("Figure 4 with COR: the restitution law resets v from v^l, no amplification") {
    auto direct = trajectory(paper_scene("figure4/cor075.toml", "direct"));
    auto fb = trajectory(paper_scene("figure4/cor075.toml", "fb_newton"));
    const Difference d = max_difference(direct, fb, direct.size());
    INFO("max |du| = " << d.u << ", max |dv| = " << d.v);
    // Measured 1.4e-15 and 1.0e-13.
    CHECK(d.u <= 1e-9);
    CHECK(d.v <= 1e-9);
  }
  SECTION("Figure 4 without COR: equal to round-off up to the second impact, then apart") {
    auto direct = trajectory(paper_scene("figure4/no_cor.toml", "direct"));
    auto fb = trajectory(paper_scene("figure4/no_cor.toml", "fb_newton"));
    // Just before the second impact (t = 2.839) the particle is 7.8e-5 above the floor, where the
    // smoothed pair already gives N = eps/(2a) = 6e-12. Without COR the rebound velocity
    // 2 (phi - u^l)/h - v^l turns a perturbation du of u^l into 2 du/h, so each later impact
    // multiplies the difference by ~2/h = 2000.
    const Difference before = max_difference(direct, fb, 2838);
    const Difference all = max_difference(direct, fb, direct.size());
    INFO("before t = 2.838: " << before.u << ", " << before.v << "; overall: " << all.u << ", "
                              << all.v);
    CHECK(before.u <= 1e-12);
    CHECK(before.v <= 1e-12);
    CHECK(all.v >= 1e-3);  // measured 0.54: the divergence is real, see paper_notes/claims.md
  }
}

TEST_CASE("C19: discrete invariants of Section 4 hold on seeded random scenes",
          "[direct][fb_newton][invariants][claim]") {
  std::mt19937_64 rng(20130401);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 60; ++trial) {
    const double phi = -5 + 10 * unit(rng);
    const double u0 = phi + 10 * unit(rng);
    const double v0 = -10 + 20 * unit(rng);
    const double f = trial % 3 == 0 ? 0.0 : -20 * unit(rng);
    const double h = std::pow(10.0, -4 + 3 * unit(rng));
    const double T = 1 + 4 * unit(rng);
    for (std::string method : {"direct", "fb_newton"}) {
      std::string text =
          "[initial]\nu0 = " + impact::round_trip(u0) + "\nv0 = " + impact::round_trip(v0) +
          "\n[floor]\nphi = " + impact::round_trip(phi) +
          "\n[force]\nf = " + impact::round_trip(f) + "\n[time]\nT = " + impact::round_trip(T) +
          "\nh = " + impact::round_trip(h) + "\n[method]\nname = \"" + method + "\"\n";
      Scene scene = parse_scene(text, "random-" + std::to_string(trial));
      auto rows = trajectory(scene);
      INFO(method << " " << text);
      const double v_start = v0, f_used = f;
      double impulse = 0, max_v = 0, max_u = 0;
      for (const Row& r : rows) {
        max_u = std::fmax(max_u, std::fabs(r.s.u));
        max_v = std::fmax(max_v, std::fabs(r.s.v));
      }
      const double energy_roundoff = impact::energy_evaluation_roundoff(f_used, T, max_u, max_v);
      bool above = true, nonnegative = true, complementary = true, energy_down = true;
      for (std::size_t l = 1; l < rows.size(); ++l) {
        const State& s = rows[l].s;
        const double N = rows[l].info.contact_force;
        const double gap = s.u - phi;
        above = above && gap >= 0;
        nonnegative = nonnegative && N >= 0;
        // (4-3): direct sets the gap to exactly 0 in contact; the smoothed pair of fb_newton
        // gives a N = eps / 2 (eps = 1e-15) instead of 0, with the gap resolved only to one ulp
        // of the floor position.
        const double resolution =
            1e-15 + 2 * std::nextafter(std::fabs(phi), 1e300) - 2 * std::fabs(phi);
        complementary = complementary &&
                        std::fabs(N * gap) <= (method == "direct" ? 0.0 : resolution * (1 + N));
        // E^{l+1} <= E^l (proof of Lemma 3), up to round-off (analysis/tolerances.hpp).
        const State& before = rows[l - 1].s;
        const double E0 = energy(scene.model, before), E1 = energy(scene.model, s);
        const double rebound = impact::rebound_energy_roundoff(phi, h, before.u, s.v, N);
        energy_down = energy_down && E1 <= E0 + energy_roundoff + rebound;
        impulse += h * N;
      }
      CHECK(above);
      CHECK(nonnegative);
      CHECK(complementary);
      CHECK(energy_down);
      // (4-9) with a body force: h sum N^l = v^n - v^0 - f T_n, T_n = n h. Each of the n terms
      // carries round-off of order eps max|v|, hence the tolerance.
      const double Tn = scene.grid.t(scene.grid.steps);
      const double tol =
          4 * kEps * static_cast<double>(rows.size()) * (max_v + std::fabs(f_used) * Tn);
      CHECK(impulse == Approx(rows.back().s.v - v_start - f_used * Tn).margin(tol));
    }
  }
}

TEST_CASE(
    "C5: reading of (5-3): eps belongs inside the square root: a contact step of fb_newton "
    "satisfies (u - phi) N = eps/2",
    "[fb_newton][claim]") {
  // F_eps(a, b) = a + b - sqrt(a^2 + b^2 + eps) = 0 iff a + b > 0 and a b = eps/2. With eps
  // outside the root, a + b - sqrt(a^2 + b^2) = eps, the pair would need a b = eps (a + b) +
  // eps^2/2 instead. A larger eps makes the product measurable above round-off.
  const double eps = 1e-6, h = 1e-3;
  Model model;
  model.f = -9.80665;
  FbNewtonParams params;
  params.epsilon = eps;
  FbNewton fb(model, h, params);
  State s{0.0, 0.0};  // resting on the floor: every step is a contact step with N close to -f
  fb.initialize(s, 0);
  for (std::int64_t l = 0; l < 10; ++l) {
    const StepInfo info = fb.do_step(s, l);
    REQUIRE(info.converged);
    INFO("l = " << l << ", a = " << s.u << ", N = " << info.contact_force);
    CHECK(s.u * info.contact_force == Approx(eps / 2).epsilon(1e-6));
  }
}

TEST_CASE(
    "direct with free_flight = paper is (5-1) and (4-2) as printed: the closed form's "
    "discrete solution up to rounding",
    "[direct][property]") {
  // Before the first impact both evaluate u0 + v0 t + f t^2/2 and v0 + f t at t = l h: the closed
  // form once, (5-1) by accumulating increments. A rounding r of u^{l+1} (|r| <= ulp, |u| <= 10)
  // enters v^{l+1} from (4-2) as 2 r / h and stays there (dv_{l+1} = dv_l + 2 r_l / h), and u
  // integrates it: |dv_l| <= 2 l ulp / h and |du_l| <= l^2 ulp + l ulp.
  Model model;
  model.f = -9.80665;
  const State initial{5.0, -1.0};
  const double h = 1e-3;
  const Grid grid{h, 900};  // the first impact is at t1 = 0.9120...
  DirectParams paper;
  paper.free_flight = impact::FreeFlightForm::paper;
  auto closed = trajectory(Direct(model, h, {}), initial, grid);
  auto printed = trajectory(DirectAsPrinted(model, h, paper), initial, grid);
  for (std::size_t l = 0; l < closed.size(); ++l) {
    INFO("l = " << l);
    const double n = static_cast<double>(l) + 1;
    const double ulp = 10 * kEps;
    CHECK(printed[l].s.u == Approx(closed[l].s.u).epsilon(0).margin((n * n + n) * ulp));
    CHECK(printed[l].s.v == Approx(closed[l].s.v).epsilon(0).margin(4 * n * ulp / h));
    CHECK(printed[l].info.contact_force == 0.0);
  }
}
