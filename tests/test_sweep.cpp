// `impact sweep` and what it is built from: the streaming summary (summary.hpp) and its ensemble
// lanes, the SPECs and points of a sweep (sweep_grid.hpp), and the command itself, run as a
// separate process (IMPACT_CLI): a point equals `impact run` of its scene bit for bit, the bytes do
// not depend on --threads, shards merge into the unsharded file, failures are rows.
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/rest.hpp"
#include "cli_support.hpp"
#include "impact/ensemble.hpp"
#include "impact/error_norms.hpp"
#include "impact/output.hpp"
#include "impact/summary.hpp"
#include "scene/read_scene.hpp"
#include "scene/sweep_grid.hpp"

using Catch::Contains;
using namespace impact;
using namespace impact::testing;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;
const std::string kFigure4 = kSource + "/experiments/figure4/no_cor.toml";
const std::string kFigure4Cor = kSource + "/experiments/figure4/cor075.toml";

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// A CSV row of `impact sweep`: the fields, the failure reason (quoted, may hold commas) last.
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      field += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  out.push_back(field);
  return out;
}

std::vector<std::vector<std::string>> rows_of(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') rows.push_back(fields(line));
  return rows;
}

double number(const std::string& field) {
  char* end = nullptr;
  const double x = std::strtod(field.c_str(), &end);
  REQUIRE((!field.empty() && *end == '\0'));
  return x;
}

// Models and initial states over every branch of the kernels (free flight, impacts, chatter, rest,
// COR 0 and 1, floors away from 0, upward forces), as in test_ensemble.cpp.
void random_particles(std::size_t n, std::uint32_t seed, std::vector<Model>& models,
                      std::vector<State>& initial) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    Model m;
    m.phi = i % 3 == 0 ? 0.0 : -3.0 + 6.0 * unit(rng);
    const double forces[] = {0.0, -9.80665, -20.0 * unit(rng), 5.0 * unit(rng)};
    m.f = forces[i % 4];
    const double cors[] = {-1, 0.75, 0.0, 1.0, unit(rng)};
    if (const double c = cors[i / 4 % 5]; c >= 0) m.cor = c;
    models.push_back(m);
    initial.push_back({m.phi + (i % 7 == 0 ? 0.0 : 6.0 * unit(rng)), -5.0 + 10.0 * unit(rng)});
  }
}

void check_same(const PointSummary& got, const PointSummary& want) {
  CHECK(same_bits(got.final.u, want.final.u));
  CHECK(same_bits(got.final.v, want.final.v));
  CHECK(same_bits(got.energy_final, want.energy_final));
  CHECK(got.contact_steps == want.contact_steps);
  CHECK(got.impacts == want.impacts);
  CHECK(same_bits(got.first_impact_time, want.first_impact_time));
  CHECK(got.rest_time.has_value() == want.rest_time.has_value());
  CHECK(same_bits(got.rest_time.value_or(-1), want.rest_time.value_or(-1)));
  CHECK(same_bits(got.max_u, want.max_u));
  CHECK(got.iterations == want.iterations);
}

}  // namespace

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
  std::vector<std::optional<PointSummary>> out(3);
  summarize_together({EnsembleMethod::direct, 0.5}, Grid{1e-10, 3}, models, initial, out);
  CHECK(out[0].has_value());
  CHECK_FALSE(out[1].has_value());
  CHECK_FALSE(out[2].has_value());
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
               {number(trajectory[l][1]), number(trajectory[l][2])}, info);
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
