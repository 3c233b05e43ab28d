// Section 5.2: "we must alter the velocity at the instant that the particle is in contact with the
// surface", COR = -v_a / v_b. Read as (paper_notes/restitution.md): on a step whose complementarity
// solve gives a contact force, N^l > 0, the force stays the one the solve gives (the paper says COR
// "has no effect on the results of the contact force"), and the velocity after the step is
// overwritten by v^{l+1} = -COR v^l, with v_b = v^l the last velocity before contact. A step that
// ends exactly on the floor with N^l = 0 is not an impact yet: the impulse, and the COR, come in
// the next step, as without COR. Without COR the scheme's own velocity (4-2) is kept.
//
// A particle resting on the floor takes a contact step at every step, so the rule multiplies v by
// -COR again and again: v decays into the subnormal range and ends on a fixed point of the rounded
// product (COR = 0.75: |v| = 2^-1073 = 2 units of 2^-1074, since 0.75 * 2 units rounds back to 2
// units; the sign flips at each step). On Intel processors every multiply with a subnormal operand
// or result takes a microcode assist (an Intel Xeon, family 6 model 167: 34 ns of CPU instead of
// 0.5 ns, experiments/performance/README.md), which made a resting particle 10x as costly as a
// flying one. So the rule does not form the product where it knows the result: for |v| at most
// the largest subnormal fixed point of this COR (restitution_fixed_point), -COR v is -v bit for
// bit, a sign flip. Every other v is multiplied as before; the results are the same bits.
#pragma once

#include <cstdint>
#include <cstring>

#include "impact/model/contact_law.hpp"
#include "impact/model/model.hpp"

namespace impact {

// The largest m < 2^52 such that the rounded product -COR v is -v, bit for bit, for every
// v = +-k 2^-1074, k = 0..m (the subnormals and zero up to m units), as this processor rounds it;
// -1 when not even +-0 maps to its negative (COR negative or not a number).
std::int64_t restitution_fixed_point(double cor);

// A contact law as the rule below reads it (direct, fb_newton, the ensemble): whether Newton's law
// acts (has_cor), its COR (0 where it does not act, never read there) and restitution_fixed_point
// of it (-1 where it does not act). In this order, the members the steppers kept before the law
// was a value, so that their step reads the same layout.
struct RestitutionRule {
  double cor = 0.0;
  bool has_cor = false;
  std::int64_t fixed_point = -1;
};

inline RestitutionRule restitution_rule(const ContactLaw& law) {
  const auto* newton = std::get_if<NewtonLaw>(&law);
  if (!newton) return {};
  return {newton->e, true, restitution_fixed_point(newton->e)};
}

// A step on which Newton's law acted (has_cor and N^l > 0), whose info holds N^l of (4-3): the
// contact impulse over h becomes the jump of the velocity over where the free flight would have
// ended, (v_after - v_free) / h = (v^{l+1} - v^l - h f^l) / h, so that h sum N = v^n - v^0 - int f
// holds with a COR too; N^l is kept beside it as the scheme's force.
inline void restitute(StepInfo& info, double v_after, double v_free, double h) {
  info.scheme_force = info.contact_force;
  info.restituted = true;
  info.contact_force = (v_after - v_free) / h;
}

// Real is double (Mask = bool, Bits = std::int64_t) or a vector of lanes (Mask and Bits its
// integer vector), so that direct and its ensemble share this one rule (see direct.hpp). The
// result is written through `v_after` because a function returning a vector type would change the
// ABI between instruction sets. `fixed_point` is restitution_fixed_point(cor). A comparison of
// vectors gives lanes of long under GCC and of long long under clang, so the contact mask is
// converted to the type of has_cor (same size, same bits) before they are combined.
template <class Real, class Mask, class Bits, class Comparison>
[[gnu::always_inline]] inline void velocity_after_step(const Mask& has_cor, const Real& cor,
                                                       const Bits& fixed_point,
                                                       const Comparison& contact_force_positive,
                                                       const Real& v_before, const Real& v_scheme,
                                                       Real& v_after) {
  // |v| as the bits of a double: an integer that orders like |v|.
  Bits magnitude;
  std::memcpy(&magnitude, &v_before, sizeof magnitude);
  const auto fixed = (magnitude & 0x7fffffffffffffff) <= fixed_point;
  // The product sees 0 instead of a fixed point, so that it never has a subnormal operand there.
  const Real product = -cor * (fixed ? Real{} : v_before);
  const Real restituted = fixed ? -v_before : product;
  v_after = (has_cor & (Mask)contact_force_positive) ? restituted : v_scheme;
}

}  // namespace impact
