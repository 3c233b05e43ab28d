#include "analysis/convergence.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <variant>

#include "analysis/experiment.hpp"
#include "analysis/quadrature.hpp"
#include "impact/output.hpp"
#include "impact/registry.hpp"
#include "scene/read_scene.hpp"

namespace impact {

namespace {

// The scene of one run, with the scene reader's grid rule and the method's default parameters.
Scene scene_of(std::string_view method, const Model& model, const State& initial, double T,
               double h) {
  const MethodInfo* info = find_method(method);
  if (!info) throw std::invalid_argument("unknown method '" + std::string(method) + "'");
  return make_scene(model, initial, T, h, info->defaults);
}

// The impact times in (0, T] and the time the particle comes to rest, if it does: where u has kinks
// and the cumulative impulse jumps. Before a Zeno accumulation the impact times crowd together;
// one closer than kMinSpacing to the previous kept time is dropped (its jump, at most
// (1 + e) e^k V1, falls below the quadrature tolerance long before the spacing does, and GSL
// cannot subdivide intervals a few ulp wide).
std::vector<double> impact_times(const ExactSolution& x, double T) {
  constexpr std::int64_t kImpactCap = 400;
  const double min_spacing = 1e-9 * std::fmax(1.0, T);
  std::vector<double> times;
  for (std::int64_t k = 1; k <= kImpactCap; ++k) {
    const auto t = x.impact_time(k);
    if (!t || *t > T) break;
    if (times.empty() || *t - times.back() > min_spacing) times.push_back(*t);
  }
  if (const auto rest = x.rest_time(); rest && *rest <= T) times.push_back(*rest);
  return times;
}

}  // namespace

ConvergencePoint measure_convergence(std::string_view method, const Model& model,
                                     const State& initial, double T, double h,
                                     const std::optional<Model>& reference) {
  const Scene scene = scene_of(method, model, initial, T, h);
  AnyStepper stepper = make_stepper(scene);
  ConvergencePoint point;
  point.h = scene.grid.h;
  point.t_end = scene.grid.t(scene.grid.steps);
  point.initial = scene.initial;
  point.f = scene.model.f;
  point.tallies.last = scene.initial;
  std::visit(
      [&](auto& inner) {
        TallyingStepper tallying(inner, scene.model, scene.grid.h, point.tallies);
        point.errors =
            measure_errors(tallying, reference.value_or(scene.model), scene.initial, scene.grid);
      },
      stepper);
  point.final = point.tallies.last;
  return point;
}

double sup_distance(std::string_view method_a, std::string_view method_b, const Model& model,
                    const State& initial, double T, double h) {
  const Scene scene_a = scene_of(method_a, model, initial, T, h);
  const Scene scene_b = scene_of(method_b, model, initial, T, h);
  AnyStepper a = make_stepper(scene_a), b = make_stepper(scene_b);
  return std::visit(
      [&](auto& stepper_a, auto& stepper_b) {
        LockstepStepper pair(stepper_a, stepper_b, scene_a.initial, scene_a.grid.h);
        simulate(pair, scene_a.initial, scene_a.grid,
                 [](std::int64_t, const State&, const StepInfo&) {});
        return pair.sup_distance();
      },
      a, b);
}

double sup_distance(const ExactSolution& u, const ExactSolution& w, double T) {
  constexpr int kSamples = 10000;
  std::vector<double> times = impact_times(u, T);
  const std::vector<double> w_times = impact_times(w, T);
  times.insert(times.end(), w_times.begin(), w_times.end());
  for (int i = 0; i <= kSamples; ++i) times.push_back(T * i / kSamples);
  double sup = 0;
  for (double t : times) sup = std::fmax(sup, std::fabs(u.at(t).u - w.at(t).u));
  return sup;
}

WeakSolutionCheck check_weak_solution(const ExactSolution& x, const Model& model, double T) {
  constexpr int kSamples = 100000;
  const std::vector<double> kinks = impact_times(x, T);
  WeakSolutionCheck check;

  // (2-2), u >= phi: on a fine sampling and at the impact times.
  check.min_gap = x.at(0).u - model.phi;
  for (int i = 0; i <= kSamples; ++i)
    check.min_gap = std::fmin(check.min_gap, x.at(T * i / kSamples).u - model.phi);
  for (double t : kinks) check.min_gap = std::fmin(check.min_gap, x.at(t).u - model.phi);

  // (2-2), N >= 0 as a measure: the impulse of every cell of a partition of (0, T] whose points
  // include each impact time (so each atom falls into one cell) is >= 0.
  std::vector<double> partition;
  for (int i = 0; i <= kSamples / 10; ++i) partition.push_back(T * i / (kSamples / 10));
  partition.insert(partition.end(), kinks.begin(), kinks.end());
  std::sort(partition.begin(), partition.end());
  check.min_cell_impulse = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < partition.size(); ++i)
    check.min_cell_impulse =
        std::fmin(check.min_cell_impulse, x.impulse(partition[i], partition[i + 1]));
  check.total_impulse = x.impulse(0, T);

  // (2-2), N (u - phi) = 0: int_(0,T] (u - phi) dI with I(t) = impulse(0, t) the cumulative
  // impulse, by parts for the continuous u: (u(T) - phi) I(T) - int_0^T I u' dt.
  // Each piece is a polynomial (u, v, I between impacts) times a smooth bump: the 21-point rule
  // reaches the round-off level with few subdivisions.
  Quadrature quad;
  const Quadrature::Rule rule{1e-13, 1e-12, GSL_INTEG_GAUSS21};
  const auto cumulative = [&](double t) { return x.impulse(0, t); };
  check.complementarity = (x.at(T).u - model.phi) * check.total_impulse -
                          quad.integrate([&](double t) { return cumulative(t) * x.at(t).v; }, 0, T,
                                         kinks, rule, "weak solution check");

  // (2-1) in the sense of distributions: int u psi'' = int psi dN + f int psi, where
  // int psi dN = -int psi' I dt (psi vanishes at the ends of its support). The bumps cover [0, T]
  // at three widths, plus one centred on each of the first impacts.
  std::vector<Bump> bumps;
  for (double radius : {T / 40, T / 10, T / 4})
    for (double c = radius * 1.01; c + radius * 1.01 < T; c += radius / 2)
      bumps.push_back({c, radius});
  for (std::size_t k = 0; k < kinks.size() && k < 8; ++k) {
    const double r = std::fmin(0.5, 0.99 * std::fmin(kinks[k], T - kinks[k]));
    if (r > 0) bumps.push_back({kinks[k], r});
  }
  for (const Bump& psi : bumps) {
    const double a = psi.center - psi.radius, b = psi.center + psi.radius;
    const double u_psi2 = quad.integrate([&](double t) { return x.at(t).u * psi.second(t); }, a, b,
                                         kinks, rule, "weak solution check");
    const double psi_dN = -quad.integrate([&](double t) { return psi.first(t) * cumulative(t); }, a,
                                          b, kinks, rule, "weak solution check");
    const double f_psi = model.f * quad.integrate([&](double t) { return psi.value(t); }, a, b, {},
                                                  rule, "weak solution check");
    check.max_weak_residual =
        std::fmax(check.max_weak_residual, std::fabs(u_psi2 - psi_dN - f_psi));
    check.max_weak_scale = std::fmax(check.max_weak_scale, std::fabs(u_psi2));
  }
  check.test_functions = static_cast<int>(bumps.size());
  return check;
}

EnergyIdentity412 energy_identity_412(const ExactSolution& u, const ExactSolution& w,
                                      const Model& model, double t) {
  const State u0 = u.at(0), w0 = w.at(0), ut = u.at(t), wt = w.at(t);
  EnergyIdentity412 r;
  const double z0 = u0.v - w0.v, zt = ut.v - wt.v;
  r.lhs = (zt * zt - z0 * z0) / 2;
  r.paper_rhs = -ut.v * wt.v + u0.v * w0.v;
  r.force_terms = model.f * (ut.u - u0.u + wt.u - w0.u);
  r.dropped_n1_u = energy(model, ut) - energy(model, u0);
  r.dropped_n2_w = energy(model, wt) - energy(model, w0);
  r.paper_413 = zt * zt - z0 * z0;
  return r;
}

toml::table order_fit_table(const OrderFit& fit) {
  return toml::table{{"order", fit.order},
                     {"h_min", fit.h_min},
                     {"h_max", fit.h_max},
                     {"points", static_cast<std::int64_t>(fit.points)},
                     {"max_log_deviation", fit.max_log_deviation}};
}

}  // namespace impact
