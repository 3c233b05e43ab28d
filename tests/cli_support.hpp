// Running the real `impact` binary from a test: a scratch directory, the command's exit status
// and what it wrote. Shared by test_cli.cpp, test_cli_run.cpp, test_hardening.cpp,
// test_hardening_output.cpp, test_scene_text.cpp and test_help.cpp.
#pragma once

#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "impact/model/event.hpp"
#include "scene/read_scene.hpp"

namespace impact::testing {

// s quoted for the shell.
inline std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Result {
  int code = -1;  // the exit status, or -1 if the process did not exit normally
  std::string out, err;
};

// A fresh directory under /tmp in which commands run; removed with everything in it (also after
// a test took its permissions away).
class TempDir {
 public:
  // Under `base`: /tmp, or a memory file system (/dev/shm) for tests that write gigabytes.
  explicit TempDir(const std::string& base = "/tmp") {
    std::string name = base + "/impact_test_XXXXXX";
    REQUIRE(mkdtemp(name.data()) != nullptr);
    path_ = name;
    char cap[] = "/tmp/impact_test_capture_XXXXXX";
    REQUIRE(mkdtemp(cap) != nullptr);
    capture_ = cap;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add, ignored);
    std::filesystem::remove_all(path_, ignored);
    std::filesystem::remove_all(capture_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::string& path() const { return path_; }
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }

  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(*this / name, std::ios::binary) << text;
    return *this / name;
  }

  // Runs `impact <args>` in this directory (standard output to `stdout_to` when given, else
  // captured).
  Result run(const std::string& args, const std::string& stdout_to = "") const {
    return shell("\"$IMPACT\" " + args + (stdout_to.empty() ? "" : " >" + quote(stdout_to)) +
                 " </dev/null");
  }

  // Runs a shell script in this directory, with $IMPACT the command; captures what the script
  // writes to standard output and error.
  Result shell(const std::string& script) const {
    const std::string out = capture_ + "/stdout", err = capture_ + "/stderr";
    const std::string command = "cd " + quote(path_) + " && IMPACT=" + quote(IMPACT_CLI) +
                                " && { " + script + "\n} >" + quote(out) + " 2>" + quote(err);
    const int status = std::system(command.c_str());
    Result r;
    r.code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  // The names in the directory (to check that nothing, not even a temporary, is left behind).
  std::set<std::string> entries(const std::string& sub = "") const {
    std::set<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(sub.empty() ? path_ : *this / sub))
      names.insert(e.path().filename().string());
    return names;
  }

 private:
  std::string path_, capture_;
};

// A short scene that reaches the floor (u0 = 0.05, v0 = -1: contact at t = 0.05).
const std::string kShort =
    "[initial]\nu0 = 0.05\nv0 = -1.0\n[time]\nT = 0.1\nh = 0.001\n[method]\nname = \"direct\"\n";

// The SceneError message the reader gives for a scene's text, or "no error".
inline std::string scene_error(const std::string& text) {
  try {
    impact::parse_scene(text, "s.toml");
  } catch (const impact::SceneError& e) {
    return e.what();
  }
  return "no error";
}

// The events of a CSV written by --events.
inline std::vector<impact::Event> read_events(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "t,kind,v_before,v_after");
  std::vector<impact::Event> events;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string t, kind, before, after;
    std::getline(fields, t, ',');
    std::getline(fields, kind, ',');
    std::getline(fields, before, ',');
    std::getline(fields, after, ',');
    // strtod, not stod, which throws on a subnormal.
    const auto number = [](const std::string& x) { return std::strtod(x.c_str(), nullptr); };
    impact::Event e{number(t), impact::EventKind::impact, number(before), number(after)};
    if (kind == "stick") e.kind = impact::EventKind::stick;
    if (kind == "lift") e.kind = impact::EventKind::lift;
    REQUIRE((kind == "impact" || kind == "stick" || kind == "lift"));
    events.push_back(e);
  }
  return events;
}

// The value of a JSON string member of a provenance sidecar, `"key": "..."`, unescaped (\n \t \"
// \\ and \uXXXX below 0x80, what the sidecar writes for a scene's text); empty when absent.
inline std::string json_member(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\": \"");
  if (at == std::string::npos) return {};
  std::string out;
  for (std::size_t i = at + key.size() + 5; i < json.size() && json[i] != '"'; ++i) {
    if (json[i] != '\\') {
      out += json[i];
      continue;
    }
    const char c = json[++i];
    if (c == 'n') {
      out += '\n';
    } else if (c == 't') {
      out += '\t';
    } else if (c == 'u') {
      out += static_cast<char>(std::stoi(json.substr(i + 1, 4), nullptr, 16));
      i += 4;
    } else {
      out += c;
    }
  }
  return out;
}

// The run must fail with `code`, a message matching `says`, and leave the directory as it was.
#define CHECK_FAILS_CLEANLY(dir, args, expected_code, says) \
  do {                                                      \
    const auto before_ = (dir).entries();                   \
    const Result r_ = (dir).run(args);                      \
    INFO("impact " << (args) << "\nstderr: " << r_.err);    \
    CHECK(r_.code == (expected_code));                      \
    CHECK_THAT(r_.err, says);                               \
    CHECK((dir).entries() == before_);                      \
  } while (false)

}  // namespace impact::testing
