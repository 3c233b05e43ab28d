#include "analysis/error_analysis/error_sweeps.hpp"

#include <cmath>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/error_analysis/error_bounds.hpp"
#include "analysis/error_analysis/error_checks.hpp"
#include "analysis/error_analysis/error_run.hpp"
#include "analysis/fit.hpp"
#include "analysis/work_precision_curves.hpp"
#include "impact/run/error_norms.hpp"
#include "scene/read_scene.hpp"

namespace impact::error_analysis {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
// Errors below this are rounding (the work-precision study leaves them out of its fits too).
constexpr double kRounding = 1e-10;

Scene with_step(Scene scene, double T, double h) {
  return make_scene(scene.model, scene.initial, T, h, scene.method);
}

std::vector<Check> checks_of(CampaignKind kind, const Scene& scene) {
  std::vector<Check> out;
  check_scene({kind, scene}, 0, out);
  return out;
}

// The check `name` of a scene's checks, or nullptr.
const Check* find(const std::vector<Check>& checks, std::string_view name) {
  for (const Check& c : checks)
    if (c.name == name) return &c;
  return nullptr;
}

// A CSV of rows of numbers, 17 significant digits.
class Csv {
 public:
  explicit Csv(std::string_view header) { out_ << header << '\n'; }
  Csv& operator<<(const std::vector<double>& row) {
    out_.precision(17);
    for (std::size_t i = 0; i < row.size(); ++i) out_ << (i ? "," : "") << row[i];
    out_ << '\n';
    return *this;
  }
  std::string text() const { return out_.str(); }

 private:
  std::ostringstream out_;
};

double measured(const Check* c) {
  return c ? c->measured : kNan;
}
double bound(const Check* c) {
  return c ? c->bound : kNan;
}
double worst(double a, const Check* c) {
  const double q = c ? c->ratio() : kNan;
  return std::isfinite(q) ? std::fmax(a, q) : a;
}

Scene scene_file(const ExperimentContext& context, const char* experiment, const char* file) {
  return load_scene(context.scene_path(experiment, file));
}

// max_l |u^l - u(t_l)| and max_l |v^l - v(t_l)| of a run over l <= end.
State sup_errors(const Trace& t, const Trace& exact, std::size_t end) {
  State worst;
  for (std::size_t l = 0; l <= end && l < t.s.size(); ++l) {
    worst.u = std::fmax(worst.u, std::fabs(t.s[l].u - exact.s[l].u));
    worst.v = std::fmax(worst.v, std::fabs(t.s[l].v - exact.s[l].v));
  }
  return worst;
}

// Statement 1: the flight of error_analysis/flight.toml before its first impact (Lemma 1.2's
// bound at the last grid time before it, where it is largest); fb_newton's smoothing before
// Figure 4's first impact (T = 0.9 s < t_1 = 0.913 s: Lemma 1.3's bound at T).
toml::table flight_sweep(const ExperimentContext& context, int points) {
  const Scene forced = scene_file(context, "error_analysis", "flight.toml");
  const Scene fig4 = scene_file(context, "figure4", "cor075.toml");
  const Harmonic& w = *forced.model.harmonic;
  Csv csv("h,direct,moreau_jean,bound,fb_newton_u,fb_newton_u_bound,fb_newton_v,fb_newton_v_bound");
  double ratio = 0;
  for (double h : log_spaced(1e-1, 1e-4, points)) {
    const CampaignScene f{CampaignKind::forced, with_step(forced, forced.T, h)};
    const SceneRuns r = run_scene_runs(f, 0);
    const auto end = static_cast<std::size_t>(std::floor(r.exact.first_impact / h));
    const double bound =
        harmonic_flight_bound(w.amplitude, w.omega, h, static_cast<double>(end) * h);
    const double direct = sup_errors(r.direct, r.exact, end).u;
    const CampaignScene s{CampaignKind::zeno, with_step(fig4, 0.9, h)};
    const SceneRuns q = run_scene_runs(s, 0);
    const std::size_t n = q.exact.s.size() - 1;
    const State fb = sup_errors(q.fb_newton, q.exact, n);
    const KickSum kicks = kicks_before(q, n);
    csv << std::vector<double>{h,     direct,        sup_errors(r.moreau_jean, r.exact, end).u,
                               bound, fb.u,          kicks.position,
                               fb.v,  kicks.velocity};
    ratio = std::fmax(ratio, direct / bound);
  }
  context.write("flight.csv", [&] { return csv.text(); });
  return toml::table{{"direct_largest_ratio", ratio}};
}

// Statement 2: Figure 4's first impact (V = 9.95 m/s at t_1 = 0.913 s), T = 1 s.
toml::table impact_sweep(const ExperimentContext& context, int points) {
  const Scene fig4 = scene_file(context, "figure4", "cor075.toml");
  Scene no_cor = fig4;
  no_cor.model.cor.reset();
  Csv csv(
      "h,theta,du,du_bound,dv,dv_bound,time,time_bound,sigma,du_mj,du_mj_bound,dv_mj,dv_mj_bound,"
      "theta_no_cor,effective_cor,effective_cor_bound");
  double ratio_u = 0, ratio_mj = 0;
  for (double h : log_spaced(2e-2, 1e-4, points)) {
    const std::vector<Check> c = checks_of(CampaignKind::zeno, with_step(fig4, 1.0, h));
    const std::vector<Check> n = checks_of(CampaignKind::no_cor, with_step(no_cor, 1.0, h));
    const Check *du = find(c, "s2.direct.du"), *dv = find(c, "s2.direct.dv");
    const Check *tm = find(c, "s2.direct.time"), *mu = find(c, "s2.moreau_jean.du");
    const Check *mv = find(c, "s2.moreau_jean.dv"), *ec = find(n, "s4.direct.effective_cor");
    if (!du || !dv || !tm || !mu || !mv || !ec) continue;
    csv << std::vector<double>{
        h,     du->x,     du->value, du->bound, dv->value, dv->bound, tm->measured, tm->bound,
        mu->x, mu->value, mu->bound, mv->value, mv->bound, ec->x,     ec->value,    ec->bound};
    ratio_u = worst(ratio_u, du);
    ratio_mj = worst(ratio_mj, mu);
  }
  context.write("impact.csv", [&] { return csv.text(); });
  return toml::table{{"direct_du_worst_ratio", ratio_u}, {"moreau_jean_du_worst_ratio", ratio_mj}};
}

// Statement 3 on Figure 4 with COR 0.75 (T = 10 s, t_inf = 7.0026 s).
toml::table zeno_sweep(const ExperimentContext& context, int points) {
  const Scene fig4 = scene_file(context, "figure4", "cor075.toml");
  Csv csv("h,sup,sup_bound,sup_mj,sup_mj_conjecture,rest,rest_bound,impacts,max_impacts");
  std::vector<double> hs, rest;
  for (double h : log_spaced(3e-2, 1e-4, points)) {
    const std::vector<Check> c = checks_of(CampaignKind::zeno, with_step(fig4, fig4.T, h));
    const Check *s = find(c, "s3.direct.sup"), *r = find(c, "s3.direct.rest");
    const Check *m = find(c, "s3.moreau_jean.sup"), *k = find(c, "s3.direct.impacts");
    csv << std::vector<double>{h,           measured(s), bound(s),    measured(m), bound(m),
                               measured(r), bound(r),    measured(k), bound(k)};
    if (r) hs.push_back(h), rest.push_back(r->measured);
  }
  context.write("zeno.csv", [&] { return csv.text(); });
  for (int i : {2, 3, 4}) {
    const CampaignScene scene{CampaignKind::zeno, with_step(fig4, fig4.T, std::pow(10.0, -i))};
    const SceneRuns runs = run_scene_runs(scene, 0);
    Csv per_impact("k,theta,delay,delay_bound,delay_identity,speed,speed_bound");
    for (const ImpactRecord& r : bouncing_run(runs, runs.direct, runs.rounding).impacts)
      per_impact << std::vector<double>{
          static_cast<double>(r.k), r.theta, r.delay,      r.delay_bound,
          r.delay_identity,         r.speed, r.speed_bound};
    context.write("zeno_k_" + std::to_string(i) + ".csv", [&] { return per_impact.text(); });
  }
  const OrderFit fit = fit_order(hs, rest);
  return toml::table{{"rest_time_order", fit.order},
                     {"rest_time_points", static_cast<std::int64_t>(hs.size())}};
}

// Statement 4 on the off-grid scene: f = 0, u0 = pi, v0 = -1 m/s, no COR, T = 10 s. The error "at
// T" is at the grid's last time t_n <= T (Grid::covering: short of T by less than h when h does
// not divide T); the same sweep with h = T / round(T / h), whose grids end at T, puts theta
// elsewhere and gives another smallest error (C93 cites both).
toml::table no_cor_sweep(const ExperimentContext& context, int points) {
  const Scene offgrid = scene_file(context, "work_precision", "offgrid.toml");
  Csv csv("h,theta,error_T,lower_bound,sup_mj,sup_mj_bound");
  double smallest_error = INFINITY;
  for (double h : log_spaced(1e-1, 1e-4, points)) {
    const std::vector<Check> c = checks_of(CampaignKind::no_cor, with_step(offgrid, offgrid.T, h));
    const Check *d = find(c, "s4.direct.lower_bound"), *m = find(c, "s2.moreau_jean.sup_single");
    if (!d || !m) continue;
    csv << std::vector<double>{h, d->x, d->measured, d->bound, m->measured, m->bound};
    smallest_error = std::fmin(smallest_error, d->measured);
  }
  double smallest_ending_at_T = INFINITY;
  for (double h : log_spaced(1e-1, 1e-4, points)) {
    const double ending_at_T = offgrid.T / std::round(offgrid.T / h);
    const std::vector<Check> c =
        checks_of(CampaignKind::no_cor, with_step(offgrid, offgrid.T, ending_at_T));
    if (const Check* d = find(c, "s4.direct.lower_bound"))
      smallest_ending_at_T = std::fmin(smallest_ending_at_T, d->measured);
  }
  context.write("no_cor.csv", [&] { return csv.text(); });
  return toml::table{{"direct_smallest_error_at_T", smallest_error},
                     {"direct_smallest_error_at_T_grid_ending_at_T", smallest_ending_at_T}};
}

// On the period-1 table, direct_located's sup error over h^2 at the steps h <= 1e-2, where the
// O(h^3) term is below 0.5% of it, against Conjecture L.3's leading constant
// (located_period1_constant): the constant, not only the order, is what tells the located scheme
// from one whose velocities carry an O(h^2) error of their own at each impact.
void insert_located_constant(toml::table& t, const Scene& scene, const std::vector<double>& hs,
                             const std::vector<double>& errors) {
  double lo = INFINITY, hi = 0;
  for (std::size_t i = 0; i < hs.size(); ++i) {
    if (hs[i] > 1e-2 * (1 + 1e-9)) continue;
    lo = std::fmin(lo, errors[i] / (hs[i] * hs[i]));
    hi = std::fmax(hi, errors[i] / (hs[i] * hs[i]));
  }
  const Harmonic& table = *scene.model.harmonic;
  t.insert("located_constant_min", lo);
  t.insert("located_constant_max", hi);
  t.insert("located_constant_predicted",
           located_period1_constant(-scene.model.f, table.amplitude, table.omega, *scene.model.cor,
                                    scene.T));
}

// direct_located against direct and moreau_jean: sup |u^l - u(t_l)| over the work-precision steps.
toml::table located_sweep(const ExperimentContext& context, double h_min) {
  struct Named {
    const char *name, *experiment, *file;
    bool period1 = false;  // the period-1 table: Conjecture L.3's constant
  };
  const Named scenes[] = {{"figure3_no_cor", "figure3", "no_cor.toml"},
                          {"figure3_cor075", "figure3", "cor075.toml"},
                          {"figure4_cor075", "figure4", "cor075.toml"},
                          {"table_period1", "work_precision", "table_period1.toml", true}};
  Csv csv("scene,h,direct_located,direct,moreau_jean");
  toml::table summary;
  for (std::size_t i = 0; i < std::size(scenes); ++i) {
    const Scene base = scene_file(context, scenes[i].experiment, scenes[i].file);
    std::vector<double> hs, located, direct, mj;
    for (double h : swept_steps()) {
      if (h < h_min * (1 - 1e-9)) continue;
      const Scene scene = with_step(base, base.T, h);
      const auto sup = [&](const MethodParams& method) {
        Scene s = scene;
        s.method = method;
        AnyStepper stepper = make_stepper(s);
        return std::visit(
            [&](auto& st) { return measure_errors(st, s.model, s.initial, s.grid).sup_u; },
            stepper);
      };
      hs.push_back(h);
      located.push_back(sup(DirectLocatedParams{}));
      direct.push_back(sup(DirectParams{}));
      mj.push_back(sup(MoreauJeanParams{}));
      csv << std::vector<double>{static_cast<double>(i), h, located.back(), direct.back(),
                                 mj.back()};
    }
    double largest = 0;
    for (double e : located) largest = std::fmax(largest, e);
    toml::table t{{"located_largest_error", largest},
                  {"direct_order", fit_order(hs, direct).order},
                  {"moreau_jean_order", fit_order(hs, mj).order}};
    // An order fitted to rounding says nothing (and moves with the platform's last bits).
    if (largest > kRounding) t.insert("located_order", fit_order(hs, located).order);
    if (scenes[i].period1) insert_located_constant(t, base, hs, located);
    summary.insert(scenes[i].name, std::move(t));
  }
  context.write("located.csv", [&] { return csv.text(); });
  return summary;
}

}  // namespace

toml::table run_sweeps(const ExperimentContext& context, const ErrorSweepOptions& options) {
  return toml::table{{"flight", flight_sweep(context, options.sweep_points)},
                     {"impact", impact_sweep(context, options.impact_points)},
                     {"zeno", zeno_sweep(context, options.sweep_points)},
                     {"no_cor", no_cor_sweep(context, options.sweep_points)},
                     {"located", located_sweep(context, options.located_h_min)}};
}

}  // namespace impact::error_analysis
