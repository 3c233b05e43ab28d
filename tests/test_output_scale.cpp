// `impact run` at scale: what it writes equals the library's own trajectory, decimated by hand, for
// every method, for output.every in {1, 2, 3, 7, 10, 1000, 65535, 65537, 2^20 + 1} and run lengths
// on both sides of 2^16, 2^17 and 1e6 steps (the run's periodic checks come every 2^16 steps, and a
// row falling between two of them once went missing), with and without --events and --against:
// every row (t, u, v, N as the mean over the row's steps, E, iterations) bit for bit, every event,
// the errors printed. Tagged [scale]: about a minute in all; the sanitizer build leaves it out.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "output_support.hpp"

using namespace impact::testing;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;

struct Case {
  std::string method, scene;
  std::vector<std::string> sets;
  double T;
};

// The channels every case writes; the iterations where the method has them.
std::vector<std::string> channel_sets(const std::string& method) {
  const bool iterations = method == "fb_newton" || method == "penalty";
  return {"method.name=" + method, std::string("output.channels=[\"u\",\"v\",\"N\",\"E\"") +
                                       (iterations ? ",\"iterations\"]" : "]")};
}

const std::int64_t kEvery[] = {1, 2, 3, 7, 10, 1000, 65535, 65537, (std::int64_t{1} << 20) + 1};

// The number after `name = ` in the --against line, read back exactly.
double printed(const std::string& err, const std::string& name) {
  const std::size_t at = err.find(name + " = ");
  REQUIRE(at != std::string::npos);
  return std::strtod(err.c_str() + at + name.size() + 3, nullptr);
}

std::string quoted_sets(const std::vector<std::string>& sets) {
  std::string text;
  for (const auto& s : sets) text += " --set " + quote(s);
  return text;
}

// One run of the CLI with --set output.every=every, its rows (and events, errors) compared with
// the library's run.
void check_run(const TempDir& dir, const Case& c, const std::vector<std::string>& sets,
               const LibraryRun& lib, std::int64_t every, bool events, bool against) {
  const std::string args = "run " + quote(kSource + "/" + c.scene) + quoted_sets(sets) +
                           " --set output.every=" + std::to_string(every) + " -o rows.csv" +
                           (events ? " --events ev.csv" : "") + (against ? " --against exact" : "");
  const Result r = dir.run(args);
  INFO("impact " << args << "\nstderr: " << r.err);
  REQUIRE(r.code == 0);
  const Table csv = read_table(slurp(dir / "rows.csv"));
  std::vector<int> columns = {0, 1, 2, 3, 4};
  if (csv.columns.size() == 6) columns.push_back(5);
  const std::string difference = first_difference(csv, decimate(lib, every), columns);
  CHECK(difference == "");
  if (events) {
    const std::vector<impact::Event> written = read_events(slurp(dir / "ev.csv"));
    REQUIRE(written.size() == lib.events.size());
    std::size_t differ = written.size();
    for (std::size_t i = 0; i < written.size() && differ == written.size(); ++i) {
      const impact::Event &a = written[i], &b = lib.events[i];
      if (a.t != b.t || a.kind != b.kind || a.v_before != b.v_before || a.v_after != b.v_after)
        differ = i;
    }
    INFO("first event that differs: " << differ << " of " << written.size());
    CHECK(differ == written.size());
  }
  if (against) {
    CHECK(printed(r.err, "sup|u - u_exact|") == lib.errors.sup_u);
    CHECK(printed(r.err, "h sum|v - v_exact|") == lib.errors.l1_v);
    CHECK(printed(r.err, "|E(T) - E_exact(T)|") == lib.errors.energy_end);
  }
}

// Every length and every `every` for one case: plain, and with --events and --against together;
// each of the two alone at two values of every.
void check_case(const Case& c, const std::vector<std::int64_t>& lengths) {
  // A run of 1e6 rows writes 70 MB; all of them 1.5 GB: in memory where there is a tmpfs.
  const TempDir dir(std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : "/tmp");
  for (const std::int64_t steps : lengths) {
    std::vector<std::string> sets = c.sets;
    for (const auto& s : channel_sets(c.method)) sets.push_back(s);
    sets.push_back("time.T=" + impact::round_trip(c.T));
    sets.push_back("time.h=" + impact::round_trip(c.T / static_cast<double>(steps)));
    const LibraryRun lib = library_run(kSource + "/" + c.scene, sets, true);
    INFO(c.method << " on " << c.scene << ", " << steps << " steps");
    REQUIRE(lib.scene.grid.steps == steps);
    for (const std::int64_t every : kEvery) {
      INFO("output.every = " << every);
      check_run(dir, c, sets, lib, every, false, false);
      check_run(dir, c, sets, lib, every, true, true);
    }
    for (const std::int64_t every : {std::int64_t{3}, (std::int64_t{1} << 20) + 1}) {
      check_run(dir, c, sets, lib, every, true, false);
      check_run(dir, c, sets, lib, every, false, true);
    }
  }
}

const std::vector<std::int64_t> kLengths = {65535, 65537, 131071, 131073, 999999, 1000001};
const std::string kFigure4 = "experiments/figure4/cor075.toml";

}  // namespace

TEST_CASE("output at scale: direct writes its trajectory, every row and event", "[cli][scale]") {
  check_case({"direct", kFigure4, {}, 10.0}, kLengths);
}

TEST_CASE("output at scale: fb_newton writes its trajectory and iterations", "[cli][scale]") {
  check_case({"fb_newton", kFigure4, {}, 10.0}, kLengths);
}

TEST_CASE("output at scale: moreau_jean writes its trajectory, every row and event",
          "[cli][scale]") {
  check_case({"moreau_jean", kFigure4, {}, 10.0}, kLengths);
}

TEST_CASE("output at scale: penalty writes its trajectory and ODE steps", "[cli][scale]") {
  check_case({"penalty", "experiments/figure4/no_cor.toml", {}, 10.0}, kLengths);
}

TEST_CASE("output at scale: exact writes its solution and its own events", "[cli][scale]") {
  check_case({"exact", kFigure4, {}, 10.0}, kLengths);
}

TEST_CASE("output at scale: event_driven writes its solution and its own events", "[cli][scale]") {
  check_case({"event_driven", kFigure4, {}, 10.0}, kLengths);
}

// A time-dependent force: E is v^2/2 - f(0) u(0) - W(t), with W summed over every step, written
// or not.
TEST_CASE("output at scale: with f(t) the E of a decimated row is the work summed over every step",
          "[cli][scale]") {
  check_case({"direct", "experiments/vibrating_table/period_one.toml", {}, 2.0}, {65537, 131071});
  check_case({"moreau_jean", "experiments/work_precision/expression.toml", {}, 10.0},
             {65535, 131073});
}
