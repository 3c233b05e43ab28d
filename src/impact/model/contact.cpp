#include "impact/model/contact.hpp"

#include <cmath>

namespace impact {

bool ContactDetector::add_step(std::int64_t l, const State& before, const State& after,
                               double contact_force) {
  const bool contact = is_contact_step(model_, after, contact_force);
  if (contact && !in_contact()) {
    recording_ = episodes_.size() < max_episodes_;
    if (recording_) {
      ContactEpisode e;
      e.first_step = l;
      e.t_start = static_cast<double>(l) * h_;
      e.linear_fraction = before.v < 0 ? (before.u - model_.phi) / (h_ * -before.v) : 0.0;
      e.flight_fraction = flight_fraction(before);
      e.speed_before = std::fabs(before.v);
      e.floor_speed_in = floor_speed(before);
      e.energy_before = energy(model_, before);
      episodes_.push_back(e);
    }
  }
  if (contact && recording_) {
    ContactEpisode& e = episodes_.back();
    ++e.steps;
    e.energy_after = energy(model_, after);
    e.floor_speed_out = floor_speed(after);
  }
  count_contact(count_, contact);
  return contact;
}

// The root s of (u - phi) + v s + f s^2 / 2 = 0 reached first, 2 d / (V + |v|) with
// V = sqrt(v^2 - 2 f d) the speed at the floor (no cancellation), over h.
double ContactDetector::flight_fraction(const State& s) const {
  const double d = s.u - model_.phi, discriminant = s.v * s.v - 2 * model_.f * d;
  if (d < 0 || s.v >= 0 || discriminant < 0) return std::numeric_limits<double>::quiet_NaN();
  return 2 * d / (std::sqrt(discriminant) - s.v) / h_;
}

double ContactDetector::floor_speed(const State& s) const {
  return std::sqrt(std::fmax(0.0, 2 * (energy(model_, s) + model_.f * model_.phi)));
}

}  // namespace impact
