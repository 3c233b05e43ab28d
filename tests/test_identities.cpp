// The two identities a user reads off `impact run`'s CSV, for every method and every kind of force
// (constant, harmonic, an expression of t, a force of the state, one that reads an internal
// variable), with a COR and without: h sum N is the momentum the floor gave, v^n - v^0 minus the
// integral of f, at output.every = 1 and 7 (a decimated N is the mean over its steps); and E is
// conserved in flight, to what the method's flight allows. A method that does not take a feature
// refuses it with exit 2 and writes nothing.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "impact/forces/force.hpp"
#include "impact/methods/capabilities.hpp"
#include "output_support.hpp"
#include "scene/read_scene.hpp"

using namespace impact;
using namespace impact::testing;

namespace {

struct Force {
  std::string name, toml;
};

const std::vector<Force> kForces = {
    {"constant f", "[force]\nf = -9.81\n"},
    {"harmonic", "[force]\nf = -9.81\namplitude = 5.0\nomega = 20.0\nphase = 0.5\n"},
    {"expression of t", "[force]\nexpression = \"-9.81 + 5 * sin(20 * t + 0.5)\"\n"},
    {"state force", "[force]\nexpression = \"-9.81 - 20 * (u - 0.3) - 0.5 * v\"\n"},
    {"internal variable",
     "[force]\nexpression = \"-9.81 + 5 * z - 0.5 * v\"\n"
     "[[internal]]\nname = \"z\"\ninitial = 1.0\nrate = \"-2 * z + u\"\n"},
};

// Dropped from 0.3 m: about five impacts in 1 s with COR 0.8, a rest or a chatter without.
std::string scene_text(const std::string& method, const Force& force, bool cor) {
  return "[initial]\nu0 = 0.3\nv0 = 0.0\n" + std::string(cor ? "[floor]\ncor = 0.8\n" : "") +
         "[time]\nT = 1.0\nh = 1e-3\n[method]\nname = \"" + method + "\"\n" + force.toml;
}

double column_of(const Table& table, const std::string& name, std::size_t row) {
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    if (table.columns[c] == name) return table.rows[row][c];
  FAIL("no column " << name);
  return 0;
}

// h sum N over the rows: sum of (t_i - t_{i-1}) N_i, a decimated N standing for its steps.
double impulse(const Table& rows) {
  double sum = 0;
  for (std::size_t i = 1; i < rows.rows.size(); ++i)
    sum += (column_of(rows, "t", i) - column_of(rows, "t", i - 1)) * column_of(rows, "N", i);
  return sum;
}

// The integral of f over [0, T] along the run's rows (every = 1): for a force of t alone by
// composite Simpson on 20000 intervals (its error below 1e-15 here); for a force of the state, the
// discrete force the time-steppers apply, the step means f^l at (u^l, v^l, z^l) (scheme_flight.hpp,
// with_internal.hpp), or, for a method that follows the motion, the trapezoidal rule on the
// rows with its error estimated by the same rule on every other row (`error`).
double force_integral(const Scene& scene, const Table& rows, bool follows_motion, double& error) {
  ForceFunction f(scene.model);
  const double T = column_of(rows, "t", rows.rows.size() - 1), h = scene.grid.h;
  error = 0;
  if (!f.state_dependent()) {
    constexpr int n = 20000;
    double sum = f.at(0) + f.at(T);
    for (int k = 1; k < n; ++k) sum += (k % 2 ? 4 : 2) * f.at(T * k / n);
    return sum * T / (3 * n);
  }
  const auto state = [&](std::size_t i) {
    StateWithInternal s{{column_of(rows, "u", i), column_of(rows, "v", i)}, {}};
    if (!scene.model.internal.empty()) s.z[0] = column_of(rows, "z", i);
    return s;
  };
  const auto at = [&](std::size_t i) {
    const StateWithInternal s = state(i);
    f.set_internal(s.z);
    return f.at(column_of(rows, "t", i), s);
  };
  double sum = 0;
  if (!follows_motion) {
    for (std::size_t i = 0; i + 1 < rows.rows.size(); ++i) {
      const StateWithInternal s = state(i);
      f.set_internal(s.z);
      sum += h * f.step_mean(column_of(rows, "t", i), h, s);
    }
    return sum;
  }
  // Its error: where f is smooth, O(h^3) per step, estimated on each pair of free steps by the rule
  // on 2h (which errs 4 times as much); on a step with an impact, where v jumps and f with it, at
  // most h/2 times the jump, bounded with the step's smooth change by h |f_b - f_a|.
  const std::size_t n = rows.rows.size();
  for (std::size_t i = 0; i + 1 < n; ++i) sum += h * (at(i) + at(i + 1)) / 2;
  for (std::size_t i = 0; i + 2 < n; i += 2) {
    const bool free = column_of(rows, "N", i + 1) == 0 && column_of(rows, "N", i + 2) == 0;
    if (free)
      error += std::fabs(h * (at(i) + 2 * at(i + 1) + at(i + 2)) / 2 - h * (at(i) + at(i + 2)));
    else
      error += h * (std::fabs(at(i + 1) - at(i)) + std::fabs(at(i + 2) - at(i + 1)));
  }
  if (n % 2 == 0) error += h * std::fabs(at(n - 1) - at(n - 2));  // the last step, unpaired
  return sum;
}

struct Identities {
  double impulse_every_1 = 0, impulse_every_7 = 0, momentum = 0, momentum_error = 0;
  double flight_drift = 0;  // the largest |E_i - E_{i-1}| over the steps with N = 0
  double energy_scale = 0;  // the largest |E|, v^2/2 and |f u| met
  int free_steps = 0;
};

Identities identities(const Scene& scene, const Table& every_1, const Table& every_7,
                      bool follows_motion) {
  Identities r;
  const std::size_t last = every_1.rows.size() - 1;
  r.impulse_every_1 = impulse(every_1);
  r.impulse_every_7 = impulse(every_7);
  double error = 0;
  const double integral = force_integral(scene, every_1, follows_motion, error);
  r.momentum = column_of(every_1, "v", last) - column_of(every_1, "v", 0) - integral;
  r.momentum_error = error;
  for (std::size_t i = 1; i <= last; ++i) {
    const double v = column_of(every_1, "v", i), E = column_of(every_1, "E", i);
    r.energy_scale = std::fmax(r.energy_scale, std::fmax(std::fabs(E), v * v / 2));
    if (column_of(every_1, "N", i) != 0) continue;
    ++r.free_steps;
    r.flight_drift = std::fmax(r.flight_drift, std::fabs(E - column_of(every_1, "E", i - 1)));
  }
  return r;
}

}  // namespace

TEST_CASE(
    "identities: h sum N is the floor's momentum and E is conserved in flight, for every "
    "method and force, at every = 1 and 7",
    "[identities][cli][regression]") {
  TempDir dir;
  for (const MethodInfo& method : methods())
    for (const Force& force : kForces)
      for (const bool cor : {true, false}) {
        const std::string name(method.name);
        INFO(name << ", " << force.name << (cor ? ", COR 0.8" : ", no COR"));
        dir.write("s.toml", scene_text(name, force, cor));
        const std::string channels =
            std::string(" --set 'output.channels=[\"u\",\"v\",\"N\",\"E\"") +
            (force.name == "internal variable" ? ",\"z\"" : "") + "]'";
        // What the capability table says the method takes (capabilities.hpp).
        const Scene reference =
            parse_scene(scene_text("event_driven", force, cor), "s.toml", {"output.every=1"});
        if (refusal(method.defaults, reference.model)) {
          CHECK_FAILS_CLEANLY(dir, "run s.toml -q -o rows.csv" + channels, 2,
                              Catch::Matchers::Contains("s.toml"));
          continue;
        }
        const Result one = dir.run("run s.toml -q --no-provenance -o rows1.csv" + channels);
        const Result seven = dir.run("run s.toml -q --no-provenance -o rows7.csv" + channels +
                                     " --set output.every=7");
        INFO(one.err << seven.err);
        REQUIRE(one.code == 0);
        REQUIRE(seven.code == 0);
        const Scene scene = load_scene(dir / "s.toml");
        const Identities r =
            identities(scene, read_table(slurp(dir / "rows1.csv")),
                       read_table(slurp(dir / "rows7.csv")), method.can.exact_events);
        INFO("h sum N = " << r.impulse_every_1 << " (every = 7: " << r.impulse_every_7
                          << "), v^n - v^0 - int f = " << r.momentum << " +- " << r.momentum_error
                          << "; E in flight: largest step " << r.flight_drift << " over "
                          << r.free_steps << " free steps, |E| up to " << r.energy_scale);
        // The impulse identity: to rounding for the time-steppers and exact (the momentum their
        // steps carry), to rk8pd's tolerance for event_driven and GSL's (rtol 1e-10) for penalty,
        // plus, for a force of the state under event_driven, the integral's own error.
        const double scale = std::fabs(r.momentum) + std::fabs(r.impulse_every_1) + 1.0;
        CHECK(std::fabs(r.impulse_every_7 - r.impulse_every_1) <= 1e-12 * scale);
        CHECK(std::fabs(r.impulse_every_1 - r.momentum) <= 1e-9 * scale + r.momentum_error);
        // E in flight: the time-steppers' free flight is v^{l+1} = v^l + h f^l, u^{l+1} = u^l +
        // h (v^l + v^{l+1}) / 2 (direct, fb_newton, direct_located, moreau_jean at theta = 1/2),
        // whose work is exactly f^l (u^{l+1} - u^l): E moves by rounding alone; exact and
        // event_driven take a flight's work from its change of v^2/2 (work_energy.hpp): E moves
        // by less than 1e-10; penalty's ODE flight leaves the step-mean work an error of at most
        // h^3 sup|f'| sup|u''| per step (second order): 1e-9 * 100 * 14.81 with f of t here
        // (penalty takes no force of the state), and rtol's 1e-10 on (3-1) for a constant force.
        // Measured on an Intel Xeon (family 6 model 167): at most 4.4e-15 (9e-16 relative) for the
        // time-steppers, 0 for exact and event_driven, 9.0e-8 for penalty with f(t).
        REQUIRE(r.free_steps > 100);
        const bool ode = std::holds_alternative<PenaltyParams>(method.defaults);
        if (method.can.exact_events)
          CHECK(r.flight_drift <= 1e-10);
        else if (ode)
          CHECK(r.flight_drift <= (constant_force(scene.model) ? 1e-9 : 1e-9 * 100 * 14.81));
        else
          CHECK(r.flight_drift <= 64 * 2.220446049250313e-16 * r.energy_scale);
      }
}
