// exact with a bonding field in the well with no damage; see exact_bonded.hpp.
#include "impact/references/exact_bonded.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "impact/format.hpp"

namespace impact {
namespace {

// The bonded model as the linear force of the well: -k (u - phi), k = gamma beta0^2.
Model as_well(const Model& model) {
  if (!bonded(model))
    throw std::invalid_argument("exact with a bonding field: the model has none that acts");
  if (!constant_force(model))
    throw std::invalid_argument(
        "method 'exact' follows a bonding field with a constant force only (force.f); "
        "event_driven takes any force with it");
  Model well = model;
  const Bonding& b = *model.bonding;
  well.linear = LinearSpring{b.gamma * b.beta0 * b.beta0, 0.0, model.phi};
  well.bonding.reset();
  return well;
}

}  // namespace

std::optional<std::string> no_damage_well_refusal(const Model& model, const State& initial) {
  if (!bonded(model)) return std::nullopt;
  if (!constant_force(model))
    return "method 'exact' follows a bonding field with a constant force only (force.f), and "
           "this scene's force is not constant (force.amplitude/force.omega or force.expression "
           "give f(t)): use event_driven";
  const Bonding& b = *model.bonding;
  const double k = b.gamma * b.beta0 * b.beta0;
  const double height = well_height(k, -model.f, initial.u - model.phi, initial.v);
  // Damage starts where gamma g^2 > eps_a in the product form, where beta0 gamma g^2 > eps_a in
  // the Frémond form (bonding.hpp; beta = beta0 until it starts); the pull saturates past L.
  const bool fremond = b.form == BondForm::fremond;
  const double undamaged = std::sqrt(b.eps_a / (fremond ? b.gamma * b.beta0 : b.gamma));
  if (height <= b.L && height <= undamaged) return std::nullopt;
  std::string why = "method 'exact' follows a bonding field only in the well with no damage, and ";
  why += "this run's first flight rises to the gap ";
  why += shortest(height);
  if (height > b.L) {
    why += ", past bonding.L = ";
    why += shortest(b.L);
  } else {
    why += fremond ? ", where beta0 gamma g^2 > bonding.eps_a (bonds break past the gap "
                   : ", where gamma g^2 > bonding.eps_a (bonds break past the gap ";
    why += shortest(undamaged);
    why += ")";
  }
  why += ": use event_driven";
  return why;
}

ExactBonded::ExactBonded(const Model& model, double h, const ExactParams& params)
    : model_(model), well_(as_well(model), h, params) {}

void ExactBonded::initialize(const StateWithInternal& s, std::int64_t l) {
  if (const auto why = no_damage_well_refusal(model_, s)) throw std::invalid_argument(*why);
  well_.initialize(s, l);
}

}  // namespace impact
