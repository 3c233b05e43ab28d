#include "performance_cli.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <memory>
#include <stdexcept>
#include <utility>

extern char** environ;

namespace impact {

double run_cli(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid;
  const int err = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) throw std::runtime_error("cannot start " + args[0]);
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("impact run failed: " + args[0] + " ... " + args.back());
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec;
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

void register_cli_run(const std::string& name, const std::vector<std::string>& args,
                      std::int64_t steps,
                      void (*add_statistics)(benchmark::internal::Benchmark*, bool)) {
  auto warm = std::make_shared<bool>(false);
  auto* b =
      benchmark::RegisterBenchmark(name.c_str(), [args, steps, warm](benchmark::State& state) {
        if (!std::exchange(*warm, true)) run_cli(args);
        for (auto _ : state) state.SetIterationTime(run_cli(args));
        state.counters["s_per_step"] = benchmark::Counter(
            static_cast<double>(steps),
            benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
      });
  add_statistics(b, true);
}

}  // namespace impact
