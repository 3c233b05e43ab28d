// A parameter sweep as a value, through the installed package: the scene component's
// impact::sweep() runs `impact sweep`'s engine (the ensemble where it can, on threads) and gives
// the columns that the command writes as CSV, bit for bit.
//   sweep_scene_file drop.toml
#include <cstdio>
#include <impact/scene/sweep_engine.hpp>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SCENE.toml\n", argv[0]);
    return 2;
  }
  try {
    // Nine coefficients of restitution; three of the summary quantities of each point.
    const impact::SweepGrid grid(argv[1], {}, {impact::SweepAxis("floor.cor=0.1:0.9:9")});
    impact::SweepSetup setup;
    setup.quantities = impact::parse_summary("rest_time,impacts,E_T", false, grid.base().model);
    setup.threads = 2;
    const impact::SweepResult r = impact::sweep(grid, setup);
    for (const std::string& name : r.names) std::printf("%12s", name.c_str());
    std::printf("\n");
    for (std::size_t i = 0; i < r.failures.size(); ++i) {
      for (const auto& column : r.columns) std::printf("%12.6g", column[i]);
      std::printf("%s\n", r.failures[i].c_str());
    }
    std::printf("%lld points, %lld failed\n", static_cast<long long>(r.points),
                static_cast<long long>(r.failed));
  } catch (const impact::SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());  // names the file or the --vary, the key, the range
    return 2;
  }
  return 0;
}
