#include "scene/method_keys.hpp"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string_view>
#include <vector>

#include "scene/scene_error.hpp"
#include "scene/toml_text.hpp"

namespace impact {
namespace {

// Typed, range-checked access to the keys of [method]; remembers which keys were read so that a
// key the method does not read (a typo) is rejected with the list of allowed keys.
class MethodKeys {
 public:
  MethodKeys(const toml::table& table, const Origins& origins, std::string_view method)
      : table_(table), origins_(origins), method_(method) {}

  // A number in [lo, hi] (open at lo when lo_open), defaulting to `fallback` when absent.
  double number(std::string_view key, double fallback, double lo, double hi, bool lo_open = false) {
    const toml::node* node = find(key);
    if (!node) return fallback;
    double x;
    if (node->is_integer())
      x = static_cast<double>(node->as_integer()->get());
    else if (node->is_floating_point())
      x = node->as_floating_point()->get();
    else
      fail(key, *node, "must be a number");
    if (!(std::isfinite(x) && (lo_open ? x > lo : x >= lo) && x <= hi)) {
      std::ostringstream range;
      range << "must be in " << (lo_open ? "(" : "[") << lo << ", " << hi << "]";
      fail(key, *node, range.str());
    }
    return x;
  }

  std::int64_t integer(std::string_view key, std::int64_t fallback, std::int64_t lo,
                       std::int64_t hi) {
    const toml::node* node = find(key);
    if (!node) return fallback;
    if (!node->is_integer() || node->as_integer()->get() < lo || node->as_integer()->get() > hi)
      fail(key, *node,
           "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return node->as_integer()->get();
  }

  std::string choice(std::string_view key, std::string_view fallback,
                     const std::vector<std::string_view>& allowed) {
    const toml::node* node = find(key);
    if (!node) return std::string(fallback);
    if (node->is_string())
      for (auto a : allowed)
        if (a == node->as_string()->get()) return std::string(a);
    fail(key, *node, "must be one of " + join(allowed));
  }

  void reject_unread() const {
    for (auto&& [key, node] : table_) {
      bool read = false;
      for (const auto& r : read_) read = read || r == key.str();
      if (!read) {
        std::vector<std::string_view> names(read_.begin(), read_.end());
        fail(
            key.str(), node,
            "unknown key for method '" + std::string(method_) + "' (allowed: " + join(names) + ")");
      }
    }
  }

 private:
  const toml::node* find(std::string_view key) {
    read_.emplace_back(key);
    return table_.get(key);
  }
  [[noreturn]] void fail(std::string_view key, const toml::node& node,
                         const std::string& allowed) const {
    throw SceneError(origins_.of("method", key) + ": method." + show_key(key) + " = " + show(node) +
                     ": " + allowed);
  }

  const toml::table& table_;
  const Origins& origins_;
  std::string_view method_;
  std::vector<std::string> read_{"name"};
};

// free_flight = "closed_form" | "paper" (free_flight.hpp).
FreeFlightForm read_free_flight(MethodKeys& keys, FreeFlightForm fallback) {
  return keys.choice("free_flight", fallback == FreeFlightForm::paper ? "paper" : "closed_form",
                     {"closed_form", "paper"}) == "paper"
             ? FreeFlightForm::paper
             : FreeFlightForm::closed_form;
}

DirectParams read(MethodKeys& keys, DirectParams p) {
  p.free_flight = read_free_flight(keys, p.free_flight);
  return p;
}

FbNewtonParams read(MethodKeys& keys, FbNewtonParams p) {
  p.epsilon = keys.number("epsilon", p.epsilon, 0.0, 1.0, true);
  p.tolerance = keys.number("tolerance", p.tolerance, 0.0, 1e-1, true);
  p.max_iterations = static_cast<int>(keys.integer("max_iterations", p.max_iterations, 1, 10000));
  p.free_flight = read_free_flight(keys, p.free_flight);
  return p;
}

MoreauJeanParams read(MethodKeys& keys, MoreauJeanParams p) {
  p.theta = keys.number("theta", p.theta, 0.0, 1.0);
  return p;
}

PenaltyParams read(MethodKeys& keys, PenaltyParams p) {
  p.stiffness = keys.number("stiffness", p.stiffness, 0.0, 1e15, true);
  const auto names = penalty_stepper_names();
  p.stepper = keys.choice("stepper", p.stepper, {names.begin(), names.end()});
  p.rtol = keys.number("rtol", p.rtol, 0.0, 1.0, true);
  p.atol = keys.number("atol", p.atol, 0.0, 1.0, true);
  return p;
}

// Methods without keys.
template <class Params>
Params read(MethodKeys&, Params p) {
  return p;
}

}  // namespace

MethodParams read_method_keys(const toml::table& method, const Origins& origins,
                              const MethodInfo& info) {
  MethodKeys keys(method, origins, info.name);
  MethodParams params = std::visit(
      [&](const auto& defaults) { return MethodParams(read(keys, defaults)); }, info.defaults);
  keys.reject_unread();
  return params;
}

}  // namespace impact
