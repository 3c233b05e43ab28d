// Where an output came from, in a sidecar FILE.json beside every CSV that `impact run`, `impact
// sweep` and the Python module write (CSV stays plain, so that no reader trips on comment lines):
// the package's version and commit, the command and its arguments, the scene file's text and the
// --set/--unset given, the scene as it ran with every default filled in (resolved_scene.hpp), the
// processor, the date and the run's summary.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "impact/output/atomic_file.hpp"
#include "impact/run/scene.hpp"

namespace impact {

struct Provenance {
  std::string command;                 // "impact run", "impact sweep", "impact.run (Python)"
  std::vector<std::string> arguments;  // as given on the command line
  std::string scene_path, scene_text;  // the file and its text as read
  std::vector<std::string> overrides, unsets;
  const Scene* scene = nullptr;  // as it ran (for a sweep: its first point)
  // The summary: names with values already written as JSON ("12", "0.25", "\"direct\"", "null").
  std::vector<std::pair<std::string, std::string>> summary;
  std::string summary_line;  // what the command printed on standard error
};

// The sidecar's text: a JSON object, one key per line.
std::string provenance_json(const Provenance& provenance);
// A JSON string literal of `text` (quotes, backslashes and control characters escaped).
std::string json_string(const std::string& text);
// A number as JSON has it: round-trip digits, null for NaN and the infinities.
std::string json_number(double x);
// The sidecar of an output path: path + ".json"; empty when the output is standard output ("" or
// "-") or is not a regular file to be created (a device, a pipe, /dev/stdout), which has no
// place beside it.
std::string sidecar_path(const std::string& output, bool written_in_place);
// The same for an output not opened yet (writes_in_place, atomic_file.hpp).
inline std::string sidecar_path(const std::string& output) {
  return sidecar_path(output, writes_in_place(output));
}
// The sidecar as check_distinct (atomic_file.hpp) names it among a command's outputs: "the
// provenance file of --out (o.csv.json)", to be moved by renaming --out or --no-provenance.
NamedPath sidecar_named(const std::string& path, const std::string& flag);
// Opens `sidecar` at `path` (not empty): an OutputError of its path (a name too long for NAME_MAX
// once ".json" is added) says that --no-provenance leaves it out.
void open_sidecar(std::optional<AtomicFile>& sidecar, const std::string& path,
                  const std::string& flag);

}  // namespace impact
