// libFuzzer target for what a user types: a scene file and the --set overrides of the command line.
// The input is the scene text, then any number of overrides, each introduced by a NUL byte (a
// command-line argument cannot contain one): "[initial]\nu0 = 5 ...\0time.h=1e-4\0floor.cor=0.5".
// A scene that loads is then run for its first kMaxSteps steps through the same CSV writer as the
// CLI, so that data the reader accepts cannot crash a solver either.
//
// Allowed outcomes: the scene loads and runs, or SceneError (bad input, exit 2 in the CLI), or
// NumericalError (exit 1). Anything else (another exception, a sanitizer report, a crash, a hang)
// is a finding: libFuzzer stops and saves the input.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "impact/loop/simulate.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"
#include "scene/read_scene.hpp"

namespace {

// Enough steps for every solver to reach its contact branch on the shipped scenes' short variants
// (u0 = 0.05 over the floor with v0 = -1 lands at step 50 for h = 0.001), few enough that an input
// runs in milliseconds.
constexpr std::int64_t kMaxSteps = 200;

std::FILE* null_sink() {
  static std::FILE* sink = std::fopen("/dev/null", "w");
  return sink;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::size_t end = input.find('\0');
  const std::string_view text = input.substr(0, end);
  std::vector<std::string> overrides;
  while (end != std::string_view::npos) {
    const std::size_t next = input.find('\0', end + 1);
    overrides.emplace_back(
        input.substr(end + 1, next == std::string_view::npos ? next : next - end - 1));
    end = next;
  }
  try {
    impact::Scene scene = impact::parse_scene(text, "fuzz.toml", overrides);
    impact::AnyStepper stepper = impact::make_stepper(scene);
    impact::Grid grid = scene.grid;
    grid.steps = std::min(grid.steps, kMaxSteps);
    impact::CsvWriter csv(null_sink(), scene.output.channels);
    csv.header();
    impact::simulate(stepper, scene.initial, grid,
                     [&](std::int64_t l, const impact::State& s, const impact::StepInfo& info) {
                       csv.row(scene.grid.t(l), {l, s, info.contact_force, info.iterations,
                                                 impact::energy(scene.model, s)});
                     });
  } catch (const impact::SceneError&) {
  } catch (const impact::NumericalError&) {
  }
  return 0;
}
