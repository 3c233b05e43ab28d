// Lemma 4 (uniqueness) and its proof (4-11)-(4-13):
//  1. Under the lemma's assumption COR = 1, different solution paths approach one trajectory:
//     direct (grid-aligned impact, no COR, f = 0; COR = 1 given otherwise), moreau_jean (e = 1) and
//     the exact solution, as h -> 0; and exact solutions with perturbed data approach it as the
//     perturbation -> 0.
//  2. Without COR = 1, (2-1)-(2-4) alone do not fix the impact: the exact solutions with COR 1
//     and 1/2 (same data) are both weak solutions (weak_solution.hpp) and differ.
//  3. The proof's step (4-12) -> (4-13), evaluated on pairs of exact solutions.
//  4. The lemma's other condition, u_t^0 = 0 and u_t(t) = w_t(t) = 0 for some t, on two solutions
//     with v0 = 0 under gravity (COR 1 and sqrt(2) - 1) whose velocities vanish together at 2 t1.
//
// run_lemma4 writes to the results directory:
//   paths_<scene>.csv   h, sup |direct - moreau_jean|, sup |direct - exact|,
//                       sup |moreau_jean - exact| (scenes f0, f0_cor_1, gravity)
//   paths_f0_as_printed.csv  h, sup |direct with (5-1) as printed - exact| on f0
//   perturbation.csv    delta, sup |u_delta - u| for u0 + delta and v0 + delta, f = 0 and
//                       f = -9.80665 (exact, COR = 1)
//   pair_<name>.csv     t, u, w, u_t, w_t and the terms of (4-12) (pairs cor, elastic, condition1)
// and returns the numbers of experiments/lemma4/reference.toml.
#pragma once

#include <toml++/toml.h>

#include <cstddef>
#include <string>
#include <vector>

#include "analysis/experiment.hpp"
#include "analysis/fit.hpp"
#include "analysis/lemma4/energy_identity.hpp"
#include "analysis/step_sweep.hpp"
#include "impact/model/model.hpp"

namespace impact::lemma4 {

inline constexpr double kLemma4T = 10.0;  // the paper's T

// What run_lemma4 computes; the defaults are the experiment.
struct Lemma4Options {
  StepSweep free{2e-2, 1e-6, 16};     // the f = 0 path scenes
  StepSweep gravity{2e-2, 1e-5, 12};  // the gravity path scene
  // Only the h >= h_floor of each path scene are run (0: all): the first rows of the experiment,
  // for a test.
  double h_floor = 0;
};

// Part 1: a scene on which direct, moreau_jean and the exact solution run in lockstep.
struct PathScene {
  std::string name;
  Model model;
  State initial;
  std::vector<double> h;
};
// f0: u0 = 5, v0 = -1, f = 0, no COR, h = 5/m (the impact on the grid, where direct bounces
// elastically); f0_cor_1: u0 = 5.0123 (off the grid), COR = 1 given, so that direct resets the
// velocity by Newton's law; gravity: u0 = 5, f = -9.80665, COR = 1 given (under gravity direct
// keeps the impacts on the grid only by luck of rounding: a misalignment theta costs 2 theta of
// the speed and moves the next impact by 4 theta V/g, thousands of steps).
std::vector<PathScene> path_scenes(const Lemma4Options& options);

// sup over the grid of the distance of two methods' paths, for each h of a scene, and its order.
// Distances below 1e-8 m are two paths that coincide up to rounding (n eps |u| with n <= 5e6
// steps and |u| <= 5 m is about 5e-9 m): no power law, so they are left out of the fit and
// counted.
struct PathDistance {
  std::vector<double> sup;
  OrderFit fit;
  std::size_t coincident = 0;
};
struct PathRun {
  std::vector<double> h;
  PathDistance direct_mj, direct_exact, mj_exact;
};
PathRun run_paths(const PathScene& scene);

// direct with (5-1) evaluated step by step as printed (FreeFlightForm::paper) against the exact
// solution, on the f0 scene: the same discrete solution as direct's closed form in exact
// arithmetic, but each step's rounding moves u, and (4-2) passes it into v times 2 / h, so the
// impact that h = 5/m puts on the grid lands off it by rounding, and without COR the rebound loses
// 2 theta of its speed (Lemma 2.2): the first order of C26's grid-aligned case holds only for the
// closed form from the last contact.
PathDistance run_paths_as_printed(const PathScene& scene);

// Part 1: exact solutions (COR = 1) from u0 + delta or v0 + delta against the one from
// u0 = 5, v0 = -1, for delta = 1e-1 .. 1e-8: f0_u0, f0_v0 (f = 0), g_u0, g_v0 (gravity).
struct PerturbationRun {
  std::vector<double> delta;
  std::vector<double> f0_u0, f0_v0, g_u0, g_v0;  // sup over [0, T] of |u_delta - u|
};
PerturbationRun run_perturbation();

// Parts 3 and 4: two exact solutions u, w and the times at which the terms of (4-12) are kept.
struct SolutionPair {
  std::string name;
  Model model_u;
  State u0;
  Model model_w;
  State w0;
  double T;
  std::vector<double> at;
};
// cor: COR 1 against 1/2 from u0 = 5, v0 = -1, f = 0; elastic: u0 = 5 against 5.5 (COR 1,
// f = 0); condition1: COR 1 against sqrt(2) - 1 from u0 = 5, v0 = 0 under gravity.
std::vector<SolutionPair> solution_pairs();
// The terms of (4-12) at each time of pair.at (for the force of u's model).
std::vector<EnergyIdentity412> identities_at(const SolutionPair& pair);

// The whole experiment: its data files and the table of summary.toml.
toml::table run_lemma4(const ExperimentContext& context, const Lemma4Options& options);
toml::table run_lemma4(const ExperimentContext& context);

extern const Experiment kLemma4Experiment;

}  // namespace impact::lemma4
