// The `impact` command, run as a separate process (IMPACT_CLI) in a fresh temporary directory:
// exit codes, messages on standard error, the CSV it writes, and that a failed run leaves no file.
#include <stdlib.h>
#include <sys/wait.h>

#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "impact/error_norms.hpp"
#include "impact/model.hpp"
#include "impact/output.hpp"
#include "impact/registry.hpp"
#include "impact/run.hpp"
#include "scene/read_scene.hpp"

using Catch::Contains;

using namespace impact::testing;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;

struct Csv {
  std::string header;
  std::vector<std::vector<double>> rows;
};

// Reads a CSV written by `impact`; every field must be a whole number as strtod reads it.
Csv read_csv(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in);
  Csv csv;
  REQUIRE(std::getline(in, csv.header));
  const auto columns =
      static_cast<std::size_t>(std::count(csv.header.begin(), csv.header.end(), ',') + 1);
  std::string line, bad;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) {
      char* end = nullptr;
      row.push_back(std::strtod(field.c_str(), &end));
      if (bad.empty() && (field.empty() || *end != '\0')) bad = line;
    }
    if (bad.empty() && row.size() != columns) bad = line;
    csv.rows.push_back(std::move(row));
  }
  INFO(path << ": first malformed line: '" << bad << "'");
  REQUIRE(bad.empty());
  return csv;
}

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

const std::string kShortScene =
    "[initial]\nu0 = 0.05\nv0 = -1.0\n"
    "[floor]\ncor = 0.75\n"
    "[force]\nf = -9.80665\n"
    "[time]\nT = 0.1\nh = 0.001\n"
    "[method]\nname = \"direct\"\n"
    "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\"]\n";

}  // namespace

TEST_CASE("cli: figure 3 without COR writes 10001 rows and conserves the energy", "[cli]") {
  TempDir dir;
  Result r = dir.run("run " + quote(kSource + "/experiments/figure3/no_cor.toml") + " --out X.csv");
  REQUIRE(r.code == 0);
  CHECK(r.out.empty());  // the CSV goes to the file, the summary to standard error
  CHECK_THAT(r.err, Contains("direct") && Contains("10000 steps"));
  CHECK(dir.entries() == std::set<std::string>{"X.csv", "X.csv.json"});

  Csv csv = read_csv(dir / "X.csv");
  CHECK(csv.header == "t,u,v,N,E");
  REQUIRE(csv.rows.size() == 10001);
  CHECK(csv.rows.front()[0] == 0.0);
  CHECK(csv.rows.front()[1] == 5.0);
  CHECK(csv.rows.front()[2] == -1.0);
  CHECK(csv.rows.back()[0] == 10.0);
  for (std::size_t l = 0; l < csv.rows.size(); ++l)
    if (csv.rows[l][0] != static_cast<double>(l) * 0.001) FAIL("t is not l h at l = " << l);
  // The particle did hit the floor and bounce back.
  const double min_u = std::min_element(csv.rows.begin(), csv.rows.end(), [](auto& a, auto& b) {
                         return a[1] < b[1];
                       })->at(1);
  CHECK(min_u == 0.0);
  CHECK(csv.rows.back()[2] > 0.0);
  // The acceptance check: E(T) = E(0) to 1e-12 relative (Lemma 1, f = 0, no COR).
  const double E0 = csv.rows.front()[4], ET = csv.rows.back()[4];
  CHECK(E0 == 0.5);
  CHECK(std::fabs(ET - E0) <= 1e-12 * std::fabs(E0));

  // --quiet: no summary line.
  r = dir.run("run " + quote(kSource + "/experiments/figure3/no_cor.toml") + " -q -o Y.csv");
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK(slurp(dir / "Y.csv") == slurp(dir / "X.csv"));
}

TEST_CASE("cli: the figure 4 scenes finish with finite values", "[cli]") {
  TempDir dir;
  for (const char* scene : {"figure4/no_cor.toml", "figure4/cor075.toml", "figure3/cor075.toml"}) {
    INFO(scene);
    Result r = dir.run("run " + quote(kSource + "/experiments/" + scene) + " --out X.csv");
    REQUIRE(r.code == 0);
    const std::string text = slurp(dir / "X.csv");
    std::string lower = text;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    CHECK(lower.find("nan") == std::string::npos);
    CHECK(lower.find("inf") == std::string::npos);
    Csv csv = read_csv(dir / "X.csv");
    CHECK(csv.header == "t,u,v,N,E");
    CHECK(csv.rows.size() == 10001);
    bool finite = true, above_floor = true;
    for (const auto& row : csv.rows) {
      for (double x : row) finite = finite && std::isfinite(x);
      above_floor = above_floor && row[1] >= 0.0;
    }
    CHECK(finite);
    CHECK(above_floor);
    CHECK(dir.entries() == std::set<std::string>{"X.csv", "X.csv.json"});
  }
}

TEST_CASE("cli: a mistyped key exits 2 and leaves no file", "[cli]") {
  TempDir dir;
  dir.write("typo.toml",
            "[initial]\nu0 = 5.0\nv0 = -1.0\n[time]\nT = 10.0\nhh = 0.001\n"
            "[method]\nname = \"direct\"\n");
  Result r = dir.run("run typo.toml --out X.csv");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("typo.toml") && Contains("time.hh") && Contains("0.001") &&
                        Contains("unknown key") && Contains("T, h"));
  CHECK(dir.entries() == std::set<std::string>{"typo.toml"});  // no X.csv, no X.csv.tmp.*

  // A missing scene file and an invalid one are bad input, too.
  r = dir.run("run missing.toml --out X.csv");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("missing.toml"));
  dir.write("broken.toml", "[initial\nu0 = 5.0\n");
  r = dir.run("run broken.toml --out X.csv");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("broken.toml") && Contains("not a valid TOML scene"));
  CHECK(dir.entries() == std::set<std::string>{"typo.toml", "broken.toml"});
}

TEST_CASE("cli: bad --set overrides exit 2", "[cli]") {
  TempDir dir;
  const std::string scene = quote(kSource + "/experiments/figure3/no_cor.toml");
  Result r = dir.run("run " + scene + " --set time.h=-1 --out X.csv");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("--set time.h=-1: time.h = -1") && Contains("must be > 0"));

  r = dir.run("run " + scene + " --set time.h --out X.csv");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("--set time.h") && Contains("expected table.key=value"));

  r = dir.run("run " + scene + " --set 'output.channels=[1,' --out X.csv");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("output.channels=[1,") && Contains("not a TOML value"));

  r = dir.run("run " + scene + " --set h=1 --out X.csv");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("table.key"));
  CHECK(dir.entries().empty());

  // Good overrides, before or after the scene: time.h = 0.01, T = 1 gives 100 steps.
  r = dir.run("run --set time.h=0.01 " + scene +
              " --set time.T=1 --set method.name=exact -o X.csv");
  CHECK(r.code == 0);
  CHECK_THAT(r.err, Contains("exact") && Contains("100 steps"));
  CHECK(read_csv(dir / "X.csv").rows.size() == 101);
}

TEST_CASE("cli: --unset removes a key for one run", "[cli]") {
  TempDir dir;
  const std::string scene = quote(kSource + "/experiments/figure4/cor075.toml");
  // Penalty has no restitution law: on a COR scene it needs the COR removed.
  Result r = dir.run("run " + scene + " --set method.name=penalty --set time.T=0.1 -o X.csv");
  CHECK(r.code == 2);
  CHECK_THAT(r.err,
             Contains("floor.cor = 0.75: method 'penalty'") && Contains("--unset floor.cor"));
  r = dir.run("run " + scene +
              " --set method.name=penalty --unset floor.cor --set time.T=0.1 -o X.csv");
  CHECK(r.code == 0);
  CHECK_THAT(r.err, Contains("impact: penalty, 100 steps"));
  CHECK(read_csv(dir / "X.csv").rows.size() == 101);
  // Unsetting what is not there names it.
  r = dir.run("run " + scene + " --unset floor.e -o Y.csv");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("--unset floor.e: there is no floor.e in") && Contains("cor075.toml"));
  r = dir.run("run " + scene + " --unset -o Y.csv");
  CHECK(r.code == 2);
  CHECK(dir.entries() == std::set<std::string>{"X.csv", "X.csv.json"});
}

TEST_CASE("cli: a bad output path exits 2 and leaves nothing behind", "[cli]") {
  TempDir dir;
  const std::string scene = quote(kSource + "/experiments/figure3/no_cor.toml");
  std::filesystem::create_directory(dir / "sub");

  Result r = dir.run("run " + scene + " --out sub");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("sub") && Contains("directory"));

  r = dir.run("run " + scene + " --out no_such_dir/X.csv");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("no_such_dir/X.csv"));

  r = dir.run("run " + scene + " --out " + quote(dir / "sub/"));
  CHECK(r.code == 2);

  CHECK(dir.entries() == std::set<std::string>{"sub"});
  CHECK(dir.entries("sub").empty());
}

TEST_CASE("cli: standard output is the default, and a write error on it exits 1", "[cli]") {
  TempDir dir;
  const std::string scene = quote(kSource + "/experiments/figure3/no_cor.toml");
  Result r = dir.run("run " + scene + " -q --set time.T=0.01");
  CHECK(r.code == 0);
  CHECK(r.out.rfind("t,u,v,N,E\n0,5,-1,0,0.5\n", 0) == 0);
  CHECK(std::count(r.out.begin(), r.out.end(), '\n') == 12);  // header, l = 0..10
  CHECK(dir.entries().empty());

  if (!std::filesystem::exists("/dev/full")) return;  // a device on which every write fails
  r = dir.run("run " + scene, "/dev/full");
  CHECK(r.code == 1);
  CHECK_THAT(r.err, Contains("standard output") && Contains("write failed"));
}

TEST_CASE("cli: the CSV reads back bit for bit what the library computes", "[cli]") {
  TempDir dir;
  for (const auto& method : impact::methods()) {
    const std::string name(method.name);
    INFO("method " << name);
    std::string text = kShortScene;
    text.replace(text.find("\"direct\""), 8, "\"" + name + "\"");
    if (method.can.iterations_channel)
      text.replace(text.find("\"E\"]"), 4, "\"E\", \"iterations\"]");
    try {
      impact::parse_scene(text, "short.toml");
    } catch (const impact::SceneError&) {
      // A method without a restitution law (penalty) refuses floor.cor: run it without one.
      text.erase(text.find("[floor]"), std::string("[floor]\ncor = 0.75\n").size());
    }
    const std::string path = dir.write("short.toml", text);

    Result r = dir.run("run short.toml -q -o X.csv");
    INFO(r.err);
    REQUIRE(r.code == 0);
    Csv csv = read_csv(dir / "X.csv");
    CHECK(csv.header == (method.can.iterations_channel ? "t,u,v,N,E,iterations" : "t,u,v,N,E"));

    // The same scene through the library in this process.
    impact::Scene scene = impact::load_scene(path);
    impact::AnyStepper stepper = impact::make_stepper(scene);
    std::vector<std::vector<double>> expected;
    impact::simulate(stepper, scene.initial, scene.grid,
                     [&](std::int64_t l, const impact::State& s, const impact::StepInfo& info) {
                       std::vector<double> row{scene.grid.t(l), s.u, s.v, info.contact_force,
                                               impact::energy(scene.model, s)};
                       if (method.can.iterations_channel) row.push_back(info.iterations);
                       expected.push_back(row);
                     });
    REQUIRE(expected.size() == 101);
    REQUIRE(csv.rows.size() == expected.size());
    std::size_t mismatches = 0;
    for (std::size_t l = 0; l < expected.size(); ++l) {
      for (std::size_t c = 0; c < expected[l].size(); ++c)
        if (bits(csv.rows[l][c]) != bits(expected[l][c])) {
          if (mismatches++ < 5)
            UNSCOPED_INFO("row " << l << " column " << c << ": " << csv.rows[l][c]
                                 << " != " << expected[l][c]);
        }
    }
    CHECK(mismatches == 0);
  }
  // The scene did hit the floor (so the contact branch was written and read back too).
  Csv csv = read_csv(dir / "X.csv");
  CHECK(std::any_of(csv.rows.begin(), csv.rows.end(), [](auto& row) { return row[3] > 0; }));
}

TEST_CASE("cli: output.every writes every k-th step and always the last", "[cli]") {
  TempDir dir;
  // T = 1.05, h = 0.001: 1050 steps, not a multiple of 100.
  dir.write("every.toml",
            "[initial]\nu0 = 0.5\nv0 = -1.0\n[time]\nT = 1.05\nh = 0.001\n"
            "[method]\nname = \"direct\"\n[output]\nevery = 100\n");
  Result r = dir.run("run every.toml -q -o X.csv");
  REQUIRE(r.code == 0);
  Csv sparse = read_csv(dir / "X.csv");
  CHECK(sparse.header == "t,u,v");
  std::vector<std::int64_t> expected_l{0, 100, 200, 300, 400, 500, 600, 700, 800, 900, 1000, 1050};
  REQUIRE(sparse.rows.size() == expected_l.size());

  r = dir.run("run every.toml -q --set output.every=1 -o full.csv");
  REQUIRE(r.code == 0);
  Csv full = read_csv(dir / "full.csv");
  REQUIRE(full.rows.size() == 1051);
  for (std::size_t i = 0; i < expected_l.size(); ++i) {
    INFO("l = " << expected_l[i]);
    CHECK(sparse.rows[i][0] == static_cast<double>(expected_l[i]) * 0.001);
    CHECK(sparse.rows[i] == full.rows[static_cast<std::size_t>(expected_l[i])]);
  }

  // When the last step is a multiple of every, it is written once.
  r = dir.run("run every.toml -q --set time.T=1 -o X.csv");
  REQUIRE(r.code == 0);
  Csv even = read_csv(dir / "X.csv");
  REQUIRE(even.rows.size() == 11);
  CHECK(even.rows.back()[0] == 1.0);
  CHECK(even.rows[9][0] == 900 * 0.001);

  // T not a multiple of h: the grid stops at the last grid time before T, never past it.
  r = dir.run("run every.toml -q --set time.T=1.0505 -o X.csv");
  REQUIRE(r.code == 0);
  Csv short_of_T = read_csv(dir / "X.csv");
  REQUIRE(short_of_T.rows.size() == 12);  // l = 0, 100, ..., 1000 and 1050
  CHECK(short_of_T.rows[10][0] == 1.0);
  CHECK(short_of_T.rows.back()[0] == 1050 * 0.001);
}

TEST_CASE("cli: a numerical failure exits 1, names the step and leaves no output", "[cli]") {
  TempDir dir;
  // fb_newton with its default tolerance needs 14 Newton iterations on the step that lands on
  // the floor (from t = 0.004 to 0.005, where a = u - phi and N both pass near 0 and the smoothing
  // sqrt(eps) dominates); with at most 3 it stops there without meeting the tolerance.
  dir.write("fail.toml",
            "[initial]\nu0 = 0.005\nv0 = -1.0\n[time]\nT = 0.01\nh = 0.001\n"
            "[method]\nname = \"fb_newton\"\nmax_iterations = 3\n"
            "[output]\nchannels = [\"u\", \"N\", \"iterations\"]\n");
  dir.write("X.csv", "an earlier result\n");

  Result r = dir.run("run fail.toml -o X.csv");
  CHECK(r.code == 1);
  CHECK_THAT(r.err, Contains("numerical failure") && Contains("step 4 ") && Contains("t = 0.004") &&
                        Contains("did not converge after 3 iterations"));
  // No partial output: the earlier file is untouched and no temporary is left.
  CHECK(slurp(dir / "X.csv") == "an earlier result\n");
  CHECK(dir.entries() == std::set<std::string>{"fail.toml", "X.csv"});

  r = dir.run("run fail.toml -o Y.csv");
  CHECK(r.code == 1);
  CHECK(dir.entries() == std::set<std::string>{"fail.toml", "X.csv"});

  // With enough iterations the same scene runs, and the landing step is where they are needed.
  r = dir.run("run fail.toml --set method.max_iterations=50 -q -o Y.csv");
  REQUIRE(r.code == 0);
  Csv csv = read_csv(dir / "Y.csv");
  REQUIRE(csv.rows.size() == 11);
  CHECK(csv.rows[5][3] > 3);  // iterations of the step ending at t_5 = 0.005
  CHECK(csv.rows[6][2] > 0);  // N: the impact
}

TEST_CASE("cli: run --against exact prints the errors measure_errors gives for the same scene",
          "[cli]") {
  TempDir dir;
  const std::string scene = std::string(IMPACT_SOURCE_DIR) + "/experiments/figure4/cor075.toml";
  const Result r = dir.run("run " + scene + " --against exact -o X.csv");
  REQUIRE(r.code == 0);
  // The same run through the library: the printed numbers are its errors, to the last digit.
  impact::Scene s = impact::load_scene(scene);
  impact::AnyStepper stepper = impact::make_stepper(s);
  const impact::ErrorNorms e = std::visit(
      [&](auto& st) { return impact::measure_errors(st, s.model, s.initial, s.grid); }, stepper);
  CHECK_THAT(r.err, Contains("sup|u - u_exact| = " + impact::round_trip(e.sup_u)));
  CHECK_THAT(r.err, Contains("h sum|v - v_exact| = " + impact::round_trip(e.l1_v)));
  CHECK_THAT(r.err, Contains("|E(T) - E_exact(T)| = " + impact::round_trip(e.energy_end)));
  CHECK_THAT(r.err, Contains("first impact time error = " + impact::round_trip(e.first_impact)));
  // The CSV is the same as without --against.
  REQUIRE(dir.run("run " + scene + " -q -o Y.csv").code == 0);
  CHECK(slurp(dir / "X.csv") == slurp(dir / "Y.csv"));
  // Only 'exact' is a reference.
  CHECK(dir.run("run " + scene + " --against direct -o Z.csv").code == 2);
}

TEST_CASE("cli: a run of more than 1e8 rows asks for output.every or --force before it starts",
          "[cli]") {
  TempDir dir;
  const std::string scene = std::string(IMPACT_SOURCE_DIR) + "/experiments/figure3/no_cor.toml";
  // h = 1e-8 over T = 10: 1e9 steps, 1e9 + 1 rows of four channels (about 125 GB).
  Result r = dir.run("run " + scene + " --set time.h=1e-8 -o X.csv");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("1000000001 rows") && Contains("output.every") && Contains("--force"));
  CHECK(dir.entries().empty());  // nothing written, not even a temporary
  // With every = 1e3 the same run is 1e6 rows: allowed (checked only up to the start: T cut short).
  r = dir.run("run " + scene + " --set time.h=1e-8 --set time.T=1e-5 -q -o X.csv");
  CHECK(r.code == 0);
}

TEST_CASE("cli: extreme steps and a penalty run without end are refused with their reason",
          "[cli]") {
  TempDir dir;
  const std::string scene = std::string(IMPACT_SOURCE_DIR) + "/experiments/figure3/no_cor.toml";
  // 2/h^2 of (5-1) overflows (h = 1e-160) or underflows (h = 1e300): exit 2 naming h, before the
  // run, for the schemes that use it; exact and moreau_jean run.
  Result r = dir.run("run " + scene + " --set time.h=1e-160 --set time.T=1e-160 -o X.csv");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("2/h^2 of (5-1) is not representable for h = 1e-160"));
  r = dir.run("run " + scene +
              " --set time.h=1e300 --set time.T=1e300 --set method.name=fb_newton -o X.csv");
  CHECK(r.code == 2);
  CHECK(dir.run("run " + scene + " --set time.h=1e-160 --set time.T=1e-160 -q " +
                "--set method.name=moreau_jean -o X.csv")
            .code == 0);
  // A resting particle on a stiff floor with an implicit stepper: the run's budget of ODE steps
  // ends it with exit 1 and the reason, instead of minutes of work.
  dir.write("rest.toml",
            "[initial]\nu0 = 0.0\nv0 = 0.0\n[force]\nf = -9.80665\n[time]\nT = 1.0\nh = 0.001\n"
            "[method]\nname = \"penalty\"\nstepper = \"rk2imp\"\nstiffness = 1e12\n"
            "max_ode_steps = 5000\n");
  r = dir.run("run rest.toml -o R.csv");
  CHECK(r.code == 1);
  CHECK_THAT(r.err, Contains("budget of ODE steps") && Contains("method.max_ode_steps"));
  CHECK(dir.run("run rest.toml --set method.max_ode_steps=-1 -o R.csv").code == 2);
}
