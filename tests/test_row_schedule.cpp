// The schedule of a run's output (row_stream.hpp): which steps get a row, what a row that stands
// for several steps carries, and when the periodic checks come; first in the library with a stepper
// whose every step is known, then through `impact run` over random (every, steps, T/h remainder).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "impact/run/row_stream.hpp"
#include "impact/run/run_scene.hpp"
#include "output_support.hpp"

using namespace impact::testing;

namespace {

// A stepper whose step l is known without running it: u^l = l, N^l = l/2 on every fifth step, l mod
// 3 iterations.
struct Counter {
  void initialize(const impact::State&, std::int64_t) {}
  impact::StepInfo do_step(impact::State& s, std::int64_t l) {
    s = {static_cast<double>(l + 1), 0.0};
    impact::StepInfo info;
    info.contact_force = l % 5 == 0 ? 0.5 * static_cast<double>(l) : 0.0;
    info.iterations = static_cast<int>(l % 3);
    return info;
  }
};

struct Seen {
  std::vector<impact::OutputRow> rows;
  std::vector<std::int64_t> checks;
};

Seen stream(std::int64_t every, std::int64_t steps, std::int64_t check_every) {
  Seen seen;
  const impact::Grid grid{1e-3, steps};
  impact::RowStream rows(
      every, grid, [&](const impact::OutputRow& r) { seen.rows.push_back(r); }, check_every,
      [&](std::int64_t l) { seen.checks.push_back(l); });
  Counter counter;
  impact::simulate_rows(counter, impact::State{}, grid, rows, true, {});
  return seen;
}

// The rule, by hand: rows at 0, every, 2 every, ..., steps; checks at multiples of check_every.
void check_schedule(std::int64_t every, std::int64_t steps, std::int64_t check_every) {
  INFO("every = " << every << ", steps = " << steps << ", checks every " << check_every);
  const Seen seen = stream(every, steps, check_every);
  std::vector<std::int64_t> due;
  for (std::int64_t l = 0; l < steps; l += every) due.push_back(l);
  due.push_back(steps);
  REQUIRE(seen.rows.size() == due.size());
  std::int64_t previous = 0;
  std::string wrong;  // the first row that breaks the rule
  for (std::size_t i = 0; i < due.size() && wrong.empty(); ++i) {
    const impact::OutputRow& row = seen.rows[i];
    // N: the mean of N^j over the steps since the previous row, by the Counter's formula.
    double sum = 0;
    std::int64_t iterations = 0;
    for (std::int64_t j = previous; j < row.l; ++j) {
      sum += j % 5 == 0 ? 0.5 * static_cast<double>(j) : 0.0;
      iterations += j % 3;
    }
    const double mean = row.l == previous ? 0.0 : sum / static_cast<double>(row.l - previous);
    if (row.l != due[i] || row.state.u != static_cast<double>(row.l) || row.contact_force != mean ||
        row.iterations != iterations)
      wrong = "row " + std::to_string(i) + " at l = " + std::to_string(row.l) + " (due " +
              std::to_string(due[i]) + "), N = " + impact::round_trip(row.contact_force) +
              " (due " + impact::round_trip(mean) + "), iterations " +
              std::to_string(row.iterations) + " (due " + std::to_string(iterations) + ")";
    previous = row.l;
  }
  CHECK(wrong == "");
  std::vector<std::int64_t> checks;
  for (std::int64_t l = check_every; check_every > 0 && l <= steps; l += check_every)
    checks.push_back(l);
  CHECK(seen.checks == checks);
}

}  // namespace

TEST_CASE("row schedule: every row at its step, N the mean and iterations the sum of its steps",
          "[output][regression]") {
  const std::int64_t check = std::int64_t{1} << 16;
  for (const std::int64_t every : {1, 2, 3, 7, 10, 1000, 65535, 65536, 65537, (1 << 20) + 1})
    for (const std::int64_t steps :
         {1, 2, 65535, 65536, 65537, 131071, 131072, 131073, 999999, 1000000, 1000001})
      check_schedule(every, steps, check);
  check_schedule(3, 10, 0);  // no checks
}

TEST_CASE("row schedule: random every, steps and check intervals", "[output][property]") {
  std::mt19937_64 random(20261127);
  for (int i = 0; i < 200; ++i) {
    const auto steps = std::uniform_int_distribution<std::int64_t>(1, 400000)(random);
    const auto every = std::int64_t{1} << std::uniform_int_distribution<int>(0, 19)(random);
    const auto jitter = std::uniform_int_distribution<std::int64_t>(-1, 1)(random);
    const auto check = std::uniform_int_distribution<std::int64_t>(1, 70000)(random);
    check_schedule(std::max<std::int64_t>(1, every + jitter), steps, check);
  }
}

TEST_CASE("row schedule: run_scene's checks come every check_every steps of a real run",
          "[output][regression]") {
  impact::Scene scene = impact::make_scene({0.0, -9.80665, 0.75, {}, {}}, {5.0, -1.0}, 3.0, 1e-5,
                                           impact::DirectParams{});
  scene.output.every = 7;
  std::vector<std::int64_t> checks, rows;
  impact::RunOutputs outputs;
  outputs.rows = [&](const impact::OutputRow& r) { rows.push_back(r.l); };
  outputs.check_every = 1 << 16;
  outputs.check = [&](std::int64_t l) { checks.push_back(l); };
  impact::AnyStepper stepper = impact::make_stepper(scene);
  impact::run_scene(scene, stepper, outputs);
  REQUIRE(scene.grid.steps == 300000);
  CHECK(checks == std::vector<std::int64_t>{65536, 131072, 196608, 262144});
  CHECK(rows.size() == 300000 / 7 + 2);
  CHECK(rows.back() == 300000);
}

// `impact run` on random grids: T = (steps + r) h with a remainder r in (0, 1) (the grid stops at
// floor(T/h), short of T), every anywhere from 1 to past the run's length.
TEST_CASE("row schedule: impact run writes the library's rows for random every, steps, T/h",
          "[cli][property]") {
  const TempDir dir;
  std::mt19937_64 random(1127);
  const std::string scene = std::string(IMPACT_SOURCE_DIR) + "/experiments/figure4/cor075.toml";
  for (int i = 0; i < 24; ++i) {
    const auto steps = std::uniform_int_distribution<std::int64_t>(1000, 300000)(random);
    const double remainder = std::uniform_real_distribution<double>(0.01, 0.99)(random);
    const auto every = std::max<std::int64_t>(
        1, static_cast<std::int64_t>(
               std::exp(std::uniform_real_distribution<double>(0.0, 13.0)(random))));
    const double h = 1e-4, T = (static_cast<double>(steps) + remainder) * h;
    const std::vector<std::string> sets = {"time.T=" + impact::round_trip(T), "time.h=1e-4",
                                           "output.channels=[\"u\",\"v\",\"N\",\"E\"]"};
    const LibraryRun lib = library_run(scene, sets, false);
    INFO("steps = " << steps << ", T = " << impact::round_trip(T) << ", every = " << every);
    REQUIRE(lib.scene.grid.steps == steps);
    std::string args =
        "run " + quote(scene) + " -q -o rows.csv --set output.every=" + std::to_string(every);
    for (const auto& s : sets) args += " --set " + quote(s);
    const Result r = dir.run(args);
    INFO("stderr: " << r.err);
    REQUIRE(r.code == 0);
    CHECK(first_difference(read_table(slurp(dir / "rows.csv")), decimate(lib, every),
                           {0, 1, 2, 3, 4}) == "");
  }
}
