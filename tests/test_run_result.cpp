// The value API a program uses: impact::run() gives, bit for bit, the rows, events, errors and
// final state that `impact run` writes for the same scene, however the run is observed;
// read_scene() gives the same Scene from a file and from its text.
#include <stdio.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/run_result.hpp"
#include "impact/run/scene.hpp"
#include "impact/run/step_events.hpp"
#include "scene/provenance.hpp"
#include "scene/read_scene.hpp"
#include "scene/resolved_scene.hpp"

namespace fs = std::filesystem;
using namespace impact;
using impact::testing::quote;
using impact::testing::Result;
using impact::testing::slurp;
using impact::testing::TempDir;

namespace {

// Every shipped scene (a [method] table) of experiments/, and one with an internal variable under
// event_driven (written into `dir`).
std::vector<std::string> scenes(const TempDir& dir) {
  std::vector<std::string> paths;
  for (const auto& experiment : fs::directory_iterator(fs::path(IMPACT_SOURCE_DIR) / "experiments"))
    if (experiment.is_directory())
      for (const auto& file : fs::directory_iterator(experiment.path()))
        if (file.path().extension() == ".toml" &&
            slurp(file.path().string()).find("\n[method]") != std::string::npos)
          paths.push_back(file.path().string());
  paths.push_back(dir.write("internal.toml",
                            "[initial]\nu0 = 0.2\nv0 = 0.0\n[floor]\ncor = 0.2\n[force]\n"
                            "expression = \"5 - 15 * z\"\n[time]\nT = 2.0\nh = 1e-3\n[method]\n"
                            "name = \"event_driven\"\n[[internal]]\nname = \"z\"\ninitial = 1.0\n"
                            "rate = \"-z\"\n[output]\nevery = 3\n"));
  return paths;
}

// What `write` prints to a stream, as text.
template <class Write>
std::string printed(Write write) {
  char* text = nullptr;
  std::size_t size = 0;
  FILE* out = open_memstream(&text, &size);
  REQUIRE(out != nullptr);
  write(out);
  std::fclose(out);
  std::string copy(text, size);
  std::free(text);
  return copy;
}

std::string rows_csv(const Scene& scene, const std::vector<OutputRow>& rows) {
  return printed([&](FILE* out) {
    CsvWriter csv(out, scene.output.channels, scene.model);
    csv.header();
    for (const OutputRow& row : rows) csv.row(scene.grid.t(row.l), row);
  });
}

std::string events_csv(const Scene& scene, const std::vector<Event>& events) {
  return printed([&](FILE* out) {
    write_event_header(out, scene.model);
    for (const Event& e : events) write_event(out, e, event_variables(scene.model).size());
  });
}

// A number member of a provenance sidecar (`"key": 1.5`), as it is written.
std::string json_number_member(const std::string& json, const std::string& key) {
  std::string quoted = "\"";
  quoted += key;
  quoted += "\": ";
  const std::size_t at = json.find(quoted);
  if (at == std::string::npos) return {};
  const std::size_t from = at + quoted.size();
  return json.substr(from, json.find_first_of(",}\n", from) - from);
}

bool same_bits(const StateWithInternal& a, const StateWithInternal& b) {
  return std::memcmp(&a.u, &b.u, sizeof a.u) == 0 && std::memcmp(&a.v, &b.v, sizeof a.v) == 0 &&
         std::memcmp(a.z.data(), b.z.data(), sizeof a.z) == 0;
}

StateWithInternal state_of(const OutputRow& row) {
  StateWithInternal s;
  s.u = row.state.u;
  s.v = row.state.v;
  s.z = row.internal;
  return s;
}

}  // namespace

TEST_CASE(
    "run() keeps the rows, events and errors impact run writes, bit for bit, on every shipped "
    "scene",
    "[run][cli]") {
  TempDir dir;
  for (const std::string& path : scenes(dir)) {
    INFO(path);
    std::string args = "run ";
    args += quote(path);
    args += " -q -o rows.csv --events events.csv --against exact";
    const Result cli = dir.run(args);
    INFO("stderr: " << cli.err);
    REQUIRE(cli.code == 0);

    const Scene scene = read_scene(SceneFile{path});
    RunOptions options;
    options.keep_rows = true;
    options.keep_events = true;
    options.against_reference = true;
    const RunResult result = run(scene, options);
    CHECK(rows_csv(scene, result.rows) == slurp(dir / "rows.csv"));
    CHECK(events_csv(scene, result.events) == slurp(dir / "events.csv"));
    const std::string sidecar = slurp(dir / "rows.csv.json");
    REQUIRE(result.errors);
    CHECK(json_number(result.errors->sup_u) == json_number_member(sidecar, "err_u_sup"));
    CHECK(json_number(result.errors->energy_end) == json_number_member(sidecar, "err_E_T"));
    CHECK(json_number_member(sidecar, "contact_steps") ==
          std::to_string(result.steps.contact_steps));
    // The final state is the last row's, at the grid's last step.
    REQUIRE(!result.rows.empty());
    CHECK(result.rows.back().l == scene.grid.steps);
    CHECK(same_bits(result.final, state_of(result.rows.back())));
  }
}

TEST_CASE("run() gives one final state however the run is observed", "[run]") {
  TempDir dir;
  for (const std::string& path : scenes(dir)) {
    INFO(path);
    const Scene scene = read_scene(SceneFile{path});
    RunOptions streamed;
    OutputRow last;
    std::int64_t rows = 0;
    streamed.on_row = [&](const OutputRow& row) {
      last = row;
      ++rows;
    };
    const RunResult with_rows = run(scene, streamed);
    CHECK(with_rows.rows.empty());  // streamed, not kept
    CHECK(last.l == scene.grid.steps);
    CHECK(same_bits(with_rows.final, state_of(last)));
    // Nothing asked: the final state alone.
    const RunResult bare = run(scene);
    CHECK(same_bits(bare.final, with_rows.final));
    CHECK(bare.steps.steps == with_rows.steps.steps);
    CHECK(bare.steps.contact_steps == with_rows.steps.contact_steps);
    CHECK(bare.steps.iterations == with_rows.steps.iterations);
    CHECK(!bare.summary);
    CHECK(!bare.errors);
    // The summary's final state, and summarize() (a sweep's point) as the same run.
    RunOptions summarized;
    summarized.summary = true;
    const RunResult with_summary = run(scene, summarized);
    REQUIRE(with_summary.summary);
    CHECK(same_bits(with_summary.final, with_rows.final));
    const PointOutcome point = summarize(scene, false);
    CHECK(std::memcmp(&point.summary.final, &with_summary.summary->final, sizeof(State)) == 0);
    CHECK(point.summary.contact_steps == with_summary.summary->contact_steps);
    CHECK(point.summary.impacts == with_summary.summary->impacts);
  }
}

TEST_CASE("read_scene gives the same Scene from a file and from its text, edits included",
          "[run][scene]") {
  TempDir dir;
  for (const std::string& path : scenes(dir)) {
    INFO(path);
    const std::string text = slurp(path);
    CHECK(resolved_scene(read_scene(SceneFile{path})) ==
          resolved_scene(read_scene(SceneText{text})));
    CHECK(resolved_scene(read_scene(SceneFile{path})) == resolved_scene(load_scene(path)));
    SceneEdits edits{{"time.T=0.5", "method.name=moreau_jean"}, {}};
    if (text.find("\n[output]") != std::string::npos) edits.unset.push_back("output");
    const Scene from_file = read_scene(SceneFile{path}, edits);
    CHECK(resolved_scene(from_file) == resolved_scene(read_scene(SceneText{text, path}, edits)));
    CHECK(resolved_scene(from_file) == resolved_scene(load_scene(path, edits.set, edits.unset)));
    CHECK(from_file.T == 0.5);
  }
  // A bad value: the message names the source, a file's path or the text's name.
  const std::string bad = "[time]\nT = -1.0\nh = 1e-3\n";
  const std::string path = dir.write("bad.toml", bad);
  CHECK_THROWS_WITH(read_scene(SceneFile{path}), Catch::StartsWith(path + ":"));
  CHECK_THROWS_WITH(read_scene(SceneText{bad, "my scene"}), Catch::StartsWith("my scene:"));
  CHECK_THROWS_WITH(read_scene(SceneText{bad}), Catch::StartsWith("<string>:"));
}
