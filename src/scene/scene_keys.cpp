#include "scene/scene_keys.hpp"

#include "impact/format.hpp"
#include "scene/toml_text.hpp"

namespace impact {
namespace {

std::span<const std::string_view> method_names() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> out;
    for (const auto& m : methods()) out.push_back(m.name);
    return out;
  }();
  return names;
}

std::span<const std::string_view> channel_names() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> out;
    for (const ChannelInfo& c : channels()) out.push_back(c.name);
    return out;
  }();
  return names;
}

constexpr Range kPositive{.lo = 0.0, .lo_open = true};

const TableSpec kTables[] = {
    {"initial", true}, {"floor", false}, {"force", false},  {"force.linear", false},
    {"time", true},    {"method", true}, {"output", false}, {"bonding", false},
};

// Required keys have no default; an optional key's default is the plain struct's (Scene{}).
const KeySpec kKeys[] = {
    {.table = "initial",
     .key = "u0",
     .type = KeyType::number,
     .required = true,
     .also = ">= floor.phi",
     .meaning = "initial position",
     .set = [](Scene& s, const KeyValue& v) { s.initial.u = std::get<double>(v); }},
    {.table = "initial",
     .key = "v0",
     .type = KeyType::number,
     .required = true,
     .meaning = "initial velocity",
     .set = [](Scene& s, const KeyValue& v) { s.initial.v = std::get<double>(v); }},
    {.table = "floor",
     .key = "phi",
     .type = KeyType::number,
     .meaning = "floor position",
     .get = [](const Scene& s) -> KeyValue { return s.model.phi; },
     .set = [](Scene& s, const KeyValue& v) { s.model.phi = std::get<double>(v); }},
    {.table = "floor",
     .key = "cor",
     .type = KeyType::number,
     .range = {.lo = 0.0, .hi = 1.0},
     .also = "not with penalty",
     .meaning = "coefficient of restitution; none: no restitution law",
     .get = [](const Scene& s) -> KeyValue {
       return s.model.cor ? KeyValue(*s.model.cor) : KeyValue();
     },
     .set = [](Scene& s, const KeyValue& v) { s.model.cor = std::get<double>(v); }},
    {.table = "time",
     .key = "T",
     .type = KeyType::number,
     .range = kPositive,
     .required = true,
     .meaning = "final time",
     .set = [](Scene& s, const KeyValue& v) { s.T = std::get<double>(v); }},
    {.table = "time",
     .key = "h",
     .type = KeyType::number,
     .range = kPositive,
     .required = true,
     .also = "<= time.T, T/h <= 2^53",
     .meaning = "time step",
     .set = [](Scene& s, const KeyValue& v) { s.grid.h = std::get<double>(v); }},
    {.table = "method",
     .key = "name",
     .type = KeyType::name,
     .choices = method_names,
     .required = true,
     .meaning = "the method; its keys follow",
     .set = [](Scene& s,
               const KeyValue& v) { s.method = find_method(std::get<std::string>(v))->defaults; }},
    {.table = "output",
     .key = "channels",
     .type = KeyType::names,
     .choices = channel_names,
     .meaning = "the CSV's columns after t (see Channels)",
     // Read by read_channels(), since what a method can write depends on the method.
     .get = [](const Scene& s) -> KeyValue {
       std::vector<std::string> names;
       for (Channel c : s.output.channels) names.emplace_back(channel_name(c, s.model));
       return names;
     }},
    {.table = "output",
     .key = "every",
     .type = KeyType::integer,
     .range = {.lo = 1.0},
     .meaning = "write every k-th step (t = 0 and the last step always)",
     .get = [](const Scene& s) -> KeyValue { return s.output.every; },
     .set = [](Scene& s, const KeyValue& v) { s.output.every = std::get<std::int64_t>(v); }},
};

}  // namespace

std::string Range::text() const {
  if (lo == -std::numeric_limits<double>::infinity() &&
      hi == std::numeric_limits<double>::infinity())
    return "";
  if (hi == std::numeric_limits<double>::infinity()) return (lo_open ? "> " : ">= ") + shortest(lo);
  return std::string("in ") + (lo_open ? "(" : "[") + shortest(lo) + ", " + shortest(hi) + "]";
}

std::span<const TableSpec> scene_tables() {
  return kTables;
}

// The [force] keys are force_keys.cpp's, the [bonding] keys bonding_keys.cpp's; each table's keys
// in the order of kTables.
std::span<const KeySpec> scene_keys() {
  static const std::vector<KeySpec> keys = [] {
    std::vector<KeySpec> all;
    for (const TableSpec& t : kTables) {
      for (const KeySpec& k : kKeys)
        if (k.table == t.name) all.push_back(k);
      if (t.name == "force") all.insert(all.end(), force_keys().begin(), force_keys().end());
      if (t.name == "bonding") all.insert(all.end(), bonding_keys().begin(), bonding_keys().end());
    }
    return all;
  }();
  return keys;
}

const KeySpec* find_scene_key(std::string_view table, std::string_view key) {
  for (const auto& k : scene_keys())
    if (k.table == table && k.key == key) return &k;
  return nullptr;
}

std::vector<std::string_view> key_names(std::string_view table, std::string_view method) {
  std::vector<std::string_view> names;
  for (const auto& k : scene_keys())
    if (k.table == table) names.push_back(k.key);
  // A table inside this one (force.linear in [force]) is one of its keys.
  for (const TableSpec& t : kTables)
    if (t.name.size() > table.size() && t.name.starts_with(table) && t.name[table.size()] == '.')
      names.push_back(t.name.substr(table.size() + 1));
  for (const auto& k : method_keys())
    if (k.table == table && k.method() == method) names.push_back(k.key);
  return names;
}

std::string show_value(const KeyValue& value) {
  struct Show {
    std::string operator()(std::monostate) const { return "none"; }
    std::string operator()(double x) const { return show_float(x); }
    std::string operator()(std::int64_t i) const { return std::to_string(i); }
    std::string operator()(const std::string& name) const { return show_string(name); }
    std::string operator()(const std::vector<std::string>& names) const {
      std::string out = "[";
      for (const auto& n : names) out += (out.size() > 1 ? ", " : "") + show_string(n);
      return out + "]";
    }
  };
  return std::visit(Show{}, value);
}

}  // namespace impact
