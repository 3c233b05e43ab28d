// The suite itself: every ctest entry runs the one test case it is named after and every test case
// has one entry (tests/cmake/CtestEntries.cmake over this build), and a test executable whose
// filter matches nothing fails (tests/main.cpp). Catch2 names holding a ';' used to become two
// entries that ran nothing and passed, so that three claim tests never ran.
#include <catch2/catch.hpp>
#include <string>

#include "cli_support.hpp"

using impact::testing::quote;
using impact::testing::Result;
using impact::testing::TempDir;

namespace {

const std::string kSelf = std::string(IMPACT_TESTS_BINARY_DIR) + "/test_ctest_entries";
const std::string kMapName =
    "suite: every ctest entry runs exactly the test case it names and each test case has one entry";
const std::string kSplitName =
    "suite: the map check names a test case whose entry was split and an entry that runs nothing";
const std::string kNoTestsName =
    "suite: a test executable exits 2 when its filter matches no test case (--warn NoTests)";

// CtestEntries.cmake on the ctest entries of `ctest_dir`, for the executables of this build's
// tests/ named after the test_*.cpp of `sources_dir`.
Result check_map(const TempDir& dir, const std::string& ctest_dir, const std::string& sources_dir) {
  return dir.shell(quote(IMPACT_CMAKE) + " -D CTEST_COMMAND=" + quote(IMPACT_CTEST) +
                   " -D CTEST_DIR=" + quote(ctest_dir) +
                   " -D EXECUTABLE_DIR=" + quote(IMPACT_TESTS_BINARY_DIR) +
                   " -D SOURCES_DIR=" + quote(sources_dir) + " -P " +
                   quote(std::string(IMPACT_SOURCE_DIR) + "/tests/cmake/CtestEntries.cmake"));
}

// A CTestTestfile.cmake line: the entry `name` runs this executable with `filter` (ctest names an
// entry "test_x:<test case>").
std::string entry(const std::string& name, const std::string& filter) {
  return "add_test([==[test_ctest_entries:" + name + "]==] [==[" + kSelf + "]==] [==[" + filter +
         "]==])\n";
}

}  // namespace

TEST_CASE(kMapName, "[suite][regression]") {
  TempDir dir;
  const Result r = check_map(dir, IMPACT_BUILD_DIR, std::string(IMPACT_SOURCE_DIR) + "/tests");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(r.out.find("each entry runs its one test case, each test case has one entry") !=
        std::string::npos);
}

TEST_CASE(kSplitName, "[suite]") {
  // What catch_discover_tests made of a name "A; B": the entries "A" and " B", neither of which
  // selects the test case; and an entry whose wildcard selects all three.
  TempDir dir;
  const std::string sources = dir / "sources";
  REQUIRE(dir.shell("mkdir sources && : > sources/test_ctest_entries.cpp").code == 0);
  const std::size_t cut = kSplitName.find(" whose");
  dir.write("CTestTestfile.cmake", entry(kMapName, kMapName) + entry(kNoTestsName, kNoTestsName) +
                                       entry(kSplitName.substr(0, cut), kSplitName.substr(0, cut)) +
                                       entry(kSplitName.substr(cut), kSplitName.substr(cut)) +
                                       entry("suite: *", "suite: *"));
  const Result r = check_map(dir, dir.path(), sources);
  INFO(r.out << r.err);
  CHECK(r.code != 0);
  CHECK(r.err.find("entry 'test_ctest_entries:" + kSplitName.substr(0, cut) +
                   "': its filter selects no test case") != std::string::npos);
  CHECK(r.err.find("entry 'test_ctest_entries:" + kSplitName.substr(cut) +
                   "': its filter selects no test case") != std::string::npos);
  CHECK(r.err.find("entry 'test_ctest_entries:suite: *': its filter selects several") !=
        std::string::npos);
  CHECK(r.err.find("test_ctest_entries: '" + kSplitName + "' has no ctest entry that runs it") !=
        std::string::npos);
  CHECK(r.err.find(kMapName + "' has no") == std::string::npos);
}

TEST_CASE(kNoTestsName, "[suite]") {
  TempDir dir;
  CHECK(dir.shell(quote(kSelf) + " 'suite: no such test case'").code == 2);
  CHECK(dir.shell(quote(kSelf) + " '[no_such_tag]'").code == 2);
  CHECK(dir.shell(quote(kSelf) + " " + quote(kNoTestsName) + " --list-test-names-only").code == 1);
}
