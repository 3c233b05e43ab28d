// What `impact sweep` writes, run as a separate process (IMPACT_CLI): each point's numbers are
// those of `impact run` of its scene bit for bit, a failing point is a row with its reason, the
// bytes do not depend on --threads, shards merge into the unsharded file, --against exact and
// Figure 4's h sweep give the numbers of the analyses.
#include "sweep_support.hpp"

TEST_CASE("sweep: each point's numbers are what impact run of its scene writes, bit for bit",
          "[sweep][regression]") {
  TempDir dir;
  struct Case {
    std::string scene, sets, vary;
    std::vector<int> points;  // 1-based rows to compare with impact run
  };
  // 70 points on one grid: direct and moreau_jean step them in the ensemble; fb_newton and exact
  // point by point.
  const Case cases[] = {
      {kFigure4Cor, "--set time.T=2", "--vary initial.u0=0.5:3:70", {1, 33, 70}},
      {kFigure4,
       "--set time.T=2 --set method.name=moreau_jean",
       "--vary initial.v0=-3:2:70",
       {2, 70}},
      {kFigure4,
       "--set time.T=1.5 --set method.name=fb_newton",
       "--vary initial.u0=0.5,2 --vary time.h=1e-3,7e-4",
       {1, 4}},
      {kFigure4Cor, "--set time.T=3 --set method.name=exact", "--vary floor.cor=0.2,0.9", {2}},
  };
  for (const Case& c : cases) {
    INFO(c.sets << " " << c.vary);
    const Result sweep =
        dir.run("sweep " + quote(c.scene) + " " + c.sets + " " + c.vary + " -q --out S.csv");
    REQUIRE(sweep.code == 0);
    const auto rows = rows_of(slurp(dir / "S.csv"));
    const auto& header = rows.front();
    const std::size_t varied = std::count(c.vary.begin(), c.vary.end(), '=');
    for (int point : c.points) {
      const auto& row = rows.at(static_cast<std::size_t>(point));
      std::string sets = c.sets;
      for (std::size_t k = 0; k < varied; ++k) sets += " --set " + header[k] + "=" + row[k];
      const Result run =
          dir.run("run " + quote(c.scene) + " " + sets + " --set " +
                  quote("output.channels=[\"u\",\"v\",\"N\",\"E\"]") + " --out R.csv");
      REQUIRE(run.code == 0);
      // The run's trajectory through the observer: the summary a sweep must have written.
      const auto trajectory = rows_of(slurp(dir / "R.csv"));
      std::vector<std::string> set_list;
      std::istringstream words(sets);
      for (std::string w; words >> w;)
        if (w != "--set") set_list.push_back(w);
      const Scene point_scene = load_scene(c.scene, set_list);
      SummaryObserver replay(point_scene.model, point_scene.grid);
      for (std::size_t l = 1; l < trajectory.size(); ++l) {
        StepInfo info;
        info.contact_force = number(trajectory[l][3]);
        replay(static_cast<std::int64_t>(l - 1),
               State{number(trajectory[l][1]), number(trajectory[l][2])}, info);
      }
      RunSummary run_summary;
      // `impact run` prints the iteration count of an iterative method on standard error.
      if (const auto at = run.err.find(" iterations ("); at != std::string::npos)
        run_summary.iterations = std::stoll(run.err.substr(run.err.rfind(", ", at) + 2));
      const PointSummary want = replay.result(run_summary);
      INFO("point " << point);
      REQUIRE(trajectory.size() == static_cast<std::size_t>(point_scene.grid.steps) + 2);
      CHECK(same_bits(number(row[varied + 0]), want.final.u));
      CHECK(same_bits(number(row[varied + 1]), want.final.v));
      CHECK(same_bits(number(row[varied + 2]), want.energy_final));
      CHECK(number(row[varied + 3]) == static_cast<double>(want.contact_steps));
      CHECK(number(row[varied + 4]) == static_cast<double>(want.impacts));
      CHECK(same_bits(number(row[varied + 5]), want.first_impact_time));
      CHECK(same_bits(number(row[varied + 6]), want.rest_time.value_or(NAN)));
      CHECK(same_bits(number(row[varied + 7]), want.max_u));
      CHECK(number(row[varied + 8]) == static_cast<double>(want.iterations));
      CHECK(row.back().empty());
    }
  }
}

TEST_CASE("sweep: a point that fails is a row with its reason, and the exit code is 1",
          "[sweep][regression]") {
  TempDir dir;
  // u0 + v0 h = 2e308 overflows on the first step (test_hardening.cpp); the run says why.
  dir.write("overflow.toml",
            "[initial]\nu0 = 1e308\nv0 = 1e308\n[time]\nT = 10.0\nh = 1.0\n"
            "[method]\nname = \"direct\"\n");
  const Result run = dir.run("run overflow.toml --out R.csv");
  REQUIRE(run.code == 1);
  const std::string reason = "step 0 (from t = 0): non-finite result u = inf";
  CHECK_THAT(run.err, Contains(reason));
  // Alone (2 points), and as lanes of the ensemble (70 points on one grid), which re-runs a
  // failed lane alone to name the step.
  for (const auto& [vary, failed] :
       {std::pair<std::string, int>{"--vary initial.v0=1,1e308", 1},
        std::pair<std::string, int>{"--vary initial.v0=1,1e308 --vary force.f=-1:0:35", 35}}) {
    INFO(vary);
    const Result r = dir.run("sweep overflow.toml " + vary + " --out S.csv");
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains(std::to_string(failed) + " failed"));
    const auto rows = rows_of(slurp(dir / "S.csv"));
    REQUIRE(rows.size() == static_cast<std::size_t>(2 * failed + 1));
    const std::size_t first_failed = static_cast<std::size_t>(failed) + 1;
    const std::size_t u_T = rows[0].size() - 10;  // the nine quantities and the failure follow
    CHECK(rows[1].back().empty());
    CHECK(number(rows[1][u_T]) == 1e308);    // the first point ran: u0 + 10 m rounds to u0
    CHECK(rows[first_failed][u_T].empty());  // a failed one has no numbers, only its reason
    CHECK_THAT(rows[first_failed].back(), Contains(reason));
    CHECK(rows[first_failed].size() == rows[0].size());
  }
}

TEST_CASE("sweep: the output is the same bytes whatever --threads is", "[sweep][regression]") {
  TempDir dir;
  // 3000 points of about 100 steps in chunks of 192: direct in the ensemble (a chunk that spans two
  // step sizes has one group too small for it, stepped point by point), and fb_newton point by
  // point; wall_s is left out, as it differs from run to run.
  for (const std::string sets : {"", "--set method.name=fb_newton"}) {
    const std::string args = "sweep " + quote(kFigure4Cor) + " --set time.T=0.1 " + sets +
                             " --vary time.h=1e-3,7e-4,1.3e-3 --vary initial.u0=0:0.2:1000 -q";
    REQUIRE(dir.run(args + " --threads 1 --out 1.csv").code == 0);
    REQUIRE(dir.run(args + " --threads 2 --out 2.csv").code == 0);
    REQUIRE(dir.run(args + " --threads 3 --out 3.csv").code == 0);
    CHECK(rows_of(slurp(dir / "1.csv")).size() == 3001);
    CHECK(slurp(dir / "1.csv") == slurp(dir / "2.csv"));
    CHECK(slurp(dir / "1.csv") == slurp(dir / "3.csv"));
    // Every vector code of the ensemble gives the same bytes too.
    for (const std::string_view isa : Ensemble::supported_instruction_sets()) {
      REQUIRE(dir.run(args + " --instruction-set " + std::string(isa) + " --out isa.csv").code ==
              0);
      CHECK(slurp(dir / "isa.csv") == slurp(dir / "1.csv"));
    }
  }
  // wall_s when asked for: a time per point.
  REQUIRE(dir.run("sweep " + quote(kFigure4) +
                  " --vary time.h=1e-3,1e-2 --summary wall_s,E_T -q "
                  "--out W.csv")
              .code == 0);
  const auto rows = rows_of(slurp(dir / "W.csv"));
  CHECK(rows[0] == std::vector<std::string>{"time.h", "wall_s", "E_T", "failure"});
  CHECK(number(rows[1][1]) >= 0.0);
}

TEST_CASE("sweep: the final state alone (u_T, v_T, E_T) is the full summary's, byte for byte",
          "[sweep][regression]") {
  // 1000 points in the ensemble, which then keeps only its finite check (summary.hpp).
  TempDir dir;
  for (const char* method : {"direct", "moreau_jean"}) {
    INFO(method);
    const std::string args = "sweep " + quote(kFigure4Cor) +
                             " --set time.T=0.5 --set method.name=" + method +
                             " --vary initial.u0=0:0.2:1000 -q";
    REQUIRE(dir.run(args + " --out full.csv").code == 0);
    REQUIRE(dir.run(args + " --summary u_T,v_T,E_T --out final.csv").code == 0);
    const auto full = rows_of(slurp(dir / "full.csv")), final = rows_of(slurp(dir / "final.csv"));
    REQUIRE(full.size() == 1001);
    REQUIRE(final.size() == full.size());
    REQUIRE(full[0][1] == "u_T");
    REQUIRE(full[0][3] == "E_T");
    for (std::size_t r = 0; r < full.size(); ++r)
      CHECK(std::vector<std::string>(full[r].begin(), full[r].begin() + 4) ==
            std::vector<std::string>(final[r].begin(), final[r].begin() + 4));
  }
}

TEST_CASE("sweep: shards merged are the unsharded file, byte for byte", "[sweep][regression]") {
  TempDir dir;
  const std::string args = "sweep " + quote(kFigure4Cor) +
                           " --set time.T=0.5 --vary initial.u0=0.1:2:10 --vary floor.cor=0,0.5 -q";
  REQUIRE(dir.run(args + " --out all.csv").code == 0);
  for (int k = 1; k <= 3; ++k)
    REQUIRE(
        dir.run(args + " --shard " + std::to_string(k) + "/3 --out p" + std::to_string(k) + ".csv")
            .code == 0);
  CHECK_THAT(slurp(dir / "p2.csv"), Contains("# impact sweep part 2/3 of 20 points, sweep "));
  // Parts in any order.
  REQUIRE(dir.run("sweep --merge p3.csv p1.csv p2.csv --out merged.csv").code == 0);
  CHECK(slurp(dir / "merged.csv") == slurp(dir / "all.csv"));
  // One shard of one; more shards than points (shards 6 and 7 of 7 have none).
  REQUIRE(dir.run(args + " --shard 1/1 --out q.csv").code == 0);
  REQUIRE(dir.run("sweep --merge q.csv --out merged1.csv").code == 0);
  CHECK(slurp(dir / "merged1.csv") == slurp(dir / "all.csv"));
  const std::string few = "sweep " + quote(kFigure4) + " --vary time.h=1e-3:1e-2:5 -q";
  REQUIRE(dir.run(few + " --out few.csv").code == 0);
  std::string parts;
  for (int k = 1; k <= 7; ++k) {
    REQUIRE(
        dir.run(few + " --shard " + std::to_string(k) + "/7 --out r" + std::to_string(k) + ".csv")
            .code == 0);
    parts += " r" + std::to_string(k) + ".csv";
  }
  REQUIRE(dir.run("sweep --merge" + parts + " --out merged7.csv").code == 0);
  CHECK(slurp(dir / "merged7.csv") == slurp(dir / "few.csv"));
}

TEST_CASE("sweep: merging parts that do not belong together is rejected", "[sweep][regression]") {
  TempDir dir;
  const std::string args = "sweep " + quote(kFigure4) + " --vary time.h=1e-3:1e-2:7 -q";
  for (int k = 1; k <= 2; ++k)
    REQUIRE(
        dir.run(args + " --shard " + std::to_string(k) + "/2 --out p" + std::to_string(k) + ".csv")
            .code == 0);
  REQUIRE(dir.run(args + " --summary E_T --shard 2/2 --out other.csv").code == 0);
  REQUIRE(dir.run(args + " --out plain.csv").code == 0);
  const std::string p1 = slurp(dir / "p1.csv");
  dir.write("cut.csv", p1.substr(0, p1.size() - 1));                         // no last newline
  dir.write("short.csv", p1.substr(0, p1.rfind('\n', p1.size() - 2) + 1));   // a row less
  dir.write("long.csv", p1 + p1.substr(p1.rfind('\n', p1.size() - 2) + 1));  // a row more
  const std::pair<std::string, std::string> cases[] = {
      {"p1.csv", "shard 2 of 2 is missing"},
      {"p2.csv", "shard 1 of 2 is missing"},
      {"p1.csv p1.csv p2.csv", "is given twice"},
      {"p1.csv other.csv", "belongs to another sweep"},
      {"p1.csv plain.csv", "not a part of a sweep"},
      {"cut.csv p2.csv", "cut short"},
      {"short.csv p2.csv", "incomplete"},
      {"long.csv p2.csv", "more rows"},
      {"p1.csv missing.csv", "missing.csv: cannot open the part: No such file or directory"},
      // An option right after --merge is taken for a part: say so.
      {"-o M.csv p1.csv p2.csv",
       "-o: cannot open the part: No such file or directory (this looks "
       "like an option: give the parts right after --merge"},
      {"-q p1.csv p2.csv", "-q: cannot open the part: No such file or directory (this looks"},
      {"p1.csv,p2.csv",
       "p1.csv,p2.csv: cannot open the part: No such file or directory (parts "
       "are separated by spaces, not commas)"},
  };
  for (const auto& [parts, message] : cases) {
    INFO(parts);
    const Result r = dir.run("sweep --merge " + parts + " --out M.csv");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains(message));
    CHECK(dir.entries().count("M.csv") == 0);
  }
}

TEST_CASE("sweep: --against exact writes measure_errors' numbers", "[sweep][regression]") {
  TempDir dir;
  for (const std::string method : {"direct", "fb_newton", "moreau_jean"}) {
    INFO(method);
    const std::string sets = "--set time.T=3 --set method.name=" + method;
    REQUIRE(dir.run("sweep " + quote(kFigure4Cor) + " " + sets +
                    " --vary time.h=1e-3,3e-3 --against exact -q --out E.csv")
                .code == 0);
    const auto rows = rows_of(slurp(dir / "E.csv"));
    REQUIRE(rows[0].size() == 15);  // time.h, 9 quantities, 4 errors, failure
    CHECK(rows[0][10] == "err_u_sup");
    for (std::size_t r = 1; r < rows.size(); ++r) {
      const Scene scene =
          load_scene(kFigure4Cor, {"time.T=3", "method.name=" + method, "time.h=" + rows[r][0]});
      AnyStepper stepper = make_stepper(scene);
      const ErrorNorms e = measure_errors(stepper, scene.model, scene.initial, scene.grid);
      CHECK(same_bits(number(rows[r][10]), e.sup_u));
      CHECK(same_bits(number(rows[r][11]), e.l1_v));
      CHECK(same_bits(number(rows[r][12]), e.energy_end));
      CHECK(same_bits(number(rows[r][13]), e.first_impact));
    }
  }
}

TEST_CASE("sweep: Figure 4's h sweep gives the rest times and energies of analyse_rest",
          "[sweep][regression]") {
  TempDir dir;
  REQUIRE(dir.run("sweep " + quote(kFigure4) +
                  " --vary time.h=1e-4:1e-2:41:log --summary rest_time,E_T,impacts -q --out H.csv")
              .code == 0);
  const auto rows = rows_of(slurp(dir / "H.csv"));
  REQUIRE(rows.size() == 42);
  for (std::size_t r = 1; r < rows.size(); ++r) {
    INFO("h = " << rows[r][0]);
    const RestAnalysis a = analyse_rest(load_scene(kFigure4, {"time.h=" + rows[r][0]}));
    REQUIRE(a.rest_time.has_value());  // without COR the scheme rests at every h (figure4)
    CHECK(same_bits(number(rows[r][1]), *a.rest_time));
    CHECK(same_bits(number(rows[r][2]), a.energy_final));
    CHECK(number(rows[r][3]) == static_cast<double>(a.impacts));
  }
}
