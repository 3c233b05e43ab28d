#include "scene/provenance.hpp"

#include <chrono>
#include <cmath>
#include <ctime>

#include "impact/ensemble/processor.hpp"
#include "impact/output/csv.hpp"
#include "impact/version.hpp"
#include "scene/resolved_scene.hpp"

namespace impact {
namespace {

std::string json_list(const std::vector<std::string>& items) {
  std::string out = "[";
  for (const auto& item : items) {
    if (out.size() > 1) out += ", ";
    out += json_string(item);
  }
  return out + "]";
}

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// The length of the valid UTF-8 sequence that starts at text[i] (1 to 4 bytes), or 0 where the
// bytes there are not one (a stray continuation byte, a truncated or overlong sequence, a
// surrogate, a code point past U+10FFFF).
std::size_t utf8_length(const std::string& text, std::size_t i) {
  const auto at = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = at(i);
  std::size_t n;
  unsigned lo = 0x80, hi = 0xbf;  // the range of the second byte
  if (lead >= 0xc2 && lead <= 0xdf)
    n = 2;
  else if (lead >= 0xe0 && lead <= 0xef) {
    n = 3;
    if (lead == 0xe0) lo = 0xa0;
    if (lead == 0xed) hi = 0x9f;
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    n = 4;
    if (lead == 0xf0) lo = 0x90;
    if (lead == 0xf4) hi = 0x8f;
  } else {
    return 0;
  }
  if (i + n > text.size() || at(i + 1) < lo || at(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (at(i + k) < 0x80 || at(i + k) > 0xbf) return 0;
  return n;
}

}  // namespace

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x80) {
      // Valid UTF-8 as it is; a byte that is not (a file name in another encoding) as \udcXX,
      // Python's surrogateescape, so that the JSON stays valid and os.fsencode gives it back.
      if (const std::size_t n = utf8_length(text, i); n > 0) {
        out.append(text, i, n);
        i += n - 1;
      } else {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\udc%02x", byte);
        out += escaped;
      }
    } else if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (byte < 0x20 || byte == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", byte);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string json_number(double x) {
  return std::isfinite(x) ? round_trip(x) : "null";
}

std::string sidecar_path(const std::string& output, bool written_in_place) {
  if (output.empty() || output == "-" || written_in_place) return {};
  return output + ".json";
}

NamedPath sidecar_named(const std::string& path, const std::string& flag) {
  return {"the provenance file of " + flag + " (" + path + ")", path,
          "give " + flag + " another name, or pass --no-provenance to leave the provenance out"};
}

void open_sidecar(std::optional<AtomicFile>& sidecar, const std::string& path,
                  const std::string& flag) {
  try {
    sidecar.emplace(path);
  } catch (const OutputError& e) {
    if (!e.bad_path) throw;
    throw OutputError(std::string(e.what()) + "; it is the provenance file of " + flag +
                          " (its name plus .json): give " + flag +
                          " a shorter name, or pass --no-provenance to leave it out",
                      true);
  }
}

std::string provenance_json(const Provenance& p) {
  const Processor cpu = this_processor();
  std::string out = "{\n";
  const auto line = [&](const std::string& key, const std::string& value, bool last = false) {
    out += "  " + json_string(key) + ": " + value + (last ? "\n" : ",\n");
  };
  line("impact_version", json_string(std::string(version())));
  line("impact_commit", json_string(std::string(commit())));
  line("command", json_string(p.command));
  line("arguments", json_list(p.arguments));
  line("scene_path", json_string(p.scene_path));
  line("scene_text", json_string(p.scene_text));
  line("overrides", json_list(p.overrides));
  line("unsets", json_list(p.unsets));
  if (p.scene) {
    line("method", json_string(std::string(method_name(p.scene->method))));
    line("force_depends_on_t", constant_force(p.scene->model) ? "false" : "true");
    line("scene_as_run", json_string(resolved_scene(*p.scene)));
  }
  line("processor", json_string(cpu.describe()));
  line("date", json_string(utc_now()));
  std::string summary = "{";
  for (const auto& [name, value] : p.summary)
    summary += (summary.size() > 1 ? ", " : "") + json_string(name) + ": " + value;
  line("summary", summary + "}");
  line("summary_line", json_string(p.summary_line), true);
  return out + "}\n";
}

}  // namespace impact
