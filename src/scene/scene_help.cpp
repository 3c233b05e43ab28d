#include "scene/scene_help.hpp"

#include <vector>

#include "impact/methods/capabilities.hpp"
#include "scene/scene_keys.hpp"
#include "scene/toml_text.hpp"

namespace impact {
namespace {

// Columns of a key's row: name, default, then what is allowed and what the key is for.
constexpr std::size_t kNameEnd = 19, kDefaultEnd = 34;

std::size_t columns(std::string_view text) {
  std::size_t n = 0;
  for (unsigned char c : text) n += (c & 0xC0) != 0x80;  // not a UTF-8 continuation byte
  return n;
}

std::string pad(std::string text, std::size_t to) {
  const std::size_t n = columns(text);
  text += n < to ? std::string(to - n, ' ') : "  ";
  return text;
}

// What a key accepts: "> 0", "integer in [1, 10000]", "closed_form, paper", ...
std::string allowed(const KeySpec& spec) {
  std::string out;
  switch (spec.type) {
    case KeyType::number:
      out = spec.range.text().empty() ? "finite" : spec.range.text();
      break;
    case KeyType::integer:
      out = "integer " + spec.range.text();
      break;
    case KeyType::text:
      out = "a string";
      break;
    case KeyType::name:
    case KeyType::names: {
      const auto choices = spec.choices();
      out = join({choices.begin(), choices.end()});
      if (spec.type == KeyType::names) out = "a list of " + out;
      break;
    }
  }
  if (!spec.also.empty()) out.append(", ").append(spec.also);
  if (spec.only_with)
    out.append(", ")
        .append(spec.only_some)
        .append(" with ")
        .append(join(methods_with(spec.only_with)))
        .append(" only");
  return out;
}

// One row: `name` and the key's default, then what it accepts and means, wrapped under itself.
std::string row(std::string name, const KeySpec& spec, const Scene& defaults, std::size_t width) {
  const std::string fallback = spec.required ? "required"
                               : spec.get    ? show_value(spec.get(defaults))
                                             : "none";
  const std::string head = pad(pad(std::move(name), kNameEnd) + fallback, kDefaultEnd);
  return head +
         wrap(allowed(spec) + ": " + std::string(spec.meaning), width, kDefaultEnd, columns(head)) +
         "\n";
}

}  // namespace

std::string wrap(std::string_view text, std::size_t width, std::size_t indent, std::size_t start) {
  std::string out;
  std::size_t column = start == std::string::npos ? indent : start;
  bool line_start = true;
  while (!text.empty()) {
    const std::size_t end = text.find_first_of(" \n");
    const std::string_view word = text.substr(0, end);
    if (!word.empty()) {
      if (!line_start && column + 1 + columns(word) > width) {
        out += '\n';
        out.append(indent, ' ');
        column = indent;
        line_start = true;
      }
      if (!line_start) {
        out += ' ';
        ++column;
      }
      out.append(word);
      column += columns(word);
      line_start = false;
    }
    if (end == std::string_view::npos) break;
    if (text[end] == '\n') {  // a line break of the text: kept, and the next line unindented
      out += '\n';
      column = 0;
      line_start = true;
      indent = 0;
    }
    text.remove_prefix(end + 1);
  }
  return out;
}

std::string scene_help(std::size_t width) {
  const Scene defaults;
  std::string out = wrap(
      "Scene keys (table.key, default, allowed values: meaning). [initial], [time] and "
      "[method] are required; a key left out is absent, not zero:",
      width);
  out += '\n';
  for (const KeySpec& spec : scene_keys())
    out += row("  " + std::string(spec.table) + "." + std::string(spec.key), spec, defaults, width);

  out += "\nMethod keys (in [method], all optional):\n";
  for (const MethodInfo& m : methods()) {
    out += "  " + std::string(m.name) + ":";
    Scene method_defaults;
    method_defaults.method = m.defaults;
    bool any = false;
    for (const KeySpec& spec : method_keys()) {
      if (spec.method() != m.name) continue;
      out += any ? "" : "\n";
      out += row("    " + std::string(spec.key), spec, method_defaults, width);
      any = true;
    }
    if (!any) out += " none\n";
  }

  out += "\nMethods (method.name):\n";
  for (const MethodInfo& m : methods())
    out += pad("  " + std::string(m.name), kNameEnd) + wrap(m.summary, width, kNameEnd) + "\n";

  out += "\nChannels (output.channels; the CSV's header is t, then the channels):\n";
  for (const auto& list : {channels(), bonding_channels()})
    for (const ChannelInfo& c : list) {
      std::string meaning(c.meaning);
      if (c.needs) meaning += " (" + join(methods_with(c.needs)) + " only)";
      out += pad("  " + std::string(c.name), kNameEnd) + wrap(meaning, width, kNameEnd) + "\n";
    }
  out += pad("  <name>", kNameEnd) +
         wrap(
             "an internal variable of [[internal]], by its name (written by default after u "
             "and v)",
             width, kNameEnd) +
         "\n";

  out += "\n" +
         wrap("Internal variables ([[internal]], one table each, at most " +
                  std::to_string(kMaxInternal) + "; " +
                  join(methods_with(&Capabilities::internal_variables)) + " only):",
              width) +
         "\n";
  out += "  " +
         wrap(
             "z' = g(t, u, v, z). z is continuous across impacts and evolves at rest; the "
             "time-steppers take it by explicit Euler (first order), event_driven in its ODE. "
             "--set, --unset and --vary name a variable's key as internal.NAME.key (--set "
             "internal.D.initial=0.5, --vary internal.D.initial=0:1:11); --unset internal.NAME "
             "removes the variable, --unset internal all of them. Keys (all required):",
             width, 2) +
         "\n";
  for (const KeySpec& spec : internal_keys())
    out +=
        pad("    " + std::string(spec.key), kNameEnd) +
        wrap(std::string(spec.meaning) + (spec.also.empty() ? "" : "; " + std::string(spec.also)),
             width, kNameEnd) +
        "\n";
  return out;
}

}  // namespace impact
