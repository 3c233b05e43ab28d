// Figure 4 (Section 5.2, f = -9.80665, u0 = 5, v0 = -1, T = 10, h = 1e-3): when the particle comes
// to rest and how much energy it loses, the paper's claims about them, measured on the data of the
// experiment's recipe (figure4_data), and its key numbers against
// experiments/figure4/reference.toml.
#include <toml++/toml.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "analysis/figure4/figure4.hpp"
#include "analysis/figure4/figure4_readings.hpp"
#include "analysis/fit.hpp"
#include "analysis/reference.hpp"
#include "impact/model/event.hpp"
#include "impact/references/exact.hpp"
#include "impact/references/exact_march.hpp"

using namespace impact;
using namespace impact::figure4;

namespace {

constexpr double kG = 9.80665;  // |f|
constexpr double kH = 1e-3;     // the paper's step
// Indices of kFigure4Scenes and kFigure4Methods.
constexpr std::size_t kNoCor = 0, kCor = 1, kDirect = 0, kFbNewton = 1;

const ExperimentContext kContext{IMPACT_SOURCE_DIR, ""};
// The sweep at its quarter decades only, h = 10^-(2 + k/4), k = 0..12: the h of summary.toml.
const Figure4Options kQuarterDecades{4};

// Computed once per process (about a second).
const Figure4Data& data() {
  static const Figure4Data d = figure4_data(kContext, kQuarterDecades);
  return d;
}

// The rest times of the ensemble (u0 moved by k ulps, |k| <= 200), sorted; +inf for a member that
// still bounces at T.
std::vector<double> ensemble(std::size_t scene, std::size_t method) {
  std::vector<double> times;
  for (const std::optional<double>& t : data().ensemble_rest[scene][method])
    times.push_back(t.value_or(INFINITY));
  std::sort(times.begin(), times.end());
  return times;
}

// The exact Zeno time of (2-1)-(2-4) with COR e < 1 (exact.hpp):
// t_inf = t1 + 2 e V1 / (|f| (1 - e)).
double zeno_time(const Scene& s) {
  const ExactSolution exact(s.model, s.initial);
  const double e = *s.model.cor;
  return *exact.impact_time(1) + 2 * e * *exact.impact_speed(1) / (-s.model.f * (1 - e));
}

}  // namespace

TEST_CASE(
    "C10: at h = 1e-3 our schemes (closed form) rest at 5.801 s (direct) and 5.864 s "
    "(fb_newton) and not near 7.5 s while the exact elastic solution never rests",
    "[figure4][claim]") {
  // The paper: the particle bounces "until coming to a stop at around t = 7.5". Rest time: the
  // first grid time from which every step ends in contact (RestAnalysis, analysis/rest.hpp).
  const Figure4Column& column = data().column[kNoCor];
  const std::optional<double> direct = column.rest[kDirect].rest_time;
  const std::optional<double> fb = column.rest[kFbNewton].rest_time;
  REQUIRE(direct);
  REQUIRE(fb);
  CHECK(std::fabs(*direct - 5.801) < kH / 2);
  CHECK(std::fabs(*fb - 5.864) < kH / 2);
  CHECK(std::fabs(*direct - 7.5) > 1.0);
  CHECK(std::fabs(*fb - 7.5) > 1.0);
  // Without COR the exact reference is elastic (COR = 1): it bounces to T and keeps its energy.
  const Scene& s = column.scene;
  const ExactSolution exact(s.model, s.initial);
  CHECK_FALSE(exact.rest_time().has_value());
  CHECK(exact.impacts_until(s.T) == 5);
  CHECK(energy(s.model, exact.at(s.T)) == Approx(energy(s.model, s.initial)).epsilon(1e-12));
}

TEST_CASE(
    "C10: the rest time without COR is ill-conditioned: moving u0 by up to 200 ulps moves "
    "the closed form's by more than 2 s but never to 7.5 s (with COR it does not move)",
    "[figure4][claim]") {
  // Each impact of the direct scheme without COR rebounds with |1 - 2 theta| |v| (restitution.md),
  // and the next impact's theta, the fraction of its step before the floor, moves by 2 / (|f| h)
  // per unit change of the rebound speed w (the flight lasts 2 w / |f|): the bounce map expands
  // errors by ~4 w / (|f| h) per impact (3800 after the first at h = 1e-3), so which impact ends
  // in the chatter is decided by the last bits of u0.
  REQUIRE(data().ensemble_u0.size() == 401);
  const std::vector<double> no_cor = ensemble(kNoCor, kDirect);
  CHECK(no_cor.back() - no_cor.front() > 2.0);
  CHECK(no_cor.back() < 7.5);
  // With COR the rebound is COR |v^l|, a contraction: the same perturbations leave it unchanged.
  const std::vector<double> cor = ensemble(kCor, kDirect);
  CHECK(cor.front() == cor.back());
}

TEST_CASE(
    "C10: the rest time 5.801 s is where the particle stays on the floor: from then on u = phi "
    "and |v| < h |f| / 2 at every step, and a run that ends inside a two-step impact is not at "
    "rest",
    "[figure4][claim]") {
  // The rest rule of contact.hpp (a final contact episode of at least three steps) against the
  // trajectory itself. On the floor (5-1) leaves it in the next step iff v^l > h |f| / 2, and
  // (4-2) turns v into -v on a contact step from the floor, so the particle rests from t_m iff
  // u^l = phi and |v^l| < h |f| / 2 for every l >= m. An impact with theta > 1/2 lasts two
  // contact steps and leaves with |v| (2 theta - 1) > h |f| / 2: a run that ends there bounces.
  const Figure4Column& column = data().column[kNoCor];
  const std::vector<Sample> run = record(column.scene);
  const double phi = column.scene.model.phi, stay = kH * kG / 2;
  std::size_t m = run.size();
  while (m > 0 && run[m - 1].u == phi && std::fabs(run[m - 1].v) < stay) --m;
  REQUIRE(m < run.size());
  REQUIRE(column.rest[kDirect].rest_time);
  CHECK(run[m].t == *column.rest[kDirect].rest_time);
  CHECK(std::fabs(run[m].t - 5.801) < kH / 2);

  const std::vector<ContactEpisode>& episodes = column.rest[kDirect].episodes;
  const auto two_step = std::find_if(episodes.begin(), episodes.end(),
                                     [](const ContactEpisode& e) { return e.steps == 2; });
  REQUIRE(two_step != episodes.end());
  const std::int64_t end = two_step->first_step + 2;
  INFO("the run cut at t = " << column.scene.grid.t(end) << ", after impact "
                             << two_step - episodes.begin() + 1);
  const Scene cut = make_scene(column.scene.model, column.scene.initial, column.scene.grid.t(end),
                               kH, column.scene.method);
  REQUIRE(cut.grid.steps == end);
  CHECK(std::fabs(record(cut).back().v) > stay);
  const RestAnalysis cut_rest = analyse_rest(cut);
  CHECK_FALSE(cut_rest.rest_time.has_value());
  CHECK(cut_rest.impacts == two_step - episodes.begin() + 1);
}

TEST_CASE(
    "C11 (error in the paper): the energy loss does not vanish as h decreases: at every h "
    "from 1e-2 to 1e-5 the scheme ends at rest and keeps at most (h f)^2 / 8 of E(0)",
    "[figure4][claim]") {
  // The paper: "as the time step size h_t gets smaller and smaller, numerical simulations show
  // that the energy function becomes flatter". At rest the scheme chatters on the floor with
  // |v| <= h |f| / 2 (a larger upward v would lift off in the next step), so E(T) <= (h f)^2 / 8;
  // fb_newton's smoothed contact leaves the particle up to sqrt(eps / 2) = 2.2e-8 m above phi,
  // worth |f| sqrt(eps / 2) = 2.2e-7 J/kg more.
  const double lift = kG * std::sqrt(1e-15 / 2);
  REQUIRE(data().sweep.size() == 13);
  for (const Figure4SweepRow& row : data().sweep)
    for (std::size_t m : {kDirect, kFbNewton}) {
      const RestAnalysis& a = row.run[kNoCor][m];
      INFO(kFigure4Methods[m] << ", h = " << row.h);
      CHECK(a.rest_time.has_value());
      CHECK(a.energy_final <= (row.h * kG) * (row.h * kG) / 8 + lift);
    }
}

TEST_CASE(
    "C11 (error in the paper): the energy lost at the first impact is 2 theta (1 - theta) "
    "V^2 + |f| theta h V and jumps non-monotonically with h",
    "[figure4][claim]") {
  // (4-6): the impact step removes N^l (u^l - phi) with N^l = (2/h) V (1 - theta) + |f| and
  // u^l - phi = theta h V; a second contact step (theta > 1/2) starts on the floor and removes
  // nothing. theta is the fractional part of a flight time over h, erratic in h.
  std::vector<double> losses;
  for (const Figure4SweepRow& row : data().sweep) {
    const RestAnalysis& a = row.run[kNoCor][kDirect];
    const ContactEpisode& e = a.episodes.front();
    const double V = e.speed_before, theta = e.linear_fraction;
    INFO("h = " << row.h);
    CHECK(first_impact_loss(a) ==
          Approx(2 * theta * (1 - theta) * V * V + kG * theta * row.h * V).epsilon(1e-9));
    losses.push_back(first_impact_loss(a));
  }
  // Measured on h = 10^-(2 + k/4), k = 0..12: 8 changes of direction in 11 possible, a spread
  // from 5.0 to 49.4 J/kg, and more lost at h = 1e-5 (47.2) than at h = 1e-2 (41.5). The first
  // impact comes after one exact free flight, so these numbers are well-conditioned.
  int turns = 0;
  for (std::size_t i = 2; i < losses.size(); ++i)
    turns += (losses[i] - losses[i - 1]) * (losses[i - 1] - losses[i - 2]) < 0;
  CHECK(turns == 8);
  CHECK(*std::max_element(losses.begin(), losses.end()) >
        5 * *std::min_element(losses.begin(), losses.end()));
  CHECK(losses.back() > losses.front());
}

TEST_CASE(
    "C12: with COR = 0.75 the rest time converges to the exact Zeno time t_inf = 7.0026 s "
    "from below at first order up to a logarithm",
    "[figure4][claim]") {
  const Scene& s = data().column[kCor].scene;
  const double zeno = zeno_time(s);
  CHECK(*ExactSolution(s.model, s.initial).rest_time() == Approx(zeno).epsilon(1e-12));
  CHECK(zeno == Approx(7.0026470737395).epsilon(1e-12));
  // Each scheme impact restarts from the floor at the end of the step with COR |v^l|: it lags the
  // exact impact by (1 - theta) h and its speed is short by theta h |f|, which shortens all later
  // flights by 2 theta h COR / (1 - COR) in total. Per impact the rest time moves by
  // h (1 - theta (1 + COR) / (1 - COR)) = h (1 - 7 theta), between -6 h and h; over K impacts,
  // K ~ ln(2 V1 / (h |f|)) / ln(1 / COR), that is |error| <= 6 h K, plus the final chatter and the
  // first step of rest (2 h).
  std::vector<double> h, direct_error;
  for (const Figure4SweepRow& row : data().sweep)
    for (std::size_t m : {kDirect, kFbNewton}) {
      const RestAnalysis& a = row.run[kCor][m];
      INFO(kFigure4Methods[m] << ", h = " << row.h);
      REQUIRE(a.rest_time);
      const double error = *a.rest_time - zeno;
      CHECK(error < 0);
      CHECK(-error <= 6 * row.h * static_cast<double>(a.impacts + 2));
      if (m == kDirect) {
        h.push_back(row.h);
        direct_error.push_back(-error);
      }
    }
  // The slope of h ln(1/h) is 1 - 1 / ln(1/h), from 0.78 to 0.91 on [1e-5, 1e-2]; the per-impact
  // lags scatter around it.
  const OrderFit fit = fit_order(h, direct_error);
  CHECK(fit.points == 13);
  CHECK(fit.order > 0.75);
  CHECK(fit.order < 1.0);
  CHECK(direct_error.back() < direct_error.front() / 100);
}

TEST_CASE(
    "C10: Figure 4's rest time is decided by rounding: (5-1) in closed form rests at 5.801 s "
    "and never at >= 7.5 s over 401 data within 200 ulps, while as printed it rests at 6.998 s, "
    "and 97 of "
    "the 401 at >= 7.5 s",
    "[figure4][claim]") {
  // The same discrete solution (free_flight.hpp) evaluated two ways: from the last contact in
  // closed form, or (5-1) term by term as printed with v from (4-2), one rounding per step. The
  // bounce map without COR expands errors by ~4 w / (|f| h) per impact, so the two arithmetics,
  // and the last bits of u0, decide which impact ends in the chatter.
  const Figure4Readings& r = data().readings;
  const std::optional<double> closed = data().column[kNoCor].rest[kDirect].rest_time;
  REQUIRE(closed);
  REQUIRE(r.paper_rest);
  CHECK(std::fabs(*closed - 5.801) < kH / 2);
  CHECK(std::fabs(*r.paper_rest - 6.998) < kH / 2);
  CHECK(std::fabs(*r.paper_rest - *closed) > 1.0);
  const std::vector<double> closed_form = ensemble(kNoCor, kDirect);
  const std::vector<double> paper = sorted_rest_times(r.paper_ensemble);
  REQUIRE(paper.size() == 401);
  const auto at_or_after = [](const std::vector<double>& t, double s) {
    return t.end() - std::lower_bound(t.begin(), t.end(), s);
  };
  // Closed form: 5.243 ... 7.375 s, median 5.715, none at 7.5 or later.
  CHECK(at_or_after(closed_form, 7.5) == 0);
  CHECK(closed_form[200] == Approx(5.715).margin(kH / 2));
  // As printed: 5.832 ... 9.518 s, median 6.852, 96 rest at >= 7.5 s and 1 still bounces at T:
  // the paper's "around t = 7.5" lies inside its own arithmetic's spread.
  CHECK(at_or_after(paper, 7.5) == 97);
  CHECK(std::count(paper.begin(), paper.end(), INFINITY) == 1);
  CHECK(paper.front() < 7.5);
  CHECK(paper[200] == Approx(6.852).margin(kH / 2));
  CHECK(paper[200] - closed_form[200] > 1.0);
}

TEST_CASE(
    "C12 (reproduced under either COR reading, which decides when): with COR = 0.75 at h = 1e-3 "
    "v := -COR v^l rests at 6.939 s near the Zeno time 7.0026 s, and scaling the scheme's own "
    "rebound, v := COR v_scheme, rests at 2.854 s",
    "[figure4][claim]") {
  // restitution.md reads "alter the velocity" as v^{l+1} = -COR v^l on a step with N^l > 0. The
  // other reading keeps the scheme's rebound (4-2), |v^l| (1 - 2 theta) (to O(h f)), and scales
  // it by COR: each impact then also removes the scheme's own 2 theta (1 - theta) v^2, and the
  // particle rests seconds before the Zeno time. Both come to rest, which is what the paper
  // says; only ours rests near the exact solution's Zeno time.
  const RestAnalysis& ours = data().column[kCor].rest[kDirect];
  const RestAnalysis& scaled = data().readings.scaled_rebound;
  REQUIRE(ours.rest_time);
  REQUIRE(scaled.rest_time);
  CHECK(std::fabs(*ours.rest_time - 6.939) < kH / 2);
  CHECK(std::fabs(*scaled.rest_time - 2.854) < kH / 2);
  CHECK(scaled.impacts == 8);
  CHECK(zeno_time(data().column[kCor].scene) - *scaled.rest_time > 4.0);
}

TEST_CASE(
    "C12: the Zeno time 7.0026 s, followed impact by impact by the event-driven exact solution, "
    "is the closed form's to within the chatter cut-off's window (6.1e-8 s)",
    "[figure4][claim]") {
  // exact with a harmonic part of amplitude 0 finds each impact by its certified search and
  // Brent's root (flight_search.hpp) instead of the closed form t_k of exact.hpp; it cuts the
  // chatter at the first impact slower than 1e-8 of the first one (exact_march.hpp) and sticks
  // there, W = 2 e V / (|f| (1 - e)) before the accumulation point, W <= 2 e 1e-8 V1 / (|f| (1 -
  // e)) = 6.1e-8 s. Each impact time is a root to an ulp or two of t (8.9e-16 s below 8 s); a root
  // late by d launches the rest e |f| d faster, which moves every later impact by at most
  // (1 + 2 e / (1 - e)) d: the k-th time is within (1 + 2 e / (1 - e)) k 2 ulp of the closed form
  // (measured 1.8e-13 s after 66 roots, bound 8.2e-13 s), its speed within |f| times that.
  const Scene& s = data().column[kCor].scene;
  const ExactSolution closed(s.model, s.initial);
  const double e = *s.model.cor, V1 = *closed.impact_speed(1), t_inf = zeno_time(s);
  CHECK(std::fabs(t_inf - 7.0026) < 5e-5);
  Model harmonic = s.model;
  harmonic.harmonic = Harmonic{0.0, 1.0, 0.0};
  ClosedFormMarch track(harmonic, s.initial, 0.0);
  std::vector<Event> events;
  track.set_event_sink([&](const Event& event) { events.push_back(event); });
  double impulse = 0;
  for (std::int64_t l = 1; l <= s.grid.steps; ++l) track.advance(s.grid.t(l), impulse);
  REQUIRE(events.size() >= 3);
  REQUIRE(events.back().kind == EventKind::stick);
  const std::size_t impacts = events.size() - 1;
  double worst_time = 0, worst_speed = 0;
  for (std::size_t k = 0; k < impacts; ++k) {
    const auto index = static_cast<std::int64_t>(k) + 1;
    worst_time = std::fmax(worst_time, std::fabs(events[k].t - *closed.impact_time(index)));
    worst_speed =
        std::fmax(worst_speed, std::fabs(-events[k].v_before - *closed.impact_speed(index)));
  }
  INFO(impacts << " impacts: largest time error " << worst_time << " s, speed error " << worst_speed
               << " m/s; stick " << t_inf - events.back().t << " s before t_inf");
  const double bound = (1 + 2 * e / (1 - e)) * static_cast<double>(impacts) * 2 * 8.9e-16;
  CHECK(worst_time <= bound);
  CHECK(worst_speed <= kG * bound);
  const double window = 2 * e * 1e-8 * V1 / (kG * (1 - e));
  CHECK(window == Approx(6.1e-8).epsilon(0.01));
  CHECK(events.back().t <= t_inf + 1e-13);
  CHECK(t_inf - events.back().t <= window);
  CHECK(-events[impacts - 1].v_before < 1e-8 * V1);
  CHECK(-events[impacts - 2].v_before >= 1e-8 * V1);
}

TEST_CASE(
    "C32 (reproduced for the paper's COR = 0.75): the contact step changes E by -(1 - COR^2) "
    "v^2/2 + f (u^l - phi): it falls at every h with COR = 0.75, and with COR = 1 and f > 0 "
    "rises by O(h) (4.81e-3 at h = 1e-3), an artefact of the discrete COR rule",
    "[figure4][claim]") {
  // u0 = 0.01, v0 = -1, f = +9.80665 (away from the floor): one impact near t = 0.0101 s. The COR
  // rule sets v^{l+1} = -COR v^l at u^{l+1} = phi, so E^{l+1} - E^l = -(1 - COR^2) (v^l)^2 / 2
  // - f (phi - u^l), with u^l - phi = theta h |v^l| <= h |v^l|: a rise only when
  // f (u^l - phi) > (1 - COR^2) (v^l)^2 / 2, i.e. with COR = 1 (or COR near 1, or a large h). The
  // exact impact at u = phi keeps E (COR = 1) or removes (1 - COR^2) v^2/2: the rise is the
  // scheme's, the work of f over the part of the step the particle did not fly.
  const std::vector<ContactStepEnergy>& rows = data().readings.contact_energy;
  REQUIRE(rows.size() == 13);
  std::vector<double> h, rise;
  for (const ContactStepEnergy& row : rows) {
    INFO("h = " << row.h);
    for (std::size_t c = 0; c < 2; ++c)
      CHECK(row.change[c] == Approx(row.predicted[c]).margin(1e-15));
    CHECK(row.change[1] < -0.15);  // COR = 0.75: E falls by 0.151 ... 0.176 of 0.4019 J/kg
    CHECK(row.change[0] > 0);
    CHECK(row.change[0] <= 9.80665 * row.h);  // f theta h |v^l| with |v^l| <= 1
    h.push_back(row.h);
    rise.push_back(row.change[0]);
  }
  CHECK(rows[4].change[0] == Approx(4.8085192111250e-3).epsilon(1e-9));  // h = 1e-3
  CHECK(rows[8].change[0] == Approx(3.9806743026533e-4).epsilon(1e-9));  // h = 1e-4
  // theta scatters in [0, 1) with h, so the points scatter below the line f h: fitted order 1.15.
  const OrderFit fit = fit_order(h, rise);
  CHECK(fit.order > 0.8);
  CHECK(fit.order < 1.5);
}

TEST_CASE("C6: Figure 4: direct and fb_newton agree to rounding with COR but not without it",
          "[figure4][claim]") {
  // The paper: "The results, which are almost indistinguishable". With COR the bounce map
  // contracts (COR < 1) and the two schemes differ by rounding and by the smoothing force
  // eps / (2 (u - phi)) ~ 1e-12 near the floor; without COR it expands rounding differences
  // (see the ensemble claim) and the two part after a few impacts (0.54 m/s at h = 1e-3).
  const ChannelDifference& cor = data().column[kCor].difference;
  CHECK(cor.u <= 1e-12);
  CHECK(cor.v <= 1e-10);
  CHECK(cor.N <= 1e-7);  // 5e-12 relative to the largest N, 2 V1 / h ~ 2e4
  CHECK(data().column[kNoCor].difference.v > 0.1);
}

TEST_CASE("Figure 4: key numbers match reference.toml", "[figure4][regression]") {
  // The runs are deterministic IEEE arithmetic (C++20 without extensions, so no FMA contraction):
  // every number is compared to 1e-9 of max(1, |reference|) (ReferenceRule), counts exactly.
  // Without COR the rest time, the impact count and the direct - fb_newton differences are
  // ill-conditioned (the ensemble claim: moving u0 by a few ulps moves the rest time by seconds),
  // so a change of rounding anywhere in a solver changes them; if only those fail after such a
  // change, regenerate reference.toml (make figure4) and say so. The sweep is run at its quarter
  // decades only (13 h instead of the driver's 121): what summary.toml states over the whole sweep
  // is not reproduced and not compared.
  ReferenceRule rule;
  for (const char* method : {"direct", "fb_newton"})
    for (const char* key : {"no_cor_%_rest_time_min", "no_cor_%_rest_time_max",
                            "no_cor_%_energy_loss_min", "cor075_%_rest_time_order"}) {
      std::string k = key;
      k.replace(k.find('%'), 1, method);
      rule.skip.push_back("h_sweep." + k);
    }
  const toml::table measured = run_figure4(kContext, kQuarterDecades);
  for (const std::string& difference :
       compare_with_reference(measured, read_reference(IMPACT_SOURCE_DIR, "figure4"), rule))
    FAIL_CHECK(difference);
}
