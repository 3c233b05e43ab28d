#include "impact/run/scene.hpp"

namespace impact {

Scene make_scene(const Model& model, const State& initial, double T, double h,
                 const MethodParams& method) {
  Scene scene;
  scene.initial = initial;
  scene.model = model;
  scene.T = T;
  scene.grid = Grid::covering(T, h);
  scene.method = method;
  return scene;
}

}  // namespace impact
