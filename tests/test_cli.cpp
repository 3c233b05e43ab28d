// The `impact` command, run as a separate process (IMPACT_CLI) in a fresh temporary directory:
// exit codes, messages on standard error, the CSV it writes, and that a failed run leaves no file.
// What a run writes, its decimation, failures, --against and the refused runs are in
// test_cli_run.cpp.
#include "cli_csv_support.hpp"

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
