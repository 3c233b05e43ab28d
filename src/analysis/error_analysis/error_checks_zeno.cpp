// Statement 3 (many impacts, f < 0, COR e) of paper_notes/error_analysis.md checked on one scene's
// runs, and the exactness of direct_located under a constant force.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "analysis/error_analysis/error_bounds.hpp"
#include "analysis/error_analysis/error_checks.hpp"
#include "impact/model/contact.hpp"
#include "impact/references/exact.hpp"
#include "impact/steppers/direct_located.hpp"

namespace impact::error_analysis {
namespace {

constexpr double kUnit = 0x1p-53;

// A contact episode of a run: its first step, its length, where the scheme's own flight reaches
// the floor in that step (t_l + tau) and the velocity after the step (the relaunch speed W_k).
struct Episode {
  std::size_t first = 0, steps = 0;
  double landing = 0, theta = 0, relaunch = 0;
};

// The impacts of a run: in each contact episode (a run of contact steps), the first step whose
// flight from t_l reaches the floor within the step. An episode without one is fb_newton's
// smoothing alone (a step ending within sqrt(eps / 2) above the floor), not an impact; one that
// starts with such a step has its impact in a later step.
std::vector<Episode> episodes(const SceneRuns& r, const Trace& t, bool smoothing) {
  const Model& m = r.scene.scene.model;
  const double h = r.scene.scene.grid.h;
  std::vector<Episode> out;
  bool in = false, found = false;
  for (std::size_t l = 0; l + 1 < t.s.size(); ++l) {
    const bool contact = r.contact_step(t, l, smoothing);
    if (!contact) {
      in = false;
      continue;
    }
    if (!in) found = false;
    in = true;
    if (found) {
      ++out.back().steps;
      continue;
    }
    if (!r.impact_step(t, l, smoothing)) continue;
    const FloorArrival a = floor_arrival({r.gap(t, l), t.s[l].v}, m.f);
    found = true;
    Episode e;
    e.first = l;
    e.steps = 1;
    e.theta = std::fmin(a.tau / h, 1.0);
    e.landing = (static_cast<double>(l) + e.theta) * h;
    e.relaunch = t.s[l + 1].v;
    out.push_back(e);
  }
  return out;
}

double sup_error(const SceneRuns& r, const Trace& t) {
  double worst = 0;
  for (std::size_t l = 0; l < t.s.size(); ++l)
    worst = std::fmax(worst, std::fabs(t.s[l].u - r.exact.s[l].u));
  return worst;
}

Rounding with_smoothing(const SceneRuns& r, const Trace& t) {
  // fb_newton's contact steps stop up to h sqrt(eps) / 2 above the floor, and its free flights
  // carry the kicks of Lemma 1.3: here their sum over the run as fb_newton reports them (the
  // h N^l of its steps that do not end on the floor), acting for up to T.
  const Scene& scene = r.scene.scene;
  const double h = scene.grid.h;
  double kicks = 0;
  for (std::size_t l = 0; l + 1 < t.s.size(); ++l)
    if (!(t.s[l + 1].u - scene.model.phi == 0)) kicks += h * t.N[l + 1];
  Rounding rd = r.rounding;
  rd.position += h * std::sqrt(r.eps) / 2 + scene.grid.end() * kicks;
  rd.velocity += kicks;
  rd.kicks = kicks;
  return rd;
}

// Theorem 3.1-3.3 on one run of direct (proved, with the identities of their proofs) or of
// fb_newton (Conjecture 3.4: the same bounds, up to its smoothing).
void check_bouncing(const SceneRuns& r, const std::string& p, const Trace& t, bool smoothing,
                    std::vector<Check>& out) {
  const Scene& scene = r.scene.scene;
  const Model& m = scene.model;
  const double h = scene.grid.h, g = -m.f, e = r.cor(), t_end = scene.grid.end();
  const ExactSolution exact(m, scene.initial);
  const auto t1 = exact.impact_time(1);
  const auto V1 = exact.impact_speed(1);
  if (!t1 || !V1 || !(*V1 > 0)) return;
  const Rounding rd = smoothing ? with_smoothing(r, t) : r.rounding;
  const BouncingRun run = bouncing_run(r, t, rd, smoothing);
  // The worst impact of the run for each quantity, by measured / (bound + allowance).
  struct Worst {
    double score = -1;
    Check check;
    void offer(const Check& c) {
      const double s = c.measured / (c.bound + c.allowance);
      if (s > score) score = s, check = c;
    }
  } timing, timing_identity, speed, speed_identity;
  for (const ImpactRecord& i : run.impacts) {
    const auto x = static_cast<double>(i.k);
    if (i.k >= 2) {
      timing.offer(
          make_check(r, p + ".timing", std::fabs(i.delay), i.delay_bound, i.delay_round, x));
      if (!smoothing)
        timing_identity.offer(make_check(r, p + ".timing_identity",
                                         std::fabs(i.delay - i.delay_identity), 0,
                                         i.delay_identity_round, x));
    }
    if (!i.relaunched) continue;
    speed.offer(make_check(r, p + ".speed", std::fabs(i.speed), i.speed_bound, rd.velocity, x));
    if (!smoothing)
      speed_identity.offer(make_check(r, p + ".speed_identity",
                                      std::fabs(i.speed - i.speed_identity), 0,
                                      i.speed_identity_round, x));
  }
  for (const Worst* w : {&timing, &timing_identity, &speed, &speed_identity})
    if (w->score >= 0) out.push_back(w->check);
  const ZenoData data{*t1, *V1, g, e, h, t_end};
  const double bound = sup_bound(data);
  if (std::isfinite(bound))
    out.push_back(
        make_check(r, p + ".sup", sup_error(r, t), bound, rd.position + t_end * rd.velocity));
  if (!run.rest || !exact.rest_time()) return;
  out.push_back(make_check(r, p + ".rest", std::fabs(*run.rest - *exact.rest_time()),
                           rest_bound(data), run.rest_round));
  out.push_back(make_check(r, p + ".impacts", static_cast<double>(run.impacts_before_rest),
                           static_cast<double>(max_impacts(*V1, g, h, e)), 0));
}

}  // namespace

BouncingRun bouncing_run(const SceneRuns& r, const Trace& t, const Rounding& rd, bool smoothing) {
  const Scene& scene = r.scene.scene;
  const Model& m = scene.model;
  const double h = scene.grid.h, g = -m.f, e = r.cor(), t_end = scene.grid.end();
  const ExactSolution exact(m, scene.initial);
  const std::vector<Episode> found = episodes(r, t, smoothing);
  BouncingRun run;
  // The identities' running sums: delta_{k+1} = delta_k + (1 - theta_k) h + 2 eps_k / g,
  // eps_k = e eps_{k-1} - e g theta_k h; and the rounding they carry through the thetas, each
  // known to allow_t / h (a landing time's rounding).
  double drift = 0, deficit = 0, drift_round = 0, deficit_round = 0;
  for (std::size_t k = 1; k <= found.size(); ++k) {
    const Episode& ep = found[k - 1];
    const auto tk = exact.impact_time(static_cast<std::int64_t>(k));
    const auto Vk = exact.impact_speed(static_cast<std::int64_t>(k));
    if (!tk || !Vk || *tk > t_end || ep.landing > t_end) break;
    ImpactRecord i;
    i.k = static_cast<std::int64_t>(k);
    i.theta = ep.theta;
    // A kick changes a flight's duration by at most 2 kick / g (fb_newton).
    const double allow_t = rd.time(std::fmin(*Vk, std::fabs(t.s[ep.first].v))) +
                           8 * kUnit * (*tk + h) + 2 * rd.kicks / g;
    i.delay = ep.landing - *tk;
    i.delay_bound = h * timing_factor(e, i.k);
    i.delay_round = allow_t;
    i.delay_identity = drift;
    i.delay_identity_round = allow_t + drift_round;
    deficit = e * deficit - e * g * ep.theta * h;
    deficit_round = e * deficit_round + e * g * allow_t + rd.velocity;
    drift += (1 - ep.theta) * h + 2 * deficit / g;
    drift_round += allow_t + 2 * deficit_round / g;
    // A bounce: one contact step, and the run goes on; else the scheme rests from here on.
    i.relaunched = ep.steps == 1 && k < found.size();
    i.speed = ep.relaunch - e * *Vk;
    i.speed_bound = speed_bound(g, h, e, i.k);
    i.speed_identity = deficit;
    i.speed_identity_round = deficit_round + rd.velocity;
    run.impacts.push_back(i);
    if (!i.relaunched) break;
  }
  // Rest: the run ends in a contact episode of at least kMinRestSteps steps, before T.
  const auto rest = exact.rest_time();
  if (e >= 1 || found.empty() || !rest || *rest > t_end) return run;
  const Episode& last = found.back();
  if (last.first + last.steps + 1 != t.s.size() ||
      last.steps < static_cast<std::size_t>(kMinRestSteps))
    return run;
  run.rest = static_cast<double>(last.first + 1) * h;
  run.rest_round = drift_round + 8 * kUnit * t_end;
  run.impacts_before_rest = static_cast<std::int64_t>(found.size());
  return run;
}

void check_zeno(const SceneRuns& r, std::vector<Check>& out) {
  const Model& m = r.scene.scene.model;
  if (r.scene.kind != CampaignKind::zeno || !m.cor || !(m.f < 0)) return;
  if (!r.direct.failed) check_bouncing(r, "s3.direct", r.direct, false, out);
  // Conjecture 3.4 needs gravity to win over the smoothing at the floor (a particle resting there
  // is kicked up by up to sqrt(eps) per step and pulled down by g h), and a run whose output
  // resolves the last bounces before rest, g h^2 / 8 high (fb_newton's contact steps are told
  // from its free steps by a gap below h sqrt(eps) / 2: on a floor at 1e6, whose ulp is 1.2e-10 m,
  // a lower bounce is not seen).
  const double h = r.scene.scene.grid.h;
  if (!r.fb_newton.failed && -m.f * h >= 10 * std::sqrt(r.eps) &&
      r.rounding.position <= 1e-3 * -m.f * h * h / 8)
    check_bouncing(r, "s3.fb_newton", r.fb_newton, true, out);
  if (!r.moreau_jean.failed) {
    const ExactSolution exact(m, r.scene.scene.initial);
    const auto t1 = exact.impact_time(1);
    const auto V1 = exact.impact_speed(1);
    // Conjecture 3.5 is for a first bounce that the grid resolves: 2 V_1 / g >= 2 h.
    if (t1 && V1 && *V1 >= -m.f * r.scene.scene.grid.h) {
      const Scene& s = r.scene.scene;
      const double bound =
          moreau_jean_sup_conjecture({*t1, *V1, -m.f, r.cor(), s.grid.h, s.grid.end()});
      if (std::isfinite(bound))
        out.push_back(
            make_check(r, "s3.moreau_jean.sup", sup_error(r, r.moreau_jean), bound,
                       r.rounding.stepped_position + s.grid.end() * r.rounding.stepped_velocity));
    }
  }
}

void check_located(const SceneRuns& r, std::vector<Check>& out) {
  if (r.scene.scene.model.harmonic || r.located.failed) return;
  const ExactSolution exact(r.scene.scene.model, r.scene.scene.initial);
  const double impacts = static_cast<double>(
      std::min<std::int64_t>(exact.impacts_until(r.scene.scene.grid.end()), 1 << 20));
  out.push_back(make_check(r, "located.direct_located.exact", sup_error(r, r.located), 0,
                           r.rounding.position * (1 + impacts)));
}

}  // namespace impact::error_analysis
