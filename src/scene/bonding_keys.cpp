#include "scene/bonding_keys.hpp"

#include <cmath>
#include <string>

#include "impact/forces/force.hpp"
#include "impact/format.hpp"
#include "impact/references/exact_bonded.hpp"
#include "scene/toml_text.hpp"

namespace impact {
namespace {

// The bonding field, created by each of its keys as force.linear is.
Bonding& bonding(Scene& s) {
  if (!s.model.bonding) s.model.bonding.emplace();
  return *s.model.bonding;
}

KeyValue bonding_value(const Scene& s, double Bonding::*member) {
  if (!s.model.bonding || !std::isfinite(*s.model.bonding.*member)) return KeyValue();
  return *s.model.bonding.*member;
}

constexpr std::string_view kOnly = "a bonding field";

std::span<const std::string_view> bond_forms() {
  static constexpr std::string_view kForms[] = {"product", "fremond"};
  return kForms;
}

// Left out: gamma = 0 (no field), L none (no saturation, R(g) = g), eps_a = 0, beta0 = 1.
const KeySpec kBondingKeys[] = {
    {.table = "bonding",
     .key = "gamma",
     .type = KeyType::number,
     .range = {.lo = 0.0},
     .also = "0: no bonding field, the paper's model bit for bit",
     .only_some = kOnly,
     .only_with = &Capabilities::bonding,
     .meaning = "adhesion stiffness: the pull is gamma beta^2 min(u - phi, L)",
     .get = [](const Scene& s) { return bonding_value(s, &Bonding::gamma); },
     .set = [](Scene& s, const KeyValue& v) { bonding(s).gamma = std::get<double>(v); }},
    {.table = "bonding",
     .key = "L",
     .type = KeyType::number,
     .range = {.lo = 0.0, .lo_open = true},
     .only_some = kOnly,
     .only_with = &Capabilities::bonding,
     .meaning = "bond length: the gap past which the pull saturates at gamma beta^2 L; none: "
                "no saturation",
     .get = [](const Scene& s) { return bonding_value(s, &Bonding::L); },
     .set = [](Scene& s, const KeyValue& v) { bonding(s).L = std::get<double>(v); }},
    {.table = "bonding",
     .key = "eps_a",
     .type = KeyType::number,
     .range = {.lo = 0.0},
     .only_some = kOnly,
     .only_with = &Capabilities::bonding,
     .meaning = "the energy density gamma R^2 below which bonds do not break: beta' = "
                "-beta (gamma R^2 - eps_a)_+",
     .get = [](const Scene& s) { return bonding_value(s, &Bonding::eps_a); },
     .set = [](Scene& s, const KeyValue& v) { bonding(s).eps_a = std::get<double>(v); }},
    {.table = "bonding",
     .key = "beta0",
     .type = KeyType::number,
     .range = {.lo = 0.0, .hi = 1.0},
     .also = "0: no bonding field, the paper's model bit for bit",
     .only_some = kOnly,
     .only_with = &Capabilities::bonding,
     .meaning = "the fraction of active bonds at t = 0",
     .get = [](const Scene& s) { return bonding_value(s, &Bonding::beta0); },
     .set = [](Scene& s, const KeyValue& v) { bonding(s).beta0 = std::get<double>(v); }},
    {.table = "bonding",
     .key = "form",
     .type = KeyType::name,
     .choices = bond_forms,
     .also = "fremond needs bonding.b",
     .only_some = kOnly,
     .only_with = &Capabilities::bonding,
     .meaning = "the damage law: product, beta' = -beta (gamma R^2 - eps_a)_+; fremond "
                "(LMGC90's MAC_CZM), b beta' = -(beta gamma R^2 - eps_a)_+",
     // Left out, and so not written back, for the product form: a scene's sidecar as before.
     .get = [](const Scene& s) -> KeyValue {
       if (!s.model.bonding || s.model.bonding->form != BondForm::fremond) return KeyValue();
       return std::string("fremond");
     },
     .set =
         [](Scene& s, const KeyValue& v) {
           bonding(s).form =
               std::get<std::string>(v) == "fremond" ? BondForm::fremond : BondForm::product;
         }},
    {.table = "bonding",
     .key = "b",
     .type = KeyType::number,
     .range = {.lo = 0.0, .lo_open = true},
     .also = "read with form = \"fremond\" only, and required there",
     .only_some = kOnly,
     .only_with = &Capabilities::bonding,
     .meaning = "the viscosity of the Frémond form's damage law, b beta' = "
                "-(beta gamma R^2 - eps_a)_+",
     .get = [](const Scene& s) { return bonding_value(s, &Bonding::b); },
     .set = [](Scene& s, const KeyValue& v) { bonding(s).b = std::get<double>(v); }},
    {.table = "bonding",
     .key = "debond_below",
     .type = KeyType::number,
     .range = {.lo = 0.0, .hi = 1.0},
     .also = "default 0.01; 0: only a beta that underflows to 0",
     .only_some = kOnly,
     .only_with = &Capabilities::bonding,
     .meaning = "the fraction of active bonds at or below which the bond counts as broken: "
                "the debond event and the sweep's debond_time (a beta0 at or below it starts "
                "broken)",
     .get = [](const Scene& s) { return bonding_value(s, &Bonding::debond_below); },
     .set = [](Scene& s, const KeyValue& v) { bonding(s).debond_below = std::get<double>(v); }},
};

}  // namespace

std::span<const KeySpec> bonding_keys() {
  return kBondingKeys;
}

void check_bonding(const KeyReader& r, const toml::table& root, Scene& scene) {
  if (scene.model.bonding) {
    const Bonding& b = *scene.model.bonding;
    if (b.form == BondForm::fremond && std::isnan(b.b))
      r.fail("bonding", "form",
             "\"fremond\" needs bonding.b, the viscosity of its damage law (a number > 0)");
    if (b.form == BondForm::product && !std::isnan(b.b)) {
      std::string what = shortest(b.b);
      what +=
          " given, but b is read with form = \"fremond\" only: the product form has no "
          "viscosity; set bonding.form = \"fremond\" or leave b out";
      r.fail("bonding", "b", what);
    }
  }
  if (!bonded(scene.model)) return;
  const std::string where = "[bonding]";
  if (!scene.model.internal.empty())
    r.fail_table("bonding", where,
                 "is not taken together with [[internal]] (a run's internal state holds beta "
                 "and D); write the bonds as [[internal]] data, or leave [[internal]] out");
  // A force of t (force.amplitude/omega, a force.expression of t) is taken: its work W(t) makes
  // E (work_energy.hpp). A force of the state is not: with it the pull and f would be two forces
  // of the state, and no test holds E + D = E(0) for that.
  if (state_force(scene.model))
    r.fail_table("bonding", where,
                 "is taken with a force of t only (force.f, force.amplitude and force.omega, or a "
                 "force.expression of t), not with a force of the state (a force.expression "
                 "that reads u, v or an internal variable, or force.linear)");
  // Whether the method takes a bonding field is refusal()'s (capabilities.hpp), asked once the
  // whole scene is read; whether exact can follow this one is a property of its flights.
  if (std::holds_alternative<ExactParams>(scene.method))
    if (const auto why = no_damage_well_refusal(scene.model, scene.initial))
      r.fail_value("method", "name", *root.get("method")->as_table()->get("name"), *why);
  // Written by default, after u and v (output.channels chooses otherwise).
  for (const ChannelInfo& c : bonding_channels()) scene.output.channels.push_back(c.channel);
}

}  // namespace impact
