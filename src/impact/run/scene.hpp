// A scene: everything one run needs (initial data, floor, force, time grid, method, output), as
// plain values. The scene reader (src/scene/) fills one from a TOML file; code can build one
// directly (make_scene).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "impact/methods/method_params.hpp"
#include "impact/model/model.hpp"
#include "impact/output/channels.hpp"

namespace impact {

// A scene is three plain parts, as in DifferentialEquations.jl's problem / algorithm / solve and
// Siconos's dynamical system + law / integrator: what the solution is of, how it is computed, and
// what a run writes of it. Code that needs one part takes that part (a Scene is each of them).

// The physics and its data: the model (floor, force, contact law) from an initial state over [0,
// T].
struct Problem {
  Model model;
  State initial;
  double T = 0.0;
};

// How it is solved: the method with its keys, on the grid t = l h (Grid::covering(T, h)).
struct Algorithm {
  MethodParams method;
  Grid grid;
};

// What a run writes: the channels of its rows, every k-th step (t = 0 and the last step always).
struct Output {
  std::vector<Channel> channels{Channel::u, Channel::v};
  std::int64_t every = 1;
};

struct Scene : Problem, Algorithm {
  Output output;
};

// A scene with the given data and the default output; the grid covers [0, T] by Grid::covering.
Scene make_scene(const Model& model, const State& initial, double T, double h,
                 const MethodParams& method);

}  // namespace impact
