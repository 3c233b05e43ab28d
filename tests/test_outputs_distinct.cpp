// Every output of `impact run`, `impact sweep` and `impact work-precision` (the CSV, the events,
// the provenance sidecar OUT.json, the figure) is checked against every input and every other
// output as the files they lead to: an output may not be its own sidecar, a sidecar may not be the
// scene, a link or a hard link does not hide one from the other. Each such run exits 2 before any
// work, and every file keeps what it had. The sidecar's JSON stays valid whatever bytes the names
// hold, and a name too long for its sidecar says how to do without one.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <climits>
#include <filesystem>
#include <string>

#include "cli_support.hpp"

using Catch::Contains;
using namespace impact::testing;

namespace {

// The three commands that write a CSV and its sidecar, each with its scene last-but-one.
const std::vector<std::string> kCommands = {
    "run s.toml -q",
    "sweep s.toml -q --vary time.h=1e-3,5e-4",
    "work-precision s.toml -q --methods direct --h 1e-2,5e-3 --repeat 1",
};

// A scene that every command takes, at the path `name`.
void scene_at(const TempDir& dir, const std::string& name) {
  dir.write(name, kShort);
}

}  // namespace

TEST_CASE("outputs: the CSV and its own sidecar are never one file, however linked",
          "[output][paths][regression]") {
  for (const std::string& command : kCommands) {
    INFO(command);
    TempDir dir;
    scene_at(dir, "s.toml");
    // o.csv.json a link to o.csv: the sidecar used to be written over the CSV.
    dir.write("o.csv", "OLD\n");
    std::filesystem::create_symlink("o.csv", dir / "o.csv.json");
    CHECK_FAILS_CLEANLY(dir, command + " -o o.csv", 2,
                        Contains("the provenance file of --out (o.csv.json) and --out lead to the "
                                 "same output") &&
                            Contains("--no-provenance"));
    CHECK(slurp(dir / "o.csv") == "OLD\n");
    // Without a sidecar there is nothing to collide.
    CHECK(dir.run(command + " --no-provenance -o o.csv").code == 0);
    // g.csv a link to g.csv.json; and a hard link.
    dir.write("g.csv.json", "OLD\n");
    std::filesystem::create_symlink("g.csv.json", dir / "g.csv");
    CHECK_FAILS_CLEANLY(dir, command + " -o g.csv", 2, Contains("lead to the same output"));
    CHECK(slurp(dir / "g.csv.json") == "OLD\n");
    dir.write("h.csv", "OLD\n");
    std::filesystem::create_hard_link(dir / "h.csv", dir / "h.csv.json");
    CHECK_FAILS_CLEANLY(dir, command + " -o h.csv", 2, Contains("lead to the same output"));
    CHECK(slurp(dir / "h.csv") == "OLD\n");
  }
}

TEST_CASE("outputs: no output replaces the scene, the sidecar included",
          "[output][paths][regression]") {
  for (const std::string& command : kCommands) {
    INFO(command);
    TempDir dir;
    // The scene named as the sidecar of the output: it used to be replaced by the sidecar.
    scene_at(dir, "r.csv.json");
    std::string with_scene = command;
    with_scene.replace(with_scene.find("s.toml"), 6, "r.csv.json");
    CHECK_FAILS_CLEANLY(dir, with_scene + " -o r.csv", 2,
                        Contains("the provenance file of --out (r.csv.json) names the scene file "
                                 "itself"));
    CHECK(slurp(dir / "r.csv.json") == kShort);
    // A link to the scene as the output, and as the output's sidecar.
    scene_at(dir, "s.toml");
    std::filesystem::create_symlink("s.toml", dir / "link.csv");
    CHECK_FAILS_CLEANLY(dir, command + " -o link.csv", 2, Contains("names the scene file itself"));
    std::filesystem::create_symlink("s.toml", dir / "x.csv.json");
    CHECK_FAILS_CLEANLY(dir, command + " -o x.csv", 2, Contains("names the scene file itself"));
    CHECK(slurp(dir / "s.toml") == kShort);
  }
}

TEST_CASE("outputs: run's events and work-precision's figure against every other file",
          "[output][paths][regression]") {
  TempDir dir;
  scene_at(dir, "s.toml");
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o o.csv --events o.csv.json", 2,
                      Contains("lead to the same output"));
  std::filesystem::create_symlink("o.csv", dir / "ev.csv");
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o o.csv --events ev.csv", 2,
                      Contains("--events and --out lead to the same output"));
  const std::string wp = "work-precision s.toml -q --methods direct --h 1e-2,5e-3 --repeat 1 ";
  std::filesystem::create_symlink("w.csv.json", dir / "sidecar.svg");
  CHECK_FAILS_CLEANLY(dir, wp + "-o w.csv --plot sidecar.svg", 2,
                      Contains("--plot and the provenance file of --out (w.csv.json) lead to the "
                               "same output"));
  std::filesystem::create_symlink("s.toml", dir / "fig.svg");
  CHECK_FAILS_CLEANLY(dir, wp + "-o w.csv --plot fig.svg", 2,
                      Contains("--plot names the scene file itself"));
  // A sweep's parts: --merge may not write over one of them.
  REQUIRE(dir.run("sweep s.toml -q --vary time.h=1e-3,5e-4 --shard 1/1 -o part.csv").code == 0);
  const std::string part = slurp(dir / "part.csv");
  std::filesystem::create_symlink("part.csv", dir / "merged.csv");
  CHECK_FAILS_CLEANLY(dir, "sweep --merge part.csv -o merged.csv", 2,
                      Contains("names the part part.csv itself"));
  CHECK(slurp(dir / "part.csv") == part);
}

TEST_CASE("outputs: a sidecar's JSON is valid whatever bytes the names hold",
          "[output][provenance][regression]") {
  TempDir dir;
  scene_at(dir, "s.toml");
  // A Latin-1 name (0xe9) and a stray continuation byte: not UTF-8.
  const std::string name = "caf\xe9-\x80.csv";
  REQUIRE(dir.run("run s.toml -q -o " + quote(name)).code == 0);
  const Result check = dir.shell(
      "/usr/bin/python3 -c \"import json, os, sys; d = json.load(open(sys.argv[1], "
      "encoding='utf-8')); print(os.fsencode(d['arguments'][-1]) == sys.argv[2].encode('utf-8', "
      "'surrogateescape'))\" " +
      quote(name + ".json") + " " + quote(name));
  INFO(check.err);
  CHECK(check.code == 0);
  CHECK(check.out == "True\n");
}

TEST_CASE("outputs: a name too long for its sidecar names --no-provenance",
          "[output][provenance][regression]") {
  TempDir dir;
  scene_at(dir, "s.toml");
  const long name_max = pathconf(dir.path().c_str(), _PC_NAME_MAX);
  REQUIRE(name_max > 10);
  // NAME_MAX - 4 bytes: the CSV fits, CSV.json does not.
  const std::string name = std::string(static_cast<std::size_t>(name_max) - 8, 'a') + ".csv";
  for (const std::string& command : kCommands) {
    INFO(command);
    CHECK_FAILS_CLEANLY(dir, command + " -o " + name, 2,
                        Contains("NAME_MAX") && Contains("--no-provenance"));
    REQUIRE(dir.run(command + " --no-provenance -o " + name).code == 0);
    std::filesystem::remove(dir / name);
  }
}
