// The Frémond form of the bonding field, b beta' = -(beta gamma R^2 - eps_a)_+ (bonding.hpp;
// paper_notes/bonding_field.md). What these tests protect: the time-steppers' update is LMGC90's
// MAC_CZM update, step for step and bit for bit; with eps_a = 0 and b = 1 it is the product form's
// law; beta stays in [0, beta0], never rising, in every method, on a stiff bond too; at a fixed
// opening it stops at eps_a/(gamma R^2) where the product form decays to 0; event_driven keeps
// E + D + the impacts' losses at E(0); exact takes the run only below the Frémond form's own
// no-damage bound; the keys are checked.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "bonding_support.hpp"
#include "cli_support.hpp"

using namespace impact;
using namespace impact::testing;
using Catch::Matchers::Contains;

namespace {

// LMGC90's damage update of the MAC_CZM law, written as updt_CZM states it (LMGC90,
// src/Core/shared/mod_tact_behav.f90, subroutine updt_CZM, case i_MAC_CZM; read in the copy
// petrasvestartas/lmgc90_installation at commit 57644a92b64f), in the normal direction alone
// (nucut = 0, so its g1overg2*ct*nucut terms are 0) with the opening ucun at the step's end:
//   nucun = ((dabs(ucun)+ucun)*0.5)**2
//   beta = ((H*w) + (internal(4))*b) /(b + H*( (g1overg2*ct*nucut) + cn*nucun))
//   if (beta < mac_beta_tol) taz(1) = 0.d0
//   if (beta <= internal(4) .and. w <= (internal(4)*((g1overg2*ct*nucut) + cn*nucun))) taz(1) =
//   beta
// taz(1) enters the step as internal(4), beta_n (init_CZM); mac_beta_tol = 1.d-12.
double mac_czm_update(double cn, double w, double b, double H, double ucun, double beta_n) {
  const double mac_beta_tol = 1e-12;
  const double nucut = 0.0, g1overg2 = 1.0, ct = 0.0;
  const double nucun = std::pow((std::fabs(ucun) + ucun) * 0.5, 2);
  double taz = beta_n;
  double beta;
  if ((b + H * ((g1overg2 * ct * nucut) + cn * nucun)) == 0.0)
    beta = 1.0;
  else
    beta = ((H * w) + beta_n * b) / (b + H * ((g1overg2 * ct * nucut) + cn * nucun));
  if (beta < mac_beta_tol) taz = 0.0;
  if (beta <= beta_n && w <= (beta_n * ((g1overg2 * ct * nucut) + cn * nucun))) taz = beta;
  return taz;
}

Bonding fremond(double gamma, double eps_a, double b) {
  Bonding bonds;
  bonds.gamma = gamma;
  bonds.eps_a = eps_a;
  bonds.form = BondForm::fremond;
  bonds.b = b;
  return bonds;
}

// The breaking scene of test_bonding.cpp (elastic, f = -9.81, from the floor at v0 = 1; bonds
// saturating at L = 0.03) in the Frémond form with `bonds` for the rest of [bonding].
std::string scene(const std::string& method, const std::string& bonds, double T = 3.0,
                  double cor = 1.0) {
  return "[initial]\nu0 = 0.0\nv0 = 1.0\n[force]\nf = -9.81\n[floor]\ncor = " +
         std::to_string(cor) + "\n[time]\nT = " + std::to_string(T) +
         "\nh = 0.001\n[method]\nname = \"" + method + "\"\n[bonding]\n" + bonds;
}
const std::string kBreaking =
    "gamma = 100.0\nL = 0.03\neps_a = 0.05\nbeta0 = 1.0\nform = \"fremond\"\nb = 0.01\n";

}  // namespace

TEST_CASE("fremond: bond_step is MAC_CZM's update, step for step and bit for bit",
          "[bonding][fremond]") {
  // A prescribed opening history: g_n = 0.01 (1 + 3n/2000) sin(2 pi n / 500), h = 1e-3, over 4
  // periods of a growing amplitude (0.01 to 0.04), so that each opening damages the bonds anew;
  // its negative half is compression, where MAC_CZM's <u_n>_+ and the package's R(g) are both 0.
  // cn = gamma = 1e4, w = eps_a = 0.5, b = 0.01: bonds break past the gap sqrt(w/(cn beta)) =
  // 0.0071 at beta = 1, and beta falls towards w/(cn 0.04^2) = 0.031 at the last peak. No
  // saturation (L infinite): MAC_CZM has none.
  const double h = 1e-3, pi = std::acos(-1.0);
  const Bonding bonds = fremond(1e4, 0.5, 0.01);
  double beta = 1.0, mac = 1.0, spent = 0.0;
  int taken = 0;
  for (int n = 1; n <= 2000; ++n) {
    const double gap = 0.01 * (1 + 3.0 * n / 2000) * std::sin(2 * pi * n / 500);
    const double before = beta;
    bond_step(bonds, h, gap, beta, spent);
    mac = mac_czm_update(bonds.gamma, bonds.eps_a, bonds.b, h, gap, mac);
    INFO("step " << n << ", gap " << gap);
    REQUIRE(beta == mac);  // the same bits
    REQUIRE(beta <= before);
    REQUIRE(beta > 0.0);
    if (beta < before) ++taken;
  }
  // The history does damage the bonds, in every opening (281 updates taken, beta(2) = 0.0423 as
  // measured), and beta stays above MAC_CZM's cut mac_beta_tol = 1e-12, below which its update
  // zeroes a rejected beta and the package keeps it.
  CHECK(taken > 200);
  CHECK(beta < 0.05);
  CHECK(beta > 1e-12);
}

TEST_CASE("fremond: with eps_a = 0 and b = 1 the time-steppers' update is the product form's",
          "[bonding][fremond]") {
  // b beta' = -(beta gamma R^2)_+ is beta' = -beta gamma R^2 at b = 1: both updates are
  // beta_n / (1 + h gamma R^2), computed as gamma (R R) and (gamma R) R, a rounding apart per
  // step. 1000 steps, a relative 1e-12 (1000 steps of a few ulps of 2.2e-16 each).
  Bonding product;
  product.gamma = 1e4;
  product.L = 0.03;
  const Bonding same = [&] {
    Bonding b = fremond(1e4, 0.0, 1.0);
    b.L = 0.03;
    return b;
  }();
  double beta_p = 1.0, beta_f = 1.0, spent_p = 0.0, spent_f = 0.0;
  for (int n = 1; n <= 1000; ++n) {
    const double gap = 0.04 * std::fabs(std::sin(0.01 * n));
    bond_step(product, 1e-3, gap, beta_p, spent_p);
    bond_step(same, 1e-3, gap, beta_f, spent_f);
  }
  CHECK(beta_p < 0.5);
  CHECK(beta_f == Approx(beta_p).epsilon(1e-12));
  CHECK(spent_f == Approx(spent_p).epsilon(1e-12));
}

TEST_CASE("fremond: at a fixed opening beta stops at eps_a/(gamma R^2), the product form's decays",
          "[bonding][fremond]") {
  // gamma R^2 = 1 at the gap 0.1, eps_a = 0.05: the Frémond update is a weighted mean of beta_n
  // and eps_a/(gamma R^2) = 0.05, which it approaches as (b/(b + h))^n; the product form's is
  // beta_n/(1 + h 0.95), (1 + 0.95e-3)^-n -> 0. After 1e5 steps of h = 1e-3 (t = 100) the
  // Frémond beta is 0.05 to rounding: the step contracts by 1/(1 + h gamma R^2/b) = 1/1.001, so
  // its fixed point in floating point sits within 1/(1 - 1/1.001) = 1000 roundings of a few ulps
  // of 0.05, a relative 1e-12 (measured 2.1e-13). The product beta is e^-95 = 5.8e-42: neither
  // is 0.
  Bonding product;
  product.gamma = 100.0;
  product.eps_a = 0.05;
  const Bonding frem = fremond(100.0, 0.05, 1.0);
  double beta_p = 1.0, beta_f = 1.0, spent = 0.0;
  for (int n = 0; n < 100000; ++n) {
    bond_step(product, 1e-3, 0.1, beta_p, spent);
    bond_step(frem, 1e-3, 0.1, beta_f, spent);
  }
  CHECK(beta_f == Approx(0.05).epsilon(1e-12));
  CHECK(beta_p > 0.0);
  CHECK(beta_p < 1e-40);
}

TEST_CASE(
    "fremond: beta in [0, beta0], never rising, D never falling, on a stiff bond and as "
    "bonds let go",
    "[bonding][fremond]") {
  // The stiff case of test_bonding_steppers.cpp (gamma = 1e12, eps_a = 1e-12, h = 1e-3), and
  // the escape (f = 0, v0 = 30) under event_driven, both in the Frémond form with b = 0.01.
  const std::string stiff =
      "gamma = 1e12\neps_a = 1e-12\nbeta0 = 1.0\nform = \"fremond\"\nb = 0.01\n";
  for (const char* method : {"direct", "moreau_jean"}) {
    INFO(method);
    const Sampled run = run_bonded(scene(method, stiff, 0.3));
    check_bonds_monotone(run);
    // Damage takes beta far down, but a taken update is a mean with eps_a/(gamma R^2) > 0 and
    // the rejected ones keep beta: beta stays > 0 (the product form underflows to 0 here).
    CHECK(run.states.back().z[kBondFraction] < 1e-6);
    CHECK(run.states.back().z[kBondFraction] > 0.0);
    // The same scene in the product form: its implicit update underflows beta to 0.
    const Sampled product = run_bonded(scene(method, stiff.substr(0, stiff.find("form")), 0.3));
    CHECK(product.states.back().z[kBondFraction] == 0.0);
  }
  const Sampled escape = run_bonded(
      "[initial]\nu0 = 0.0\nv0 = 30.0\n[force]\nf = 0.0\n[floor]\ncor = 1.0\n[time]\nT = 2.0\n"
      "h = 0.001\n[method]\nname = \"event_driven\"\n[bonding]\ngamma = 100.0\nL = 1.0\n"
      "eps_a = 1.0\nbeta0 = 1.0\nform = \"fremond\"\nb = 0.01\n");
  check_bonds_monotone(escape);
  // The escape ends at the gap 60 and more, where gamma R^2 = 100 saturates: the Frémond beta
  // stops near eps_a/(gamma L^2) = 0.01, with b = 0.01 fast enough to get there.
  CHECK(escape.states.back().z[kBondFraction] == Approx(0.01).epsilon(1e-6));
  // E + D = E(0) = 450 with no impact: rk8pd's rtol 1e-12 on a D of order 450.
  CHECK(energy_balance_error(escape) <= 1e-9);
}

TEST_CASE("fremond: event_driven keeps E + D + the impacts' losses at E(0) while bonds break",
          "[bonding][fremond][event_driven]") {
  // The breaking scene, COR 1 and 0.9, T = 3. The bound is test_bonding.cpp's for the product
  // form, 1e-10 (rk8pd's rtol 1e-12 over the run's flights).
  for (const double cor : {1.0, 0.9}) {
    INFO("COR " << cor);
    const Sampled run = run_bonded(scene("event_driven", kBreaking, 3.0, cor));
    check_bonds_monotone(run);
    CHECK(run.states.back().z[kBondFraction] < 1.0);  // bonds do break
    CHECK(energy_balance_error(run) <= 1e-10);
  }
}

TEST_CASE("fremond: exact takes the well below beta0 gamma g^2 = eps_a only, and agrees there",
          "[bonding][fremond][exact]") {
  // beta0 = 0.5, gamma = 100, eps_a = 0.02, f = -9.81: the Frémond form breaks past the gap
  // sqrt(eps_a/(gamma beta0)) = 0.02, the product form past sqrt(eps_a/gamma) = 0.0141. At
  // v0 = 0.6 the first flight rises to 0.01794 (well_height, k = gamma beta0^2 = 25): only the
  // product form refuses; at v0 = 0.8 (0.03137) both refuse, naming event_driven.
  const std::string bonds =
      "gamma = 100.0\neps_a = 0.02\nbeta0 = 0.5\nform = \"fremond\"\nb = 0.1\n";
  const std::string head = "[initial]\nu0 = 0.0\nv0 = ";
  auto at = [&](const char* v0, const char* method, const std::string& b) {
    return head + v0 +
           "\n[force]\nf = -9.81\n[floor]\ncor = 1.0\n[time]\nT = 1.0\nh = 0.001\n[method]\n"
           "name = \"" +
           method + "\"\n[bonding]\n" + b;
  };
  const Sampled exact = run_bonded(at("0.6", "exact", bonds));
  const Sampled ode = run_bonded(at("0.6", "event_driven", bonds));
  REQUIRE(exact.states.size() == ode.states.size());
  // No bond breaks under event_driven either: beta stays beta0 exactly (its rate is 0), and the
  // two agree to rk8pd's tolerance over the run (1e-9: rtol 1e-12 over 8 flights; measured 1.2e-14
  // in v).
  CHECK(ode.states.back().z[kBondFraction] == 0.5);
  CHECK(std::fabs(ode.states.back().u - exact.states.back().u) <= 1e-9);
  CHECK(std::fabs(ode.states.back().v - exact.states.back().v) <= 1e-9);
  TempDir dir;
  std::string product = bonds.substr(0, bonds.find("form"));
  dir.write("p.toml", at("0.6", "exact", product));
  CHECK_FAILS_CLEANLY(dir, "run p.toml -o p.csv", 2, Contains("event_driven"));
  dir.write("f.toml", at("0.8", "exact", bonds));
  CHECK_FAILS_CLEANLY(dir, "run f.toml -o f.csv", 2,
                      Contains("beta0 gamma g^2 > bonding.eps_a") && Contains("event_driven"));
}

TEST_CASE("fremond: bonding.form and bonding.b are checked, naming the file, key and value",
          "[bonding][fremond][cli]") {
  TempDir dir;
  const std::string head =
      "[initial]\nu0 = 0.0\nv0 = 1.0\n[force]\nf = -9.81\n[time]\nT = 0.1\n"
      "h = 0.001\n[method]\nname = \"direct\"\n[bonding]\ngamma = 100.0\n";
  dir.write("form.toml", head + "form = \"fremont\"\n");
  CHECK_FAILS_CLEANLY(dir, "run form.toml -o o.csv", 2,
                      Contains("form.toml") && Contains("bonding.form") && Contains("'fremont'") &&
                          Contains("fremond"));
  dir.write("b.toml", head + "form = \"fremond\"\nb = 0.0\n");
  CHECK_FAILS_CLEANLY(dir, "run b.toml -o o.csv", 2,
                      Contains("b.toml") && Contains("bonding.b") && Contains("> 0"));
  dir.write("nob.toml", head + "form = \"fremond\"\n");
  CHECK_FAILS_CLEANLY(dir, "run nob.toml -o o.csv", 2,
                      Contains("nob.toml") && Contains("bonding.form") && Contains("bonding.b"));
  dir.write("prod.toml", head + "b = 0.5\n");
  CHECK_FAILS_CLEANLY(
      dir, "run prod.toml -o o.csv", 2,
      Contains("prod.toml") && Contains("bonding.b") && Contains("0.5") && Contains("fremond"));
  // --set takes them as every key: the Frémond run of the same scene differs from the product's.
  dir.write("ok.toml", head + "L = 0.03\neps_a = 0.05\n");
  CHECK(dir.run("run ok.toml -q -o p.csv").code == 0);
  CHECK(dir.run("run ok.toml -q -o f.csv --set bonding.form=fremond --set bonding.b=0.01").code ==
        0);
  CHECK(slurp(dir / "p.csv") != slurp(dir / "f.csv"));
}
