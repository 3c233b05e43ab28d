// The [force] table: the body force f(t) = f + amplitude sin(omega t + phase), or f + a muparser
// expression of t, read into Model; each bad input a SceneError naming the file (or the --set),
// the key, the value and what is allowed.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>

#include "cli_support.hpp"
#include "impact/forces/force.hpp"
#include "impact/forces/work_energy.hpp"
#include "scene/read_scene.hpp"
#include "scene_support.hpp"

namespace {

const std::string kHarmonic = "[force]\nf = -9.80665\namplitude = 14.71\nomega = 62.831853\n";

}  // namespace

TEST_CASE("force: the harmonic keys and the expression are read into Model", "[force]") {
  impact::Scene s = parse(kBase + kHarmonic + "phase = 0.5\n");
  CHECK(s.model.f == -9.80665);
  REQUIRE(s.model.harmonic.has_value());
  CHECK(s.model.harmonic->amplitude == 14.71);
  CHECK(s.model.harmonic->omega == 62.831853);
  CHECK(s.model.harmonic->phase == 0.5);
  CHECK(s.model.expression.empty());

  // Without f the constant part is 0; without phase the phase is 0.
  s = parse(kBase + "[force]\namplitude = 2\nomega = 3\n");
  CHECK(s.model.f == 0.0);
  REQUIRE(s.model.harmonic.has_value());
  CHECK(s.model.harmonic->amplitude == 2.0);
  CHECK(s.model.harmonic->phase == 0.0);

  s = parse(kBase + "[force]\nexpression = \"-9.80665 + 14.71 * sin(62.831853 * t)\"\n");
  CHECK(s.model.f == 0.0);
  CHECK_FALSE(s.model.harmonic.has_value());
  CHECK(s.model.expression == "-9.80665 + 14.71 * sin(62.831853 * t)");

  // A constant force stays a constant: no harmonic part, no expression.
  s = parse(kBase + "[force]\nf = -9.80665\n");
  CHECK(impact::constant_force(s.model));

  // --set adds the keys as the file would.
  s = parse(kBase + "[force]\nf = -9.8\n", {"force.amplitude=1.5", "force.omega=2"});
  REQUIRE(s.model.harmonic.has_value());
  CHECK(s.model.harmonic->amplitude == 1.5);
  s = parse(kBase, {"force.expression=\"2 * t\""});
  CHECK(s.model.expression == "2 * t");
}

TEST_CASE("force: the harmonic part needs amplitude and omega > 0, each finite", "[force]") {
  CHECK_SCENE_ERROR(
      parse(kBase + "[force]\nf = -9.8\namplitude = 14.71\n"),
      Contains("scene.toml: force.amplitude = 14.71: needs force.omega") && Contains("> 0"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nomega = 6.0\n"),
                    Contains("scene.toml: force.omega = 6.0: given without force.amplitude"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nphase = 1.0\n"),
                    Contains("force.phase = 1.0: given without force.amplitude"));
  CHECK_SCENE_ERROR(parse(kBase + kHarmonic, {"force.omega=0"}),
                    Contains("--set force.omega=0: force.omega = 0: must be > 0"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\namplitude = 1.0\nomega = -62.8\n"),
                    Contains("scene.toml: force.omega = -62.8: must be > 0"));
  CHECK_SCENE_ERROR(parse(kBase + kHarmonic + "phase = nan\n"),
                    Contains("force.phase = nan: must be a finite number"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\namplitude = inf\nomega = 1.0\n"),
                    Contains("force.amplitude = inf: must be a finite number"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\namplitude = -inf\nomega = 1.0\n"),
                    Contains("force.amplitude = -inf: must be a finite number"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\namplitude = 1.0\nomega = 1.0\nphase = \"zero\"\n"),
                    Contains("force.phase = 'zero': must be a number"));
}

TEST_CASE("force: an empty [force] table is refused", "[force]") {
  CHECK_SCENE_ERROR(parse(kBase + "[force]\n"),
                    Contains("scene.toml: [force]: the table is empty") &&
                        Contains("give f, or amplitude and omega") && Contains("expression"));
}

TEST_CASE("force: an expression is exclusive with the harmonic keys", "[force]") {
  for (const std::string key : {"amplitude = 1.0\n", "omega = 2.0\n", "phase = 0.0\n"})
    CHECK_SCENE_ERROR(
        parse(kBase + "[force]\nexpression = \"sin(t)\"\n" + key),
        Contains("scene.toml: force.expression = 'sin(t)': is exclusive with force.") &&
            Contains("not both"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nexpression = \"sin(t)\"\n", {"force.omega=3"}),
                    Contains("is exclusive with force.omega = 3"));
}

// An expression is the whole force: f beside it would add a second constant part, which a scene
// writing gravity in both would double silently.
TEST_CASE("force: an expression is exclusive with the constant f", "[force]") {
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nf = -9.80665\nexpression = \"-9.80665 + sin(t)\"\n"),
                    Contains("scene.toml: force.expression = '-9.80665 + sin(t)': is exclusive "
                             "with force.f = -9.80665") &&
                        Contains("whole force"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nf = -1\n", {"force.expression=\"sin(t)\""}),
                    Contains("is exclusive with force.f = -1") && Contains("--unset force.f"));
}

TEST_CASE("force: an expression that is empty, too long or not evaluable at t = 0", "[force]") {
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nexpression = \"\"\n"),
                    Contains("scene.toml: force.expression = '': the expression is empty"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nexpression = \"   \"\n"),
                    Contains("the expression is empty"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nexpression = 3.0\n"),
                    Contains("force.expression = 3.0: must be a string"));

  // 4096 characters are allowed, 4097 are not; the message shows the start of the value only.
  std::string sum = "t";
  while (sum.size() < 4095) sum += "+t";
  REQUIRE(sum.size() == 4095);
  CHECK(parse(kBase + "[force]\nexpression = \"" + sum + " \"\n").model.expression.text().size() ==
        4096);
  const std::string message = scene_error(kBase + "[force]\nexpression = \"" + sum + "+t\"\n");
  CHECK_THAT(message, Contains("force.expression = 't+t+t") &&
                          Contains("has 4097 characters; at most 4096 are allowed"));
  CHECK(message.size() < 600);

  // muparser's position is 1-based in the message: "sin(t" ends at 5, "2 * x" has x at 5.
  CHECK_SCENE_ERROR(
      parse(kBase + "[force]\nexpression = \"sin(t\"\n"),
      Contains("force.expression = 'sin(t'") && Contains("does not parse at position"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nexpression = \"2 * x\"\n"),
                    Contains("force.expression = '2 * x': the expression uses \"x\" at position 5, "
                             "which is no variable") &&
                        Contains("the variables are t, u and v"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nexpression = \"1 / t\"\n"),
                    Contains("force.expression = '1 / t': the expression is inf at t = 0"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nexpression = \"sqrt(t - 1)\"\n"),
                    Contains("nan at t = 0; it must be finite"));
  CHECK_SCENE_ERROR(parse(kBase, {"force.expression=\"log(t)\""}),
                    Contains("--set force.expression=\"log(t)\": force.expression = 'log(t)'") &&
                        Contains("at t = 0"));
}

TEST_CASE("force: a list of values, an assignment or a malformed number is refused",
          "[force][regression]") {
  // muparser evaluates "a,b" to its last value and "t=0" assigns to t: both ran as another force.
  CHECK_SCENE_ERROR(
      parse(kBase + "[force]\nexpression = \"1e300,-9.8\"\n"),
      Contains("force.expression = '1e300,-9.8'") && Contains("2 values separated by commas"));
  CHECK_SCENE_ERROR(parse(kBase, {"force.expression=\"sin(t), cos(t), 1\""}),
                    Contains("3 values separated by commas"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nexpression = \"(t=0)+sin(20*t)\"\n"),
                    Contains("force.expression = '(t=0)+sin(20*t)'") &&
                        Contains("assigns to t with '=' at position 3") && Contains("'=='"));
  CHECK_SCENE_ERROR(parse(kBase, {"force.expression=\"t = 1\""}), Contains("at position 3"));
  // Comparisons are fine.
  for (const char* comparison : {"(t == 0) - 9.8", "(t >= 1) - 9.8", "(t != 1) * (t <= 2) - 1"})
    CHECK(parse(kBase, {"force.expression=\"" + std::string(comparison) + "\""}).model.expression ==
          comparison);
  // A number muparser cannot read used to be reported as the unknown name "9".
  CHECK_SCENE_ERROR(
      parse(kBase + "[force]\nexpression = \"-9.8e\"\n"),
      Contains("the number \"9.8e\" at position 2 is malformed") && !Contains("uses \"9\""));
  CHECK_SCENE_ERROR(parse(kBase, {"force.expression=\"t*2.5e+\""}),
                    Contains("the number \"2.5e+\" at position 3 is malformed"));
}

TEST_CASE("force: penalty with a COR and an expression points to event_driven, not exact",
          "[force][regression]") {
  const std::string penalty = "[method]\nname = \"penalty\"\n[floor]\ncor = 0.5\n";
  CHECK_SCENE_ERROR(parse(with_method(penalty) + "[force]\nexpression = \"-9.8 + sin(t)\"\n"),
                    Contains("has no restitution law") && Contains("event_driven") &&
                        !Contains(" exact,") && !Contains(" exact or") && !Contains("or exact"));
  CHECK_SCENE_ERROR(parse(with_method(penalty) + kHarmonic),
                    Contains(" exact,") || Contains(" exact or") || Contains("or exact"));
}

TEST_CASE("force: exact with an expression force points to event_driven", "[force]") {
  CHECK_SCENE_ERROR(
      parse(with_method("[method]\nname = \"exact\"\n") +
            "[force]\nexpression = \"-9.8 + sin(t)\"\n"),
      Contains("scene.toml: method.name = 'exact'") && Contains("method.name = \"event_driven\""));
  CHECK_SCENE_ERROR(
      parse(kBase + "[force]\nexpression = \"-9.8\"\n", {"method.name=exact"}),
      Contains("--set method.name=exact: method.name = 'exact'") && Contains("event_driven"));
  // A harmonic force is exact's.
  CHECK(parse(with_method("[method]\nname = \"exact\"\n") + kHarmonic).model.harmonic.has_value());
}

namespace {

// E(T) - E(0) of WorkEnergy along a trajectory sampled on t_l = l h, l = 0..n.
template <class Trajectory>
double energy_drift(const impact::Model& model, double h, std::int64_t n, Trajectory at) {
  impact::WorkEnergy work(model, at(0.0), h);
  const double E0 = work.energy(at(0.0));
  for (std::int64_t l = 1; l <= n; ++l) work.step(l, at(static_cast<double>(l) * h));
  return work.energy(at(static_cast<double>(n) * h)) - E0;
}

}  // namespace

TEST_CASE("force: E is v^2/2 - f u bit for bit for a constant force", "[force]") {
  impact::Model model;
  model.f = -9.80665;
  model.phi = 0.25;
  impact::WorkEnergy work(model, {5.0, -1.0}, 1e-3);
  for (std::int64_t l = 1; l <= 1000; ++l) {
    const impact::State s{5.0 - 1e-3 * static_cast<double>(l) + 1e-7 * static_cast<double>(l * l),
                          std::sin(static_cast<double>(l))};
    work.step(l, s);
    if (work.energy(s) != impact::energy(model, s)) FAIL("E differs at l = " << l);
  }
  const impact::State start{5.0, -1.0};
  CHECK(impact::initial_energy(model, start) == impact::energy(model, start));
}

TEST_CASE("force: E with a harmonic force is conserved to second order, through an elastic impact",
          "[force]") {
  impact::Model model;
  model.f = -9.80665;
  model.harmonic = impact::Harmonic{4.0, 7.0, 0.3};
  const impact::ForceFunction force(model);
  // One elastic impact at t* = 0.3037 (inside a step for every h below) with speed V = 5 on the
  // floor u = 0: the flights before and after it in closed form (ForceFunction::flight, backwards
  // in time before t*). Both stay above the floor on [0, 0.6]: |u''| <= 13.8 cannot stop a speed
  // of 5 within 0.31. Measured drifts: 4.7e-4, 1.2e-4, 3.0e-5 in free flight, -2.0e-3, -3.9e-4,
  // -1.4e-4 with the impact (h = 1e-2, 5e-3, 2.5e-3).
  const double t_star = 0.3037, V = 5.0, T = 0.6;
  const auto bouncing = [&](double t) {
    return force.flight({0.0, t < t_star ? -V : V}, t_star, t);
  };
  // Free flight only (the same force, no impact) for comparison.
  const auto flying = [&](double t) { return force.flight({1.0, 2.0}, 0.0, t); };
  // The bound of work_energy.hpp: h^2 (T sup|f'| sup|u''| + sup|f'| |jump of v|), with
  // sup|f'| = amplitude omega = 28 and sup|u''| = |f| + amplitude = 13.8.
  const double fprime = 28.0, accel = 13.80665;
  for (double h : {1e-2, 5e-3, 2.5e-3}) {
    const auto n = static_cast<std::int64_t>(std::llround(T / h));
    const double free_drift = energy_drift(model, h, n, flying);
    const double impact_drift = energy_drift(model, h, n, bouncing);
    INFO("h = " << h << ": free " << free_drift << ", with the impact " << impact_drift);
    CHECK(std::fabs(free_drift) <= h * h * T * fprime * accel);
    CHECK(std::fabs(impact_drift) <= h * h * (T * fprime * accel + fprime * 2 * V));
    // Halving h divides the free-flight drift by 4 (second order), to within 10%.
    const double half = energy_drift(model, h / 2, 2 * n, flying);
    CHECK(free_drift / half == Approx(4.0).epsilon(0.1));
  }
  // What v^2/2 - f(t) u does instead: it drifts by O(1) over the run.
  const impact::State end = bouncing(T), start = bouncing(0.0);
  CHECK(std::fabs((0.5 * end.v * end.v - force.at(T) * end.u) -
                  (0.5 * start.v * start.v - force.at(0.0) * start.u)) > 0.1);
}

TEST_CASE("force: an expression force that turns non-finite during the run exits 1 naming t",
          "[force]") {
  TempDir dir;
  dir.write("s.toml", kShort +
                          "[force]\nexpression = \"sqrt(0.05 - t)\"\n[output]\nchannels = "
                          "[\"u\", \"v\", \"E\"]\n");
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o out.csv", 1,
                      Contains("the force expression is") && Contains("nan at t = 0.05") &&
                          Contains("(no output file written)"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o out.csv --events events.csv", 1,
                      Contains("nan at t = 0.05") && Contains("(no output file written)"));
  // exact refuses the expression before any output, pointing to event_driven.
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o out.csv --set method.name=exact", 2,
                      Contains("use method.name = \"event_driven\""));
  // Without E, each time-stepper meets it in its own step (penalty inside its ODE driver).
  for (const std::string method : {"direct", "fb_newton", "moreau_jean", "penalty"})
    CHECK_FAILS_CLEANLY(dir, "run s.toml -o out.csv --unset output --set method.name=" + method, 1,
                        Contains("nan at t = 0.05") && Contains("(no output file written)"));
}

TEST_CASE("force: a harmonic scene runs with each method, first impact where the flight lands",
          "[force]") {
  // u0 = 0.5 at rest under f(t) = -9.80665 + 5 sin(10 t); the first impact is the first root of
  // the closed-form flight, bracketed on a 1e-3 grid and bisected to rounding.
  impact::Model model;
  model.f = -9.80665;
  model.harmonic = impact::Harmonic{5.0, 10.0, 0.0};
  const impact::ForceFunction force(model);
  const auto height = [&](double t) { return force.flight({0.5, 0.0}, 0.0, t).u; };
  double lo = 0.0;
  while (height(lo + 1e-3) > 0) lo += 1e-3;
  double hi = lo + 1e-3;
  for (int i = 0; i < 60; ++i) (height((lo + hi) / 2) > 0 ? lo : hi) = (lo + hi) / 2;
  const double first_impact = hi;

  TempDir dir;
  dir.write("table.toml",
            "[initial]\nu0 = 0.5\nv0 = 0.0\n[floor]\ncor = 0.5\n"
            "[force]\nf = -9.80665\namplitude = 5.0\nomega = 10.0\n"
            "[time]\nT = 1.0\nh = 1e-4\n[method]\nname = \"direct\"\n"
            "[output]\nchannels = [\"u\", \"v\", \"E\"]\nevery = 100\n");
  // How far each method's first impact may be from the root: exact and event_driven to rounding
  // (event_driven's rk8pd flight at its tight tolerance); penalty to its ODE tolerance (rtol
  // 1e-10); direct and fb_newton fly the scheme's trapezoidal sum, second order, off by at most
  // h^2 sup|f'| t / 12 = 1.6e-8 in u, 5e-9 in t at the impact speed 2.9; moreau_jean places the
  // impact within its step. Measured: 0 (exact), 5.6e-17 (event_driven, both forms), 1e-12,
  // 9.3e-10, 9.3e-10, 1.0e-5.
  const std::map<std::string, double> tolerance{{"exact", 1e-12},    {"event_driven", 1e-12},
                                                {"penalty", 1e-10},  {"direct", 5e-9},
                                                {"fb_newton", 5e-9}, {"moreau_jean", 1e-4}};
  // The same force as an expression, for every method that takes one.
  const std::string expression =
      " --unset force --set 'force.expression=\"-9.80665 + 5 * sin(10 * t)\"'";
  for (const auto& [method, within] : tolerance) {
    for (const std::string& form : {std::string(), expression}) {
      if (method == "exact" && !form.empty()) continue;
      INFO(method << form);
      const std::string cor = method == "penalty" ? " --unset floor.cor" : "";
      const Result r =
          dir.run("run table.toml -q -o rows.csv --events events.csv --set method.name=" + method +
                  cor + form);
      REQUIRE(r.code == 0);
      CHECK(r.err.empty());
      const std::string events = slurp(dir / "events.csv");
      const std::size_t line = events.find('\n') + 1;
      REQUIRE(events.substr(0, line) == "t,kind,v_before,v_after\n");
      REQUIRE(events.find(",impact,", line) != std::string::npos);
      CHECK(std::fabs(std::stod(events.substr(line)) - first_impact) <= within);
      CHECK(slurp(dir / "rows.csv").rfind("t,u,v,E\n", 0) == 0);
    }
  }
}

TEST_CASE("force: the sweep's E_T is impact run's last E, bit for bit, with a harmonic force",
          "[force]") {
  TempDir dir;
  dir.write("s.toml",
            "[initial]\nu0 = 0.5\nv0 = 0.0\n[floor]\ncor = 0.5\n"
            "[force]\nf = -9.80665\namplitude = 5.0\nomega = 10.0\n"
            "[time]\nT = 1.0\nh = 1e-3\n[method]\nname = \"direct\"\n"
            "[output]\nchannels = [\"E\"]\nevery = 1000\n");
  const Result sweep = dir.run("sweep s.toml --vary force.amplitude=5 --summary E_T -q");
  REQUIRE(sweep.code == 0);
  const Result run = dir.run("run s.toml -q");
  REQUIRE(run.code == 0);
  // The last rows: "5,<E_T>," and "1,<E>".
  const std::string e_t = sweep.out.substr(sweep.out.rfind("\n5,") + 3);
  const std::string e = run.out.substr(run.out.rfind("\n1,") + 3);
  CHECK(e_t.substr(0, e_t.find(',')) + "\n" == e);
  CHECK(e.find("nan") == std::string::npos);
}
