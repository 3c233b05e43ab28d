// Numerical stability on stiff and extreme cases: every method driven to its limits.
//
// Usage: exp_stability RESULTS_DIR [README]
// With README (experiments/stability/README.md), replaces its text between the lines
// kTableBegin and kTableEnd by table.md. Writes to RESULTS_DIR:
//   cases.csv, map_cases.dat  the extreme cases: method x case x h (check_stability per run)
//   eps.csv, map_eps.dat      fb_newton: epsilon x h, on a bounce and on resting contact
//   stiff.csv, map_stiff.dat  penalty: GSL stepper x c_N (h = 1e-3), bounce and resting contact,
//                             with the first contact resolved finely (penetration, duration)
//   map_penalty.dat           penalty rk8pd and msbdf: c_N x h, resting contact
//   labels.gp                 tic labels for plot.gp
//   table.md                  the README table (experiment.mk splices it into README.md)
//   summary.toml              the key numbers (reference.toml has the same keys)
#include "impact/stability.hpp"

#include <toml++/toml.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "impact/exact.hpp"
#include "impact/output.hpp"
#include "impact/registry.hpp"
#include "impact/run.hpp"
#include "impact/scene.hpp"

namespace {

using namespace impact;

constexpr double kGravity = -9.80665;

// 3 significant digits, for the table.
std::string short_num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

void write_file(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  std::fputs(text.c_str(), file.stream());
  file.commit();
}

// One extreme case: the scene data and its natural duration T (a run at step h covers
// min(T, max_steps h): the smallest steps see the start of the case only).
struct Case {
  std::string name;
  std::string what;
  double phi, gap0, v0, f;
  std::optional<double> cor;
  double T;
};

const std::vector<Case>& extreme_cases() {
  static const std::vector<Case> cases = {
      {"paper_f0", "Figure 3 left: u0 = 5, v0 = -1, f = 0", 0, 5, -1, 0, {}, 10},
      {"paper_gravity", "Figure 4 left: u0 = 5, v0 = -1, f = -9.80665", 0, 5, -1, kGravity, {}, 10},
      {"cor0", "Figure 4 scene, COR = 0 (plastic)", 0, 5, -1, kGravity, 0.0, 10},
      {"cor1", "Figure 4 scene, COR = 1 (elastic)", 0, 5, -1, kGravity, 1.0, 10},
      {"cor_0.999", "u0 = 0.01, COR = 0.999: ~1000 impacts before t_inf = 90.3", 0, 0.01, 0,
       kGravity, 0.999, 100},
      {"bounces_1e4",
       "u0 = 1e-4, elastic: 1.1e4 bounces of 9e-3 s in T = 100",
       0,
       1e-4,
       0,
       kGravity,
       {},
       100},
      {"v0_-1e8", "u0 = 1, v0 = -1e8, f = 0", 0, 1, -1e8, 0, {}, 1},
      {"v0_-1e8_gravity", "u0 = 1, v0 = -1e8, f = -9.80665", 0, 1, -1e8, kGravity, {}, 1},
      {"f_-1e8", "u0 = 1, v0 = 0, f = -1e8: 3500 bounces in T = 1", 0, 1, 0, -1e8, {}, 1},
      {"f_+1e8", "u0 = 1, v0 = -1e8, f = +1e8 (pushing away)", 0, 1, -1e8, 1e8, {}, 1},
      {"f_+9.8", "u0 = 0.01, v0 = -1, f = +9.80665 (pushing away)", 0, 0.01, -1, -kGravity, {}, 1},
      {"f_+9.8_cor1", "the same with COR = 1", 0, 0.01, -1, -kGravity, 1.0, 1},
      {"contact_v0<0", "u0 = phi, v0 = -1, gravity", 0, 0, -1, kGravity, {}, 1},
      {"contact_v0=0", "u0 = phi, v0 = 0, gravity: resting contact", 0, 0, 0, kGravity, {}, 1},
      {"contact_v0>0", "u0 = phi, v0 = +1, gravity", 0, 0, 1, kGravity, {}, 1},
      {"contact_f0", "u0 = phi, v0 = 0, f = 0", 0, 0, 0, 0, {}, 1},
      {"phi_1e6", "phi = 1e6, u0 = phi + 5, v0 = -1, gravity", 1e6, 5, -1, kGravity, {}, 10},
      {"phi_1e6_near",
       "phi = 1e6, u0 = phi + 1e-3, v0 = -1, gravity",
       1e6,
       1e-3,
       -1,
       kGravity,
       {},
       1},
      {"phi_1e6_rest", "phi = 1e6, u0 = phi, v0 = 0, gravity", 1e6, 0, 0, kGravity, {}, 1},
  };
  return cases;
}

const std::vector<std::string> kMethods = {"direct", "fb_newton", "moreau_jean", "exact",
                                           "penalty"};
constexpr int kLogHMin = -9, kLogHMax = 0;
// Grid steps per run (penalty: fewer, it costs ~1 us per step) and the work budget of penalty.
constexpr double kMaxSteps = 1e5, kMaxPenaltySteps = 2e4;
constexpr std::int64_t kMaxOdeSteps = 2'000'000;

std::string scene_text(double phi, double gap0, double v0, double f, std::optional<double> cor,
                       double T, double h, const std::string& method,
                       const std::string& method_keys = "") {
  // u0 = phi + gap0 rounds to the floor's ulp; gap0 = 0 gives u0 = phi exactly.
  std::string text = "[initial]\nu0 = " + impact::round_trip(phi + gap0) +
                     "\nv0 = " + impact::round_trip(v0) +
                     "\n[floor]\nphi = " + impact::round_trip(phi) + "\n";
  if (cor) text += "cor = " + impact::round_trip(*cor) + "\n";
  text += "[force]\nf = " + impact::round_trip(f) + "\n[time]\nT = " + impact::round_trip(T) +
          "\nh = " + impact::round_trip(h) + "\n[method]\nname = \"" + method + "\"\n" +
          method_keys;
  return text;
}

struct Cell {
  StabilityCheck check;
  double T = 0, h = 0, seconds = 0;
};

Cell run_cell(const std::string& text, const std::string& source, double T, double h,
              std::int64_t budget) {
  Cell cell;
  cell.T = T;
  cell.h = h;
  const auto start = std::chrono::steady_clock::now();
  try {
    const Scene scene = parse_scene(text, source);
    cell.check = check_stability(scene, {budget});
  } catch (const SceneError& e) {
    cell.check.outcome = Outcome::rejected;
    cell.check.message = e.what();
  }
  cell.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return cell;
}

// One letter per outcome, for the README table.
char letter(Outcome o) {
  switch (o) {
    case Outcome::ok:
      return 'o';
    case Outcome::inaccurate:
      return 'i';
    case Outcome::energy_grows:
      return 'E';
    case Outcome::failure:
      return 'F';
    case Outcome::non_finite:
      return 'N';
    case Outcome::over_budget:
      return 'B';
    case Outcome::rejected:
      return '-';
  }
  return '?';
}

std::string csv_row(const std::string& prefix, const Cell& c) {
  const StabilityCheck& k = c.check;
  std::string message = k.message;
  for (char& ch : message)
    if (ch == ',' || ch == '\n') ch = ';';
  return prefix + "," + impact::round_trip(c.h) + "," + impact::round_trip(c.T) + "," +
         std::to_string(k.steps) + "," + std::string(outcome_name(k.outcome)) + "," +
         std::to_string(static_cast<int>(k.outcome)) + "," + impact::round_trip(k.min_gap) + "," +
         std::to_string(k.energy_rises) + "," + impact::round_trip(k.max_energy_rise) + "," +
         std::to_string(k.max_iterations) + "," + impact::round_trip(k.mean_iterations) + "," +
         std::to_string(k.work) + "," + impact::round_trip(k.error_u) + "," +
         impact::round_trip(k.amplitude) + "," + impact::round_trip(k.error_energy) + "," +
         impact::round_trip(c.seconds) + ",\"" + message + "\"\n";
}

constexpr const char* kCellHeader =
    "h,T,steps,outcome,code,min_gap,energy_rises,max_energy_rise,max_iterations,mean_iterations,"
    "work,error_u,amplitude,error_energy,seconds,message\n";

// ---- Part 1: the extreme cases, method x case x h. ----

struct CaseResults {
  // cells[method][case][i], i = log10 h - kLogHMin
  std::map<std::string, std::vector<std::vector<Cell>>> cells;
};

CaseResults run_cases(const std::string& dir) {
  CaseResults r;
  std::string csv = "method,case," + std::string(kCellHeader);
  std::string map = "# method_index case_index log10_h code\n";
  const auto& cases = extreme_cases();
  for (std::size_t m = 0; m < kMethods.size(); ++m) {
    const std::string& method = kMethods[m];
    auto& by_case = r.cells[method];
    for (std::size_t c = 0; c < cases.size(); ++c) {
      const Case& k = cases[c];
      by_case.emplace_back();
      for (int e = kLogHMin; e <= kLogHMax; ++e) {
        const double h = std::pow(10.0, e);
        const double max_steps = method == "penalty" ? kMaxPenaltySteps : kMaxSteps;
        const double T = std::fmin(k.T, max_steps * h);
        const Cell cell =
            run_cell(scene_text(k.phi, k.gap0, k.v0, k.f, k.cor, T, h, method),
                     k.name + "/" + method, T, h, method == "penalty" ? kMaxOdeSteps : 0);
        by_case.back().push_back(cell);
        csv += csv_row(method + "," + k.name, cell);
        map += std::to_string(m) + " " + std::to_string(c) + " " + std::to_string(e) + " " +
               std::to_string(static_cast<int>(cell.check.outcome)) + "\n";
      }
    }
    map += "\n\n";
  }
  write_file(dir + "/cases.csv", csv);
  write_file(dir + "/map_cases.dat", map);
  return r;
}

// ---- Part 2: fb_newton's smoothing parameter, epsilon x h. ----

struct EpsResults {
  // the largest iteration counts
  int max_iterations = 0;
  double max_mean_iterations = 0;
  int failures = 0, runs = 0, energy_violations = 0;
};

EpsResults run_eps(const std::string& dir) {
  EpsResults r;
  std::string csv = "scene,epsilon," + std::string(kCellHeader);
  std::string map = "# scene_index log10_eps log10_h code\n";
  struct EpsScene {
    std::string name;
    double gap0, v0, T;
  };
  // The bounce has COR = 1, so that its scheme is accurate as h -> 0 and the map shows where the
  // smoothing spoils it; without COR the scheme's impact loses energy whatever eps (README).
  const std::vector<EpsScene> scenes = {{"bounce", 1, 0, 2}, {"rest", 0, 0, 1}};
  for (std::size_t s = 0; s < scenes.size(); ++s) {
    for (int le = -15; le <= -2; ++le) {
      const double eps = std::pow(10.0, le);
      for (int e = kLogHMin; e <= kLogHMax; ++e) {
        const double h = std::pow(10.0, e);
        const double T = std::fmin(scenes[s].T, kMaxSteps * h);
        const Cell cell =
            run_cell(scene_text(0, scenes[s].gap0, scenes[s].v0, kGravity,
                                s == 0 ? std::optional<double>(1.0) : std::nullopt, T, h,
                                "fb_newton", "epsilon = " + impact::round_trip(eps) + "\n"),
                     "eps/" + scenes[s].name, T, h, 0);
        const StabilityCheck& k = cell.check;
        ++r.runs;
        r.failures += k.outcome == Outcome::failure || k.outcome == Outcome::non_finite;
        r.energy_violations += k.outcome == Outcome::energy_grows;
        r.max_iterations = std::max(r.max_iterations, k.max_iterations);
        r.max_mean_iterations = std::fmax(r.max_mean_iterations, k.mean_iterations);
        csv += csv_row(scenes[s].name + "," + impact::round_trip(eps), cell);
        map += std::to_string(s) + " " + std::to_string(le) + " " + std::to_string(e) + " " +
               std::to_string(static_cast<int>(k.outcome)) + "\n";
      }
    }
    map += "\n\n";
  }
  write_file(dir + "/eps.csv", csv);
  write_file(dir + "/map_eps.dat", map);
  return r;
}

// ---- Part 3: penalty as c_N grows, per GSL stepper. ----

struct Stepper {
  std::string name;
  bool implicit;
};
const std::vector<Stepper> kSteppers = {
    {"rk8pd", false}, {"rkf45", false}, {"rkck", false}, {"msadams", false},
    {"msbdf", true},  {"rk4imp", true}, {"bsimp", true},
};
constexpr int kLogCMin = 2, kLogCMax = 12;
// The resting-contact runs last kRestT; a run may take kStiffBudget ODE steps (1e6 per second of
// simulated time), beyond which the stepper is counted as not usable at that c_N.
constexpr double kRestT = 0.1;
constexpr std::int64_t kStiffBudget = 100'000;

// The first contact of the bounce scene (impact speed V = sqrt(2 |f| 1)), integrated on a grid of
// contact_time / 200: penetration, duration and impulse, with their closed forms for the spring
// u'' = f + c_N (phi - u): about the equilibrium g_eq = f / c_N the contact is an oscillation of
// frequency w = sqrt(c_N) entered at phase alpha = atan2(V / w, -g_eq), so it lasts
// 2 (pi - alpha) / w and reaches g_eq - sqrt(g_eq^2 + V^2 / c_N).
struct Contact {
  double penetration = NAN, duration = NAN, impulse = NAN;
  double penetration_exact = 0, duration_exact = 0;
  Outcome outcome = Outcome::ok;
};

Contact resolve_contact(const std::string& stepper, double c_N) {
  Contact c;
  const double V = std::sqrt(2 * -kGravity * 1.0), w = std::sqrt(c_N), g_eq = kGravity / c_N;
  const double alpha = std::atan2(V / w, -g_eq);
  c.duration_exact = 2 * (std::numbers::pi - alpha) / w;
  c.penetration_exact = -g_eq + std::sqrt(g_eq * g_eq + V * V / c_N);
  const double h = c.duration_exact / 200, T = 1.5 * c.duration_exact;
  try {
    const Scene scene = parse_scene(
        scene_text(0, 0, -V, kGravity, {}, T, h, "penalty",
                   "stiffness = " + impact::round_trip(c_N) + "\nstepper = \"" + stepper + "\"\n"),
        "contact/" + stepper);
    AnyStepper solver = make_stepper(scene);
    double min_gap = 0, impulse = 0, exit_time = NAN;
    State before = scene.initial;
    simulate(solver, scene.initial, scene.grid,
             [&](std::int64_t l, const State& s, const StepInfo& info) {
               if (l == 0) return;
               min_gap = std::fmin(min_gap, s.u);
               if (std::isnan(exit_time)) {
                 impulse += h * info.contact_force;
                 // Leaving the floor between t_{l-1} and t_l: interpolate the crossing.
                 if (before.u < 0 && s.u >= 0)
                   exit_time = scene.grid.t(l - 1) + h * -before.u / (s.u - before.u);
               }
               before = s;
             });
    c.penetration = -min_gap;
    c.duration = exit_time;
    c.impulse = impulse;
  } catch (const NumericalError& e) {
    c.outcome = e.converged ? Outcome::non_finite : Outcome::failure;
  }
  return c;
}

// A penalty run measured like check_stability, plus the energy that counts the spring,
// v^2/2 - f (u - phi) + c_N max(phi - u, 0)^2 / 2, which the compliance model conserves.
struct StiffRun {
  Cell cell;
  double energy_drift = 0;  // max_l |E_spring^l - E_spring^0|
};

StiffRun run_stiff(const std::string& stepper, double c_N, double gap0, double T, double h) {
  StiffRun r;
  const std::string keys =
      "stiffness = " + impact::round_trip(c_N) + "\nstepper = \"" + stepper + "\"\n";
  const std::string text = scene_text(0, gap0, 0, kGravity, {}, T, h, "penalty", keys);
  r.cell = run_cell(text, "stiff/" + stepper, T, h, kStiffBudget);
  if (r.cell.check.outcome == Outcome::ok || r.cell.check.outcome == Outcome::inaccurate) {
    const Scene scene = parse_scene(text, "stiff/" + stepper);
    AnyStepper solver = make_stepper(scene);
    auto spring_energy = [&](const State& s) {
      const double pen = std::fmax(-s.u, 0.0);
      return 0.5 * s.v * s.v - kGravity * s.u + 0.5 * c_N * pen * pen;
    };
    const double E0 = spring_energy(scene.initial);
    simulate(solver, scene.initial, scene.grid, [&](std::int64_t, const State& s, const StepInfo&) {
      r.energy_drift = std::fmax(r.energy_drift, std::fabs(spring_energy(s) - E0));
    });
  }
  return r;
}

struct StiffResults {
  std::map<std::string, std::map<int, Contact>> contact;  // stepper -> log10 c_N
  std::map<std::string, std::map<int, StiffRun>> bounce, rest;
  // Resting contact: the largest c_N each stepper finished within the budget.
  std::map<std::string, double> rest_limit;
};

StiffResults run_stiff_study(const std::string& dir) {
  StiffResults r;
  std::string csv =
      "stepper,implicit,c_N,scene,energy_drift,penetration,penetration_exact,duration,"
      "duration_exact,impulse," +
      std::string(kCellHeader);
  std::string map = "# scene_index stepper_index log10_c_N code\n";
  const double h = 1e-3;
  for (int scene = 0; scene < 2; ++scene) {
    for (std::size_t i = 0; i < kSteppers.size(); ++i) {
      const Stepper& st = kSteppers[i];
      for (int lc = kLogCMin; lc <= kLogCMax; ++lc) {
        const double c_N = std::pow(10.0, lc);
        // Bounce: u0 = 1, two impacts in T = 2. Rest: u0 = phi, v0 = 0 under gravity.
        StiffRun run =
            scene == 0 ? run_stiff(st.name, c_N, 1, 2, h) : run_stiff(st.name, c_N, 0, kRestT, h);
        Contact contact;
        if (scene == 0) {
          contact = resolve_contact(st.name, c_N);
          r.contact[st.name][lc] = contact;
          r.bounce[st.name][lc] = run;
        } else {
          r.rest[st.name][lc] = run;
          const Outcome o = run.cell.check.outcome;
          if (o == Outcome::ok || o == Outcome::inaccurate) r.rest_limit[st.name] = c_N;
        }
        csv += csv_row(st.name + "," + (st.implicit ? "1" : "0") + "," + impact::round_trip(c_N) +
                           "," + (scene == 0 ? "bounce" : "rest") + "," +
                           impact::round_trip(run.energy_drift) + "," +
                           impact::round_trip(contact.penetration) + "," +
                           impact::round_trip(contact.penetration_exact) + "," +
                           impact::round_trip(contact.duration) + "," +
                           impact::round_trip(contact.duration_exact) + "," +
                           impact::round_trip(contact.impulse),
                       run.cell);
        map += std::to_string(scene) + " " + std::to_string(i) + " " + std::to_string(lc) + " " +
               std::to_string(static_cast<int>(run.cell.check.outcome)) + "\n";
      }
    }
    map += "\n\n";
  }
  write_file(dir + "/stiff.csv", csv);
  write_file(dir + "/map_stiff.dat", map);

  // c_N x h for one explicit and one implicit stepper, resting contact.
  std::string pmap = "# stepper_index log10_c_N log10_h code\n";
  std::string pcsv = "stepper,c_N," + std::string(kCellHeader);
  const std::vector<std::string> pair = {"rk8pd", "msbdf"};
  for (std::size_t i = 0; i < pair.size(); ++i) {
    for (int lc = kLogCMin; lc <= kLogCMax; ++lc) {
      const double c_N = std::pow(10.0, lc);
      for (int e = -6; e <= -1; ++e) {
        const double hh = std::pow(10.0, e), T = std::fmin(kRestT, kMaxPenaltySteps * hh);
        const StiffRun run = run_stiff(pair[i], c_N, 0, T, hh);
        pcsv += csv_row(pair[i] + "," + impact::round_trip(c_N), run.cell);
        pmap += std::to_string(i) + " " + std::to_string(lc) + " " + std::to_string(e) + " " +
                std::to_string(static_cast<int>(run.cell.check.outcome)) + "\n";
      }
    }
    pmap += "\n\n";
  }
  write_file(dir + "/penalty_h.csv", pcsv);
  write_file(dir + "/map_penalty.dat", pmap);
  return r;
}

// ---- Outputs ----

// The rows of the stability map: each case's data (gnuplot enhanced text; SI units, phi = 0 unless
// given, g = -9.80665). The case names are for the CSV files and the README's table.
const std::map<std::string, std::string> kCaseLabels = {
    {"paper_f0", "Fig. 3: u_0 = 5, v_0 = -1, f = 0"},
    {"paper_gravity", "Fig. 4: u_0 = 5, v_0 = -1, f = g"},
    {"cor0", "Fig. 4 with COR = 0"},
    {"cor1", "Fig. 4 with COR = 1"},
    {"cor_0.999", "u_0 = 0.01, v_0 = 0, f = g, COR = 0.999"},
    {"bounces_1e4", "u_0 = 10^{-4}, v_0 = 0, f = g"},
    {"v0_-1e8", "u_0 = 1, v_0 = -10^8, f = 0"},
    {"v0_-1e8_gravity", "u_0 = 1, v_0 = -10^8, f = g"},
    {"f_-1e8", "u_0 = 1, v_0 = 0, f = -10^8"},
    {"f_+1e8", "u_0 = 1, v_0 = -10^8, f = +10^8"},
    {"f_+9.8", "u_0 = 0.01, v_0 = -1, f = -g (upward)"},
    {"f_+9.8_cor1", "u_0 = 0.01, v_0 = -1, f = -g, COR = 1"},
    {"contact_v0<0", "u_0 = {/Symbol f}, v_0 = -1, f = g"},
    {"contact_v0=0", "u_0 = {/Symbol f}, v_0 = 0, f = g (resting)"},
    {"contact_v0>0", "u_0 = {/Symbol f}, v_0 = +1, f = g"},
    {"contact_f0", "u_0 = {/Symbol f}, v_0 = 0, f = 0"},
    {"phi_1e6", "{/Symbol f} = 10^6, u_0 = {/Symbol f} + 5, v_0 = -1, f = g"},
    {"phi_1e6_near", "{/Symbol f} = 10^6, u_0 = {/Symbol f} + 10^{-3}, v_0 = -1, f = g"},
    {"phi_1e6_rest", "{/Symbol f} = 10^6, u_0 = {/Symbol f}, v_0 = 0, f = g"},
};

std::string gnuplot_labels() {
  std::string cases = "set_case_tics = \"set ytics (";
  const auto& list = extreme_cases();
  for (std::size_t c = 0; c < list.size(); ++c)
    cases += (c ? ", " : "") + std::string("'") + kCaseLabels.at(list[c].name) + "' " +
             std::to_string(c);
  cases += ")\"\n";
  std::string steppers = "set_stepper_tics = \"set ytics (";
  for (std::size_t i = 0; i < kSteppers.size(); ++i)
    steppers += (i ? ", " : "") + std::string("'") + kSteppers[i].name +
                (kSteppers[i].implicit ? " (impl.)" : "") + "' " + std::to_string(i);
  steppers += ")\"\n";
  return cases + steppers;
}

std::string table(const CaseResults& r) {
  const auto& cases = extreme_cases();
  std::string out;
  out +=
      "Outcome per h = 1e-9, 1e-8, ..., 1 (one letter each): o ok, i inaccurate (error > 1% of "
      "the amplitude), E energy grows where the theory forbids it, F failure reported, "
      "N non-finite caught, B over the work budget, - rejected (penalty has no COR).\n\n";
  out += "| case | T | direct | fb_newton | moreau_jean | exact | penalty |\n";
  out += "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (std::size_t c = 0; c < cases.size(); ++c) {
    out += "| " + cases[c].name + " | " + short_num(cases[c].T) + " |";
    for (const auto& method : kMethods) {
      std::string letters;
      for (const Cell& cell : r.cells.at(method)[c]) letters += letter(cell.check.outcome);
      out += " `" + letters + "` |";
    }
    out += "\n";
  }
  out +=
      "\nPer case and method, over the 10 runs of the h sweep: runs that finished (all values "
      "finite), min(u - phi), runs with an energy rise beyond round-off (where the theory "
      "bounds it: direct, fb_newton, exact) and the largest rise, Newton iterations per step "
      "(fb_newton; penalty: ODE steps) max and largest mean, runs stopped by a failure, and "
      "max_l |u^l - u(t_l)| / amplitude at h = 1e-3 and at the worst h (a particle at rest, "
      "amplitude 0: relative to 1e-10 max(1, |phi|)). E excludes penalty's spring energy.\n\n";
  out +=
      "| case | method | finished | min(u - phi) | E rises | max rise | iter. max | iter. mean "
      "| failed | rel. error h=1e-3 | worst rel. error |\n";
  out += "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (std::size_t c = 0; c < cases.size(); ++c) {
    for (const auto& method : kMethods) {
      const auto& cells = r.cells.at(method)[c];
      int finished = 0, rises = 0, failed = 0, rejected = 0, iter_max = 0;
      double min_gap = INFINITY, max_rise = -INFINITY, iter_mean = 0, worst = 0, at_1e3 = NAN;
      for (std::size_t i = 0; i < cells.size(); ++i) {
        const StabilityCheck& k = cells[i].check;
        if (k.outcome == Outcome::rejected) {
          ++rejected;
          continue;
        }
        const bool done = k.message.empty();
        finished += done;
        failed += k.outcome == Outcome::failure || k.outcome == Outcome::non_finite;
        min_gap = std::fmin(min_gap, k.min_gap);
        if (k.energy_bound && k.energy_rises > 0) ++rises;
        if (k.steps > 0) max_rise = std::fmax(max_rise, k.max_energy_rise);
        iter_max = std::max(iter_max, k.max_iterations);
        iter_mean = std::fmax(iter_mean, k.mean_iterations);
        if (done) {
          // Relative to the amplitude, or to the accuracy floor for a particle at rest.
          const double scale = std::fmax(
              k.amplitude, kAccuracyFloor / kAccuracy * std::fmax(1.0, std::fabs(cases[c].phi)));
          const double rel = k.error_u / scale;
          worst = std::fmax(worst, rel);
          if (static_cast<int>(i) + kLogHMin == -3) at_1e3 = rel;
        }
      }
      if (rejected == static_cast<int>(cells.size())) {
        out +=
            "| " + cases[c].name + " | " + method + " | rejected: no COR law | | | | | | | | |\n";
        continue;
      }
      const bool bound = cells.front().check.energy_bound;
      out += "| " + cases[c].name + " | " + method + " | " + std::to_string(finished) + "/" +
             std::to_string(cells.size()) + " | " + short_num(min_gap) + " | " +
             (bound ? std::to_string(rises) : std::string("n/a")) + " | " + short_num(max_rise) +
             " | " + std::to_string(iter_max) + " | " + short_num(iter_mean) + " | " +
             std::to_string(failed) + " | " + short_num(at_1e3) + " | " + short_num(worst) + " |\n";
    }
  }
  return out;
}

constexpr const char* kTableBegin = "<!-- table: begin (written by exp_stability) -->";
constexpr const char* kTableEnd = "<!-- table: end -->";

// Puts `table` between the marker lines of the README; rewrites the file only when it changes.
void splice_table(const std::string& readme, const std::string& table) {
  std::ifstream in(readme);
  if (!in) throw std::runtime_error(readme + ": cannot read");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const auto begin = text.find(kTableBegin), end = text.find(kTableEnd);
  if (begin == std::string::npos || end == std::string::npos || end < begin)
    throw std::runtime_error(readme + ": no table markers");
  const auto after_begin = text.find('\n', begin) + 1;
  const std::string spliced = text.substr(0, after_begin) + table + "\n" + text.substr(end);
  if (spliced != text) write_file(readme, spliced);
}

int count(const CaseResults& r, const std::string& method, Outcome o) {
  int n = 0;
  for (const auto& row : r.cells.at(method))
    for (const Cell& cell : row) n += cell.check.outcome == o;
  return n;
}

const Cell& cell(const CaseResults& r, const std::string& method, const std::string& name,
                 int log_h) {
  const auto& cases = extreme_cases();
  for (std::size_t c = 0; c < cases.size(); ++c)
    if (cases[c].name == name) return r.cells.at(method)[c][log_h - kLogHMin];
  throw std::out_of_range("no case " + name);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: exp_stability RESULTS_DIR [README]\n");
    return 2;
  }
  const std::string dir = argv[1];
  try {
    const auto start = std::chrono::steady_clock::now();
    const CaseResults cases = run_cases(dir);
    const EpsResults eps = run_eps(dir);
    const StiffResults stiff = run_stiff_study(dir);
    write_file(dir + "/labels.gp", gnuplot_labels());
    const std::string table_text = table(cases);
    write_file(dir + "/table.md", table_text);
    if (argc == 3) splice_table(argv[2], table_text);

    toml::table outcomes;
    for (const auto& method : kMethods) {
      toml::table t;
      for (Outcome o : {Outcome::ok, Outcome::inaccurate, Outcome::energy_grows, Outcome::failure,
                        Outcome::non_finite, Outcome::over_budget, Outcome::rejected})
        t.insert(outcome_name(o), count(cases, method, o));
      outcomes.insert(method, t);
    }
    const Cell& far_rest = cell(cases, "fb_newton", "phi_1e6_rest", -9);
    const Cell& push = cell(cases, "direct", "f_+9.8_cor1", -3);
    toml::table stiff_table;
    for (const auto& st : kSteppers) {
      const Contact& c6 = stiff.contact.at(st.name).at(6);
      const Contact& c12 = stiff.contact.at(st.name).at(12);
      stiff_table.insert(
          st.name, toml::table{
                       {"penetration_1e6", c6.penetration},
                       {"penetration_1e12", c12.penetration},
                       {"duration_1e6", c6.duration},
                       {"duration_1e12", c12.duration},
                       {"impulse_1e12", c12.impulse},
                       {"bounce_ode_steps_1e6", stiff.bounce.at(st.name).at(6).cell.check.work},
                       {"bounce_ode_steps_1e12", stiff.bounce.at(st.name).at(12).cell.check.work},
                       {"bounce_error_u_1e12", stiff.bounce.at(st.name).at(12).cell.check.error_u},
                       {"rest_ode_steps_1e6", stiff.rest.at(st.name).at(6).cell.check.work},
                       {"rest_largest_c_N",
                        stiff.rest_limit.count(st.name) ? stiff.rest_limit.at(st.name) : 0.0},
                   });
    }
    toml::table summary{
        {"outcomes", outcomes},
        {"fb_newton_phi_1e6_rest_h_1e-9",
         toml::table{{"max_energy_rise", far_rest.check.max_energy_rise},
                     {"error_u", far_rest.check.error_u},
                     {"max_iterations", far_rest.check.max_iterations}}},
        {"direct_cor1_push_h_1e-3", toml::table{{"max_energy_rise", push.check.max_energy_rise},
                                                {"energy_rises", push.check.energy_rises}}},
        {"eps", toml::table{{"runs", eps.runs},
                            {"failures", eps.failures},
                            {"energy_violations", eps.energy_violations},
                            {"max_iterations", eps.max_iterations},
                            {"max_mean_iterations", eps.max_mean_iterations}}},
        {"penalty", stiff_table},
    };
    std::ostringstream text;
    text << "# experiments/stability: measured by exp_stability (see README.md)\n"
         << summary << "\n";
    write_file(dir + "/summary.toml", text.str());
    std::fprintf(stderr, "exp_stability: %.1f s\n",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exp_stability: %s\n", e.what());
    return 1;
  }
  return 0;
}
