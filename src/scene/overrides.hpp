// The command line's changes to a scene (--set table.key=value, --unset table.key), and where each
// key of a scene came from, so that a message blames the --set that put a bad value there, or the
// --unset that removed a required key, not the file.
#pragma once

#include <toml++/toml.h>

#include <string>
#include <string_view>
#include <vector>

namespace impact {

// Where the keys of a scene came from: the scene file, or the --set or --unset that last changed
// them.
class Origins {
 public:
  explicit Origins(std::string file) : file_(std::move(file)) {}
  // `change` ("--set time.h=1e-4") set table.key; an empty key: it made the table.
  void record(std::string_view table, std::string_view key, std::string change);
  // What a message about table.key (or about the table, for an empty key) names as its source.
  const std::string& of(std::string_view table, std::string_view key = {}) const;
  const std::string& file() const { return file_; }

 private:
  struct Change {
    std::string table, key, change;
  };
  std::string file_;
  std::vector<Change> changes_;  // in command-line order: the last one wins
};

// Applies one --set ("table.key=value": the value is read as a TOML value, or as a string when it
// is a bare word) and records it in `origins`; throws SceneError for a malformed one.
void apply_set(toml::table& root, const std::string& assignment, Origins& origins);

// Removes table.key, or a whole table, that the scene file has ("--unset floor.cor"), and records
// it in `origins`; throws SceneError if it is not there (with the nearest names the file has), is
// malformed, or is also one of `sets`. Unsets are applied before the sets.
void apply_unset(toml::table& root, const std::string& path, const std::vector<std::string>& sets,
                 Origins& origins);

}  // namespace impact
