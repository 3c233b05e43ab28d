// impact::sweep(), the value API that the Python module calls: its columns are the CSV of
// `impact sweep` read back, bit for bit, whatever the threads, for a shard, a failed point and a
// scene given as text.
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "scene/read_scene.hpp"
#include "scene/sweep_engine.hpp"
#include "sweep_support.hpp"

namespace {

// The CSV's field as the number it writes: empty (a failed point) as NaN.
double csv_number(const std::string& field) {
  return field.empty() ? std::numeric_limits<double>::quiet_NaN() : number(field);
}

void check_columns_are_csv(const SweepResult& got, const std::string& csv) {
  const auto rows = rows_of(csv);
  REQUIRE(rows.size() == got.failures.size() + 1);
  REQUIRE(rows[0].size() == got.names.size() + 1);
  for (std::size_t k = 0; k < got.names.size(); ++k) {
    CHECK(rows[0][k] == got.names[k]);
    REQUIRE(got.columns[k].size() == got.failures.size());
    for (std::size_t i = 0; i < got.failures.size(); ++i) {
      const double want = csv_number(rows[i + 1][k]);
      INFO(got.names[k] << " at point " << i << ": " << rows[i + 1][k]);
      CHECK((same_bits(got.columns[k][i], want) ||
             (std::isnan(want) && std::isnan(got.columns[k][i]))));
    }
  }
  for (std::size_t i = 0; i < got.failures.size(); ++i)
    CHECK(rows[i + 1].back() == got.failures[i]);
}

// Two sweeps' columns, bit for bit (a NaN, a failed point's, matches any NaN).
void check_same_columns(const SweepResult& got, const SweepResult& want) {
  REQUIRE(got.names == want.names);
  CHECK(got.failures == want.failures);
  for (std::size_t k = 0; k < want.columns.size(); ++k)
    for (std::size_t i = 0; i < want.columns[k].size(); ++i) {
      INFO(want.names[k] << " at point " << i);
      CHECK((same_bits(got.columns[k][i], want.columns[k][i]) ||
             (std::isnan(got.columns[k][i]) && std::isnan(want.columns[k][i]))));
    }
}

}  // namespace

TEST_CASE("sweep: impact::sweep()'s columns are the CSV of impact sweep, bit for bit",
          "[sweep][regression]") {
  TempDir dir;
  // The ensemble (70 points on one grid), point by point (fb_newton) and a point that overflows
  // on its first step (test_sweep_output.cpp), with counts, times and NaN rest times among the
  // columns.
  const std::string scene =
      "[initial]\nu0 = 1.0\nv0 = 0.0\n[force]\nf = -9.81\n[floor]\ncor = 0.5\n"
      "[time]\nT = 2.0\nh = 1e-3\n[method]\nname = \"direct\"\n";
  dir.write("drop.toml", scene);
  const std::vector<std::string> varies = {"initial.v0=1,1e308", "force.f=-20:0:35"};
  for (const std::string method : {"direct", "fb_newton"})
    for (const Shard shard : {Shard{}, Shard{1, 3, true}}) {
      INFO(method << ", shard " << shard.k << "/" << shard.n);
      const std::vector<std::string> sets = {"method.name=" + method};
      std::vector<SweepAxis> axes(varies.begin(), varies.end());
      const SweepGrid grid(dir / "drop.toml", sets, axes);
      const SweepSetup setup{parse_summary("", false, grid.base().model), false, shard, 2, "", {}};
      const SweepResult got = impact::sweep(grid, setup);
      std::string args = "sweep drop.toml --set method.name=" + method +
                         " --vary initial.v0=1,1e308 --vary force.f=-20:0:35 -q --out S.csv";
      if (shard.given) args += " --shard 2/3";
      REQUIRE(dir.run(args).code == 1);
      check_columns_are_csv(got, slurp(dir / "S.csv"));
      // Points 35 to 69 have v0 = 1e308: those of the shard fail.
      std::int64_t points = 0, failed = 0;
      for (std::int64_t i = shard.k; i < 70; i += shard.n, ++points) failed += i >= 35;
      CHECK(got.points == points);
      CHECK(got.failed == failed);
      CHECK_THAT(got.failures.back(), Contains("non-finite result"));
      // The same scene as text gives the same columns, on one thread.
      const SweepGrid from_text(SceneText{scene, "<text>"}, sets, axes);
      SweepSetup one = setup;
      one.threads = 1;
      check_same_columns(impact::sweep(from_text, one), got);
    }
}

TEST_CASE("sweep: impact::sweep() refuses a thread count out of range", "[sweep][regression]") {
  TempDir dir;
  dir.write(
      "drop.toml",
      "[initial]\nu0 = 1.0\nv0 = 0.0\n[time]\nT = 1.0\nh = 1e-2\n[method]\nname = \"direct\"\n");
  const SweepGrid grid(dir / "drop.toml", {}, {SweepAxis("initial.u0=1:2:3")});
  for (const int threads : {0, -1, kMaxThreads + 1}) {
    SweepSetup setup{parse_summary("", false), false, Shard{}, threads, "", {}};
    CHECK_THROWS_WITH(impact::sweep(grid, setup), Contains("threads (1 to 4096)"));
  }
}

TEST_CASE("sweep: a Scene value and axes of values sweep as the file and its --vary do",
          "[sweep][regression]") {
  TempDir dir;
  const std::string scene =
      "[initial]\nu0 = 1.0\nv0 = 0.0\n[force]\nf = -9.81\n[floor]\ncor = 0.5\n"
      "[time]\nT = 1.0\nh = 1e-3\n[method]\nname = \"moreau_jean\"\n[output]\nevery = 10\n";
  dir.write("drop.toml", scene);
  const std::vector<SweepAxis> varied = {SweepAxis("floor.cor=0:1:5"),
                                         SweepAxis("time.h=1e-4:1e-2:3:log")};
  const SweepGrid from_file(dir / "drop.toml", {}, varied);
  // The same values as lists, on the scene the reader gives for the file.
  std::vector<SweepAxis> listed;
  for (const SweepAxis& axis : varied) {
    std::vector<double> values;
    for (std::int64_t j = 0; j < axis.size(); ++j) values.push_back(axis.value(j));
    listed.emplace_back(axis.key(), values);
  }
  const Scene base = load_scene(dir / "drop.toml");
  const SweepSetup setup{parse_summary("", false, base.model), false, Shard{}, 1, "", {}};
  const SweepResult want = impact::sweep(from_file, setup);
  const SweepResult got = impact::sweep(base, listed, setup);
  CHECK(got.points == 15);
  check_same_columns(got, want);
  // Point 0's scene is the file's with the first values, grid included.
  const SweepGrid grid(base, listed);
  CHECK(grid.base().model.cor == from_file.base().model.cor);
  CHECK(same_bits(grid.base().grid.h, from_file.base().grid.h));
  CHECK(grid.base().grid.steps == from_file.base().grid.steps);
  CHECK(grid.scene_text().empty());
}

TEST_CASE("sweep: axes of values are checked as --vary is, naming the axis and the point",
          "[sweep][regression]") {
  TempDir dir;
  dir.write("drop.toml",
            "[initial]\nu0 = 1.0\nv0 = 0.0\n[time]\nT = 1.0\nh = 1e-2\n[method]\nname = "
            "\"direct\"\n");
  const Scene base = load_scene(dir / "drop.toml");
  CHECK_THROWS_WITH(SweepAxis("floor.cor", {}), Contains("axis floor.cor: no values"));
  CHECK_THROWS_WITH(SweepAxis("floor.cor", {0.5, std::nan("")}),
                    Contains("axis floor.cor: nan is not a finite number"));
  // Out of the key's range, at the point that has it.
  // The axis is named as the program gave it: no command-line flag it did not write.
  CHECK_THROWS_WITH(SweepGrid(base, {SweepAxis("floor.cor", {0.5, 2.0})}),
                    Contains("point 2 of 2 (floor.cor=2): axis floor.cor: floor.cor = 2") &&
                        !Contains("--set") && !Contains("--vary"));
  // A key of another method, a variable the scene does not have, a key no sweep varies.
  CHECK_THROWS_WITH(SweepGrid(base, {SweepAxis("method.stiffness", {1e6})}),
                    Contains("method.stiffness is not a key of the scene's method direct"));
  CHECK_THROWS_WITH(SweepGrid(base, {SweepAxis("internal.z.initial", {1.0})}),
                    Contains("the scene has no internal variable z"));
  CHECK_THROWS_WITH(
      SweepGrid(base, {SweepAxis("force.expression", {1.0})}),
      Contains("axis force.expression: not a key a sweep can vary") && !Contains("--vary"));
  CHECK_THROWS_WITH(SweepGrid(base, {SweepAxis("floor.cor", {0.5}), SweepAxis("floor.cor", {1.0})}),
                    Contains("axis floor.cor: the key is varied twice"));
}
