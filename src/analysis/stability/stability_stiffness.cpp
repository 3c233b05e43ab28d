#include "analysis/stability/stability_stiffness.hpp"

#include <cmath>
#include <stdexcept>

#include "impact/output/csv.hpp"
#include "impact/run/scene.hpp"

namespace impact::stability {
namespace {

// The resting-contact runs last kRestT; a run may take kStiffBudget ODE steps (1e6 per second of
// simulated time), beyond which the stepper is counted as not usable at that c_N.
constexpr double kRestT = 0.1;
constexpr std::int64_t kStiffBudget = 100'000;
constexpr double kStep = 1e-3;
const std::vector<std::string> kStepMapSteppers = {"rk8pd", "msbdf"};

StiffnessCell bounce_cell(std::size_t i, int log_c) {
  const std::string& stepper = stiffness_steppers()[i].name;
  const double c_N = std::pow(10.0, log_c);
  // u0 = 1: two impacts in T = 2.
  return {i, log_c, false, run_stiff(penalty_scene(stepper, c_N, {1, 0}, 2, kStep), kStiffBudget),
          resolve_contact(stepper, c_N)};
}

StiffnessCell rest_cell(std::size_t i, int log_c) {
  const std::string& stepper = stiffness_steppers()[i].name;
  const Scene scene = penalty_scene(stepper, std::pow(10.0, log_c), {0, 0}, kRestT, kStep);
  return {i, log_c, true, run_stiff(scene, kStiffBudget), {}};
}

bool finished(const StabilityRun& run) {
  return run.check.outcome == Outcome::ok || run.check.outcome == Outcome::inaccurate;
}

}  // namespace

const std::vector<OdeStepper>& stiffness_steppers() {
  static const std::vector<OdeStepper> steppers = {
      {"rk8pd", false}, {"rkf45", false}, {"rkck", false}, {"msadams", false},
      {"msbdf", true},  {"rk4imp", true}, {"bsimp", true},
  };
  return steppers;
}

StiffnessStudy StiffnessStudy::run(const std::vector<int>& bounce_exponents,
                                   const std::vector<int>& rest_exponents) {
  StiffnessStudy study;
  const std::size_t n = stiffness_steppers().size();
  for (std::size_t i = 0; i < n; ++i)
    for (const int k : bounce_exponents) study.cells_.push_back(bounce_cell(i, k));
  for (std::size_t i = 0; i < n; ++i)
    for (const int k : rest_exponents) study.cells_.push_back(rest_cell(i, k));
  return study;
}

const StiffnessCell& StiffnessStudy::find(const std::string& stepper, int log_c, bool rest) const {
  for (const StiffnessCell& cell : cells_)
    if (stiffness_steppers()[cell.stepper].name == stepper && cell.log_c == log_c &&
        cell.rest == rest)
      return cell;
  throw std::out_of_range("stiffness study: no " + std::string(rest ? "rest" : "bounce") +
                          " run of " + stepper + " at c_N = 1e" + std::to_string(log_c));
}

const StiffnessCell& StiffnessStudy::bounce(const std::string& stepper, int log_c) const {
  return find(stepper, log_c, false);
}

const StiffnessCell& StiffnessStudy::rest(const std::string& stepper, int log_c) const {
  return find(stepper, log_c, true);
}

double StiffnessStudy::rest_limit(const std::string& stepper) const {
  double limit = 0;
  for (const StiffnessCell& cell : cells_)
    if (cell.rest && stiffness_steppers()[cell.stepper].name == stepper && finished(cell.run.run))
      limit = std::pow(10.0, cell.log_c);
  return limit;
}

std::string StiffnessStudy::csv() const {
  std::string text =
      "stepper,implicit,c_N,scene,energy_drift,penetration,penetration_exact,duration,"
      "duration_exact,impulse," +
      std::string(kStabilityRunColumns);
  for (const StiffnessCell& cell : cells_) {
    const OdeStepper& st = stiffness_steppers()[cell.stepper];
    const ContactResolution& c = cell.contact;
    text += stability_csv_row(
        st.name + "," + (st.implicit ? "1" : "0") + "," + round_trip(std::pow(10.0, cell.log_c)) +
            "," + (cell.rest ? "rest" : "bounce") + "," + round_trip(cell.run.energy_drift) + "," +
            round_trip(c.penetration) + "," + round_trip(c.penetration_exact) + "," +
            round_trip(c.duration) + "," + round_trip(c.duration_exact) + "," +
            round_trip(c.impulse),
        cell.run.run);
  }
  return text;
}

std::string StiffnessStudy::dat() const {
  std::string text = "# scene_index stepper_index log10_c_N code\n";
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const StiffnessCell& cell = cells_[i];
    text += map_point({cell.rest ? 1 : 0, static_cast<int>(cell.stepper), cell.log_c},
                      cell.run.run.check.outcome);
    if (i + 1 == cells_.size() || cells_[i + 1].rest != cell.rest) text += "\n\n";
  }
  return text;
}

PenaltyStepMap PenaltyStepMap::run() {
  PenaltyStepMap map;
  for (std::size_t i = 0; i < kStepMapSteppers.size(); ++i)
    for (int log_c = kLogStiffnessMin; log_c <= kLogStiffnessMax; ++log_c)
      for (int log_h = -6; log_h <= -1; ++log_h) {
        const double h = std::pow(10.0, log_h), T = std::fmin(kRestT, kMaxPenaltySteps * h);
        const Scene scene = penalty_scene(kStepMapSteppers[i], std::pow(10.0, log_c), {0, 0}, T, h);
        map.cells.push_back({i, log_c, log_h, run_stability_check(scene, {kStiffBudget, {}})});
      }
  return map;
}

std::string PenaltyStepMap::csv() const {
  std::string text = "stepper,c_N," + std::string(kStabilityRunColumns);
  for (const Cell& cell : cells)
    text += stability_csv_row(
        kStepMapSteppers[cell.stepper] + "," + round_trip(std::pow(10.0, cell.log_c)), cell.run);
  return text;
}

std::string PenaltyStepMap::dat() const {
  std::string text = "# stepper_index log10_c_N log10_h code\n";
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Cell& cell = cells[i];
    text +=
        map_point({static_cast<int>(cell.stepper), cell.log_c, cell.log_h}, cell.run.check.outcome);
    if (i + 1 == cells.size() || cells[i + 1].stepper != cell.stepper) text += "\n\n";
  }
  return text;
}

}  // namespace impact::stability
