#include "impact/registry.hpp"

#include <sstream>
#include <string>

#include "impact/scene.hpp"

namespace impact {
namespace {

constexpr MethodInfo kMethods[] = {
    {"direct", false, "the paper's scheme (4-1)-(4-3) solved in closed form, (5-1)"},
    {"fb_newton", true, "(4-1)-(4-3) as the smoothed Fischer-Burmeister equation (5-3), Newton"},
    {"moreau_jean", false, "Moreau-Jean theta time-stepping with Newton's impact law"},
    {"penalty", true, "normal compliance N = c_N max(phi - u, 0), GSL odeiv2"},
    {"exact", false, "event-driven closed-form solution sampled on t = l h"},
};

std::string show_number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

template <class Stepper, class... Args>
AnyStepper build(const Scene& scene, Args&&... args) {
  MethodParams reader(scene);
  auto params = Stepper::read_params(reader);
  reader.reject_unread();
  return AnyStepper(std::in_place_type<Stepper>, scene.model, scene.grid.h, params,
                    std::forward<Args>(args)...);
}

}  // namespace

std::span<const MethodInfo> methods() {
  return kMethods;
}

const MethodInfo* find_method(std::string_view name) {
  for (const auto& m : kMethods)
    if (m.name == name) return &m;
  return nullptr;
}

AnyStepper make_stepper(const Scene& scene) {
  if (scene.method == "direct") return build<Direct>(scene);
  if (scene.method == "fb_newton") return build<FbNewton>(scene);
  if (scene.method == "moreau_jean") return build<MoreauJean>(scene);
  if (scene.method == "penalty") {
    // Compliance has no impact law to apply a COR to: refuse rather than silently run elastic.
    if (scene.model.cor)
      throw SceneError(
          scene.source + ": floor.cor = " + show_number(*scene.model.cor) +
          ": method 'penalty' has no restitution law (its compliance contact is "
          "elastic); remove floor.cor or choose direct, fb_newton, moreau_jean or exact");
    return build<Penalty>(scene);
  }
  if (scene.method == "exact") return build<ExactStepper>(scene, scene.initial);
  throw SceneError(scene.source + ": method.name = \"" + scene.method + "\": unknown method");
}

}  // namespace impact
