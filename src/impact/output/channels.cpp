#include "impact/output/channels.hpp"

#include <algorithm>
#include <ranges>

namespace impact {
namespace {

// In the order of the enum, so that channel_info() can index by it (checked below).
constexpr ChannelInfo kChannels[] = {
    {Channel::u, "u", "position", nullptr, [](const OutputRow& r) { return r.state.u; }},
    {Channel::v, "v", "velocity", nullptr, [](const OutputRow& r) { return r.state.v; }},
    {Channel::N, "N",
     "the mean contact force over the steps since the previous row: with output.every = 1, "
     "N^{l-1} of (4-1), the contact impulse over (t_{l-1}, t_l] divided by h",
     nullptr, [](const OutputRow& r) { return r.contact_force; }},
    {Channel::E, "E",
     "energy v^2/2 - f u, (3-1); with a time-dependent force v^2/2 - f(0) u(0) - W(t), W the "
     "work of f so far",
     nullptr, [](const OutputRow& r) { return r.energy; }},
    {Channel::iterations, "iterations",
     "Newton or ODE-driver iterations of the steps since the previous row",
     &Capabilities::iterations_channel,
     [](const OutputRow& r) { return static_cast<double>(r.iterations); }},
    {Channel::N_scheme, "N_scheme",
     "N^l of (4-3) as the scheme's solve gives it, the mean over the steps since the previous row "
     "as N: with floor.cor, Newton's law then replaces the velocity, and h N_scheme (2|v| at an "
     "impact) is not the floor's impulse (1 + COR)|v|, which N carries; without floor.cor equal to "
     "N. The paper's N of Figures 3 and 4",
     &Capabilities::scheme_force_channel, [](const OutputRow& r) { return r.scheme_force; }},
    {Channel::z1, "z1", "internal variable 1", &Capabilities::internal_variables,
     [](const OutputRow& r) { return r.internal[0]; }},
    {Channel::z2, "z2", "internal variable 2", &Capabilities::internal_variables,
     [](const OutputRow& r) { return r.internal[1]; }},
    {Channel::z3, "z3", "internal variable 3", &Capabilities::internal_variables,
     [](const OutputRow& r) { return r.internal[2]; }},
    {Channel::z4, "z4", "internal variable 4", &Capabilities::internal_variables,
     [](const OutputRow& r) { return r.internal[3]; }},
    {Channel::beta, "beta", "the fraction of active bonds, in [0, 1], never rising ([bonding])",
     &Capabilities::bonding, [](const OutputRow& r) { return r.internal[kBondFraction]; }},
    {Channel::D, "D",
     "the energy spent breaking bonds, int 2 gamma beta^2 Phi(g) (gamma R^2 - eps_a)_+ dt: E + D "
     "is E(0) less the impacts' losses ([bonding])",
     &Capabilities::bonding, [](const OutputRow& r) { return r.internal[kBondEnergy]; }},
};
constexpr std::size_t kFixed = 6;                        // the channels before z1
constexpr std::size_t kBonding = kFixed + kMaxInternal;  // the first of the bonding field's
static_assert(std::size(kChannels) == kBonding + 2 && kMaxInternal == 4);
static_assert(std::ranges::all_of(std::views::iota(std::size_t{0}, std::size(kChannels)),
                                  [](std::size_t i) {
                                    return kChannels[i].channel == static_cast<Channel>(i);
                                  }),
              "kChannels must list the channels in the order of the enum");

}  // namespace

std::span<const ChannelInfo> channels() {
  return std::span<const ChannelInfo>(kChannels).first(kFixed);
}

std::span<const ChannelInfo> bonding_channels() {
  return std::span<const ChannelInfo>(kChannels).subspan(kBonding);
}

Channel internal_channel(std::size_t i) {
  return kChannels[kFixed + i].channel;
}

std::optional<std::size_t> internal_index(Channel channel) {
  const auto i = static_cast<std::size_t>(channel);
  if (i < kFixed || i >= kBonding) return std::nullopt;
  return i - kFixed;
}

std::string_view channel_name(Channel channel, const Model& model) {
  if (const auto i = internal_index(channel); i && *i < model.internal.size())
    return model.internal[*i].name;
  return channel_name(channel);
}

const ChannelInfo& channel_info(Channel channel) {
  return kChannels[static_cast<int>(channel)];
}

bool can_write(const MethodInfo& method, Channel channel) {
  const ChannelInfo& info = channel_info(channel);
  return !info.needs || method.can.*info.needs;
}

double channel_value(const OutputRow& row, Channel channel) {
  return channel_info(channel).value(row);
}

}  // namespace impact
