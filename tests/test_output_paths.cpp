// Where `impact run --out` writes, and what a signal leaves behind: the output rows of the table in
// tests/README.md that test_cli.cpp and test_hardening.cpp do not cover. A path the user names
// that is a regular file (or does not exist yet) is written to a temporary file and renamed over
// it; anything else (a descriptor such as /dev/stdout, a device, a pipe) is written in place. The
// `impact` command runs as a separate process (IMPACT_CLI) in a fresh directory.
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "cli_support.hpp"

using Catch::Contains;

using namespace impact::testing;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;
const std::string kFigure3 = kSource + "/experiments/figure3/no_cor.toml";

// u0 + v0 h = 2e308 overflows on the first step: a run that starts fails with exit 1, so exit 2
// shows that the output path was refused before the run.
const std::string kOverflow =
    "[initial]\nu0 = 1e308\nv0 = 1e308\n[time]\nT = 10.0\nh = 1.0\n[method]\nname = \"direct\"\n";

// What `impact run s.toml -q` writes to standard output, for comparison.
std::string expected_csv(const TempDir& dir) {
  const Result r = dir.run("run s.toml -q");
  REQUIRE(r.code == 0);
  REQUIRE(!r.out.empty());
  return r.out;
}

// Starts `impact args...` in `cwd` as from a shell prompt: every signal at its default action and
// unblocked (whatever the test runner ignores, e.g. SIGPIPE or SIGHUP, would be inherited, and
// impact leaves an ignored signal ignored), no core file (SIGQUIT, SIGABRT, ... dump core into
// the directory whose entries are checked), standard input and output on /dev/null.
pid_t spawn(const std::vector<std::string>& args, const std::string& cwd) {
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    for (int sig = 1; sig < NSIG; ++sig) sigaction(sig, &default_action, nullptr);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    const rlimit no_core{0, 0};
    setrlimit(RLIMIT_CORE, &no_core);
    if (chdir(cwd.c_str()) != 0 || !freopen("/dev/null", "r", stdin) ||
        !freopen("/dev/null", "w", stdout))
      _exit(127);
    std::vector<char*> argv{const_cast<char*>(IMPACT_CLI)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(IMPACT_CLI, argv.data());
    _exit(127);
  }
  return pid;
}

// Whether a temporary `X.csv.tmp.*` (and `E.csv.tmp.*` when `events`) appears in `dir` within
// `seconds`.
bool temporary_appears(const TempDir& dir, double seconds, bool events = false) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    bool rows = false, event_rows = !events;
    for (const auto& name : dir.entries()) {
      rows = rows || name.rfind("X.csv.tmp.", 0) == 0;
      event_rows = event_rows || name.rfind("E.csv.tmp.", 0) == 0;
    }
    if (rows && event_rows) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

}  // namespace

TEST_CASE("output paths: every signal that ends a run removes the temporary", "[output]") {
  // Every signal whose default action ends the process (signal(7)) but SIGKILL, which cannot be
  // caught, and SIGXFSZ, which impact ignores (test_hardening_output.cpp, "a file size limit ...").
  std::vector<int> signals{SIGHUP,  SIGINT,  SIGQUIT, SIGILL,  SIGTRAP,   SIGABRT, SIGUSR1,
                           SIGUSR2, SIGPIPE, SIGALRM, SIGTERM, SIGSTKFLT, SIGXCPU, SIGVTALRM,
                           SIGPROF, SIGIO,   SIGPWR,  SIGSYS,  SIGRTMIN,  SIGRTMAX};
#ifndef __SANITIZE_ADDRESS__
  // AddressSanitizer installs its own handlers for these three (make asan-test), and impact keeps
  // a handler it finds; elsewhere impact removes the temporary on a crash too.
  for (int sig : {SIGBUS, SIGFPE, SIGSEGV}) signals.push_back(sig);
#endif
  for (int sig : signals) {
    INFO("signal " << sig << " (" << strsignal(sig) << ")");
    TempDir dir;
    dir.write("X.csv", "an earlier result\n");
    // 1e11 steps: minutes of work, signalled once its temporary exists (within milliseconds;
    // 30 s leaves room for a loaded machine).
    const pid_t pid = spawn({"run", kFigure3, "--set", "time.T=100", "--set", "time.h=1e-9",
                             "--set", "output.every=1000000000", "-q", "-o", "X.csv"},
                            dir.path());
    const bool started = temporary_appears(dir, 30.0);
    kill(pid, started ? sig : SIGKILL);
    int status = 0;
    REQUIRE(waitpid(pid, &status, 0) == pid);
    REQUIRE(started);
    // Killed by the signal itself, as a shell expects (the handler re-raises it).
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == sig);
    CHECK(dir.entries() == std::set<std::string>{"X.csv"});
    CHECK(slurp(dir / "X.csv") == "an earlier result\n");
  }
}

TEST_CASE("output paths: a signal removes both temporaries, the rows' and the events'",
          "[output]") {
  for (int sig : {SIGINT, SIGTERM}) {
    INFO("signal " << sig << " (" << strsignal(sig) << ")");
    TempDir dir;
    const pid_t pid =
        spawn({"run", kFigure3, "--set", "time.T=100", "--set", "time.h=1e-9", "--set",
               "output.every=1000000000", "-q", "-o", "X.csv", "--events", "E.csv"},
              dir.path());
    const bool started = temporary_appears(dir, 30.0, true);
    kill(pid, started ? sig : SIGKILL);
    int status = 0;
    REQUIRE(waitpid(pid, &status, 0) == pid);
    REQUIRE(started);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == sig);
    CHECK(dir.entries().empty());
  }
}

TEST_CASE("output paths: /dev/stdout and the other names of a descriptor honour >> and >",
          "[output]") {
  TempDir dir;
  dir.write("s.toml", kShort);
  const std::string csv = expected_csv(dir);
  const std::vector<std::pair<std::string, std::string>> names{{"/dev/stdout", ">>"},
                                                               {"/dev/fd/1", ">>"},
                                                               {"/proc/self/fd/1", ">>"},
                                                               {"/dev/stderr", "2>>"}};
  for (const auto& [name, append] : names) {
    INFO("-o " << name << " " << append << " log.csv");
    // The CSV is appended to what the log held; it used to be renamed over the log.
    dir.write("log.csv", "KEEP\n");
    const Result r = dir.shell("\"$IMPACT\" run s.toml -q -o " + name + " " + append + " log.csv");
    CHECK(r.code == 0);
    CHECK(slurp(dir / "log.csv") == "KEEP\n" + csv);
    CHECK(dir.entries() == std::set<std::string>{"s.toml", "log.csv"});
  }
  // Two runs under one `>` write one after the other, as two `echo`s would: both write at the
  // offset of the one descriptor the shell opened. Not with /dev/stdout: once the first run had
  // renamed over the log, the code before this test found no file behind /dev/stdout and renamed
  // over /dev/stdout itself; /dev/fd and /proc/self/fd hold no files of their own.
  for (const std::string name : {"/dev/fd/1", "/proc/self/fd/1"}) {
    INFO("-o " << name << " twice under > log.csv");
    const Result r = dir.shell("{ \"$IMPACT\" run s.toml -q -o " + name +
                               "; \"$IMPACT\" run s.toml -q -o " + name + "; } > log.csv");
    CHECK(r.code == 0);
    CHECK(slurp(dir / "log.csv") == csv + csv);
  }
  // A link of one's own to /dev/stdout leads there too, and stays a link.
  std::filesystem::create_symlink("/dev/stdout", dir / "out.csv");
  dir.write("log.csv", "KEEP\n");
  Result r = dir.shell("\"$IMPACT\" run s.toml -q -o out.csv >> log.csv");
  CHECK(r.code == 0);
  CHECK(slurp(dir / "log.csv") == "KEEP\n" + csv);
  CHECK(std::filesystem::is_symlink(dir / "out.csv"));
  // Standard output a pipe: the reader gets the CSV.
  r = dir.shell("\"$IMPACT\" run s.toml -q -o /dev/stdout | cat");
  CHECK(r.code == 0);
  CHECK(r.out == csv);
  CHECK(dir.entries() == std::set<std::string>{"s.toml", "log.csv", "out.csv"});
}

TEST_CASE("output paths: a dangling symbolic link creates the file it names", "[output]") {
  TempDir dir;
  dir.write("s.toml", kShort);
  const std::string csv = expected_csv(dir);
  // As `>` in a shell does: the link stays and leads to the new file (it used to be replaced by a
  // regular file).
  std::filesystem::create_directory(dir / "sub");
  std::filesystem::create_symlink("sub/real.csv", dir / "link.csv");
  Result r = dir.run("run s.toml -q -o link.csv");
  CHECK(r.code == 0);
  CHECK(std::filesystem::is_symlink(dir / "link.csv"));
  CHECK(slurp(dir / "sub/real.csv") == csv);
  CHECK(dir.entries("sub") == std::set<std::string>{"real.csv"});
  // A chain of links, relative to the directory of each.
  std::filesystem::create_symlink("../sub/chained.csv", dir / "sub/second.csv");
  std::filesystem::create_symlink("sub/second.csv", dir / "first.csv");
  r = dir.run("run s.toml -q -o first.csv");
  CHECK(r.code == 0);
  CHECK(slurp(dir / "sub/chained.csv") == csv);
  CHECK(std::filesystem::is_symlink(dir / "first.csv"));
  CHECK(std::filesystem::is_symlink(dir / "sub/second.csv"));
  // A link into a missing directory, and a link to itself: exit 2, the links stay.
  std::filesystem::create_symlink("no_such_dir/X.csv", dir / "nowhere.csv");
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o nowhere.csv", 2,
                      Contains("nowhere.csv: cannot create the output file: No such file"));
  std::filesystem::create_symlink("loop.csv", dir / "loop.csv");
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o loop.csv", 2,
                      Contains("loop.csv: ") && Contains("Too many levels of symbolic links"));
  CHECK(std::filesystem::is_symlink(dir / "loop.csv"));
}

TEST_CASE("output paths: a name longer than NAME_MAX or PATH_MAX exits 2 before the run",
          "[output]") {
  TempDir dir;
  dir.write("s.toml", kShort);
  dir.write("overflow.toml", kOverflow);
  // 255 bytes is the longest name (NAME_MAX): it works, its temporary's name is cut to fit; its
  // provenance sidecar would be 260 bytes long, so it is refused before the run unless left out.
  const std::string longest = std::string(251, 'x') + ".csv";
  CHECK_FAILS_CLEANLY(dir, "run s.toml -q -o " + longest, 2,
                      Contains(longest + ".json: the file name is 260 bytes long"));
  Result r = dir.run("run s.toml -q --no-provenance -o " + longest);
  CHECK(r.code == 0);
  CHECK(dir.entries() == std::set<std::string>{"s.toml", "overflow.toml", longest});
  std::filesystem::remove(dir / longest);
  const std::string with_sidecar = std::string(246, 'x') + ".csv";
  r = dir.run("run s.toml -q -o " + with_sidecar);
  CHECK(r.code == 0);
  CHECK(dir.entries() ==
        std::set<std::string>{"s.toml", "overflow.toml", with_sidecar, with_sidecar + ".json"});
  std::filesystem::remove(dir / with_sidecar);
  std::filesystem::remove(dir / (with_sidecar + ".json"));
  // 256 bytes: refused at once (it used to fail at the rename after the whole run, exit 1).
  const std::string too_long = std::string(252, 'x') + ".csv";
  for (const std::string scene : {"s.toml", "overflow.toml"})
    CHECK_FAILS_CLEANLY(
        dir, "run " + scene + " -o " + too_long, 2,
        Contains(too_long + ": the file name is 256 bytes long") && Contains("255 (NAME_MAX)"));
  // The same name reached through a symbolic link: the link stays as it is.
  std::filesystem::create_symlink(too_long, dir / "link.csv");
  CHECK_FAILS_CLEANLY(dir, "run overflow.toml -o link.csv", 2,
                      Contains("link.csv: the file name it leads to is 256 bytes long"));
  CHECK(std::filesystem::is_symlink(dir / "link.csv"));
  // A path of 4096 bytes or more (PATH_MAX counts the terminating NUL), each name short enough.
  std::string deep;
  for (int i = 0; i < 17; ++i) deep += std::string(250, 'd') + "/";
  deep += "X.csv";
  CHECK_FAILS_CLEANLY(
      dir, "run overflow.toml -o " + deep, 2,
      Contains(deep + ": the path is 4272 bytes long") && Contains("4095 (PATH_MAX)"));
}

TEST_CASE("output paths: a read-only file is refused with exit 2", "[output]") {
  TempDir dir;
  dir.write("s.toml", kShort);
  dir.write("overflow.toml", kOverflow);
  dir.write("X.csv", "an earlier result\n");
  // Mode bits rather than access(2): root may write anything, and the tests run as root in CI.
  chmod((dir / "X.csv").c_str(), 0444);
  CHECK_FAILS_CLEANLY(dir, "run overflow.toml -o X.csv", 2,
                      Contains("X.csv: is read-only (mode 0444"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o X.csv", 2, Contains("X.csv: is read-only"));
  // Through a link too.
  std::filesystem::create_symlink("X.csv", dir / "link.csv");
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o link.csv", 2, Contains("link.csv: is read-only"));
  CHECK(slurp(dir / "X.csv") == "an earlier result\n");
  struct stat info;
  REQUIRE(stat((dir / "X.csv").c_str(), &info) == 0);
  CHECK((info.st_mode & 07777) == 0444);
}

TEST_CASE("output paths: a read-only directory is named, exit 2", "[output]") {
  TempDir dir;
  dir.write("s.toml", kShort);
  std::filesystem::create_directory(dir / "ro");
  dir.write("ro/X.csv", "an earlier result\n");
  // The file is writable, but its replacement is created beside it. Checked by the directory's
  // mode bits, which hold for root as well.
  chmod((dir / "ro").c_str(), 0555);
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o ro/X.csv", 2,
                      Contains("ro/X.csv: cannot create the output file: the directory 'ro' is "
                               "not writable"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o ro/new.csv", 2,
                      Contains("ro/new.csv: cannot create the output file: the directory 'ro' is "
                               "not writable"));
  CHECK(dir.entries("ro") == std::set<std::string>{"X.csv"});
  CHECK(slurp(dir / "ro/X.csv") == "an earlier result\n");
  // Writable again, so that TempDir can empty it when the test runs as another user than root.
  chmod((dir / "ro").c_str(), 0755);
}

TEST_CASE("output paths: a numerical failure tells whether rows went out", "[output]") {
  TempDir dir;
  // fb_newton stops at step 4 (test_cli_run.cpp, "a numerical failure exits 1, ..."): rows for
  // l = 0..3 have been written by then.
  dir.write("fail.toml",
            "[initial]\nu0 = 0.005\nv0 = -1.0\n[time]\nT = 0.01\nh = 0.001\n"
            "[method]\nname = \"fb_newton\"\nmax_iterations = 3\n");
  dir.write("log.csv", "KEEP\n");
  Result r = dir.shell("\"$IMPACT\" run fail.toml -o /dev/stdout >> log.csv");
  CHECK(r.code == 1);
  CHECK_THAT(r.err, Contains("numerical failure") && !Contains("no output file written"));
  CHECK(slurp(dir / "log.csv").rfind("KEEP\nt,u,v\n0,", 0) == 0);
  // To a file of its own name, nothing is written.
  r = dir.run("run fail.toml -o X.csv");
  CHECK(r.code == 1);
  CHECK_THAT(r.err, Contains("(no output file written)"));
  CHECK(dir.entries() == std::set<std::string>{"fail.toml", "log.csv"});
}
