// What the floor does to the particle: the contact law, as a value (in the spirit of Siconos's
// non-smooth law), read from the Model in one place, contact_law() below. Each stepper resolves
// it once in its constructor into the members its step uses, so the step loop reads no law.
//
// The paper's contact is Signorini's (2-2), 0 <= u - phi ⟂ N >= 0, which says nothing of the
// velocity after an impact; Section 5.2 adds Newton's impact law through a coefficient of
// restitution, COR = -v_a / v_b in [0, 1] ("we must alter the velocity at the instant that the
// particle is in contact with the surface"), and Section 5's normal compliance replaces (2-2) by a
// force N = c_N max(phi - u, 0). A scene's floor.cor states Newton's law; without it, what the
// floor does is each family of methods' own reading, stated here once:
//
//   family                                 without floor.cor        with floor.cor = e
//   the paper's scheme (4-1)-(4-3):        SchemeLaw                NewtonLaw{e}
//     direct, fb_newton
//   event-driven and velocity-level:       NewtonLaw{1}             NewtonLaw{e}
//     exact, event_driven, moreau_jean,    (kElasticReading)
//     direct_located
//   normal compliance: penalty             ComplianceLaw{c_N}       refused
//
// SchemeLaw is "no restitution law": the scheme's own velocity (4-2) on a contact step, the
// complementarity (4-3) read at position level, which is not elastic on the grid (an effective COR
// |1 - 2 theta|, theta the fraction of the step left before the floor, paper_notes/restitution.md):
// the paper's Figures 3 and 4, left columns. It is not NewtonLaw{1}: direct with COR = 1 and
// direct without COR are different motions. The event-driven readings without COR are elastic,
// e = 1, the case in which Lemma 1 conserves energy and Lemma 4 proves uniqueness; for them
// COR = 1 and no COR are the same law, bit for bit.
//
// Adhesion (a floor that also pulls, N >= -a) would be one more alternative; no method reads one
// today, so it is not built.
#pragma once

#include <stdexcept>
#include <variant>

#include "impact/model/model.hpp"

namespace impact {

// No restitution law: the complementarity (4-3) as the paper's scheme solves it, velocity (4-2).
struct SchemeLaw {
  bool operator==(const SchemeLaw&) const = default;
};

// Newton's impact law v+ = -e v- (Section 5.2), e in [0, 1].
struct NewtonLaw {
  double e = 1.0;
  bool operator==(const NewtonLaw&) const = default;
};

// Normal compliance N = c_N max(phi - u, 0) (Section 5), c_N = stiffness > 0: its own impact law,
// elastic, with no velocity jump for a COR to act on.
struct ComplianceLaw {
  double stiffness = 0.0;
  bool operator==(const ComplianceLaw&) const = default;
};

using ContactLaw = std::variant<SchemeLaw, NewtonLaw, ComplianceLaw>;

// What the event-driven and velocity-level methods read without a COR: the elastic limit.
inline constexpr NewtonLaw kElasticReading{1.0};

// The law a method whose law without COR is `without_cor` (its family's reading, above) applies
// to the model's floor: NewtonLaw{COR} when the floor gives a COR, else `without_cor`. Throws
// std::invalid_argument for a COR given to a compliance law, which has no impact to apply it to.
inline ContactLaw contact_law(const Model& model, const ContactLaw& without_cor) {
  if (!model.cor) return without_cor;
  if (std::holds_alternative<ComplianceLaw>(without_cor))
    throw std::invalid_argument("normal compliance has no restitution law: it cannot take a COR");
  return NewtonLaw{*model.cor};
}

// The e of a law that is Newton's; std::logic_error for any other (a method of the elastic
// reading always has one).
inline double newton_e(const ContactLaw& law) {
  if (const auto* newton = std::get_if<NewtonLaw>(&law)) return newton->e;
  throw std::logic_error("newton_e: the contact law is not Newton's impact law");
}

}  // namespace impact
