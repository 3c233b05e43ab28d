#include "impact/run/step_events.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "impact/model/contact.hpp"
#include "impact/output/channels.hpp"
#include "impact/output/csv.hpp"

namespace impact {

StepEvents::StepEvents(const Model& model, double h, EventSink sink)
    : force_(model), carried_(event_variables(model).size()), h_(h), sink_(std::move(sink)) {}

void StepEvents::operator()(std::int64_t l, const StateWithInternal& s, const StepInfo& info) {
  z_after_ = s.z;
  force_.set_internal(z_before_);  // a force of the state reads z at the step's start
  (*this)(l, static_cast<const State&>(s), info);
  z_before_ = s.z;
}

void StepEvents::emit(Event event) const {
  const std::size_t n = carried_;
  if (n > 0) {
    const double start = static_cast<double>(l_ - 1) * h_;
    const double w = std::clamp((event.t - start) / h_, 0.0, 1.0);
    for (std::size_t i = 0; i < n; ++i)
      event.internal[i] = z_before_[i] + w * (z_after_[i] - z_before_[i]);
  }
  sink_(event);
}

void StepEvents::operator()(std::int64_t l, const State& s, const StepInfo& info) {
  l_ = l;
  if (l > 0) {
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    // (4-3)'s force decides a contact step (contact.hpp), with or without Newton's law.
    const double N = scheme_force(info);
    const bool contact = is_contact_step(force_.model(), s, N) &&
                         h_ * N > 8 * kEps * (std::fabs(before_.v) + std::fabs(s.v));
    if (contact) {
      contact_step(l - 1, s, force_.step_mean(static_cast<double>(l - 1) * h_, h_, before_));
    } else {
      if (phase_ == Phase::stuck) emit({static_cast<double>(l - 1) * h_, EventKind::lift, 0, 0});
      phase_ = Phase::free;
    }
  }
  before_ = s;
}

// Step l, from before_ at t_l to `after` at t_{l+1}, is a contact step.
void StepEvents::contact_step(std::int64_t l, const State& after, double mean_force) {
  const double t = static_cast<double>(l) * h_, rest = h_ * std::fabs(mean_force);
  if (phase_ == Phase::pending_stick) {
    if (std::fabs(after.v) <= rest) {
      emit({stick_t_, EventKind::stick, 0, 0});
      phase_ = Phase::stuck;
      return;
    }
    phase_ = Phase::contact;  // v passed through 0 inside a compliant contact (penalty)
  }
  if (phase_ == Phase::free) {
    const double s = floor_time(mean_force), v = before_.v + mean_force * s;
    if (v < 0 && std::fabs(before_.v) > rest) emit({t + s, EventKind::impact, v, after.v});
    phase_ = Phase::contact;
  }
  if (phase_ == Phase::contact && std::fabs(after.v) <= rest) {
    stick_t_ = std::fabs(before_.v) <= rest ? t : t + h_;
    phase_ = Phase::pending_stick;
  }
}

// The first root s in [0, h] of d + v s + fbar s^2 / 2 = 0, d = u^l - phi: 2 d / (V - v) with
// V = sqrt(v^2 - 2 fbar d) (no cancellation); 0 for a particle at or below the floor, h where the
// flight under fbar does not reach the floor within the step (the scheme's contact came first).
double StepEvents::floor_time(double mean_force) const {
  const double d = before_.u - force_.model().phi, v = before_.v;
  if (d <= 0) return 0.0;
  const double discriminant = v * v - 2 * mean_force * d;
  if (discriminant < 0) return h_;
  const double root = 2 * d / (std::sqrt(discriminant) - v);
  return std::isfinite(root) ? std::clamp(root, 0.0, h_) : h_;
}

std::vector<std::string> event_variables(const Model& model) {
  std::vector<std::string> names;
  if (bonded(model))
    for (const ChannelInfo& c : bonding_channels()) names.emplace_back(c.name);
  else
    for (const InternalVariable& z : model.internal) names.push_back(z.name);
  return names;
}

void write_event_header(std::FILE* out, const Model& model) {
  std::string line = "t,kind,v_before,v_after";
  for (const std::string& name : event_variables(model)) {
    line += ',';
    line += name;
  }
  line += "\n";
  std::fputs(line.c_str(), out);
}

std::size_t write_event(std::FILE* out, const Event& event, std::size_t internal) {
  char buf[256];  // 3 + kMaxInternal fields of at most 24 characters, a kind and the separators
  char* p = format_double(buf, buf + sizeof buf, event.t);
  *p++ = ',';
  const std::string_view kind = event_name(event.kind);
  p = std::copy(kind.begin(), kind.end(), p);
  *p++ = ',';
  p = format_double(p, buf + sizeof buf, event.v_before);
  *p++ = ',';
  p = format_double(p, buf + sizeof buf, event.v_after);
  for (std::size_t i = 0; i < internal && i < kMaxInternal; ++i) {
    *p++ = ',';
    p = format_double(p, buf + sizeof buf, event.internal[i]);
  }
  *p++ = '\n';
  const auto bytes = static_cast<std::size_t>(p - buf);
  std::fwrite(buf, 1, bytes, out);
  return bytes;
}

}  // namespace impact
