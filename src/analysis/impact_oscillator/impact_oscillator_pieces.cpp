// The diagrams, grazing, chatter and work-precision pieces of the experiment impact_oscillator.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "analysis/impact_oscillator/impact_oscillator.hpp"
#include "analysis/impact_oscillator/oscillator_grazing.hpp"
#include "analysis/impact_oscillator/oscillator_law.hpp"
#include "analysis/impact_oscillator/oscillator_orbits.hpp"
#include "analysis/impact_oscillator/oscillator_work_precision.hpp"
#include "analysis/work_precision_lyapunov.hpp"
#include "impact/format.hpp"
#include "scene/read_scene.hpp"

namespace impact::impact_oscillator {

namespace {

// 100 periods of transient, the impacts of the next 40 kept (at most 32 per point).
const DiagramSettings kDiagram{100, 40, 32};
// A diagram point is on the period-one branch when its kept impacts all lie within this of the
// closed-form speed; its agreement is reported where the multiplier is at most kSettled (the
// transient of 100 periods has then shrunk a step of the sweep's by 0.9^100 = 3e-5 or more).
constexpr double kOnBranch = 1e-6, kSettled = 0.9;

struct DiagramSpec {
  SweepParameter parameter;
  const char* name;
  double low, high, step;
  State low_start, high_start;
};

toml::table diagram_piece(const ExperimentContext& context, const DiagramSpec& spec) {
  const std::vector<double> up = parameter_grid(spec.low, spec.high, spec.step);
  const std::vector<double> down = parameter_grid(spec.high, spec.low, -spec.step);
  const auto rising = sweep(spec.parameter, kAcceptance, up, spec.low_start, kDiagram);
  const auto falling = sweep(spec.parameter, kAcceptance, down, spec.high_start, kDiagram);
  context.write(std::string("diagram_") + spec.name + ".csv", [&] {
    return "direction,parameter,kind,phase,V\n" + diagram_rows(rising, "up", spec.parameter) +
           diagram_rows(falling, "down", spec.parameter);
  });
  context.write(std::string("branches_") + spec.name + ".csv", [&] {
    return "parameter,stable,unstable,saddle,phase,saddle_phase\n" +
           branch_rows(spec.parameter, kAcceptance,
                       parameter_grid(spec.low, spec.high, spec.step / 4));
  });
  std::int64_t failures = 0, sticking = 0, stable = 0, on_branch = 0;
  double worst = 0;
  for (const auto* points : {&rising, &falling})
    for (const DiagramPoint& p : *points) {
      failures += !p.converged;
      sticking += p.sticks > 0;
      const auto orbit = period_one_orbit(p.o);
      if (!orbit || !orbit_is_admissible(p.o, *orbit)) continue;
      const double multiplier = leading_multiplier(orbit_trace(p.o, orbit->V), p.o.r);
      if (multiplier >= 1.0) continue;
      ++stable;
      double error = p.events.empty() ? INFINITY : 0.0;
      for (const Event& e : p.events)
        error = std::fmax(
            error, e.kind == EventKind::impact ? std::fabs(-e.v_before - orbit->V) : INFINITY);
      if (error > kOnBranch) continue;
      ++on_branch;
      if (multiplier <= kSettled) worst = std::fmax(worst, error);
    }
  return toml::table{{"points", static_cast<std::int64_t>(up.size() + down.size())},
                     {"failures", failures},
                     {"points_with_rests", sticking},
                     {"stable_orbit_points", stable},
                     {"on_branch_points", on_branch},
                     {"on_branch_max_V_error", worst}};
}

std::string event_rows(const char* runner, const std::vector<Event>& events) {
  std::ostringstream out;
  for (const Event& e : events)
    out << runner << ',' << event_name(e.kind) << ',' << round_trip(e.t) << ','
        << round_trip(e.v_before) << '\n';
  return out.str();
}

std::optional<double> first_event(const std::vector<Event>& events, EventKind kind) {
  for (const Event& e : events)
    if (e.kind == kind) return e.t;
  return std::nullopt;
}

// The sticking run of the chatter figure: from the wall with this speed, over this time.
constexpr double kStickingSpeed = 0.05, kStickingT = 3.0;

}  // namespace

toml::table diagram_summary(const ExperimentContext& context) {
  const State start{1.0, 0.0};
  return toml::table{
      {"sigma",
       diagram_piece(context,
                     {SweepParameter::sigma, "sigma", -1.9, 0.3, 0.005, {2.9, 0.0}, start})},
      {"omega",
       diagram_piece(context, {SweepParameter::omega, "omega", 1.5, 5.0, 0.005, start, start})}};
}

toml::table grazing_summary(const ExperimentContext& context) {
  const GrazingLaw law = grazing_law(kOmega, kRestitution, -10, 4, 9, true);
  context.write("grazing.csv", [&] {
    std::ostringstream out;
    out << "delta,V,exact,event_driven,orbit_V\n";
    for (const GrazingPoint& p : law.points)
      out << round_trip(p.delta) << ',' << round_trip(p.V) << ',' << round_trip(p.exact) << ','
          << round_trip(p.event_driven) << ',' << round_trip(p.orbit_V) << '\n';
    return out.str();
  });
  return toml::table{{"points", static_cast<std::int64_t>(law.points.size())},
                     {"delta_min", law.points.front().delta},
                     {"delta_max", law.points.back().delta},
                     {"exponent", law.reference.order},
                     {"exponent_minus_half", law.reference.order - 0.5},
                     {"prefactor", std::exp(law.reference.log_constant)},
                     {"sqrt_2a", law.sqrt_2a},
                     {"max_relative_deviation_from_exact", law.max_relative_deviation},
                     {"event_driven_exponent", law.event_driven.order},
                     {"event_driven_exponent_minus_half", law.event_driven.order - 0.5},
                     {"orbit_exponent", law.orbit.order},
                     {"orbit_prefactor", std::exp(law.orbit.log_constant)}};
}

toml::table chatter_summary(const ExperimentContext& context) {
  const Oscillator& o = kAcceptance;
  const std::vector<double> speeds{1e-2, 1e-3, 1e-4, 1e-5};
  toml::table out{{"v0", toml_array(speeds)}};
  std::ostringstream rows;
  rows << "omega_t0,v0,impacts,t_inf,relative_deviation,relative_deviation_first_order\n";
  for (double omega_t0 : {0.0, 1.0}) {
    std::vector<double> deviation, first_order, impacts;
    for (double v0 : speeds) {
      const ChatterPoint p = chatter_accumulation(o, omega_t0 / o.omega, v0);
      deviation.push_back(p.relative_deviation());
      first_order.push_back(p.relative_deviation_first_order());
      impacts.push_back(p.impacts);
      rows << omega_t0 << ',' << round_trip(v0) << ',' << p.impacts << ',' << round_trip(p.t_inf)
           << ',' << round_trip(p.relative_deviation()) << ','
           << round_trip(p.relative_deviation_first_order()) << '\n';
    }
    out.insert(omega_t0 == 0.0 ? "at_omega_t0_0" : "at_omega_t0_1",
               toml::table{{"relative_deviation", toml_array(deviation)},
                           {"relative_deviation_first_order", toml_array(first_order)},
                           {"impacts", toml_array(impacts)}});
  }
  context.write("chatter.csv", [&] { return rows.str(); });
  const StickingRun run = sticking_run(o, kStickingSpeed, kStickingT);
  context.write("sticking_events.csv", [&] {
    return "runner,kind,t,v_before\n" + event_rows("reference", run.reference) +
           event_rows("event_driven", run.event_driven);
  });
  context.write("sticking_trajectory.csv", [&] {
    LinearTrack track = oscillator_track(o, {o.phi(), kStickingSpeed}, 0.0);
    std::ostringstream out;
    out << "t,u,v\n";
    for (int l = 0; l <= 6000; ++l) {
      double impulse = 0.0;
      const double t = kStickingT * l / 6000;
      const State s = track.advance(t, impulse);
      out << round_trip(t) << ',' << round_trip(s.u) << ',' << round_trip(s.v) << '\n';
    }
    return out.str();
  });
  const auto value = [](std::optional<double> x) { return x.value_or(std::nan("")); };
  out.insert(
      "sticking",
      toml::table{{"v0", kStickingSpeed},
                  {"t_inf", run.t_inf},
                  {"lift_off", run.lift_off},
                  {"reference_stick", value(first_event(run.reference, EventKind::stick))},
                  {"reference_lift", value(first_event(run.reference, EventKind::lift))},
                  {"event_driven_stick", value(first_event(run.event_driven, EventKind::stick))},
                  {"event_driven_lift", value(first_event(run.event_driven, EventKind::lift))}});
  return out;
}

State periodic_scene_start() {
  const PeriodOneOrbit orbit = *period_one_orbit(kAcceptance);
  return orbit_state_at_zero(kAcceptance, orbit);
}

toml::table work_precision_summary(const ExperimentContext& context,
                                   const std::optional<TimingRule>& timing) {
  const std::vector<double> steps = steps_125(0.1, 1e-4);
  const std::vector<double> tolerances{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11};
  toml::array methods, refused;
  for (std::string_view m : state_force_methods()) methods.push_back(std::string(m));
  for (std::string_view m : refusing_methods()) refused.push_back(std::string(m));
  toml::table out{{"methods", methods},
                  {"refused", refused},
                  {"step_max", steps.front()},
                  {"step_min", steps.back()}};
  std::string rows = "scene,method,h,tolerance,sup_u,sup_v,cpu_min,cpu_median\n";
  for (const char* name : {"periodic", "chaotic"}) {
    const Scene scene =
        load_scene(context.scene_path("impact_oscillator", std::string(name) + ".toml"));
    const auto curves = oscillator_curves(scene, steps, tolerances, 1e-2, timing);
    rows += curve_rows(name, curves);
    toml::table t{{"T", scene.T}};
    for (const OscillatorCurve& c : curves) {
      toml::table m;
      if (c.step_sweep) {
        m.insert("sup_u_order", c.order.order);
        m.insert("sup_u_at_h_1e-3",
                 std::find_if(c.points.begin(), c.points.end(), [](const auto& p) {
                   return p.h == 1e-3;
                 })->sup_u);
        m.insert("sup_u_finest", c.points.back().sup_u);
      } else {
        double floor = INFINITY;
        for (const OscillatorPoint& p : c.points) floor = std::fmin(floor, p.sup_u);
        m.insert("sup_u_floor", floor);
        m.insert("sup_u_loosest", c.points.front().sup_u);
      }
      t.insert(c.method, m);
    }
    if (std::string(name) == "chaotic") {
      const LyapunovEstimate e = estimate_lyapunov(scene, 60.0, 1e-2);
      t.insert("lyapunov", e.lambda);
      t.insert("lyapunov_time", e.lyapunov_time);
      t.insert("growth_over_T", std::exp(e.lambda * scene.T));
      context.write("lyapunov.csv", [&] { return lyapunov_csv(e); });
    }
    out.insert(name, t);
  }
  context.write("work_precision.csv", [&] { return rows; });
  return out;
}

}  // namespace impact::impact_oscillator
