// What the scene reader does with the text of a scene or a --set before toml++ reads it, as the
// `impact` command shows it (a separate process, IMPACT_CLI, in a fresh directory): keys and
// values nested too deep for toml++'s recursion, a UTF-8 byte-order mark, and text of any length
// in a message.
#include <catch2/catch.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "scene/read_scene.hpp"

using Catch::Contains;

using namespace impact::testing;

// toml++ 3.3 builds a table per part of a dotted key or table name and walks and frees them
// recursively: [a.a.a...] with 40000 parts overflowed 8 MiB of stack (SIGSEGV), 6000 parts 1 MiB.
// The reader rejects keys of more than 8 parts, and values nested more than 8 deep, before toml++
// sees the text, so no input depends on the stack size; every case runs with 1 MiB of stack too.
TEST_CASE("text: a deeply nested key or value exits 2 whatever the stack size", "[text]") {
  TempDir dir;
  const auto dotted = [](std::size_t parts) {
    std::string key = "a";
    for (std::size_t i = 1; i < parts; ++i) key += ".a";
    return key;
  };
  // n nested empty arrays and a newline.
  const auto brackets = [](std::size_t n) {
    return std::string(n, '[') + std::string(n, ']') + '\n';
  };
  const auto check = [&](const std::string& args, const std::string& says) {
    for (const std::string limit : {"", "ulimit -s 1024; "}) {
      const Result r = dir.shell(limit + "\"$IMPACT\" " + args);
      INFO(limit << "impact " << args.substr(0, 200) << "\nstderr: " << r.err.substr(0, 400));
      CHECK(r.code == 2);
      CHECK_THAT(r.err, Contains(says));
      CHECK(r.err.size() < 1000);
    }
  };
  dir.write("header.toml", "[" + dotted(40000) + "]\n");
  check("run header.toml -o X.csv", "header.toml:1:17: not a valid scene: a dotted key");
  dir.write("key.toml", kShort + "[output]\n" + dotted(7000) + " = 1\n");
  check("run key.toml -o X.csv", "key.toml:10:16: not a valid scene: a dotted key");
  dir.write("array_table.toml", "[[" + dotted(7000) + "]]\n");
  check("run array_table.toml -o X.csv", "array_table.toml:1:18: not a valid scene");
  dir.write("inline.toml", "x = {" + dotted(7000) + " = 1}\n");
  check("run inline.toml -o X.csv", "inline.toml:1:21: not a valid scene: a dotted key");
  // Arrays and inline tables nested 255 deep (toml++ stops at 256) with 8-part keys in each: 2000
  // levels of tables, beyond 256 KiB of stack.
  std::string nested = "x = ";
  for (int i = 0; i < 255; ++i) nested += '{' + dotted(7) + " = ";
  nested += '1' + std::string(255, '}') + '\n';
  dir.write("nested.toml", nested);
  check("run nested.toml -o X.csv", "nested.toml:1:");
  const Result small = dir.shell("ulimit -s 256; \"$IMPACT\" run nested.toml -o X.csv");
  CHECK(small.code == 2);
  dir.write("arrays.toml", "x = " + brackets(255));
  check("run arrays.toml -o X.csv",
        "arrays.toml:1:13: not a valid scene: arrays and inline tables");
  // Through --set: an inline table as the value, or more TOML after a newline.
  dir.write("s.toml", kShort);
  check("run s.toml --set " + quote("time.h={" + dotted(40000) + " = 1}") + " -o X.csv",
        "--set time.h={a.a.a");
  check("run s.toml --set \"$(printf 'time.h=1\\n" + dotted(7000) + "=1')\" -o X.csv",
        "a dotted key");
  CHECK(dir.entries() == std::set<std::string>{"header.toml", "key.toml", "array_table.toml",
                                               "inline.toml", "nested.toml", "arrays.toml",
                                               "s.toml"});

  // Within the bound, and dots in strings, comments and numbers, are left to the reader.
  const auto message = scene_error;
  CHECK_THAT(message("[" + dotted(8) + "]\n"), Contains("s.toml: a: unknown table"));
  CHECK_THAT(message("[" + dotted(9) + "]\n"), Contains("s.toml:1:17: not a valid scene"));
  CHECK_THAT(message("[ a . a . 'a' . \"a\" . a.a.a.a.a ]\n"), Contains("s.toml:1:"));
  CHECK_THAT(message(kShort + "[output] # " + dotted(20) + "\nchannels = ['" + dotted(20) +
                     "']\n'" + dotted(20) + "' = [1.5, 2.5, 3.5, 4.5, 5.5, 6.5, 7.5, 8.5, 9.5]\n"),
             Contains("s.toml: output.") && Contains("unknown key"));
  CHECK_THAT(message("x = " + brackets(8)), Contains("s.toml: x: unknown table"));
  CHECK_THAT(message("x = " + brackets(9)), Contains("s.toml:1:13: not a valid scene"));
}

// TOML asks for a valid UTF-8 document, which may start with a byte-order mark; Windows editors
// write one. It used to be "1:1: non-ASCII byte 0xef".
TEST_CASE("text: a UTF-8 byte-order mark is skipped at the start and named elsewhere", "[text]") {
  TempDir dir;
  const std::string bom = "\xEF\xBB\xBF";
  dir.write("plain.toml", kShort);
  dir.write("bom.toml", bom + kShort);
  const Result plain = dir.run("run plain.toml -q"), with_bom = dir.run("run bom.toml -q");
  REQUIRE(plain.code == 0);
  CHECK(with_bom.code == 0);
  CHECK(with_bom.err.empty());
  CHECK(with_bom.out == plain.out);
  // Columns on line 1 count from after the mark, as an editor shows them.
  dir.write("bom_error.toml", bom + "[initial\n");
  CHECK_FAILS_CLEANLY(dir, "run bom_error.toml", 2, Contains("bom_error.toml:1:9:"));
  dir.write("twice.toml", bom + bom + kShort);
  CHECK_FAILS_CLEANLY(dir, "run twice.toml", 2,
                      Contains("twice.toml:1:1: not a valid scene: a UTF-8 byte-order mark") &&
                          Contains("only at the start of the file"));
  dir.write("middle.toml", kShort + bom + "[floor]\n");
  CHECK_FAILS_CLEANLY(dir, "run middle.toml", 2,
                      Contains("middle.toml:9:1:") && Contains("byte-order mark"));
}

// A value or key of any length is cut at 200 characters in a message: a 130 000-character --set
// used to be echoed whole.
TEST_CASE("text: a long value or key is cut in every message", "[text]") {
  TempDir dir;
  dir.write("s.toml", kShort);
  const std::string many(130000, '7'), word(130000, 'k');
  const std::vector<std::string> sets{
      "time.h=" + many,                  // not representable in 64 bits
      "time.h=" + many + ".5",           // a float: shown whole by toml++'s description
      "time.h=1'" + word,                // malformed
      "time.h=" + word,                  // a bare word: must be a number
      "time." + word + "=1",             // an unknown key
      word + ".h=1",                     // an unknown table
      word + "=1",                       // not table.key
      "method.name=" + word,             // an unknown method
      "time.h=\"" + word + "\"\nT = 1",  // more than one value
      "time.h=[" + word.substr(0, 2000) + "]",
  };
  for (const auto& set : sets) {
    const Result r = dir.run("run s.toml -o X.csv --set " + quote(set));
    INFO("--set " << set.substr(0, 40) << "...: " << r.err.substr(0, 2000));
    CHECK(r.code == 2);
    CHECK(r.err.size() < 1000);
    CHECK_THAT(r.err, Contains("--set "));
  }
  for (const auto& text :
       {"[initial]\n" + word + " = 1\n", "[" + word + "]\n", "[initial]\nu0 = '" + word + "'\n",
        "[initial]\nu0 = " + many + "\n", "[initial]\nu0 = " + word + "\n"}) {
    dir.write("long.toml", text);
    const Result r = dir.run("run long.toml -o X.csv");
    INFO(r.err.substr(0, 2000));
    CHECK(r.code == 2);
    CHECK(r.err.size() < 1000);
    CHECK_THAT(r.err, Contains("long.toml"));
  }
  CHECK(dir.entries() == std::set<std::string>{"s.toml", "long.toml"});
}
