// The parts of Figure 4's verdicts (Section 5.2) that hinge on how the paper is read or evaluated
// rather than on the model, each measured against the alternative:
// - C10: the rest time without COR with (5-1) evaluated in closed form (our `direct`) and term by
//   term as printed (free_flight = "paper", free_flight.hpp), at h = 1e-3 and over the ensemble of
//   u0 moved by <= 200 ulps;
// - C12: the rest time with COR = 0.75 under the alternative COR reading v^{l+1} = COR v_scheme
//   (the scheme's own rebound (4-2) scaled), against ours, v^{l+1} = -COR v^l (restitution.md);
// - C32: the energy change on the contact step of a particle pushed away from the floor
//   (f = +9.80665) over h, with COR = 1 and with the paper's COR = 0.75.
#pragma once

#include <toml++/toml.h>

#include <optional>
#include <vector>

#include "analysis/rest.hpp"
#include "impact/run/scene.hpp"

namespace impact::figure4 {

// C32's scene: u0 = 0.01 m, v0 = -1 m/s, f = +9.80665 m/s^2 (away from the floor), phi = 0,
// T = 0.05 s: one impact near t = 0.0101 s, then the particle flies off.
struct ContactStepEnergy {
  double h = 0;
  double change[2] = {0, 0};     // E^{l+1} - E^l on the contact step, [COR = 1, COR = 0.75]
  double predicted[2] = {0, 0};  // -(1 - COR^2) (v^l)^2/2 + f (u^l - phi) at that step
  double before[2] = {0, 0};     // E^l on that step (E(0) = 0.5 - 0.0981 = 0.4019 J/kg)
};
inline constexpr double kContactStepCor[2] = {1.0, 0.75};

struct Figure4Readings {
  std::optional<double> paper_rest;                   // C10: as printed, unperturbed
  std::vector<std::optional<double>> paper_ensemble;  // C10: as printed, per ensemble member
  RestAnalysis scaled_rebound;                        // C12: v^{l+1} = COR v_scheme, h = 1e-3
  std::vector<ContactStepEnergy> contact_energy;      // C32: h = 10^-(2 + k/4), k = 0..12
};

// no_cor and cor075 are Figure 4's scenes (method direct, h = 1e-3); ensemble_u0 the perturbed
// u0 of Figure4Data.
Figure4Readings figure4_readings(const Scene& no_cor, const Scene& cor075,
                                 const std::vector<double>& ensemble_u0);

// Sorted rest times, +inf for a member that still bounces at T.
std::vector<double> sorted_rest_times(const std::vector<std::optional<double>>& rest);

// Keys for summary.toml: the as-printed rest time into [no_cor], its ensemble spread into
// [ensemble], the alternative-reading rest time into [cor075], and the table [contact_energy].
void add_readings_summary(const Figure4Readings& r, toml::table& summary);

// contact_energy.csv: h, the energy change and its prediction for COR = 1 and 0.75.
std::string contact_energy_csv(const Figure4Readings& r);

}  // namespace impact::figure4
