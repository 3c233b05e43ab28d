#include "impact/channels.hpp"

namespace impact {
namespace {

// In the order of the enum, so that channel_info() can index by it.
const ChannelInfo kChannels[] = {
    {Channel::u, "u", "position"},
    {Channel::v, "v", "velocity"},
    {Channel::N, "N",
     "the mean contact force over the steps since the previous row: with output.every = 1, "
     "N^{l-1} of (4-1), the contact impulse over (t_{l-1}, t_l] divided by h"},
    {Channel::E, "E",
     "energy v^2/2 - f u, (3-1); with a time-dependent force v^2/2 - f(0) u(0) - W(t), W the "
     "work of f so far"},
    {Channel::iterations, "iterations",
     "Newton or ODE-driver iterations of the steps since the previous row",
     &Capabilities::iterations_channel},
};

}  // namespace

std::span<const ChannelInfo> channels() {
  return kChannels;
}

const ChannelInfo& channel_info(Channel channel) {
  return kChannels[static_cast<int>(channel)];
}

bool can_write(const MethodInfo& method, Channel channel) {
  const ChannelInfo& info = channel_info(channel);
  return !info.needs || method.can.*info.needs;
}

}  // namespace impact
