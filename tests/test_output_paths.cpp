// Where `impact run --out` writes, and what a signal leaves behind: the output rows of the table in
// tests/README.md that test_cli.cpp and test_hardening.cpp do not cover. The `impact` command runs
// as a separate process (IMPACT_CLI) in a fresh directory.
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

// Whether a temporary `X.csv.tmp.*` appears in `dir` within `seconds`.
bool temporary_appears(const TempDir& dir, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    for (const auto& name : dir.entries())
      if (name.rfind("X.csv.tmp.", 0) == 0) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

}  // namespace

TEST_CASE("output paths: every signal that ends a run removes the temporary", "[output]") {
  // Every signal whose default action ends the process (signal(7)) but SIGKILL, which cannot be
  // caught, and SIGXFSZ, which impact ignores (test_hardening.cpp, "a file size limit ...").
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
