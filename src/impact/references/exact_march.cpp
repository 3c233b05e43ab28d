// The exact solution for a constant or harmonic force; conventions in exact_march.hpp.
#include "impact/references/exact_march.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace impact {

namespace {

// The checks that only a harmonic force needs, before the generic ones of ExactMarch.
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

std::string describe_stop(const TrackStop& stop, std::string_view law_failure,
                          std::int64_t max_events, std::int64_t budget) {
  std::ostringstream msg;
  msg.precision(6);
  switch (stop.reason) {
    case TrackStop::Reason::events:
      msg << "the solution passed " << stop.events
          << " events (impacts, sticks and lifts) from t = " << stop.first_event << " to " << stop.t
          << ", one every " << (stop.t - stop.first_event) / static_cast<double>(stop.events)
          << " s, more than method.max_events allows (";
      if (max_events > 0)
        msg << max_events;
      else
        msg << "automatic: " << kAutomaticBudget << " + " << kAutomaticBudgetPerGridStep
            << " per grid step, " << budget << " here";
      msg << "): the force makes events faster than a run of this length can follow; shorten "
             "time.T, or raise method.max_events";
      break;
    case TrackStop::Reason::stalled:
      msg << "the contact search stalled: its certified steps from t = " << stop.t
          << " reached only t = " << stop.certified
          << " (a step is at most sqrt(2 gap / B) near the floor, with B = " << stop.force_bound
          << " the bound on |f|; a touch at rounding or a force of this size stops it)";
      break;
    case TrackStop::Reason::law:
      msg << law_failure;
      break;
    case TrackStop::Reason::none:
      break;
  }
  return msg.str();
}

ClosedFormMarch::ClosedFormMarch(const Model& model, const State& initial, double t0)
    : ExactMarch<ClosedFormLaw>(ClosedFormLaw(closed_form_model(model)), model, initial, t0) {}

}  // namespace impact
