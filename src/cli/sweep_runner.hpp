// The engine of `impact sweep`: a shard's points cut into chunks, run on a pool of threads (the
// ensemble where the method allows it, point by point otherwise) and written in order.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cli/sweep_csv.hpp"
#include "impact/output.hpp"
#include "scene/sweep_grid.hpp"

namespace impact::cli {

// The points one process runs: shard k of n (0-based k) holds points k, k + n, k + 2n, ...
struct Shard {
  std::int64_t k = 0, n = 1;
  bool given = false;  // --shard was given: the output is a part, for --merge
};

std::int64_t shard_points(const SweepGrid& grid, const Shard& shard);

struct SweepRun {
  std::int64_t points = 0, failed = 0;
};

// Runs the shard's points on `threads` threads and appends their rows to `file` in the order of
// the points, so that the bytes do not depend on the number of threads. With `progress`, a line on
// standard error shows the points done, the rate and the time left.
// `instruction_set` is the ensemble's vector code (empty: the widest this processor has).
// A caller's way to stop a sweep (the Python module's Ctrl-C): `poll`, when given, is called by
// the calling thread at least every 20 ms while it waits, and what it throws leaves run_points;
// `stop`, set by it, is read by every thread between points and every `poll_steps` steps inside
// them (Interrupted, run.hpp), so that the threads stop too.
struct SweepPoll {
  std::function<void()> poll;
  const std::atomic<bool>* stop = nullptr;
  std::int64_t poll_steps = 0;
};
SweepRun run_points(const SweepGrid& grid, const std::vector<Quantity>& quantities,
                    bool against_exact, const Shard& shard, int threads,
                    const std::string& instruction_set, AtomicFile& file, bool progress,
                    const SweepPoll& poll = {});

// The most threads a sweep starts (impact sweep --threads, impact.sweep's threads).
inline constexpr int kMaxThreads = 4096;

}  // namespace impact::cli
