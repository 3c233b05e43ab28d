// Where an output came from: the sidecar OUT.json that `impact run` and `impact sweep` write beside
// a CSV file, and the scene as it ran (resolved_scene), which reads back to the same Scene.
#include <bit>
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cli_support.hpp"
#include "impact/version.hpp"
#include "scene/read_scene.hpp"
#include "scene/resolved_scene.hpp"

using Catch::Contains;
using namespace impact::testing;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;

bool same_scene(const impact::Scene& a, const impact::Scene& b) {
  const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
  const impact::Model &x = a.model, &y = b.model;
  return bits(a.initial.u) == bits(b.initial.u) && bits(a.initial.v) == bits(b.initial.v) &&
         bits(x.phi) == bits(y.phi) && bits(x.f) == bits(y.f) && x.cor == y.cor &&
         x.harmonic == y.harmonic && x.expression == y.expression && bits(a.T) == bits(b.T) &&
         bits(a.grid.h) == bits(b.grid.h) && a.grid.steps == b.grid.steps && a.method == b.method &&
         a.output.channels == b.output.channels && a.output.every == b.output.every &&
         x.internal == y.internal;
}

// The value of "key": ... on its line of a sidecar (one key per line), as written.
std::string field(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\n  \"" + key + "\": ");
  REQUIRE(at != std::string::npos);
  const std::size_t start = at + key.size() + 7, end = json.find('\n', start);
  std::string value = json.substr(start, end - start);
  if (!value.empty() && value.back() == ',') value.pop_back();
  return value;
}

}  // namespace

TEST_CASE("provenance: the scene as run reads back to the same scene, for every shipped scene",
          "[provenance][regression]") {
  std::vector<std::string> scenes;
  for (const auto& e : std::filesystem::recursive_directory_iterator(kSource + "/experiments"))
    if (e.path().extension() == ".toml" && e.path().filename() != "reference.toml")
      scenes.push_back(e.path().string());
  REQUIRE(scenes.size() >= 9);
  for (const std::string& path : scenes)
    for (const std::string method :
         {"direct", "fb_newton", "moreau_jean", "penalty", "exact", "event_driven"}) {
      impact::Scene scene;
      try {
        scene = impact::load_scene(path, {"method.name=" + method});
      } catch (const impact::SceneError&) {
        continue;  // a method the scene cannot have (penalty with a COR, exact with an expression)
      }
      INFO(path << " with " << method << "\n" << impact::resolved_scene(scene));
      CHECK(same_scene(impact::parse_scene(impact::resolved_scene(scene), "resolved.toml"), scene));
    }
}

TEST_CASE(
    "provenance: a sidecar's scene_as_run reruns to the same bytes, for every shipped scene "
    "and every kind of force and internal variables",
    "[provenance][regression]") {
  TempDir dir;
  std::vector<std::string> scenes;
  for (const auto& e : std::filesystem::recursive_directory_iterator(kSource + "/experiments"))
    if (e.path().extension() == ".toml" && e.path().filename() != "reference.toml" &&
        slurp(e.path().string()).find("[method]") != std::string::npos)
      scenes.push_back(e.path().string());
  REQUIRE(scenes.size() >= 9);
  const std::string head =
      "[initial]\nu0 = 0.3\nv0 = 0.0\n[time]\nT = 0.5\nh = 1e-3\n[method]\nname = "
      "\"event_driven\"\n[floor]\ncor = 0.8\n";
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"expression.toml", head + "[force]\nexpression = \"-9.81 + 5 * sin(20 * t)\"\n"},
           {"state.toml", head + "[force]\nexpression = \"-9.81 - 20 * (u - 0.3) - 0.5 * v\"\n"},
           {"internal.toml",
            head + "[force]\nexpression = \"-9.81 + 5 * b - D\"\n[[internal]]\nname = "
                   "\"b\"\ninitial = 1.0\nrate = \"-2 * b + u\"\n[[internal]]\nname = "
                   "\"D\"\ninitial = 0.25\nrate = 'v^2 / 2'\n"}})
    scenes.push_back(dir.write(name, text));
  for (const std::string& path : scenes) {
    INFO(path);
    // Every 100th row keeps the long scenes' files small; it is part of the scene as run.
    const Result r = dir.run("run " + quote(path) + " -q --set output.every=100 -o rows.csv");
    REQUIRE(r.code == 0);
    const std::string as_run = json_member(slurp(dir / "rows.csv.json"), "scene_as_run");
    INFO(as_run);
    dir.write("as_run.toml", as_run);
    REQUIRE(dir.run("run as_run.toml -q --no-provenance -o again.csv").code == 0);
    CHECK(slurp(dir / "again.csv") == slurp(dir / "rows.csv"));
  }
}

TEST_CASE("provenance: impact run writes OUT.json beside the rows, with what made them",
          "[provenance][cli]") {
  TempDir dir;
  dir.write("s.toml", kShort);
  const Result r = dir.run("run s.toml -o X.csv --set time.h=5e-4 --against exact");
  REQUIRE(r.code == 0);
  CHECK(dir.entries() == std::set<std::string>{"s.toml", "X.csv", "X.csv.json"});
  const std::string json = slurp(dir / "X.csv.json");
  CHECK(field(json, "impact_version") == "\"" + std::string(impact::version()) + "\"");
  CHECK(field(json, "impact_commit") == "\"" + std::string(impact::commit()) + "\"");
  CHECK(field(json, "command") == "\"impact run\"");
  CHECK_THAT(field(json, "arguments"), Contains("\"--set\", \"time.h=5e-4\""));
  CHECK(field(json, "overrides") == "[\"time.h=5e-4\"]");
  CHECK(field(json, "method") == "\"direct\"");
  CHECK(field(json, "force_depends_on_t") == "false");
  // The file's text as read, and the scene as run, defaults and the --set included.
  CHECK_THAT(field(json, "scene_text"), Contains("T = 0.1\\nh = 0.001\\n"));
  CHECK_THAT(field(json, "scene_as_run"), Contains("h = 5e-04\\n") &&
                                              Contains("free_flight = 'closed_form'") &&
                                              Contains("every = 1"));
  CHECK_THAT(field(json, "processor"), Contains("family") && Contains("model"));
  CHECK_THAT(field(json, "summary"), Contains("\"steps\": 200") && Contains("\"err_u_sup\": ") &&
                                         Contains("\"reference_s\": "));
  CHECK_THAT(field(json, "summary_line"), Contains("impact: direct, 200 steps"));
  // The sidecar is valid JSON (where a Python is there to read it).
  if (std::system("python3 -c 'import json' 2>/dev/null") == 0)
    CHECK(dir.shell("python3 -c 'import json,sys; json.load(open(\"X.csv.json\"))'").code == 0);
}

TEST_CASE("provenance: a sweep's sidecar, none for standard output or with --no-provenance",
          "[provenance][cli]") {
  TempDir dir;
  dir.write("s.toml", kShort);
  REQUIRE(dir.run("sweep s.toml --vary time.h=1e-3,5e-4 -q -o S.csv").code == 0);
  const std::string json = slurp(dir / "S.csv.json");
  CHECK(field(json, "command") == "\"impact sweep\"");
  CHECK_THAT(field(json, "summary"), Contains("\"points\": 2"));
  CHECK_THAT(field(json, "arguments"), Contains("\"--vary\", \"time.h=1e-3,5e-4\""));
  // Standard output has no place beside it; --no-provenance leaves it out.
  std::filesystem::remove(dir / "S.csv");
  std::filesystem::remove(dir / "S.csv.json");
  REQUIRE(dir.run("run s.toml -q").code == 0);
  REQUIRE(dir.run("run s.toml -q -o R.csv --no-provenance").code == 0);
  REQUIRE(dir.run("sweep s.toml --vary time.h=1e-3 -q -o S.csv --no-provenance").code == 0);
  CHECK(dir.entries() == std::set<std::string>{"s.toml", "R.csv", "S.csv"});
  // A scene and an expression with quotes and a backslash are escaped.
  dir.write("q.toml", kShort + "[force]\nexpression = \"-9.8 + 0*(t > 1)\" # \"q\" \\\\ \n");
  REQUIRE(dir.run("run q.toml -q -o Q.csv").code == 0);
  if (std::system("python3 -c 'import json' 2>/dev/null") == 0)
    CHECK(dir.shell("python3 -c 'import json; d = json.load(open(\"Q.csv.json\")); "
                    "assert d[\"force_depends_on_t\"] and \"\\\\\\\\\" in d[\"scene_text\"]'")
              .code == 0);
}

// impact plot reads the sidecar to say which energy the E channel is.
TEST_CASE("provenance: impact plot names the E of a run with f(t) from its sidecar",
          "[provenance][plot]") {
  TempDir dir;
  // A gnuplot that keeps the script it is given and draws one byte.
  std::filesystem::create_directories(dir / "fake");
  dir.write("fake/gnuplot", "#!/bin/sh\ncat > script.gp\nprintf x\n");
  std::filesystem::permissions(dir / "fake/gnuplot", std::filesystem::perms::owner_all);
  const std::string plot = "PATH=" + quote(dir / "fake") + ":\"$PATH\" \"$IMPACT\" plot ";
  const std::string table = kSource + "/experiments/vibrating_table/period_one.toml";
  const std::string channels = " --set 'output.channels=[\"u\",\"v\",\"E\"]' -q";
  REQUIRE(dir.run("run " + quote(table) + channels + " -o table.csv").code == 0);
  REQUIRE(dir.shell(plot + "table.csv").code == 0);
  CHECK_THAT(slurp(dir / "script.gp"),
             Contains("v^2/2 - f(0) u(0) - W(t)") && !Contains("v^2/2 - f u"));
  dir.write("s.toml", kShort);
  REQUIRE(dir.run("run s.toml" + channels + " -o s.csv").code == 0);
  REQUIRE(dir.shell(plot + "s.csv").code == 0);
  CHECK_THAT(slurp(dir / "script.gp"),
             Contains("E = v^2/2 - f u, kinetic plus potential energy") && !Contains("W(t)"));
  // Without a sidecar both are named.
  REQUIRE(dir.run("run s.toml" + channels + " -o bare.csv --no-provenance").code == 0);
  REQUIRE(dir.shell(plot + "bare.csv").code == 0);
  CHECK_THAT(slurp(dir / "script.gp"), Contains("for a constant force f;") &&
                                           Contains("with a force f(t): E = v^2/2 - f(0)"));
}
