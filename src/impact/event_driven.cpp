// The method event_driven; see event_driven.hpp.
#include "impact/event_driven.hpp"

#include <stdexcept>
#include <string>

namespace impact {

namespace {

void check_range(const char* key, double value, double hi) {
  if (!(value > 0.0 && value <= hi))
    throw std::invalid_argument("method 'event_driven': " + std::string(key) + " = " +
                                std::to_string(value) + " must be in (0, " + std::to_string(hi) +
                                "]");
}

}  // namespace

EventDriven::EventDriven(const Model& model, double h, const EventDrivenParams& params)
    : model_(model), h_(h), settings_{params.rtol, params.atol, params.max_step} {
  check_range("rtol", params.rtol, 1e-3);
  check_range("atol", params.atol, 1e-3);
  check_range("max_step", params.max_step, 1e300);
  const ForceFunction parses(model);  // an expression that does not parse fails here, not later
}

void EventDriven::initialize(const State& s, std::int64_t l) {
  track_.emplace(OdeLaw(model_, settings_), model_, s, static_cast<double>(l) * h_);
  track_->set_event_sink(sink_);
}

StepInfo EventDriven::do_step(State& s, std::int64_t l) {
  StepInfo info;
  double impulse = 0.0;
  s = track_->advance(static_cast<double>(l + 1) * h_, impulse);
  info.contact_force = impulse / h_;
  info.converged = track_->converged();
  return info;
}

void EventDriven::set_event_sink(EventSink sink) {
  sink_ = std::move(sink);
  if (track_) track_->set_event_sink(sink_);
}

}  // namespace impact
