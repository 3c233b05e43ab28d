// A sweep's points each stand alone: a point that fails, whatever its error (a step that is not
// finite, a force expression or a rate that is not where the run evaluates it), is a row with the
// reason in `failure`, and every other point is kept. A method that knows its events dates the rest
// by its stick, not on the grid. And work-precision refuses, before it starts, a step count no run
// can finish.
#include <bit>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>

#include "cli_support.hpp"

using Catch::Contains;
using namespace impact::testing;

namespace {

// The bits of a double, to compare two bit for bit.
std::uint64_t same_bits_of(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

std::string failure_of(const std::string& csv, std::size_t point) {
  std::istringstream lines(csv);
  std::string line;
  for (std::size_t i = 0; i <= point; ++i) std::getline(lines, line);
  std::getline(lines, line);
  const std::size_t quote_at = line.find('"');
  return quote_at == std::string::npos ? "" : line.substr(quote_at);
}

}  // namespace

TEST_CASE("sweep failures: a point that fails with any error is a row, the others are kept",
          "[sweep][regression]") {
  TempDir dir;
  const std::string head =
      "[initial]\nu0 = 1.0\nv0 = 0.0\n[time]\nT = 1.0\nh = 1e-3\n[method]\nname = \"direct\"\n";
  struct Case {
    std::string what, scene, vary, says;
  };
  const std::vector<Case> cases = {
      // A force expression that is nan past t = 0.5: a std::runtime_error, not a NumericalError
      // (it used to end the sweep with a header and one row, and no file).
      {"a force that is not finite",
       head + "[force]\nexpression = \"t < 0.5 ? -9.81 : sqrt(-1)\"\n", "time.T=0.4,1",
       "nan at t = "},
      // z' = z^2 u blows up at t = 1/u0: inside T for u0 = 3, not for 0.1.
      {"a rate that blows up",
       head + "[force]\nexpression = \"-9.81 + 0 * z\"\n[[internal]]\nname = \"z\"\ninitial = "
              "1.0\nrate = \"z^2 * u\"\n",
       "initial.u0=0.1,3", "z"},
      {"the same under event_driven",
       head + "[force]\nexpression = \"-9.81 + 0 * z\"\n[[internal]]\nname = \"z\"\ninitial = "
              "1.0\nrate = \"z^2 * u\"\n",
       "initial.u0=0.1,3 --set method.name=event_driven", "z"},
      // A force of the state that is nan below u = 0.5: from 20 m the particle stays above it,
      // from 2 m it falls through.
      {"a force of the state that is not finite",
       head + "[force]\nexpression = \"-9.81 + sqrt(u - 0.5)\"\n", "initial.u0=20,2", "at t = "},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    dir.write("s.toml", c.scene);
    const Result r = dir.run("sweep s.toml -q -o sweep.csv --vary " + c.vary);
    INFO(r.err);
    CHECK(r.code == 1);
    const std::string csv = slurp(dir / "sweep.csv");
    CHECK(std::count(csv.begin(), csv.end(), '\n') == 3);  // the header and both points
    CHECK(failure_of(csv, 0) == "");
    CHECK_THAT(failure_of(csv, 1), Contains(c.says));
  }
}

TEST_CASE("sweep failures: exact and event_driven date the rest by their stick",
          "[sweep][events][regression]") {
  TempDir dir;
  const std::string scene = std::string(IMPACT_SOURCE_DIR) + "/experiments/figure4/cor075.toml";
  for (const std::string method : {"exact", "event_driven"}) {
    INFO(method);
    for (const std::string cor : {"0.75", "0.9"}) {
      const std::string sets =
          " --set method.name=" + method + " --set floor.cor=" + cor + " --set time.T=30";
      REQUIRE(dir.run("run " + quote(scene) + sets + " -q -o rows.csv --events ev.csv").code == 0);
      const std::vector<impact::Event> events = read_events(slurp(dir / "ev.csv"));
      REQUIRE(!events.empty());
      REQUIRE(events.back().kind == impact::EventKind::stick);
      REQUIRE(dir.run("sweep " + quote(scene) + sets +
                      " -q -o sweep.csv --vary time.h=1e-3 --summary rest_time")
                  .code == 0);
      // Its row: time.h, rest_time and an empty failure.
      const std::string csv = slurp(dir / "sweep.csv");
      const std::string row = csv.substr(csv.find('\n') + 1);
      const double rest = std::strtod(row.c_str() + row.find(',') + 1, nullptr);
      // The grid's rest (a final contact episode of >= 3 steps, as the time-steppers date it)
      // would be 6.939 and 18.773 s; the sweep gives the stick's time, bit for bit (7.0026 and
      // 19.182 s).
      CHECK(same_bits_of(rest) == same_bits_of(events.back().t));
    }
  }
}

TEST_CASE("work-precision: a step count no run can finish is refused before it starts",
          "[work_precision][cli][regression]") {
  TempDir dir;
  dir.write("s.toml", kShort);
  CHECK_FAILS_CLEANLY(dir, "work-precision s.toml --h 1e-12,1e-11 -o wp.csv", 2,
                      Contains("--max-steps") && Contains("--force") && Contains("1e-12"));
  CHECK_FAILS_CLEANLY(dir, "work-precision s.toml --h 1e-3,1e-4 --max-steps 100 -o wp.csv", 2,
                      Contains("--max-steps = 100"));
  CHECK(dir.run("work-precision s.toml -q --methods direct --h 1e-3,1e-4 --repeat 1 --max-steps "
                "1000 --force -o wp.csv")
            .code == 0);
}

TEST_CASE("sweep failures: a point its method refuses is bad input, named before the sweep starts",
          "[sweep][regression]") {
  TempDir dir;
  dir.write("s.toml",
            "[initial]\nu0 = 0.05\nv0 = -1.0\n[force]\nf = -9.80665\n[time]\nT = 0.2\nh = 1e-3\n"
            "[method]\nname = \"fb_newton\"\n[bonding]\nbeta0 = 1.0\n");
  // Point 1 has no bonding field (gamma = 0), point 2 one that fb_newton refuses: it used to be
  // a failed row (exit 1) after point 1 had run; the refusal is the reader's, with its key.
  CHECK_FAILS_CLEANLY(dir, "sweep s.toml --vary bonding.gamma=0,100 -o sweep.csv", 2,
                      Contains("point 2 of 2 (bonding.gamma=100)") &&
                          Contains("'fb_newton' takes no bonding field") &&
                          Contains("use direct, moreau_jean, exact, event_driven"));
  // A step (5-1) cannot take, at the one point that has it: time.h, named with its value.
  dir.write("direct.toml",
            "[initial]\nu0 = 0.05\nv0 = -1.0\n[force]\nf = -9.80665\n[time]\nT = 1e-150\n"
            "h = 1e-150\n[method]\nname = \"direct\"\n");
  CHECK_FAILS_CLEANLY(dir, "sweep direct.toml --vary time.h=1e-150,1e-160 -o sweep.csv", 2,
                      Contains("point 2 of 2") && Contains("for h = 1e-160") &&
                          Contains("2/h^2 of (5-1) is not representable"));
}
