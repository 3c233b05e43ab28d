// The event-driven reference of the two-mass chain (chain.hpp). Between impacts the motion is
// linear and known in closed form through its two modes, which for two masses need no eigensolver:
// the centre of mass falls freely, X'' = g, and the stretch d = x2 - x1 - ell oscillates,
// d'' = -w^2 d with w^2 = k (1/m1 + 1/m2) (the non-zero eigenvalue of M^-1/2 K M^-1/2). The lower
// mass's gap then obeys gap'' = g + c2 w^2 d(t), c2 = m2 / (m1 + m2): a constant plus a harmonic
// force, the flight of flight_search.hpp, whose certified search (search_contact: steps that cannot
// jump a root, then GSL's Brent on a bracket where the gap decreases strictly) finds each impact.
// At an impact Newton's law acts on the lower mass alone, x1'+ = -e x1'- (the one particle's law,
// restitution.md), x2' unchanged, with the impulse m1 (1 + e) |x1'-|.
// Not followed: a rest of the lower mass on the floor. With e = 1 there is none; with 0 < e < 1
// the impacts may accumulate (as the paper's particle's do) and then the run's impact budget runs
// out and it says so (NumericalError); e = 0 is refused. Tests use scenes without a rest.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "impact/chain.hpp"
#include "impact/model.hpp"

namespace impact {

struct ChainReferenceParams {
  double t_end = 0;  // the reference covers [0, t_end], t_end >= 0
  std::int64_t max_impacts = 1000000;
  long max_search_steps = 10000000;  // the certified steps of all the flights' searches
};

struct ChainImpact {
  double t = 0;
  double v_before = 0, v_after = 0;  // the lower mass's velocity
};

class ChainReference {
 public:
  // Throws std::invalid_argument for bad data (check_chain, check_chain_state), COR = 0 or a
  // t_end that is not finite and >= 0; NumericalError when a budget runs out.
  ChainReference(const Chain& chain, const ChainState& initial, const ChainReferenceParams& params);

  // State at t in [0, t_end]; at an impact instant the velocity after it (right-continuous).
  ChainState at(double t) const;
  // Contact impulse on the lower mass in (t0, t1]: the sum of its impacts' m1 (1 + e) |x1'-|.
  double impulse(double t0, double t1) const;
  const std::vector<ChainImpact>& impacts() const { return impacts_; }

 private:
  // A flight from t0 with the state s0 (positions as gaps q - phi) just after an impact.
  struct Flight {
    double t0 = 0;
    ChainState s0;
  };
  ChainState gaps_at(const Flight& flight, double t) const;

  Chain chain_;
  double e_, c1_, c2_, w_;  // COR, m1 / (m1 + m2), m2 / (m1 + m2), the stretch's frequency
  double t_end_;
  std::vector<Flight> flights_;
  std::vector<ChainImpact> impacts_;
};

// The reference as a stepper (stepper.hpp), sampled at t_l = l h, so that simulate() runs it as it
// runs ChainMoreauJean; initialize() computes the flights from t_l to params.t_end.
class ChainReferenceStepper {
 public:
  using StateType = ChainState;
  ChainReferenceStepper(const Chain& chain, double h, const ChainReferenceParams& params);
  void initialize(const ChainState& s, std::int64_t l);
  // contact_force = impulse in (t_l, t_{l+1}] / h.
  StepInfo do_step(ChainState& s, std::int64_t l);

 private:
  Chain chain_;
  double h_;
  ChainReferenceParams params_;
  std::int64_t start_ = 0;
  std::optional<ChainReference> reference_;  // once initialized
};

}  // namespace impact
