// The channels a run can write (a row's columns after t), once: their names, what each is, the
// capability a method needs to write it (capabilities.hpp) and where a row (row.hpp) holds its
// value. The scene reader, the help, the CSV writer, the plot and Python read this table.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "impact/methods/capabilities.hpp"
#include "impact/model/model.hpp"
#include "impact/output/row.hpp"

namespace impact {

// z1..z4: the model's internal variables (model.hpp), named in a scene and a CSV header by the
// model's names; beta and D: a bonded model's fraction of active bonds and the energy spent on
// them (bonding.hpp), kept in the state's z as model.hpp says; channels() lists the first six.
enum class Channel { u, v, N, E, iterations, N_scheme, z1, z2, z3, z4, beta, D };

struct ChannelInfo {
  Channel channel;
  std::string_view name, meaning;
  bool Capabilities::*needs;          // what a method must have to write it; nullptr: any
  double (*value)(const OutputRow&);  // a row's value of it (iterations as a double)
};

// The channels every model has (u, v, N, E, iterations, N_scheme).
std::span<const ChannelInfo> channels();
// The bonding field's channels, beta and D, which a bonded model has (model.hpp).
std::span<const ChannelInfo> bonding_channels();
// The channel of the model's internal variable i (i < kMaxInternal), and which one a channel is.
Channel internal_channel(std::size_t i);
std::optional<std::size_t> internal_index(Channel channel);
// The name of a channel in a scene and a CSV header: the model's name for an internal variable.
std::string_view channel_name(Channel channel, const Model& model);
const ChannelInfo& channel_info(Channel channel);
inline std::string_view channel_name(Channel channel) {
  return channel_info(channel).name;
}
// Whether `method` can write `channel`.
bool can_write(const MethodInfo& method, Channel channel);

// A row's value of `channel` (row.hpp), as the CSV writes it; iterations as a double.
double channel_value(const OutputRow& row, Channel channel);

}  // namespace impact
