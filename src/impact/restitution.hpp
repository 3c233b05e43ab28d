// Section 5.2: "we must alter the velocity at the instant that the particle is in contact with the
// surface", COR = -v_a / v_b. Read as (paper_notes/restitution.md): on a step that ends in contact,
// the contact force N^l stays the one the complementarity solve gives (the paper says COR "has no
// effect on the results of the contact force"), and the velocity after the step is overwritten by
// v^{l+1} = -COR v^l, with v_b = v^l the last velocity before contact. Without COR the scheme's own
// velocity (4-2) is kept.
#pragma once

#include "impact/model.hpp"

namespace impact {

inline double velocity_after_contact(const Model& model, double v_before, double v_scheme) {
  return model.cor ? -*model.cor * v_before : v_scheme;
}

}  // namespace impact
