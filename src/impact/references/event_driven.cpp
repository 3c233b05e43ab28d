// The method event_driven; see event_driven.hpp.
#include "impact/references/event_driven.hpp"

#include <stdexcept>
#include <string>
#include <utility>

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
    : model_(model),
      h_(h),
      params_(params),
      settings_{params.rtol, params.atol, params.max_step},
      internal_count_(model.internal.size() + (bonded(model) ? 2 : 0)) {
  check_range("rtol", params.rtol, 1e-3);
  check_range("atol", params.atol, 1e-3);
  check_range("max_step", params.max_step, 1e300);
  if (params.max_events < 0 || params.max_ode_steps < 0)
    throw std::invalid_argument(
        "method 'event_driven': max_events and max_ode_steps must be >= 0 (0: automatic)");
  // An expression not yet compiled (a model built in code) that does not parse fails here, not
  // later; one the scene reader compiled is not parsed again.
  const ForceFunction parses(model);
}

void EventDriven::initialize(const StateWithInternal& s, std::int64_t l) {
  l0_ = l;
  OdeLaw law(model_, settings_);
  law.set_internal(s.z);
  track_.emplace(std::move(law), model_, s, static_cast<double>(l) * h_);
  track_->set_event_sink(sink_);
}

StepInfo EventDriven::do_step(StateWithInternal& s, std::int64_t l) {
  event_limit_ = run_budget(params_.max_events, l + 1 - l0_);
  track_->set_event_limit(event_limit_);
  track_->law().set_ode_step_limit(
      static_cast<long>(run_budget(params_.max_ode_steps, l + 1 - l0_)));
  StepInfo info;
  double impulse = 0.0;
  static_cast<State&>(s) = track_->advance(static_cast<double>(l + 1) * h_, impulse);
  if (internal_count_ > 0) s.z = track_->law().internal_at(static_cast<double>(l + 1) * h_);
  info.contact_force = impulse / h_;
  info.converged = track_->converged();
  return info;
}

void EventDriven::set_event_sink(EventSink sink) {
  sink_ = std::move(sink);
  if (track_) track_->set_event_sink(sink_);
}

std::string EventDriven::failure_reason() const {
  if (!track_) return {};
  return describe_stop(track_->stop(), track_->law().failure(), params_.max_events, event_limit_);
}

}  // namespace impact
