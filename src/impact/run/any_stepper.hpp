// The solvers chosen at run time: one variant over every method's stepper types, built from a
// method's parameters (make_stepper), and the time loop and event sink over it. Included where a
// method is chosen by name (the run of a scene, the CLI, the analyses, the tests); the plain data
// (method_params.hpp, capabilities.hpp, scene.hpp) includes no stepper.
#pragma once

#include <variant>

#include "impact/loop/simulate.hpp"
#include "impact/loop/stepper.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/methods/method_params.hpp"
#include "impact/model/event.hpp"
#include "impact/model/model.hpp"
#include "impact/references/event_driven.hpp"
#include "impact/references/exact.hpp"
#include "impact/references/exact_bonded.hpp"
#include "impact/run/scene.hpp"
#include "impact/steppers/direct.hpp"
#include "impact/steppers/direct_located.hpp"
#include "impact/steppers/fb_newton.hpp"
#include "impact/steppers/moreau_jean.hpp"
#include "impact/steppers/penalty.hpp"
#include "impact/steppers/with_internal.hpp"

namespace impact {

// One stepper type per method, and per force kind for the time-steppers direct and moreau_jean
// (ForceKind, force.hpp; direct.hpp says why types and not branches): Direct and MoreauJean for a
// constant force, DirectHarmonic and MoreauJeanHarmonic for a harmonic one, DirectGeneral and
// MoreauJeanGeneral (with_internal.hpp) for any other, with the internal variables if any;
// DirectAsPrinted is `direct` with (5-1) as printed. A new force or law is a runtime value inside
// a kind and never adds an alternative; only a new method does (ARCHITECTURE.md).
using AnyStepper = std::variant<Direct, FbNewton, MoreauJean, Penalty, ExactStepper, EventDriven,
                                DirectHarmonic, DirectGeneral, MoreauJeanHarmonic,
                                MoreauJeanGeneral, DirectAsPrinted, DirectLocated, ExactBonded>;
static_assert([]<class... S>(std::variant<S...>*) { return (Stepper<S> && ...); }(
                  static_cast<AnyStepper*>(nullptr)),
              "every method's stepper has the interface of stepper.hpp");

// The solver for one model and step; throws std::invalid_argument for parameters out of range
// and with refusal()'s message for a problem the method refuses (a COR given to penalty).
AnyStepper make_stepper(const Model& model, double h, const MethodParams& params);

// The scene's solver: make_stepper for its model, step and method, with event_driven told the
// scene's end.
AnyStepper make_stepper(const Scene& scene);

template <class Observer>
RunSummary simulate(AnyStepper& stepper, const State& initial, const Grid& grid,
                    Observer&& observe) {
  return std::visit([&](auto& s) { return simulate(s, initial, grid, observe); }, stepper);
}

// attach_event_sink (step_events.hpp) for the stepper the variant holds.
bool attach_event_sink(AnyStepper& stepper, const EventSink& sink);

}  // namespace impact
