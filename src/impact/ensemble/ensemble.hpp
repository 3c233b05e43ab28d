// Many independent particles on one time grid (a parameter sweep: each particle has its own
// initial state, floor, force and COR), stepped together. The particles live in Eigen arrays; the
// step is the single-particle solver's own kernel (direct_step of direct.hpp, moreau_jean_step of
// moreau_jean.hpp) instantiated on vectors of 2, 4 or 8 lanes, so the compiler emits one SIMD
// instruction per operation for a whole vector of particles, and every particle ends bit-identical
// to the single-particle solver run on its own.
//
// Why not Eigen's expressions for the step itself: the kernel branches per particle (contact or
// free flight), and Eigen 3.4's select() is evaluated coefficient by coefficient, not vectorised
// (measured: 2.0-2.5 ns per particle-step with Eigen arrays and select(), against 0.3-0.8 ns with
// the vector types used here, see experiments/performance/README.md).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "impact/ensemble/summary_lanes.hpp"
#include "impact/model/model.hpp"

namespace impact {

// The methods whose step is a closed-form kernel the ensemble can vectorise.
enum class EnsembleMethod { direct, moreau_jean };

// What a summary keeps: the per-step quantities (contacts, impacts, the first impact, max u) or
// only what a final state needs (the finite check), which costs a few additions a step.
enum class SummaryDepth { final_state, per_step };

class Ensemble {
 public:
  using Column = Eigen::ArrayXd::ConstSegmentReturnType;

  // Particle i has models[i] and starts from initial[i] at t = 0; all share the step h (and, for
  // moreau_jean, theta, as in MoreauJeanParams). Throws std::invalid_argument when the sizes
  // differ, h is not positive and finite, theta is outside [0, 1], a COR outside [0, 1] or a
  // body force is not constant (constant_force of model.hpp).
  Ensemble(EnsembleMethod method, std::span<const Model> models, std::span<const State> initial,
           double h, double theta = 0.5);

  // Steps every particle from t_l to t_{l + steps}, l = steps_done().
  void advance(std::int64_t steps);

  Eigen::Index size() const { return size_; }
  std::int64_t steps_done() const { return steps_done_; }
  // The state at t_l, l = steps_done(), and N^{l-1} (0 before the first step), per particle.
  Column u() const { return u_.head(size_); }
  Column v() const { return v_.head(size_); }
  Column contact_force() const { return force_.head(size_); }
  State state(Eigen::Index i) const { return {u_[i], v_[i]}; }

  // From here on (before the first advance(), else std::logic_error) every step notes whether it
  // gave a non-finite u, v or N^l (where simulate() would have stopped) and, with
  // SummaryDepth::per_step, also updates each particle's summary (summary_lanes.hpp) as a
  // SummaryObserver does for one particle; with final_state summary() is left at its start.
  void keep_summary(SummaryDepth depth = SummaryDepth::per_step);
  SummaryLanes<double> summary(Eigen::Index i) const;
  bool failed(Eigen::Index i) const { return !std::isfinite(poison_[i]); }

  // The vector code advance() runs: "avx512f" (8 lanes), "avx2" (4 lanes) or "baseline" (2 lanes,
  // SSE2 on x86-64). The constructor picks the widest this processor supports; use() picks
  // another one of supported_instruction_sets() (all give the same bits), else throws
  // std::invalid_argument.
  std::string_view instruction_set() const;
  static std::vector<std::string_view> supported_instruction_sets();
  void use(std::string_view instruction_set);

 private:
  EnsembleMethod method_;
  double h_, theta_;
  int level_;                   // index of the instruction set, see ensemble.cpp
  Eigen::Index size_, padded_;  // padded_: a whole number of blocks of every instruction set
  std::int64_t steps_done_ = 0;
  // Per particle, padded with resting particles to a whole number of vector blocks.
  Eigen::ArrayXd phi_, f_, cor_;  // cor_: RestitutionRule::cor of the contact law (restitution.hpp)
  Eigen::Array<std::int64_t, Eigen::Dynamic, 1> has_cor_;  // -1 where Newton's law acts
  // RestitutionRule::fixed_point (restitution.hpp), -1 where Newton's law does not act
  Eigen::Array<std::int64_t, Eigen::Dynamic, 1> fixed_point_;
  Eigen::ArrayXd gap_, v_, force_;  // gap u - phi, as the kernels step it
  Eigen::ArrayXd u_;  // the initial u, then phi + gap after each advance(), as the solvers return u
  Eigen::ArrayXd anchor_gap_, anchor_v_, since_;  // direct's free-flight anchor (DirectLanes)
  // The summary (empty unless keep_summary()): the fields of SummaryLanes, and the poison (see
  // ensemble.cpp), finite while every step was.
  bool summarize_ = false, per_step_ = false;
  Eigen::ArrayXd steps_, episodes_, run_, max_u_, first_l_, first_u_, first_v_, poison_;
};

}  // namespace impact
