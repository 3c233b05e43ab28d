// `impact run` as a benchmark (performance.cpp, performance_phases.cpp): one child process per
// repetition, after one untimed run; the time is the child's CPU time (user + system, from wait4),
// and the counter s_per_step is that time per step of the run.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

namespace impact {

// Runs args[0] with args[1..] (standard error to /dev/null); the child's CPU seconds. Throws
// std::runtime_error when it cannot start or does not exit with 0.
double run_cli(const std::vector<std::string>& args);

// Registers `name`: run_cli(args), `steps` steps per run; add_statistics as in performance.cpp.
void register_cli_run(const std::string& name, const std::vector<std::string>& args,
                      std::int64_t steps,
                      void (*add_statistics)(benchmark::internal::Benchmark*, bool));

}  // namespace impact
