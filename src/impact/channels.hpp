// The channels a run can write (a row's columns after t), once: their names, what each is, and the
// capability a method needs to write it (registry.hpp). The scene reader, the help and the CSV
// writer read this table.
#pragma once

#include <span>
#include <string_view>

#include "impact/registry.hpp"

namespace impact {

enum class Channel { u, v, N, E, iterations };

struct ChannelInfo {
  Channel channel;
  std::string_view name, meaning;
  bool Capabilities::*needs = nullptr;  // what a method must have to write it; nullptr: any
};

std::span<const ChannelInfo> channels();
const ChannelInfo& channel_info(Channel channel);
inline std::string_view channel_name(Channel channel) {
  return channel_info(channel).name;
}
// Whether `method` can write `channel`.
bool can_write(const MethodInfo& method, Channel channel);

}  // namespace impact
