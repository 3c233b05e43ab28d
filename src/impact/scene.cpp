#include "impact/scene.hpp"

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

AnyStepper make_stepper(const Scene& scene) {
  AnyStepper stepper = make_stepper(scene.model, scene.grid.h, scene.method);
  // A force expression need only be defined up to the scene's end: event_driven looks no further.
  if (auto* event_driven = std::get_if<EventDriven>(&stepper))
    event_driven->set_end(scene.grid.end());
  if (auto* event_driven = std::get_if<EventDrivenInternal>(&stepper))
    event_driven->set_end(scene.grid.end());
  return stepper;
}

}  // namespace impact
