// Section 4's existence proof, measured along one run of a scheme: the discrete quantities the
// proof passes to the limit h -> 0 (the impulse sum of (4-9), the complementarity sum of (4-10),
// the energy drop of (4-6)) and each contact episode with the coefficient of restitution the
// scheme realised, tallied from the same run that measure_errors() compares with the exact
// solution.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "impact/model/contact.hpp"
#include "impact/model/model.hpp"
#include "impact/run/error_norms.hpp"
#include "impact/run/scene.hpp"

namespace impact::convergence {

// The discrete quantities of Section 4, summed over the steps l = 0..n-1 of a run.
struct ProofTallies {
  double impulse = 0;                    // h sum N^l: the left side of (4-9)
  double complementarity = 0;            // h sum N^l (u^{l+1} - phi): (4-10), 0 by (4-3)
  double energy_drop = 0;                // sum N^l (u^l - phi): E^0 - E^n by (4-6) (without COR)
  State last;                            // u^n, v^n: the state after the last step
  std::vector<ContactEpisode> episodes;  // the first kMaxEpisodes only (contact.hpp)
  static constexpr std::size_t kMaxEpisodes = 64;
};

// Wraps a stepper and tallies ProofTallies from what each step reports; it is itself a stepper,
// so measure_errors() can run it and the errors and the tallies come from one and the same run.
template <class Stepper>
class TallyingStepper {
 public:
  TallyingStepper(Stepper& inner, const Model& model, double h, ProofTallies& tallies)
      : inner_(inner), model_(model), h_(h), tallies_(tallies) {}

  void initialize(const State& s, std::int64_t l) {
    inner_.initialize(s, l);
    contacts_ = ContactDetector(model_, h_, ProofTallies::kMaxEpisodes);
  }

  StepInfo do_step(State& s, std::int64_t l) {
    const State before = s;
    const StepInfo info = inner_.do_step(s, l);
    const double N = scheme_force(info), phi = model_.phi;
    tallies_.impulse += h_ * N;
    tallies_.complementarity += h_ * N * (s.u - phi);
    tallies_.energy_drop += N * (before.u - phi);
    if (contacts_.add_step(l, before, s, N)) {  // mirror the detector's episodes in the tallies
      const std::vector<ContactEpisode>& found = contacts_.episodes();
      if (found.size() > tallies_.episodes.size())
        tallies_.episodes.push_back(found.back());
      else if (!found.empty())
        tallies_.episodes.back() = found.back();
    }
    tallies_.last = s;
    return info;
  }

 private:
  Stepper& inner_;
  Model model_;
  double h_;
  ProofTallies& tallies_;
  ContactDetector contacts_{model_, h_, ProofTallies::kMaxEpisodes};
};

// One run of a scene on [0, T] against the exact solution, with the tallies of the proof.
struct ConvergencePoint {
  double h = 0;
  double t_end = 0;  // n h, the last grid time (>= T)
  State initial, final;
  double f = 0;
  ErrorNorms errors;
  ProofTallies tallies;
  // (4-9) as printed: h sum N^l - (v^n - v^0); omits the body force.
  double impulse_residual_printed() const { return tallies.impulse - (final.v - initial.v); }
  // (4-9) with the body force: h sum N^l - (v^n - v^0 - f t_n).
  double impulse_residual_corrected() const {
    return tallies.impulse - (final.v - initial.v - f * t_end);
  }
  // E^0 - E^n, to compare with the energy drop sum N^l (u^l - phi) of (4-6).
  double energy_loss(const Model& model) const {
    return energy(model, initial) - energy(model, final);
  }
  // The first impact's fraction theta of its step flown before the floor and its effective COR
  // (contact.hpp); NaN when the run has no contact step.
  double first_theta() const {
    return tallies.episodes.empty() ? std::nan("") : tallies.episodes.front().flight_fraction;
  }
  double first_cor() const {
    return tallies.episodes.empty() ? std::nan("") : tallies.episodes.front().effective_cor();
  }
};

// Runs the scene and measures its errors against the exact solution of `reference` (the scene's
// own model when absent; another one to ask which solution of (2-1)-(2-4) a sequence of runs
// approaches).
ConvergencePoint measure_convergence(const Scene& scene,
                                     const std::optional<Model>& reference = std::nullopt);

}  // namespace impact::convergence
