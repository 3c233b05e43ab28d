// Penalty as c_N grows (experiments/stability): seven GSL steppers over c_N = 1e2 .. 1e12 on a
// bounce (u0 = 1, T = 2 s, with its first contact resolved finely) and in resting contact
// (u0 = phi, T = 0.1 s), at h = 1e-3; and rk8pd and msbdf over c_N x h in resting contact.
#pragma once

#include <string>
#include <vector>

#include "analysis/stability/stability_penalty.hpp"

namespace impact::stability {

struct OdeStepper {
  std::string name;
  bool implicit;
};
const std::vector<OdeStepper>& stiffness_steppers();

// c_N = 10^k for k from kLogStiffnessMin to kLogStiffnessMax.
constexpr int kLogStiffnessMin = 2, kLogStiffnessMax = 12;

// One stepper at one c_N: the bounce (with its first contact) or resting contact.
struct StiffnessCell {
  std::size_t stepper = 0;  // index into stiffness_steppers()
  int log_c = 0;
  bool rest = false;
  StiffRun run;
  ContactResolution contact;  // the bounce's first contact; default for resting contact
};

class StiffnessStudy {
 public:
  // Every stepper on the bounce at c_N = 10^k, k in bounce_exponents, and in resting contact at
  // k in rest_exponents (ascending).
  static StiffnessStudy run(const std::vector<int>& bounce_exponents,
                            const std::vector<int>& rest_exponents);
  const StiffnessCell& bounce(const std::string& stepper, int log_c) const;
  const StiffnessCell& rest(const std::string& stepper, int log_c) const;
  // The largest c_N of the sweep at which the stepper finished resting contact within its
  // budget; 0 when none.
  double rest_limit(const std::string& stepper) const;

  std::string csv() const;  // stiff.csv
  std::string dat() const;  // map_stiff.dat: scene_index stepper_index log10_c_N code

 private:
  const StiffnessCell& find(const std::string& stepper, int log_c, bool rest) const;
  std::vector<StiffnessCell> cells_;  // bounce then rest, stepper, c_N ascending
};

// rk8pd (explicit) and msbdf (implicit) in resting contact over c_N x h (h = 1e-6 .. 0.1).
struct PenaltyStepMap {
  struct Cell {
    std::size_t stepper;
    int log_c, log_h;
    StabilityRun run;
  };
  std::vector<Cell> cells;

  static PenaltyStepMap run();
  std::string csv() const;  // penalty_h.csv
  std::string dat() const;  // map_penalty.dat: stepper_index log10_c_N log10_h code
};

}  // namespace impact::stability
