#include "scene/provenance.hpp"

#include <chrono>
#include <cmath>
#include <ctime>

#include "impact/output.hpp"
#include "impact/processor.hpp"
#include "impact/version.hpp"
#include "scene/resolved_scene.hpp"

namespace impact {
namespace {

std::string json_list(const std::vector<std::string>& items) {
  std::string out = "[";
  for (const auto& item : items) out += (out.size() > 1 ? ", " : "") + json_string(item);
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

}  // namespace

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
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
