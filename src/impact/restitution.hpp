// Section 5.2: "we must alter the velocity at the instant that the particle is in contact with the
// surface", COR = -v_a / v_b. Read as (paper_notes/restitution.md): on a step whose complementarity
// solve gives a contact force, N^l > 0, the force stays the one the solve gives (the paper says COR
// "has no effect on the results of the contact force"), and the velocity after the step is
// overwritten by v^{l+1} = -COR v^l, with v_b = v^l the last velocity before contact. A step that
// ends exactly on the floor with N^l = 0 is not an impact yet: the impulse, and the COR, come in
// the next step, as without COR. Without COR the scheme's own velocity (4-2) is kept.
#pragma once

namespace impact {

// Real is double (Mask = bool) or a vector of lanes (Mask its comparison result), so that direct
// and its ensemble share this one rule (see direct.hpp). The result is written through `v_after`
// because a function returning a vector type would change the ABI between instruction sets.
// A comparison of vectors gives lanes of long under GCC and of long long under clang, so the
// contact mask is converted to the type of has_cor (same size, same bits) before they are combined.
template <class Real, class Mask, class Comparison>
void velocity_after_step(const Mask& has_cor, const Real& cor,
                         const Comparison& contact_force_positive, const Real& v_before,
                         const Real& v_scheme, Real& v_after) {
  v_after = (has_cor & (Mask)contact_force_positive) ? -cor * v_before : v_scheme;
}

}  // namespace impact
