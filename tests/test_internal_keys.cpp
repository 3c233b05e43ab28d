// Internal variables through the command line's keys and the checks on their tables: --set,
// --unset and --vary reach a variable as internal.NAME.key through the one key table; a rate is
// one value that reads its variables and never assigns; a name the output's columns have, or one
// muparser has taken, is refused; the force and the rates are evaluated where the run starts, not
// at u = v = 0. Each refusal exits 2, names the key and leaves no file.
#include <bit>
#include <catch2/catch.hpp>
#include <string>

#include "cli_support.hpp"
#include "output_support.hpp"

using Catch::Contains;
using namespace impact::testing;

namespace {

// The bits of a double, to compare two bit for bit.
std::uint64_t same_bits_of(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

const std::string kHead =
    "[initial]\nu0 = 0.3\nv0 = 0.0\n[time]\nT = 0.2\nh = 1e-3\n[method]\nname = \"direct\"\n"
    "[force]\nexpression = \"-9.81 + 5 * z\"\n";
const std::string kZ = "[[internal]]\nname = \"z\"\ninitial = 1.0\nrate = \"-z\"\n";

double first(const Table& t, const std::string& column, std::size_t row = 0) {
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (t.columns[c] == column) return t.rows[row][c];
  FAIL("no column " << column);
  return 0;
}

}  // namespace

TEST_CASE("internal keys: --set, --unset and --vary reach a variable as internal.NAME.key",
          "[internal][cli][regression]") {
  TempDir dir;
  dir.write("s.toml", kHead + kZ + "[[internal]]\nname = \"w\"\ninitial = 0.0\nrate = \"z\"\n");
  for (const std::string method : {"direct", "moreau_jean", "event_driven"}) {
    INFO(method);
    const std::string run = "run s.toml -q --no-provenance -o rows.csv --set method.name=" + method;
    REQUIRE(dir.run(run + " --set internal.z.initial=2.5").code == 0);
    const Table set = read_table(slurp(dir / "rows.csv"));
    CHECK(first(set, "z") == 2.5);
    CHECK(first(set, "w") == 0.0);
    // A rate through --set: z' = 0 keeps z at its initial value.
    REQUIRE(dir.run(run + " --set 'internal.z.rate=\"0\"'").code == 0);
    const Table held = read_table(slurp(dir / "rows.csv"));
    CHECK(first(held, "z", held.rows.size() - 1) == 1.0);
    // --unset removes one variable: w goes, z stays (the force reads z).
    REQUIRE(dir.run(run + " --unset internal.w").code == 0);
    CHECK(read_table(slurp(dir / "rows.csv")).columns ==
          std::vector<std::string>{"t", "u", "v", "z"});
  }
  // --vary internal.z.initial: one row per value, z_T and w_T named after the variables.
  const Result sweep = dir.run("sweep s.toml -q -o sweep.csv --vary internal.z.initial=0,2");
  INFO(sweep.err);
  REQUIRE(sweep.code == 0);
  // The sweep's rows without their last column, failure (empty: no point failed).
  std::string text = slurp(dir / "sweep.csv");
  for (std::size_t at; (at = text.find(",\n")) != std::string::npos;) text.erase(at, 1);
  text.replace(text.find(",failure"), 8, "");
  const Table rows = read_table(text);
  CHECK(rows.columns.front() == "internal.z.initial");
  CHECK(std::find(rows.columns.begin(), rows.columns.end(), "z_T") != rows.columns.end());
  CHECK(std::find(rows.columns.begin(), rows.columns.end(), "w_T") != rows.columns.end());
  // z' = -z from 0 stays 0; from 2 it is 2 e^-T to first order (direct's explicit Euler).
  CHECK(first(rows, "z_T", 0) == 0.0);
  CHECK(first(rows, "z_T", 1) == Approx(2 * std::exp(-0.2)).epsilon(2e-3));
  // The point's --set text gives it back to impact run, bit for bit.
  REQUIRE(dir.run("run s.toml -q --no-provenance -o rows.csv --set internal.z.initial=2").code ==
          0);
  const Table point = read_table(slurp(dir / "rows.csv"));
  CHECK(same_bits_of(first(point, "z", point.rows.size() - 1)) ==
        same_bits_of(first(rows, "z_T", 1)));
}

TEST_CASE("internal keys: a key or a variable that is not there is refused, naming what is",
          "[internal][cli][regression]") {
  TempDir dir;
  dir.write("s.toml", kHead + kZ);
  const std::string run = "run s.toml -o out.csv ";
  CHECK_FAILS_CLEANLY(dir, run + "--set internal.q.initial=1", 2,
                      Contains("there is no internal variable 'q'") && Contains("z"));
  CHECK_FAILS_CLEANLY(dir, run + "--set internal.z.inital=1", 2,
                      Contains("initial, rate") && Contains("did you mean initial"));
  CHECK_FAILS_CLEANLY(dir, run + "--set internal.z.name=y", 2, Contains("rename it in the scene"));
  CHECK_FAILS_CLEANLY(dir, run + "--set internal.z.initial=nan", 2,
                      Contains("--set internal.z.initial=nan") && Contains("finite"));
  // --unset internal.name (a key of the table, not a variable) says which variables there are.
  CHECK_FAILS_CLEANLY(
      dir, run + "--unset internal.name", 2,
      Contains("no internal variable 'name'") && Contains("its internal variables: z"));
  CHECK_FAILS_CLEANLY(dir, run + "--unset internal.z.rate", 2,
                      Contains("needs name, initial and rate"));
  // Without the variable the force no longer parses: the message names the token.
  CHECK_FAILS_CLEANLY(dir, run + "--unset internal.z", 2, Contains("\"z\""));
  CHECK_FAILS_CLEANLY(dir, "sweep s.toml -o out.csv --vary internal.z.rate=1,2", 2,
                      Contains("not a key a sweep can vary"));
  dir.write("plain.toml", kShort);
  CHECK_FAILS_CLEANLY(dir, "run plain.toml -o out.csv --set internal.z.initial=1", 2,
                      Contains("there is no [[internal]]"));
}

TEST_CASE("internal keys: a rate or a force is one value that only reads, never assigns",
          "[internal][cli][regression]") {
  TempDir dir;
  const auto refused = [&](const std::string& force, const std::string& rate,
                           const std::string& says) {
    dir.write("s.toml", kHead.substr(0, kHead.find("[force]")) + "[force]\nexpression = \"" +
                            force + "\"\n[[internal]]\nname = \"z\"\ninitial = 1.0\nrate = \"" +
                            rate + "\"\n[[internal]]\nname = \"b\"\ninitial = 0.0\nrate = \"t\"\n");
    CHECK_FAILS_CLEANLY(dir, "run s.toml -o out.csv", 2, Contains(says));
  };
  // A comma list used to run as its last value (z' = 2).
  refused("-9.81 + z", "1,2", "2 values separated by commas");
  refused("-9.81 + z", "(1, 2)", "the rate of internal variable \"z\"");
  // An assignment in one rate wrote t for the next (b(T) = 0.3 instead of 3e-6).
  refused("-9.81 + z", "t=100", "assigns to t with '=' at position 2");
  refused("-9.81 + z", "z += 1", "assigns to z");
  refused("-9.81 + z", "(b = 3) + z", "assigns to b");
  refused("(z = 0) - 9.81", "-z", "assigns to z");
  // Comparisons are not assignments.
  dir.write("s.toml", kHead +
                          "[[internal]]\nname = \"z\"\ninitial = 1.0\nrate = \"(t <= 0.1) "
                          "- (t >= 0.1) + (t == 0) - (t != 0)\"\n");
  CHECK(dir.run("run s.toml -q -o out.csv").code == 0);
}

TEST_CASE("internal keys: a name the output or muparser has taken is refused",
          "[internal][cli][regression]") {
  TempDir dir;
  for (const std::string name :
       {"N", "E", "iterations", "N_scheme", "kind", "v_before", "v_after"}) {
    INFO(name);
    dir.write("s.toml",
              kHead + "[[internal]]\nname = \"" + name + "\"\ninitial = 7.0\nrate = \"0\"\n");
    CHECK_FAILS_CLEANLY(dir, "run s.toml -o out.csv", 2,
                        Contains("internal variable \"" + name + "\"") &&
                            Contains("taken by a column of the output"));
  }
  for (const std::string name : {"_pi", "_e", "sin", "pi", "t"}) {
    INFO(name);
    dir.write("s.toml",
              kHead + "[[internal]]\nname = \"" + name + "\"\ninitial = 7.0\nrate = \"0\"\n");
    CHECK_FAILS_CLEANLY(dir, "run s.toml -o out.csv", 2, Contains("the name is taken"));
  }
}

TEST_CASE("internal keys: the force and the rates are evaluated where the run starts",
          "[internal][force][cli][regression]") {
  TempDir dir;
  const std::string head =
      "[initial]\nu0 = 2.0\nv0 = 0.0\n[floor]\nphi = 1.0\n[time]\nT = 0.2\nh = 1e-3\n"
      "[method]\nname = \"event_driven\"\n";
  // 0.01 / u is finite wherever the particle can be (u >= phi = 1): it used to be refused as
  // inf at u = 0.
  dir.write("s.toml", head + "[force]\nexpression = \"-9.81 + 0.01 / u\"\n");
  CHECK(dir.run("run s.toml -q -o out.csv").code == 0);
  dir.write("s.toml", head +
                          "[force]\nexpression = \"-9.81 + z\"\n[[internal]]\nname = "
                          "\"z\"\ninitial = 0.0\nrate = \"1 / u\"\n");
  CHECK(dir.run("run s.toml -q -o out.csv").code == 0);
  // Not finite at the initial state: refused there, naming it.
  dir.write("s.toml", head + "[force]\nexpression = \"-9.81 + 1 / (u - 2)\"\n");
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o x.csv", 2,
                      Contains("force.expression") && Contains("the initial state: u = 2"));
  dir.write("s.toml", head +
                          "[force]\nexpression = \"-9.81 + z\"\n[[internal]]\nname = "
                          "\"z\"\ninitial = 0.0\nrate = \"1 / (u - 2)\"\n");
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o x.csv", 2,
                      Contains("rate of internal variable \"z\"") && Contains("initial state"));
  // Not finite where the run gets to: exit 1 naming t (the particle falls below u = 1.5).
  dir.write("s.toml", head + "[force]\nexpression = \"-9.81 + sqrt(u - 1.5)\"\n");
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o x.csv --set time.T=1", 1, Contains("at t = "));
  // An initial value as u0 takes it: an integer beyond 2^53 is the double nearest it.
  dir.write("s.toml", head +
                          "[force]\nexpression = \"-9.81 + 0 * z\"\n[[internal]]\nname = "
                          "\"z\"\ninitial = 9007199254740993\nrate = \"0\"\n");
  REQUIRE(dir.run("run s.toml -q --no-provenance -o out.csv").code == 0);
  CHECK(first(read_table(slurp(dir / "out.csv")), "z") == 9007199254740992.0);
}

TEST_CASE("internal keys: a stiff rate under event_driven is reported as stiff",
          "[internal][driven][cli][regression]") {
  TempDir dir;
  // z' = -1e12 (z - sin t): rk8pd's stability keeps its steps near 3e-12 s, so a million of them
  // do not reach the first grid time; the particle is in flight, far from any contact.
  dir.write("s.toml",
            "[initial]\nu0 = 1.0\nv0 = 0.0\n[time]\nT = 0.01\nh = 1e-3\n[method]\nname = "
            "\"event_driven\"\n[force]\nexpression = \"-9.81 + z\"\n[[internal]]\nname = "
            "\"z\"\ninitial = 0.0\nrate = \"-1e12 * (z - sin(t))\"\n");
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o out.csv", 1,
                      Contains("stiff system for rk8pd") &&
                          Contains("an internal variable's rate varies") &&
                          !Contains("contact search stalled"));
}
