// `impact run` as a separate process: the CSV reads back bit for bit what the library computes,
// output.every, a numerical failure, --against exact, and the runs refused before they start.
#include "cli_csv_support.hpp"

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
