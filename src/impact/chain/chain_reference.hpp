// The event-driven reference of the two-mass chain (chain.hpp). Between impacts the motion is
// linear and known in closed form through its two modes, which for two masses need no eigensolver:
// the centre of mass falls freely, X'' = g, and the stretch d = x2 - x1 - ell oscillates,
// d'' = -w^2 d with w^2 = k (1/m1 + 1/m2) (the non-zero eigenvalue of M^-1/2 K M^-1/2). The lower
// mass's gap then obeys gap'' = g + c2 w^2 d(t), c2 = m2 / (m1 + m2): a constant plus a harmonic
// force, the flight of flight_search.hpp, whose certified search (search_contact: steps that cannot
// jump a root, then GSL's Brent on a bracket where the gap decreases strictly) finds each impact.
// At an impact Newton's law acts on the lower mass alone, x1'+ = -e x1'- (the one particle's law,
// restitution.md), x2' unchanged, with the impulse m1 (1 + e) |x1'-|.
//
// Rest (chain_rest.hpp). A lower mass on the floor with zero speed (after an impact with e = 0, a
// cut-off accumulation, or at the start) rests there while the floor's push N = -(m1 g + k d) is
// >= 0: x1 = phi, x1' = 0, the upper mass oscillating in closed form. With N < 0 (or N = 0
// decreasing) it leaves at once, with zero speed, and the flight's first stretch is certified by
// chain_departure(). A rest ends at the lift-off, the first time N reaches 0 decreasing, found by
// the certified search of flight_search.hpp on N and refined by GSL's Brent; the flight resumes
// from there. During a rest the floor's impulse is the integral of N, which the upper mass's
// momentum gives in closed form: m2 (x2'(b) - x2'(a)) - (m1 + m2) g (b - a).
//
// Accumulation (0 < e < 1). Impacts accumulate as the particle's do, t_inf = t_k + 2 e V_k /
// (p (1 - e)) for a constant push per unit mass p = -(g + (k / m1) d). The reference cuts the
// sequence off as the particle's exact track does (exact_march.hpp): at an impact whose speed V is
// below kChatterCutoff (1e-8) times the largest impact speed seen, when chain_chatter_window()
// certifies that all further impacts lie within a window W after it and the lower mass rests
// after them, that impact is made plastic and the rest starts there. The reference then differs
// from the exact solution only inside that window: by at most the bounce height (e V)^2 / (2 p_min)
// (~1e-16 of the drop height Vmax^2 / (2 p): the positions' rounding) in x1, e V in x1', and in the
// upper mass by what the spring passes on from x1 over W; its rest starts up to W before t_inf
// (W ~ 2e-8 e / (1 - e) of a drop's duration). Without a certificate the impacts are followed one
// by one, up to the run's impact budget (NumericalError when it runs out). e = 1 has no
// accumulation; e = 0 makes every impact plastic.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "impact/chain/chain.hpp"
#include "impact/model/model.hpp"

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

// A rest of the lower mass on the floor, on [t, lift); lift is infinity when it lasts past t_end.
struct ChainRest {
  double t = 0;
  double lift = std::numeric_limits<double>::infinity();
};

class ChainReference {
 public:
  // Throws std::invalid_argument for bad data (check_chain, check_chain_state) or a t_end that is
  // not finite and >= 0; NumericalError when a budget runs out or the lower mass reaches the floor
  // with zero speed and zero contact force changing neither way (which way it goes is undecided).
  ChainReference(const Chain& chain, const ChainState& initial, const ChainReferenceParams& params);

  // State at t in [0, t_end]; at an impact instant the velocity after it (right-continuous).
  ChainState at(double t) const;
  // Contact impulse on the lower mass in (t0, t1]: its impacts' m1 (x1'+ - x1'-) and the integral
  // of N over its rests.
  double impulse(double t0, double t1) const;
  // The floor's push N on the lower mass at t during a rest, 0 in flight (impacts not counted).
  double contact_force(double t) const;
  const std::vector<ChainImpact>& impacts() const { return impacts_; }
  const std::vector<ChainRest>& rests() const { return rests_; }

 private:
  // A flight or a rest from t0 with the state s0 (positions as gaps q - phi); a flight has no
  // contact before `certified`.
  struct Segment {
    double t0 = 0;
    ChainState s0;
    bool resting = false;
    double certified = 0;
  };
  ChainState gaps_at(const Segment& segment, double t) const;
  const Segment& segment_at(double t) const;
  // The next event after the last segment: an impact (with a flight or a rest after it) or a
  // lift-off; false when there is none before t_end.
  bool next_impact(const ChainReferenceParams& params, long& budget);
  bool next_lift(const ChainReferenceParams& params, long& budget);
  // A lower mass on the floor with zero speed at t in the state s (gaps): a rest, or a flight.
  void settle(double t, const ChainState& s);

  Chain chain_;
  double e_, c1_, c2_, w_;  // COR, m1 / (m1 + m2), m2 / (m1 + m2), the stretch's frequency
  double t_end_;
  double fastest_ = 0;  // the largest impact speed so far, for the cut-off of an accumulation
  std::vector<Segment> segments_;
  std::vector<ChainImpact> impacts_;
  std::vector<ChainRest> rests_;
};

// The reference as a stepper (stepper.hpp), sampled at t_l = l h, so that simulate() runs it as it
// runs ChainMoreauJean; initialize() computes the flights and rests from t_l to params.t_end.
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
