// Determinism: the same scene gives byte-identical output, run after run, whatever ran before it in
// the same process, and wherever the output goes. (Across optimisation levels: `make determinism`,
// which needs a second build; see tests/README.md.)
#include <stdlib.h>
#include <sys/wait.h>

#include <bit>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "impact/loop/simulate.hpp"
#include "impact/run/any_stepper.hpp"
#include "scene/read_scene.hpp"

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct TempDir {
  std::string path;
  TempDir() {
    char name[] = "/tmp/impact_determinism_XXXXXX";
    REQUIRE(mkdtemp(name) != nullptr);
    path = name;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

// A scene that bounces several times under gravity in 0.5 s, so that every solver runs its
// contact branch (and penalty its event splitting) many times; COR where the method has a law.
std::string bouncing_scene(const impact::MethodInfo& method) {
  std::string text =
      "[initial]\nu0 = 0.05\nv0 = -1.0\n[force]\nf = -9.80665\n[time]\nT = 0.5\nh = 0.001\n"
      "[method]\nname = \"" +
      std::string(method.name) + "\"\n[output]\nchannels = [\"u\", \"v\", \"N\", \"E\"" +
      (method.can.iterations_channel ? ", \"iterations\"" : "") + "]\n";
  if (method.name != "penalty") text += "[floor]\ncor = 0.75\n";
  return text;
}

// Every value of every step, as bits.
std::vector<std::uint64_t> trajectory(const std::string& text) {
  impact::Scene scene = impact::parse_scene(text, "bounce.toml");
  impact::AnyStepper stepper = impact::make_stepper(scene);
  std::vector<std::uint64_t> bits;
  impact::simulate(stepper, scene.initial, scene.grid,
                   [&](std::int64_t, const impact::State& s, const impact::StepInfo& info) {
                     for (double x : {s.u, s.v, info.contact_force})
                       bits.push_back(std::bit_cast<std::uint64_t>(x));
                     bits.push_back(static_cast<std::uint64_t>(info.iterations));
                   });
  return bits;
}

int run_cli(const std::string& args) {
  const int status = std::system((std::string("'") + IMPACT_CLI + "' " + args).c_str());
  return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("determinism: two runs of the CLI write the same bytes, to a file or to stdout",
          "[determinism]") {
  TempDir dir;
  for (const auto& method : impact::methods()) {
    INFO("method " << method.name);
    const std::string scene = dir.path + "/bounce.toml";
    std::ofstream(scene) << bouncing_scene(method);
    REQUIRE(run_cli("run '" + scene + "' -q -o '" + dir.path + "/a.csv'") == 0);
    REQUIRE(run_cli("run '" + scene + "' -q -o '" + dir.path + "/b.csv'") == 0);
    REQUIRE(run_cli("run '" + scene + "' -q > '" + dir.path + "/c.csv'") == 0);
    const std::string a = slurp(dir.path + "/a.csv");
    CHECK(a.size() > 20000);  // 501 rows
    CHECK(slurp(dir.path + "/b.csv") == a);
    CHECK(slurp(dir.path + "/c.csv") == a);
  }
}

TEST_CASE("determinism: a run does not depend on what ran before it in the process",
          "[determinism]") {
  // Hidden state (a cache, a GSL driver, a process-wide setting) would show up as a difference
  // between the first run of a scene and a later one after every other method has run.
  std::vector<std::vector<std::uint64_t>> first;
  for (const auto& method : impact::methods()) first.push_back(trajectory(bouncing_scene(method)));
  std::size_t i = first.size();
  for (auto m = impact::methods().rbegin(); m != impact::methods().rend(); ++m) {
    --i;
    INFO("method " << m->name);
    const std::vector<std::uint64_t> again = trajectory(bouncing_scene(*m));
    REQUIRE(again.size() == first[i].size());
    CHECK(again == first[i]);
  }
}
