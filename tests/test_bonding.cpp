// The bonding field (impact/model/bonding.hpp): adhesion with damage, u'' = N + f - gamma beta^2
// R(g), beta' = -beta (gamma R^2 - eps_a)_+. What these tests protect: exact's closed-form flights
// in the well with no damage (the return time 2 atan(v0 omega / G) / omega) and event_driven's
// agreement with them; the energy identity E + D + impact losses = E(0); beta in [0, beta0] and
// never rising, D never falling; the paper's model bit for bit where the field does not act
// (gamma = 0, beta0 = 0); and [bonding]'s keys and refusals with exit 2.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "bonding_support.hpp"
#include "cli_support.hpp"

using Catch::Contains;
using namespace impact;
using namespace impact::testing;

namespace {

// The acceptance scene: elastic, f = -9.81, gamma = 100, beta0 = 1, from the floor at v0 = 1,
// eps_a and L so large that nothing breaks or saturates. omega = 10.
std::string bonded_scene(const std::string& method, const std::string& bonding,
                         const std::string& rest = "") {
  return "[initial]\nu0 = 0.0\nv0 = 1.0\n[force]\nf = -9.81\n[floor]\ncor = 1.0\n"
         "[time]\nT = 1.7\nh = 0.001\n[method]\nname = \"" +
         method + "\"\n[bonding]\n" + bonding + rest;
}
const std::string kWell = "gamma = 100.0\nL = 1e6\neps_a = 1e6\nbeta0 = 1.0\n";
// Bonds that break above the gap sqrt(eps_a/gamma) = 0.0224 and saturate at L = 0.03.
const std::string kBreaking = "gamma = 100.0\nL = 0.03\neps_a = 0.05\nbeta0 = 1.0\n";

}  // namespace

TEST_CASE("bonding: exact's impacts in the well with no damage come every 2 atan(10/9.81)/10",
          "[bonding][exact]") {
  const double period = 2 * std::atan(10 / 9.81) / 10;  // well_return_time(100, 9.81, 1)
  CHECK(well_return_time(100.0, 9.81, 1.0) == Approx(period).epsilon(1e-15));
  const Sampled exact = run_bonded(bonded_scene("exact", kWell));
  const std::vector<Event> hits = impacts(exact.events);
  REQUIRE(hits.size() == 10);
  for (std::size_t k = 0; k < hits.size(); ++k) {
    INFO("impact " << k + 1);
    CHECK(std::fabs(hits[k].t - static_cast<double>(k + 1) * period) <= 1e-12);
    // The speed returns as it left, -v0 (elastic: +v0 after).
    CHECK(std::fabs(hits[k].v_before + 1.0) <= 1e-13);
  }
  // event_driven, a generic ODE with the pull in it, agrees: rk8pd at rtol 1e-12 (its default)
  // locates each impact to about 1e-15 and drifts by no more than that per flight.
  const Sampled ode = run_bonded(bonded_scene("event_driven", kWell));
  const std::vector<Event> ode_hits = impacts(ode.events);
  REQUIRE(ode_hits.size() == hits.size());
  for (std::size_t k = 0; k < hits.size(); ++k)
    CHECK(std::fabs(ode_hits[k].t - hits[k].t) <= 1e-12);
  // And every sample agrees with exact's at the same tolerance's scale.
  REQUIRE(ode.states.size() == exact.states.size());
  double gap = 0;
  for (std::size_t l = 0; l < ode.states.size(); ++l)
    gap = std::fmax(gap, std::fabs(ode.states[l].u - exact.states[l].u) +
                             std::fabs(ode.states[l].v - exact.states[l].v) / 10);
  CHECK(gap <= 1e-11);
}

TEST_CASE("bonding: E + D + the impacts' losses stay E(0), to round-off in exact's closed form",
          "[bonding][energy]") {
  const Sampled exact = run_bonded(bonded_scene("exact", kWell), {"floor.cor=0.8"});
  CHECK(energy_balance_error(exact) <= 1e-14);
  for (const StateWithInternal& s : exact.states) {
    CHECK(s.z[kBondFraction] == 1.0);
    CHECK(s.z[kBondEnergy] == 0.0);
  }
}

TEST_CASE("bonding: event_driven keeps E + D + the impacts' losses at E(0) while bonds break",
          "[bonding][energy]") {
  for (const char* cor : {"1.0", "0.9"}) {
    INFO("COR " << cor);
    const Sampled ode = run_bonded(bonded_scene("event_driven", kBreaking),
                                   {"time.T=3", std::string("floor.cor=") + cor});
    // Bonds broke (D > 0), and the balance holds to rk8pd's tolerance (rtol 1e-12) over the
    // flights: D is carried as a state, so the identity is measured, not assumed.
    CHECK(ode.states.back().z[kBondEnergy] > 1e-4);
    CHECK(ode.states.back().z[kBondFraction] < 1.0);
    CHECK(energy_balance_error(ode) <= 1e-10);
    check_bonds_monotone(ode);
  }
}

TEST_CASE("bonding: beta stays in [0, beta0] and never rises, D never falls, when bonds let go",
          "[bonding][property]") {
  // No gravity, a fast start: the bonds break as the particle flies off (beta -> 0).
  const std::string scene =
      "[initial]\nu0 = 0.0\nv0 = 30.0\n[time]\nT = 2.0\nh = 0.01\n[method]\nname = "
      "\"event_driven\"\n[bonding]\ngamma = 100.0\nL = 1.0\neps_a = 1.0\nbeta0 = 1.0\n";
  const Sampled ode = run_bonded(scene);
  check_bonds_monotone(ode);
  CHECK(ode.states.back().z[kBondFraction] < 1e-6);
  CHECK(ode.states.back().u > 10.0);  // it escaped
}

TEST_CASE("bonding: no bond breaks below v0^2 = beta0^2 eps_a + 2 G sqrt(eps_a / gamma)",
          "[bonding][property]") {
  // gamma 100, beta0 0.7, eps_a 0.5, G = 9.81: the first flight reaches gamma g^2 = eps_a at
  // v0 = 1.2776319911 (paper_notes/bonding_field.md); below it beta stays beta0 exactly.
  const double boundary = std::sqrt(0.49 * 0.5 + 2 * 9.81 * std::sqrt(0.5 / 100));
  const std::string bonds = "gamma = 100.0\nL = 1e6\neps_a = 0.5\nbeta0 = 0.7\n";
  const Sampled below =
      run_bonded(bonded_scene("event_driven", bonds),
                 {"initial.v0=" + std::to_string(0.999 * boundary), "time.T=0.5"});
  for (const StateWithInternal& s : below.states) REQUIRE(s.z[kBondFraction] == 0.7);
  const Sampled above = run_bonded(bonded_scene("event_driven", bonds),
                                   {"initial.v0=" + std::to_string(1.01 * boundary), "time.T=0.5"});
  CHECK(above.states.back().z[kBondFraction] < 0.7);
}

TEST_CASE("bonding: [bonding] and the same model written as data agree under event_driven",
          "[bonding][equivalence]") {
  // The data form: beta an [[internal]] variable with the rate -(beta (gamma R^2 - eps_a))_+ and
  // the pull -gamma beta^2 R(g) in the force's expression (phi = 0, so g = u); [bonding] carries
  // ln beta instead, so the two integrate the same ODE in different variables, with different
  // rk8pd step sequences. At rtol 1e-13 they agree within 4.3e-11 (v, elastic); at the default
  // rtol 1e-12 the elastic case differs by 1.4e-10 in v, the integrators' own error.
  const std::string tolerances = "rtol = 1e-13\natol = 1e-15\n";
  struct Case {
    std::string f, cor, v0, T;
  };
  for (const Case& c : {Case{"-9.81", "0.9", "1.0", "3.0"}, Case{"-9.81", "1.0", "1.0", "3.0"},
                        Case{"0.0", "1.0", "30.0", "2.0"}}) {
    INFO("f " << c.f << ", COR " << c.cor << ", v0 " << c.v0);
    const std::string common = "[initial]\nu0 = 0.0\nv0 = " + c.v0 + "\n[floor]\ncor = " + c.cor +
                               "\n[time]\nT = " + c.T +
                               "\nh = 0.001\n[method]\nname = \"event_driven\"\n" + tolerances;
    const Sampled bonded = run_bonded(common + "[force]\nf = " + c.f + "\n[bonding]\n" + kBreaking);
    const Sampled data = run_bonded(common + "[force]\nexpression = \"" + c.f +
                                    " - 100 * beta^2 * min(u, 0.03)\"\n" +
                                    "[[internal]]\nname = \"beta\"\ninitial = 1.0\n" +
                                    "rate = \"-max(beta * (100 * min(u, 0.03)^2 - 0.05), 0)\"\n");
    REQUIRE(bonded.states.size() == data.states.size());
    CHECK(bonded.states.back().z[kBondFraction] < 0.999);  // bonds broke
    double worst = 0;
    for (std::size_t l = 0; l < bonded.states.size(); ++l) {
      const StateWithInternal &a = bonded.states[l], &b = data.states[l];
      worst = std::fmax(worst, std::fabs(a.u - b.u));
      worst = std::fmax(worst, std::fabs(a.v - b.v));
      worst = std::fmax(worst, std::fabs(a.z[kBondFraction] - b.z[0]));
    }
    CHECK(worst <= 1e-10);
  }
}

TEST_CASE("bonding: gamma = 0 or beta0 = 0 runs the paper's model byte for byte",
          "[bonding][cli]") {
  TempDir dir;
  const std::string plain =
      "[initial]\nu0 = 0.3\nv0 = 0.5\n[force]\nf = -9.81\n[floor]\ncor = 0.8\n[time]\nT = 1.0\n"
      "h = 0.001\n[output]\nchannels = [\"u\", \"v\", \"N\", \"E\"]\n";
  for (const char* method : {"direct", "moreau_jean", "exact", "event_driven", "fb_newton"}) {
    INFO(method);
    check_idle_bonds_are_plain(dir, plain + "[method]\nname = \"" + method + "\"\n");
  }
}

TEST_CASE("bonding: a sweep's beta_T and D_T are the run's beta and D at T", "[bonding][cli]") {
  TempDir dir;
  dir.write("s.toml", bonded_scene("event_driven", kBreaking));
  // The run's last row t,u,v,beta,D against the sweep's row v0,beta_T,D_T.
  check_sweep_rows_are_last_rows(dir, "beta_T,D_T");
}

TEST_CASE("bonding: a bad [bonding] value exits 2 naming the key, its value and the range",
          "[bonding][cli][input]") {
  TempDir dir;
  struct Bad {
    std::string set, says;
  };
  for (const Bad& bad : {Bad{"bonding.gamma=-1", "bonding.gamma = -1: must be >= 0"},
                         Bad{"bonding.L=0", "bonding.L = 0: must be > 0"},
                         Bad{"bonding.eps_a=-0.5", "bonding.eps_a = -0.5: must be >= 0"},
                         Bad{"bonding.beta0=1.5", "bonding.beta0 = 1.5: must be in [0, 1]"}}) {
    dir.write("s.toml", bonded_scene("event_driven", kWell));
    const Result r = dir.run("run s.toml -o out.csv --set " + bad.set);
    INFO(bad.set << ": " << r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains(bad.says));
    CHECK(dir.entries().count("out.csv") == 0);
  }
  // A value of the wrong type, in the file.
  dir.write("s.toml", bonded_scene("event_driven", "gamma = 100.0\nL = 1.0\nbeta0 = \"all\"\n"));
  Result r = dir.run("run s.toml -o -");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("s.toml") && Contains("bonding.beta0"));
  // A method without the bonding capability (capabilities.hpp) refuses it, naming those that take
  // it.
  for (const char* refusing : {"fb_newton", "penalty", "direct_located"}) {
    dir.write("s.toml", bonded_scene(refusing, kWell));
    r = dir.run("run s.toml -o -");
    INFO(refusing << ": " << r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err,
               Contains("method.name") && Contains("use direct, moreau_jean, exact, event_driven"));
  }
  // direct's (5-1) as printed steps (u, v) alone: it refuses the bonds, naming the key.
  dir.write("s.toml", bonded_scene("direct", kWell));
  r = dir.run("run s.toml -o - --set method.free_flight=paper");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("method.free_flight") && Contains("bonding field"));
  // exact refuses a run whose flights leave the well with no damage, and says why.
  dir.write("s.toml", bonded_scene("exact", kBreaking));
  r = dir.run("run s.toml -o -");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("bonding.L = 0.03") && Contains("event_driven"));
  dir.write("s.toml", bonded_scene("exact", "gamma = 100.0\nL = 1.0\neps_a = 0.05\nbeta0 = 1.0\n"));
  r = dir.run("run s.toml -o -");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("bonding.eps_a"));
  // The errors against the reference (event_driven's track) are measured, by a run and a sweep.
  dir.write("s.toml", bonded_scene("direct", kBreaking));
  r = dir.run("run s.toml -q -o out.csv --against exact");
  CHECK(r.code == 0);
  CHECK_THAT(r.err, Contains("sup|u - u_exact|") && Contains("sup|z - z_exact|"));
  r = dir.run("sweep s.toml -q --vary initial.v0=1,2 -o out.csv --against exact");
  CHECK(r.code == 0);
  CHECK_THAT(slurp(dir / "out.csv"), Contains("err_internal_sup"));
}
