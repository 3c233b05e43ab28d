// Statements 2 (one impact) and 4 (without COR) of paper_notes/error_analysis.md checked on one
// scene's runs.
#include <algorithm>
#include <cmath>
#include <string>

#include "analysis/error_analysis/error_bounds.hpp"
#include "analysis/error_analysis/error_checks.hpp"

namespace impact::error_analysis {
namespace {

constexpr double kUnit = 0x1p-53;

// A landing within this fraction of a grid point: rounding decides which step is the contact step,
// and the identities of Statement 2 are discontinuous there (theta = 0 and theta = 1 differ by a
// step's delay); only the bounds, which hold for both, are checked.
constexpr double kAmbiguous = 1e-9;
bool ambiguous(double theta) {
  return theta < kAmbiguous || theta > 1 - kAmbiguous;
}

Check with_value(Check c, double value) {
  c.value = value;
  return c;
}

// What Statement 2 needs of a scene: a constant force and a first impact inside the run, with a
// positive speed; theta of the scheme's first contact step l.
struct FirstImpact {
  double t1 = 0, V = 0, f = 0, h = 0, e = 1;
  std::size_t l = 0;
  double theta = 0;
};
std::optional<FirstImpact> first_impact(const SceneRuns& r, const Trace& trace, bool smoothing,
                                        std::size_t last_step_needed) {
  const Scene& scene = r.scene.scene;
  if (scene.model.harmonic || trace.failed || !r.V1 || !(*r.V1 > 0)) return std::nullopt;
  const auto l = r.first_impact_step(trace, smoothing);
  if (!l || *l + last_step_needed > static_cast<std::size_t>(scene.grid.steps)) return std::nullopt;
  FirstImpact i{r.exact.first_impact, *r.V1, scene.model.f, scene.grid.h, r.cor(), *l, 0};
  i.theta = (i.t1 - static_cast<double>(*l) * i.h) / i.h;
  // fb_newton's contact step is told from a free one by its gap (impact_step): the run must
  // resolve the distance V h flown in a step (on a floor at 1e6 its ulp is 1.2e-10 m).
  if (smoothing && r.rounding.position > 1e-3 * i.V * i.h) return std::nullopt;
  return i;
}

// The exact solution is in its first flight after the impact at t1 + span (Lemma 2.1's
// hypothesis): not at rest after a plastic impact under f < 0, not yet back at the floor.
bool in_first_flight(const FirstImpact& i, double span) {
  if (i.f >= 0) return true;
  return i.e > 0 && span < 2 * i.e * i.V / -i.f;
}

void check_direct_cor(const SceneRuns& r, const char* name, const Trace& trace, bool smoothing,
                      std::vector<Check>& out) {
  const auto i = first_impact(r, trace, smoothing, 1);
  if (!i || !(i->V > std::fmax(i->f, 0.0) * i->h / 2)) return;
  const std::string p = std::string("s2.") + name;
  const Rounding& rd = r.rounding;
  // The contact step is the one the exact impact falls in: theta in [0, 1), to the time resolution
  // of the run's output (its gaps are known to rd.position, a bounce lower than the floor's ulp
  // is not resolved at all).
  out.push_back(make_check(r, p + ".theta", std::fmax(0.0, std::fmax(-i->theta, i->theta - 1)), 0,
                           kAmbiguous + rd.time(i->V) / i->h));
  const std::size_t l = i->l;
  // fb_newton: its contact step stops a_{l+1} <= h sqrt(eps) / 2 above the floor; its v^l carries
  // the kicks of the flight before (Lemma 1.3), which the COR law scales by e.
  const KickSum kicks = smoothing ? kicks_before(r, l) : KickSum{};
  const double smooth_u = smoothing ? i->h * std::sqrt(r.eps) / 2 : 0.0;
  const double smooth_v = smoothing ? kKickRounding * i->e * kicks.velocity : 0.0;
  // The time: the linear crossing t_l + g^l / |v^l|, Lemma 2.1 (c).
  const State& before = trace.s[l];
  if (before.v < 0 && i->V > std::fmax(0.0, -i->f) * i->h) {
    const double crossing = static_cast<double>(l) * i->h + r.gap(trace, l) / -before.v;
    // fb_newton's kicks raise g^l and |v^l| changes by at most their sum (Lemma 1.3).
    const double allow = rd.time(-before.v) + 8 * kUnit * i->t1 +
                         kKickRounding * (kicks.position + i->h * kicks.velocity) / -before.v;
    out.push_back(make_check(r, p + ".time", std::fabs(crossing - i->t1),
                             linear_crossing_bound(i->V, i->f, i->h), allow, i->theta));
    if (!ambiguous(i->theta))
      out.push_back(make_check(
          r, p + ".time_identity",
          std::fabs(crossing - i->t1 - linear_crossing_error(i->V, i->theta, i->f, i->h)), 0, allow,
          i->theta));
  }
  if (!in_first_flight(*i, (1 - i->theta) * i->h)) return;
  const double du = trace.s[l + 1].u - r.exact.s[l + 1].u;
  const double dv = trace.s[l + 1].v - r.exact.s[l + 1].v;
  const ImpactError bound = direct_cor_impact_bound(i->V, i->f, i->h, i->e);
  out.push_back(with_value(
      make_check(r, p + ".du", std::fabs(du), bound.du, rd.position + smooth_u, i->theta), du));
  out.push_back(with_value(
      make_check(r, p + ".dv", std::fabs(dv), bound.dv, rd.velocity + smooth_v, i->theta), dv));
  if (ambiguous(i->theta)) return;
  const ImpactError id = direct_cor_impact(i->V, i->theta, i->f, i->h, i->e);
  out.push_back(make_check(r, p + ".du_identity", std::fabs(du - id.du), 0,
                           rd.position + rd.time(i->V) * i->V + smooth_u, i->theta));
  out.push_back(make_check(r, p + ".dv_identity", std::fabs(dv - id.dv), 0, rd.velocity + smooth_v,
                           i->theta));
}

void check_moreau_jean(const SceneRuns& r, std::vector<Check>& out) {
  const Trace& trace = r.moreau_jean;
  if (trace.failed || r.scene.scene.model.harmonic) return;
  // m: the first step with an impulse.
  std::size_t m = 0;
  while (m + 1 < trace.N.size() && !(trace.N[m + 1] > 0)) ++m;
  if (m + 1 >= trace.N.size() || !r.V1) return;
  FirstImpact i{
      r.exact.first_impact, *r.V1, r.scene.scene.model.f, r.scene.scene.grid.h, r.cor(), m, 0};
  i.theta = (i.t1 - static_cast<double>(m) * i.h) / i.h;  // sigma
  if (!(i.V >= 2 * std::fabs(i.f) * i.h)) return;
  const Rounding& rd = r.rounding;
  out.push_back(make_check(r, "s2.moreau_jean.sigma", std::fabs(i.theta),
                           moreau_jean_sigma_bound(i.V, i.f, i.h), kAmbiguous, i.theta));
  if (!in_first_flight(i, (1 - i.theta) * i.h)) return;
  const double du = trace.s[m + 1].u - r.exact.s[m + 1].u;
  const double dv = trace.s[m + 1].v - r.exact.s[m + 1].v;
  const ImpactError bound = moreau_jean_impact_bound(i.V, i.f, i.h, i.e);
  out.push_back(with_value(
      make_check(r, "s2.moreau_jean.du", std::fabs(du), bound.du, rd.stepped_position, i.theta),
      du));
  out.push_back(with_value(
      make_check(r, "s2.moreau_jean.dv", std::fabs(dv), bound.dv, rd.stepped_velocity, i.theta),
      dv));
  const ImpactError id = moreau_jean_impact(i.V, i.theta, i.f, i.h, i.e);
  out.push_back(make_check(r, "s2.moreau_jean.du_identity", std::fabs(du - id.du), 0,
                           rd.stepped_position + rd.time(i.V) * i.V, i.theta));
  out.push_back(
      make_check(r, "s2.moreau_jean.dv_identity", std::fabs(dv - id.dv), 0, rd.stepped_velocity));
}

// Statement 2 carried through the free flight that follows when f >= 0 (no second impact): the
// sup error over the run is at most |du| + (t_n - t_{l+1}) |dv| with Lemma 2.1's (2.3's) bounds.
void check_single(const SceneRuns& r, std::vector<Check>& out) {
  const Model& m = r.scene.scene.model;
  const bool elastic_f0 = r.scene.kind == CampaignKind::no_cor && m.f == 0;
  if ((r.scene.kind != CampaignKind::single && !elastic_f0) || m.f < 0 || !r.V1) return;
  const double t_end = r.scene.scene.grid.end(), h = r.scene.scene.grid.h;
  const auto sup = [&](const Trace& t) {
    double worst = 0;
    for (std::size_t l = 0; l < t.s.size(); ++l)
      worst = std::fmax(worst, std::fabs(t.s[l].u - r.exact.s[l].u));
    return worst;
  };
  const double e = r.cor(), V = *r.V1, f = m.f;
  if (!r.direct.failed && m.cor && V > f * h / 2) {
    const ImpactError b = direct_cor_impact_bound(V, f, h, e);
    out.push_back(make_check(r, "s2.direct.sup_single", sup(r.direct), b.du + t_end * b.dv,
                             r.rounding.position + t_end * r.rounding.velocity));
  }
  if (!r.moreau_jean.failed && V >= 2 * f * h) {
    const ImpactError b = moreau_jean_impact_bound(V, f, h, e);
    // Before its activation moreau_jean may be below the floor while the exact particle has
    // bounced: (1 + e) V sigma-bar h more.
    const double before = (1 + e) * V * h * moreau_jean_sigma_bound(V, f, h);
    out.push_back(make_check(r, "s2.moreau_jean.sup_single", sup(r.moreau_jean),
                             std::fmax(before, b.du + t_end * b.dv),
                             r.rounding.stepped_position + t_end * r.rounding.stepped_velocity));
  }
}

// Statement 2 for moreau_jean without COR (e = 1), with the elastic f = 0 scene's sup error.
void check_moreau_jean_elastic(const SceneRuns& r, std::vector<Check>& out) {
  check_moreau_jean(r, out);
  check_single(r, out);
}

}  // namespace

void check_impact(const SceneRuns& r, std::vector<Check>& out) {
  if (!r.scene.scene.model.cor) return;  // without COR: check_no_cor
  check_direct_cor(r, "direct", r.direct, false, out);
  check_direct_cor(r, "fb_newton", r.fb_newton, true, out);
  check_moreau_jean(r, out);
  check_single(r, out);
}

// Statement 4: without COR the contact step's rebound is V (1 - 2 theta) + f theta (1 - theta) h
// (Lemma 2.2): an effective COR |1 - 2 theta| within |f| h / (4 V); for f = 0 the scheme stays
// 2 min(theta, 1 - theta) V (t - t*) below the elastic solution (Proposition 4.2).
void check_no_cor(const SceneRuns& r, std::vector<Check>& out) {
  if (r.scene.scene.model.cor) return;
  check_moreau_jean_elastic(r, out);
  struct Scheme {
    const char* name;
    const Trace& trace;
    bool smoothing;
  };
  for (const Scheme& s :
       {Scheme{"direct", r.direct, false}, Scheme{"fb_newton", r.fb_newton, true}}) {
    const auto i = first_impact(r, s.trace, s.smoothing, 2);
    if (!i || i->f > 0) continue;
    const std::string p = std::string("s4.") + s.name;
    // fb_newton: its contact step's velocity is within sqrt(eps) of direct's (Lemma 2.2), its v^l
    // and the free flight to it carry the kicks before (Lemma 1.3), whose displacement of u^l
    // the rebound 2 (phi - u^l) / h - v^l multiplies by 2 / h.
    const KickSum kicks = s.smoothing ? kicks_before(r, i->l) : KickSum{};
    const double smooth_v =
        s.smoothing
            ? std::sqrt(r.eps) + 2 * kKickRounding * (kicks.velocity + kicks.position / i->h)
            : 0.0;
    const double rebound = s.trace.s[i->l + 1].v;
    if (!ambiguous(i->theta))
      out.push_back(
          make_check(r, p + ".rebound_identity",
                     std::fabs(rebound - direct_scheme_rebound(i->V, i->theta, i->f, i->h)), 0,
                     r.rounding.rebound + smooth_v, i->theta));
    // The speed the particle leaves the floor with: at t_{l+1}, or at t_{l+2} when the contact
    // step's velocity points down (the next step is a contact step too).
    const double leave = rebound > 0 ? rebound : s.trace.s[i->l + 2].v;
    const double theta = std::clamp(i->theta, 0.0, 1.0);
    out.push_back(with_value(
        make_check(r, p + ".effective_cor", std::fabs(leave / i->V - std::fabs(1 - 2 * theta)),
                   std::fabs(i->f) * i->h / (4 * i->V), (2 * r.rounding.rebound + smooth_v) / i->V,
                   theta),
        leave / i->V));
    const std::size_t n = s.trace.s.size() - 1;
    if (i->f == 0 && n >= i->l + 2) {
      const double t_n = r.scene.scene.grid.end();
      out.push_back(make_check(r, p + ".lower_bound", std::fabs(s.trace.s[n].u - r.exact.s[n].u),
                               no_cor_lower_bound(i->V, theta, i->t1, t_n),
                               r.rounding.position + t_n * (r.rounding.rebound + smooth_v), theta,
                               true));
    }
  }
}

}  // namespace impact::error_analysis
