// `impact sweep` and what it is built from: the streaming summary (summary.hpp) and its ensemble
// lanes, the SPECs and points of a sweep (sweep_grid.hpp), and the command itself, run as a
// separate process (IMPACT_CLI): a point equals `impact run` of its scene bit for bit, the bytes do
// not depend on --threads, shards merge into the unsharded file, failures are rows.
// What the command writes (points against `impact run`, failures, --threads, shards, --against,
// Figure 4's h sweep) is in test_sweep_output.cpp.
#include "sweep_support.hpp"

TEST_CASE("sweep: the ensemble's summary is the single-particle observer's, bit for bit",
          "[sweep][property]") {
  std::vector<Model> models;
  std::vector<State> initial;
  random_particles(203, 20130706u, models, initial);  // 203: padding lanes are exercised too
  const Grid grid{1e-3, 6000};
  for (const EnsembleMethod method : {EnsembleMethod::direct, EnsembleMethod::moreau_jean}) {
    std::vector<PointSummary> expected;
    for (std::size_t i = 0; i < models.size(); ++i) {
      SummaryObserver observer(models[i], grid);
      RunSummary run;
      if (method == EnsembleMethod::direct) {
        Direct stepper(models[i], grid.h, {});
        run = simulate(stepper, initial[i], grid, observer);
      } else {
        MoreauJean stepper(models[i], grid.h, {});
        run = simulate(stepper, initial[i], grid, observer);
      }
      expected.push_back(observer.result(run));
    }
    for (const std::string_view isa : Ensemble::supported_instruction_sets()) {
      INFO("method " << static_cast<int>(method) << ", instruction set " << isa);
      Ensemble ensemble(method, models, initial, grid.h);
      ensemble.use(isa);
      ensemble.keep_summary();
      // In two pieces: the step index l carries over from one advance() to the next.
      ensemble.advance(2500);
      ensemble.advance(grid.steps - 2500);
      for (std::size_t i = 0; i < models.size(); ++i) {
        const auto index = static_cast<Eigen::Index>(i);
        INFO("particle " << i);
        CHECK_FALSE(ensemble.failed(index));
        check_same(
            finish_summary(ensemble.summary(index), models[i], grid, ensemble.state(index), 0),
            expected[i]);
      }
    }
  }
  Ensemble late(EnsembleMethod::direct, models, initial, grid.h);
  late.advance(1);
  CHECK_THROWS_AS(late.keep_summary(), std::logic_error);
}

TEST_CASE("sweep: a lane that overflows is marked failed, the others are not",
          "[sweep][property]") {
  const std::vector<Model> models(3, Model{0.0, -9.80665, 0.75});
  // The second particle's COR step gets an infinite N and comes back finite (v = -COR v): the
  // mark must stay although its state is finite again, as simulate() stops at that step.
  const std::vector<State> initial{{5, -1}, {1e-300, -1e300}, {1e308, 1e308}};
  // The same with the finite check alone (a sweep of the final state).
  for (const SummaryDepth depth : {SummaryDepth::per_step, SummaryDepth::final_state}) {
    std::vector<std::optional<PointSummary>> out(3);
    summarize_together({EnsembleMethod::direct, 0.5}, Grid{1e-10, 3}, models, initial, out, {},
                       nullptr, 0, depth);
    CHECK(out[0].has_value());
    CHECK_FALSE(out[1].has_value());
    CHECK_FALSE(out[2].has_value());
  }
}

TEST_CASE("sweep: a final-state summary keeps the per-step one's final state, energy and failures",
          "[sweep][property]") {
  std::vector<Model> models;
  std::vector<State> initial;
  random_particles(203, 20261207u, models, initial);
  const Grid grid{1e-3, 6000};
  for (const EnsembleMethod method : {EnsembleMethod::direct, EnsembleMethod::moreau_jean})
    for (const std::string_view isa : Ensemble::supported_instruction_sets()) {
      INFO("method " << static_cast<int>(method) << ", instruction set " << isa);
      std::vector<std::optional<PointSummary>> full(models.size()), final(models.size());
      summarize_together({method, 0.5}, grid, models, initial, full, isa);
      summarize_together({method, 0.5}, grid, models, initial, final, isa, nullptr, 0,
                         SummaryDepth::final_state);
      for (std::size_t i = 0; i < models.size(); ++i) {
        INFO("particle " << i);
        REQUIRE(full[i].has_value() == final[i].has_value());
        if (!full[i]) continue;
        CHECK(same_bits(full[i]->final.u, final[i]->final.u));
        CHECK(same_bits(full[i]->final.v, final[i]->final.v));
        CHECK(same_bits(full[i]->energy_final, final[i]->energy_final));
      }
    }
}

TEST_CASE("sweep: SPECs give their values, both ends exact", "[sweep][property]") {
  const SweepAxis lin("initial.u0=1:2:5");
  REQUIRE(lin.size() == 5);
  CHECK(lin.key() == "initial.u0");
  CHECK(lin.value(0) == 1.0);
  CHECK(lin.value(2) == 1.5);
  CHECK(lin.value(4) == 2.0);
  // Figure 4's h sweep (figure4.cpp: h = 10^-(2 + i/40)) at every other of its step sizes: the
  // same doubles, so the same grids and rest times.
  const SweepAxis log("time.h=1e-4:1e-2:41:log");
  REQUIRE(log.size() == 41);
  for (int j = 0; j < 41; ++j)
    CHECK(same_bits(log.value(j), std::pow(10.0, -(2.0 + (80.0 - 2 * j) / 40))));
  CHECK(log.smallest() == 0);
  CHECK(log.largest() == 40);
  const SweepAxis down("floor.cor=1:0:3");
  CHECK(down.value(1) == 0.5);
  CHECK(down.smallest() == 2);
  const SweepAxis list("force.f=-9.81,+0,-0,3e2");
  REQUIRE(list.size() == 4);
  CHECK(list.value(0) == -9.81);
  CHECK(same_bits(list.value(2), 0.0));  // TOML reads the text "-0" as the integer 0
  CHECK(list.text(2) == "0");
  CHECK(list.text(0) == round_trip(-9.81));
  CHECK(list.smallest() == 0);
  CHECK(list.largest() == 3);
  CHECK(SweepAxis("time.T=3:3:1").size() == 1);
  for (const char* bad : {"time.h", "=1,2", "time.h=", "time.h=1:2", "time.h=1:2:0", "time.h=1:2:x",
                          "time.h=1:2:3:lin", "time.h=0:1:3:log", "time.h=1,,2", "time.h=nan",
                          "time.h=1e400", "time.h=1:2:1", "time.h=0x10"}) {
    INFO(bad);
    CHECK_THROWS_WITH(SweepAxis(bad), Contains("--vary") && Contains("SPEC"));
  }
}

TEST_CASE("sweep: a point's scene is the one impact run reads with its --set",
          "[sweep][property]") {
  const auto check_points = [](const std::string& path, const std::vector<std::string>& sets,
                               const std::vector<std::string>& varies) {
    std::vector<SweepAxis> axes;
    for (const auto& v : varies) axes.emplace_back(v);
    const SweepGrid grid(path, sets, std::move(axes));
    Scene built = grid.base();
    for (std::int64_t i = 0; i < grid.size(); ++i) {
      grid.apply(i, built);
      std::vector<std::string> all = sets;
      for (const auto& o : grid.overrides(i)) all.push_back(o);
      const Scene read = load_scene(path, all);
      INFO(grid.describe(i));
      CHECK(same_bits(built.initial.u, read.initial.u));
      CHECK(same_bits(built.initial.v, read.initial.v));
      CHECK(same_bits(built.model.phi, read.model.phi));
      CHECK(same_bits(built.model.f, read.model.f));
      CHECK(same_bits(built.model.cor.value_or(-1), read.model.cor.value_or(-1)));
      CHECK(same_bits(built.T, read.T));
      CHECK(same_bits(built.grid.h, read.grid.h));
      CHECK(built.grid.steps == read.grid.steps);
      CHECK(built.method == read.method);
    }
  };
  // Values with many digits, a log range, steps that do not divide T (Grid::covering).
  check_points(
      kFigure4, {},
      {"initial.u0=0.1:7.3:3", "floor.cor=0:1:3", "time.T=0.7,1.3", "time.h=3.3e-5:0.07:4:log"});
  check_points(
      kFigure4, {"method.name=fb_newton"},
      {"method.epsilon=1e-15:1e-3:3:log", "method.max_iterations=10:40:4", "force.f=-20:3:3"});
  check_points(kFigure4, {"method.name=moreau_jean"}, {"method.theta=0:1:5", "initial.v0=-3:3:3"});
  check_points(kFigure4, {"method.name=penalty", "time.T=0.01"},
               {"method.stiffness=1e3:1e9:3:log", "method.rtol=1e-9,1e-6", "method.atol=1e-12"});

  // Any double read back from its round_trip text by the scene reader is the same double.
  std::mt19937_64 rng(42);
  for (int k = 0; k < 300; ++k) {
    const double x = std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng), k - 150);
    const Scene s = load_scene(kFigure4, {"initial.v0=" + round_trip(x)});
    INFO(round_trip(x));
    CHECK(same_bits(s.initial.v, x == 0 ? 0.0 : x));
  }
}

TEST_CASE("sweep: invalid points and options exit 2 naming the point and the key",
          "[sweep][regression]") {
  TempDir dir;
  const std::string scene = quote(kFigure4);
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      // Valid one by one, invalid together: the third point has h > T.
      {"--vary time.T=1,10 --vary time.h=0.5,5",
       "point 2 of 4 (time.T=1, time.h=5): --set time.h=5: time.h = 5: must be <= time.T = 1"},
      {"--vary floor.phi=0,6", "point 2 of 2 (floor.phi=6)"},
      {"--vary floor.phi=0,6", "initial.u0 = 5.0: must be >= floor.phi = 6"},
      // The largest value of a range is checked by the scene reader.
      {"--vary floor.cor=0:1.5:4", "point 4 of 4 (floor.cor=1.5): --set floor.cor=1.5: floor.cor"},
      {"--vary time.h=1e-20,1e-3", "point 1 of 2 (time.h=9.9999999999999995e-21)"},
      {"--set method.name=fb_newton --vary method.max_iterations=1:10:3",
       "point 2 of 3 (method.max_iterations=5.5)"},
      {"--vary method.theta=0.1,0.2", "unknown key for method 'direct'"},
      {"--vary output.every=1,2", "--vary output.every: not a key a sweep can vary"},
      {"--vary time.h=1e-3 --vary time.h=1e-2", "varied twice"},
      {"--vary time.h=1:2", "a range is a:b:n"},
      {"--vary time.h=1e-3 --summary rest_time,bogus", "unknown quantity 'bogus'"},
      {"--vary time.h=1e-3 --summary err_u_sup", "needs --against exact"},
      // The reference would run at every point and nothing be written from it.
      {"--vary time.h=1e-3 --against exact --summary rest_time,E_T",
       "--against exact: --summary rest_time,E_T names no error measure (err_u_sup, err_v_l1, "
       "err_E_T, err_first_impact, reference_s)"},
      {"--vary time.h=1e-3 --against nothing", "the only reference is 'exact'"},
      {"--vary time.h=1e-3 --shard 3/2", "--shard 3/2"},
      {"--vary time.h=1e-3 --instruction-set sse9", "--instruction-set sse9: not one"},
      {"--vary time.h=1e-3 --merge x.csv", "--merge takes only the parts"},
  };
  for (const Case& c : cases) {
    INFO(c.args);
    const Result r = dir.run("sweep " + scene + " " + c.args + " --out X.csv");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains(c.message));
    CHECK(dir.entries().empty());
  }
  CHECK(dir.run("sweep --vary time.h=1e-3").code == 2);  // no SCENE
}
