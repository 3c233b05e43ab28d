// A scene: everything one run needs (initial data, floor, force, time grid, method, output), as
// plain values. The scene reader (src/scene/) fills one from a TOML file; code can build one
// directly.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "impact/model.hpp"
#include "impact/registry.hpp"

namespace impact {

enum class Channel { u, v, N, E, iterations };
std::string_view channel_name(Channel c);

struct OutputSpec {
  std::vector<Channel> channels{Channel::u, Channel::v};
  std::int64_t every = 1;  // write every k-th step; t = 0 and the last step always
};

struct Scene {
  State initial;
  Model model;
  double T = 0.0;
  Grid grid;  // Grid::covering(T, h)
  MethodParams method;
  OutputSpec output;
};

// A scene with the given data and the default output; the grid covers [0, T] by Grid::covering.
Scene make_scene(const Model& model, const State& initial, double T, double h,
                 const MethodParams& method);

// The scene's solver (make_stepper of registry.hpp).
AnyStepper make_stepper(const Scene& scene);

}  // namespace impact
