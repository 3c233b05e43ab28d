// Bad input and hostile environments: every row of the table in tests/README.md that
// tests/test_cli.cpp and tests/test_scene*.cpp do not already cover, the regression inputs of the
// fuzzer (tests/fuzz), and the long-run behaviour (memory, progress, interruption). The `impact`
// command runs as a separate process (IMPACT_CLI) in a fresh directory; each case checks the exit
// code, the message, and that no partial output or temporary file is left.
// Where the output goes (paths, full devices and file systems, pipes and links, terminals,
// signals, memory) is in test_hardening_output.cpp.
#include "hardening_support.hpp"

TEST_CASE("hardening: an empty, unreadable or endless scene file exits 2", "[hardening]") {
  TempDir dir;
  dir.write("empty.toml", "");
  CHECK_FAILS_CLEANLY(dir, "run empty.toml -o X.csv", 2,
                      Contains("empty.toml") && Contains("[initial]: required table is missing"));
  std::filesystem::create_directory(dir / "scene_dir");
  CHECK_FAILS_CLEANLY(dir, "run scene_dir -o X.csv", 2,
                      Contains("scene_dir: is a directory, not a scene file"));
  CHECK_FAILS_CLEANLY(dir, "run no_such.toml -o X.csv", 2,
                      Contains("no_such.toml: cannot open the scene file: No such file"));
  // A device that never ends is cut off at 1 MiB instead of being read forever.
  CHECK_FAILS_CLEANLY(dir, "run /dev/zero -o X.csv", 2,
                      Contains("/dev/zero: longer than 1048576 bytes: not a scene file"));
  // A file without read permission (root reads it anyway, so only checked for other users).
  if (geteuid() != 0) {
    dir.write("secret.toml", kShort);
    chmod((dir / "secret.toml").c_str(), 0);
    CHECK_FAILS_CLEANLY(dir, "run secret.toml -o X.csv", 2, Contains("Permission denied"));
  }
}

TEST_CASE("hardening: a scene read from a pipe runs like the file", "[hardening]") {
  TempDir dir;
  dir.write("short.toml", kShort);
  const Result from_file = dir.run("run short.toml -q");
  const Result from_pipe = dir.shell("\"$IMPACT\" run /dev/stdin -q < short.toml");
  REQUIRE(from_file.code == 0);
  CHECK(from_pipe.code == 0);
  CHECK(from_pipe.out == from_file.out);
}

TEST_CASE("hardening: binary garbage and invalid UTF-8 exit 2", "[hardening]") {
  TempDir dir;
  std::mt19937 random(20130601);  // fixed seed: the same bytes in every run
  std::string garbage(4096, '\0');
  for (char& c : garbage) c = static_cast<char>(random() & 0xff);
  dir.write("garbage.toml", garbage);
  CHECK_FAILS_CLEANLY(dir, "run garbage.toml -o X.csv", 2,
                      Contains("garbage.toml:") && Contains("not a valid"));
  dir.write("nul.toml", std::string("[initial]\nu0 = 5\0\n", 19));
  CHECK_FAILS_CLEANLY(dir, "run nul.toml -o X.csv", 2,
                      Contains("nul.toml:2:") && Contains("not a valid TOML scene"));
  dir.write("utf8.toml", "# \xff\xfe broken UTF-8 in a comment\n" + kShort);
  CHECK_FAILS_CLEANLY(dir, "run utf8.toml -o X.csv", 2,
                      Contains("utf8.toml:1:") && Contains("utf-8"));
}

// Fuzzer finding 2 (tests/fuzz/README.md): toml++ 3.3 classifies a non-ASCII character where
// whitespace may follow with a lookup that reaches __builtin_unreachable for e.g. U+00A1..U+0499
// (upstream issues #190, #295). The scene reader now rejects non-ASCII outside comments first.
TEST_CASE("hardening: non-ASCII outside a comment exits 2 (fuzz finding 2)", "[hardening]") {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases{
      {"\xc8\x9a", "1:1"},                         // the fuzzer's input: U+021A alone
      {"\xcf\x86 = 0\n", "1:1"},                   // a Greek bare key
      {"[initial]\nu0 = 5.0 \xc3\xa9\n", "2:10"},  // after a value
      {"s = \"\"\"\\\n\xc2\xa7\"\"\"\n", "2:1"},   // toml++ #190: after a line-ending '\'
      {"[initial]\n\"\xc3\xa9\" = 1\n", "2:2"},    // a quoted key
      {kShort + "[output]\nchannels = [\"\xc3\xbc\"]\n", "10:14"},  // a string value
      {"a = '''x''' \xc2\xa0\n", "1:13"},  // after a multi-line literal string
      {"\xcc\xaa", "1:1"},                 // toml++ #295
  };
  for (const auto& [text, where] : cases) {
    dir.write("u.toml", text);
    CHECK_FAILS_CLEANLY(dir, "run u.toml -o X.csv", 2,
                        Contains("u.toml:" + where + ": not a valid scene: non-ASCII byte 0x") &&
                            Contains("outside a comment"));
  }
  // In comments, anything goes (the paper's ⟂, accents).
  dir.write("comment.toml",
            "# 0 <= u - φ ⟂ N >= 0, déjà vu\n" + kShort + "[output] # sortie: ü\nevery = 10 # ½\n");
  const Result r = dir.run("run comment.toml -q -o X.csv");
  CHECK(r.code == 0);
  CHECK(dir.entries() == std::set<std::string>{"u.toml", "comment.toml", "X.csv", "X.csv.json"});
  // A '#' inside a string does not start a comment.
  dir.write("hash.toml", kShort + "[output]\nchannels = [\"u#\xc3\xa9\"]\n");
  CHECK_FAILS_CLEANLY(dir, "run hash.toml -o X.csv", 2, Contains("hash.toml:10:16"));
  // --set values are TOML too.
  CHECK_FAILS_CLEANLY(dir, "run comment.toml --set method.name=d\xc3\xafrect -o X.csv", 2,
                      Contains("--set method.name=") && Contains("non-ASCII"));
}

// Fuzzer finding 1: toml++ 3.3 asserts a precondition in parse_key() that a table header starting
// with a character that cannot start a key violates (upstream PR #301 for "[[["); assertions are
// compiled out of the packaged library, which then reports the parse error.
TEST_CASE("hardening: malformed table headers exit 2 (fuzz finding 1)", "[hardening]") {
  TempDir dir;
  for (const char* text : {"[#]\n", "[# Re]\nT = 10.0\n", "[[[1]]]\n", "[[=\n", "[[]]\n"}) {
    dir.write("h.toml", text);
    CHECK_FAILS_CLEANLY(dir, "run h.toml -o X.csv", 2,
                        Contains("h.toml:1:") && Contains("not a valid TOML scene"));
  }
  CHECK_THROWS_AS(impact::parse_scene("[#]", "h.toml"), impact::SceneError);
}

// Fuzzer finding 3: the message for an unknown key showed its value with toml++'s formatter, which
// lays out arrays by casting log10 of each number to size_t: undefined for nan, inf, |x| < 0.1
// and INT64_MIN. Values are now written by the scene reader.
TEST_CASE(
    "hardening: an array value with nan, inf or small numbers is shown in a message "
    "(fuzz finding 3)",
    "[hardening]") {
  const auto message = scene_error;
  CHECK_THAT(message("[initial]\nu=[nan]"),
             Contains("s.toml: initial.u = [nan]: unknown key (allowed in [initial]: u0, v0)"));
  CHECK_THAT(message("[initial]\nu = [0.01, -inf, -9223372036854775808, [1e-300], {a = 'x'}]"),
             Contains("initial.u = [0.01, -inf, -9223372036854775808, [1e-300], {a = 'x'}]"));
  // Strings with quotes or control characters are escaped; a long value is cut at 200 chars.
  CHECK_THAT(message("[initial]\nu = \"it's\\u001b[2J\"\n"),
             Contains("initial.u = \"it's\\u001b[2J\""));
  const std::string long_value = message("[initial]\nu = '" + std::string(1000, 'x') + "'\n");
  CHECK_THAT(long_value, Contains("'" + std::string(199, 'x') + "..."));
  CHECK(long_value.size() < 400);
  TempDir dir;
  dir.write("nan.toml", "[initial]\nu=[nan]");
  CHECK_FAILS_CLEANLY(dir, "run nan.toml -o X.csv", 2, Contains("initial.u = [nan]"));
}

TEST_CASE("hardening: duplicate keys and tables exit 2", "[hardening]") {
  TempDir dir;
  dir.write("dup_key.toml", "[initial]\nu0 = 1.0\nu0 = 2.0\nv0 = -1.0\n");
  CHECK_FAILS_CLEANLY(dir, "run dup_key.toml -o X.csv", 2,
                      Contains("dup_key.toml:3:") && Contains("redefine"));
  dir.write("dup_table.toml", kShort + "[time]\nT = 1.0\n");
  CHECK_FAILS_CLEANLY(dir, "run dup_table.toml -o X.csv", 2,
                      Contains("dup_table.toml:9:") && Contains("redefine"));
  // A table defined by a dotted key, then again by a header.
  dir.write("dotted.toml", "time.T = 2.0\n" + kShort);
  CHECK_FAILS_CLEANLY(dir, "run dotted.toml -o X.csv", 2, Contains("dotted.toml:5:"));
}

TEST_CASE("hardening: NaN and inf in every form TOML allows exit 2", "[hardening]") {
  // test_scene.cpp checks one form per key; here every form for every number a scene reads.
  const std::string base_time = "[time]\nT = 0.1\nh = 0.001\n";
  const std::vector<std::pair<std::string, std::string>> slots{
      {"initial.u0", "[initial]\nu0 = X\nv0 = -1.0\n" + base_time + "[method]\nname = 'direct'\n"},
      {"initial.v0", "[initial]\nu0 = 1.0\nv0 = X\n" + base_time + "[method]\nname = 'direct'\n"},
      {"floor.phi", kShort + "[floor]\nphi = X\n"},
      {"floor.cor", kShort + "[floor]\ncor = X\n"},
      {"force.f", kShort + "[force]\nf = X\n"},
      {"time.T",
       "[initial]\nu0 = 1.0\nv0 = -1.0\n[time]\nT = X\nh = 0.001\n[method]\nname='exact'\n"},
      {"time.h",
       "[initial]\nu0 = 1.0\nv0 = -1.0\n[time]\nT = 1.0\nh = X\n[method]\nname='exact'\n"},
      {"method.epsilon", "[initial]\nu0 = 1.0\nv0 = -1.0\n" + base_time +
                             "[method]\nname = 'fb_newton'\nepsilon = X\n"},
      {"method.tolerance", "[initial]\nu0 = 1.0\nv0 = -1.0\n" + base_time +
                               "[method]\nname = 'fb_newton'\ntolerance = X\n"},
      {"method.theta", "[initial]\nu0 = 1.0\nv0 = -1.0\n" + base_time +
                           "[method]\nname = 'moreau_jean'\ntheta = X\n"},
      {"method.stiffness", "[initial]\nu0 = 1.0\nv0 = -1.0\n" + base_time +
                               "[method]\nname = 'penalty'\nstiffness = X\n"},
      {"method.rtol",
       "[initial]\nu0 = 1.0\nv0 = -1.0\n" + base_time + "[method]\nname = 'penalty'\nrtol = X\n"},
      {"method.atol",
       "[initial]\nu0 = 1.0\nv0 = -1.0\n" + base_time + "[method]\nname = 'penalty'\natol = X\n"},
  };
  for (const auto& [key, text] : slots) {
    for (const char* value : {"nan", "+nan", "-nan", "inf", "+inf", "-inf"}) {
      std::string scene = text;
      scene.replace(scene.find('X'), 1, value);
      INFO(key << " = " << value);
      CHECK_THROWS_AS(impact::parse_scene(scene, "s.toml"), impact::SceneError);
      try {
        impact::parse_scene(scene, "s.toml");
      } catch (const impact::SceneError& e) {
        CHECK_THAT(e.what(), Contains(key));
      }
    }
  }
  // And through the command line, as a file and as an override.
  TempDir dir;
  dir.write("s.toml", kShort);
  CHECK_FAILS_CLEANLY(dir, "run s.toml --set initial.v0=-nan -o X.csv", 2,
                      Contains("initial.v0 = nan") && Contains("finite"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml --set force.f=+inf -o X.csv", 2,
                      Contains("force.f = inf") && Contains("finite"));
}

TEST_CASE("hardening: numbers beyond the double or int64 range exit 2", "[hardening]") {
  TempDir dir;
  dir.write("big.toml", "[initial]\nu0 = 1e400\nv0 = -1.0\n");
  CHECK_FAILS_CLEANLY(dir, "run big.toml -o X.csv", 2,
                      Contains("big.toml:2:") && Contains("1e400"));
  dir.write("int.toml", "[initial]\nu0 = 9223372036854775808\nv0 = -1.0\n");
  CHECK_FAILS_CLEANLY(dir, "run int.toml -o X.csv", 2,
                      Contains("int.toml:2:") && Contains("not representable in 64 bits"));
  // The same through --set: a malformed value, not a bare word taken as a string.
  dir.write("s.toml", kShort);
  CHECK_FAILS_CLEANLY(dir, "run s.toml --set initial.u0=1e400 -o X.csv", 2,
                      Contains("--set initial.u0=1e400: the value '1e400' is not a TOML value") &&
                          Contains("could not be interpreted"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml --set output.every=9223372036854775808 -o X.csv", 2,
                      Contains("not a TOML value") && Contains("64 bits"));
  // Finite, but the energy (3-1) of the E channel is not.
  dir.write("energy.toml", kShort + "[output]\nchannels = [\"u\", \"E\"]\n");
  CHECK_FAILS_CLEANLY(dir, "run energy.toml --set initial.v0=1e200 -o X.csv", 2,
                      Contains("output.channels: E") && Contains("beyond the double range") &&
                          Contains("v0 = 1e+200"));
  // The same data without E is a fine scene: u = 0.05 + 1e200 t, 1e199 at T = 0.1.
  const Result r = dir.run(
      "run energy.toml --set initial.v0=1e200 "
      "--set 'output.channels=[\"u\"]' -q -o X.csv");
  CHECK(r.code == 0);
  CHECK(slurp(dir / "X.csv").find("\n0.10000000000000001,1.0000000000000001e+199\n") !=
        std::string::npos);
}

TEST_CASE("hardening: a finite scene whose motion overflows exits 1 with no output",
          "[hardening]") {
  TempDir dir;
  // u0 + v0 h = 2e308 overflows on the first step.
  dir.write("overflow.toml",
            "[initial]\nu0 = 1e308\nv0 = 1e308\n[time]\nT = 10.0\nh = 1.0\n"
            "[method]\nname = \"direct\"\n");
  dir.write("X.csv", "an earlier result\n");
  CHECK_FAILS_CLEANLY(
      dir, "run overflow.toml -o X.csv", 1,
      Contains("numerical failure") && Contains("step 0") && Contains("non-finite result u = inf"));
  CHECK(slurp(dir / "X.csv") == "an earlier result\n");
}

TEST_CASE("hardening: output.every up to 2^63 - 1 writes the first and the last row",
          "[hardening]") {
  TempDir dir;
  dir.write("s.toml", kShort);
  // The next row index l + every used to overflow (undefined behaviour, caught by the
  // sanitizer build); now every is capped at the step count.
  const Result sparse = dir.run("run s.toml --set output.every=9223372036854775807 -q");
  REQUIRE(sparse.code == 0);
  const Result full = dir.run("run s.toml -q");
  REQUIRE(full.code == 0);
  std::vector<std::string> lines;
  std::istringstream rows(full.out);
  for (std::string line; std::getline(rows, line);) lines.push_back(line);
  REQUIRE(lines.size() == 102);  // header, l = 0..100
  CHECK(sparse.out == lines[0] + "\n" + lines[1] + "\n" + lines.back() + "\n");
}

TEST_CASE("hardening: --set with trailing TOML, a missing value or no scene exits 2",
          "[hardening]") {
  TempDir dir;
  dir.write("s.toml", kShort);
  // One value per --set: the newline would otherwise have set time.T as well.
  CHECK_FAILS_CLEANLY(dir, "run s.toml --set \"$(printf 'time.h=0.01\\nT = 5')\" -o X.csv", 2,
                      Contains("--set time.h=0.01") && Contains("not a single TOML value"));
  CHECK_FAILS_CLEANLY(dir,
                      "run s.toml --set 'time.h=0.01 # a comment is fine' --set time.T=x -o X.csv",
                      2, Contains("time.T = 'x'") && Contains("must be a number"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml --set", 2, Contains("--set"));
  CHECK_FAILS_CLEANLY(dir, "run -o X.csv", 2, Contains("SCENE"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml s.toml -o X.csv", 2, Contains("s.toml"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml --set time.hh=1 -o X.csv", 2,
                      Contains("time.hh = 1") && Contains("unknown key"));
}
