// `impact sweep` varies what the scene reader reads, through the reader's own key table: a key
// that two methods share (method.rtol: penalty's and event_driven's) is the scene's method's; its
// summaries equal the library's at run lengths on both sides of 2^16 and 2^17 steps; its times
// leave the reference out.
#include <bit>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/run_result.hpp"
#include "impact/run/scene.hpp"
#include "impact/run/summary.hpp"
#include "scene/read_scene.hpp"

using Catch::Contains;
using namespace impact::testing;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;

// The rows of a sweep CSV whose points did not fail (the failure field empty), split at commas.
std::vector<std::vector<std::string>> rows_of(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    for (std::string f; std::getline(cells, f, ',');) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

// strtod, not stod: a subnormal v_T (a resting particle's, 2^-1073) is a number, not an error.
std::uint64_t bits(const std::string& field) {
  return std::bit_cast<std::uint64_t>(std::strtod(field.c_str(), nullptr));
}
std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

// Each point of the sweep (the first `axes` fields are its values) against summarize() of the
// scene impact run reads with them; quantities u_T, v_T, E_T, contact_steps, iterations.
void check_points(const std::string& scene, const std::vector<std::string>& sets,
                  const std::string& csv, std::size_t axes) {
  const auto rows = rows_of(csv);
  REQUIRE(rows.size() > 1);
  for (std::size_t r = 1; r < rows.size(); ++r) {
    std::vector<std::string> all = sets;
    for (std::size_t k = 0; k < axes; ++k) all.push_back(rows[0][k] + "=" + rows[r][k]);
    const impact::Scene s = impact::load_scene(scene, all);
    const impact::PointSummary want = impact::summarize(s, false).summary;
    INFO("point " << r << ": " << rows[r][0]);
    REQUIRE(rows[r].size() == axes + 5);  // the quantities, then an empty failure field
    CHECK(bits(rows[r][axes]) == bits(want.final.u));
    CHECK(bits(rows[r][axes + 1]) == bits(want.final.v));
    CHECK(bits(rows[r][axes + 2]) == bits(want.energy_final));
    CHECK(std::stoll(rows[r][axes + 3]) == want.contact_steps);
    CHECK(std::stoll(rows[r][axes + 4]) == want.iterations);
  }
}

}  // namespace

TEST_CASE("sweep keys: method.rtol, atol, max_step and max_ode_steps are the scene's method's",
          "[sweep][regression]") {
  TempDir dir;
  const std::string expression = kSource + "/experiments/work_precision/expression.toml";
  const std::vector<std::string> sets = {"method.name=event_driven", "time.T=2"};
  // event_driven's rtol was set as penalty's, and the sweep died: std::get: wrong index.
  for (const std::string vary : {"--vary method.rtol=1e-10,1e-8 --vary method.max_step=0.01,0.1",
                                 "--vary method.atol=1e-14,1e-12"}) {
    INFO(vary);
    const Result r =
        dir.run("sweep " + quote(expression) + " --set method.name=event_driven --set time.T=2 " +
                vary + " --summary u_T,v_T,E_T,contact_steps,iterations -q -o s.csv");
    INFO(r.err);
    REQUIRE(r.code == 0);
    check_points(expression, sets, slurp(dir / "s.csv"),
                 vary.find("max_step") != std::string::npos ? 2 : 1);
  }
  // penalty's, and its integer budget.
  const std::string figure4 = kSource + "/experiments/figure4/no_cor.toml";
  const Result r = dir.run("sweep " + quote(figure4) +
                           " --set method.name=penalty --set time.T=1 --vary method.rtol=1e-10,1e-8"
                           " --vary method.max_ode_steps=0,2000000"
                           " --summary u_T,v_T,E_T,contact_steps,iterations -q -o p.csv");
  INFO(r.err);
  REQUIRE(r.code == 0);
  check_points(figure4, {"method.name=penalty", "time.T=1"}, slurp(dir / "p.csv"), 2);
  // A key of another method is refused by the reader, naming whose it is.
  CHECK_FAILS_CLEANLY(dir, "sweep " + quote(figure4) + " --vary method.theta=0.5,1", 2,
                      Contains("theta is a key of moreau_jean"));
  CHECK_FAILS_CLEANLY(dir, "sweep " + quote(figure4) + " --vary method.name=1", 2,
                      Contains("method.name and force.expression are not numbers"));
}

TEST_CASE("sweep keys: a point's summary at 2^16 and 2^17 steps is the library's",
          "[sweep][regression]") {
  TempDir dir;
  const std::string figure4 = kSource + "/experiments/figure4/cor075.toml";
  std::string values;
  for (const double steps : {65535.0, 65536.0, 65537.0, 131071.0, 131073.0})
    values += (values.empty() ? "" : ",") + impact::round_trip(10.0 / steps);
  for (const std::string method : {"direct", "fb_newton", "moreau_jean", "exact"}) {
    INFO(method);
    const Result r = dir.run("sweep " + quote(figure4) + " --set method.name=" + method +
                             " --vary time.h=" + values +
                             " --summary u_T,v_T,E_T,contact_steps,iterations -q -o s.csv");
    REQUIRE(r.code == 0);
    check_points(figure4, {"method.name=" + method}, slurp(dir / "s.csv"), 1);
  }
}

TEST_CASE("sweep keys: wall_s is the method's time, reference_s the reference's",
          "[sweep][regression]") {
  TempDir dir;
  const std::string figure4 = kSource + "/experiments/figure4/cor075.toml";
  CHECK_FAILS_CLEANLY(dir, "sweep " + quote(figure4) + " --vary time.h=1e-3 --summary reference_s",
                      2, Contains("'reference_s' needs --against exact"));
  const Result r = dir.run("sweep " + quote(figure4) +
                           " --vary time.h=1e-4,1e-3 --against exact --summary wall_s,reference_s "
                           "-q -o t.csv");
  REQUIRE(r.code == 0);
  const auto rows = rows_of(slurp(dir / "t.csv"));
  REQUIRE(rows.size() == 3);
  CHECK(rows[0] == std::vector<std::string>{"time.h", "wall_s", "reference_s", "failure"});
  for (std::size_t i = 1; i < rows.size(); ++i) {
    CHECK(std::stod(rows[i][1]) > 0);
    CHECK(std::stod(rows[i][2]) > 0);
  }
}
