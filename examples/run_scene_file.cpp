// A TOML scene file run through the installed package: read_scene() (the component `scene`,
// impact::scene) gives the Scene that `impact run` would run, and run() its final state, step
// counts and errors against the exact solution as values (docs/library.md shows this program).
//   run_scene_file drop.toml [table.key=value ...]
#include <cstdio>
#include <impact/impact.hpp>
#include <impact/scene/read_scene.hpp>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SCENE.toml [table.key=value ...]\n", argv[0]);
    return 2;
  }
  impact::Scene scene;
  try {
    scene = impact::read_scene(impact::SceneFile{argv[1]},
                               impact::SceneEdits{{argv + 2, argv + argc}, {}});
  } catch (const impact::SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());  // names the file, the key, the value, the range
    return 2;
  }
  impact::RunOptions options;
  options.against_reference = true;
  const impact::RunResult r = impact::run(scene, options);
  std::printf("u = %.17g, v = %.17g at t = %.17g\n", r.final.u, r.final.v, scene.grid.end());
  std::printf(
      "%lld steps, %lld in contact; against the exact solution: sup |u - u_exact| = %.3g m\n",
      static_cast<long long>(r.steps.steps), static_cast<long long>(r.steps.contact_steps),
      r.errors->sup_u);
  return 0;
}
