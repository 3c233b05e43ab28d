// The exact solution for a constant or harmonic force; conventions in event_track.hpp.
#include "impact/event_track.hpp"

#include <cmath>
#include <stdexcept>

namespace impact {

namespace {

// The checks that only a harmonic force needs, before the generic ones of EventTrackOf.
const Model& closed_form_model(const Model& model) {
  if (!model.expression.empty())
    throw std::invalid_argument(
        "method 'exact' has no closed-form flight for a force expression; use method "
        "'event_driven'");
  if (model.harmonic) {
    const Harmonic& w = *model.harmonic;
    if (!std::isfinite(w.amplitude) || !std::isfinite(w.omega) || !std::isfinite(w.phase))
      throw std::invalid_argument("exact: the harmonic force must be finite");
    if (w.amplitude != 0.0 && !(w.omega > 0.0))
      throw std::invalid_argument("exact: the harmonic force needs omega > 0");
  }
  return model;
}

}  // namespace

EventTrack::EventTrack(const Model& model, const State& initial, double t0)
    : EventTrackOf<ClosedFormLaw>(ClosedFormLaw(closed_form_model(model)), model, initial, t0) {}

}  // namespace impact
