// The engine of a parameter sweep, for `impact sweep`, impact.sweep() and a C++ program alike: a
// shard's points cut into chunks, run on a pool of threads (the ensemble where the method allows
// it, point by point otherwise) and handed to the caller in the order of the points, so that what
// it writes does not depend on the number of threads. sweep() keeps the results as columns.
// Installed as <impact/scene/sweep_engine.hpp> with the scene component.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sweep_grid.hpp"
#include "sweep_quantities.hpp"

namespace impact {

// The points one process runs: shard k of n (0-based k) holds points k, k + n, k + 2n, ...
struct Shard {
  std::int64_t k = 0, n = 1;
  bool given = false;  // --shard was given: the output is a part, for --merge
};

std::int64_t shard_points(const SweepGrid& grid, const Shard& shard);
// The grid's index of the shard's point at `position` (0, 1, ...): k + position n.
inline std::int64_t shard_point(const Shard& shard, std::int64_t position) {
  return shard.k + position * shard.n;
}

// A caller's way to stop a sweep (the Python module's Ctrl-C): `poll`, when given, is called by
// the calling thread at least every 20 ms while it waits, and what it throws leaves the sweep;
// `stop`, set by it, is read by every thread between points and every `poll_steps` steps inside
// them (Interrupted, simulate.hpp), so that the threads stop too.
struct SweepPoll {
  std::function<void()> poll;
  const std::atomic<bool>* stop = nullptr;
  std::int64_t poll_steps = 0;
};

// What to run: the quantities each point reports (parse_summary), the reference, the shard, the
// threads (at least 1) and the ensemble's vector code (empty: the widest this processor has).
struct SweepSetup {
  std::vector<Quantity> quantities;
  bool against_exact = false;
  Shard shard;
  int threads = 1;
  std::string instruction_set;
  SweepPoll poll;
};

// The most threads a sweep starts (impact sweep --threads, impact.sweep's threads).
inline constexpr int kMaxThreads = 4096;

// A run of consecutive points of the shard: results[p] is point shard_point(shard, first + p).
struct SweepChunk {
  std::int64_t first = 0;
  std::vector<PointResult> results;
  std::string text;  // what `prepare` made of them (the CSV rows), if anything
  std::int64_t failed = 0;
};

// Where the chunks go. `prepare` runs on the worker thread that ran the chunk (formatting there
// keeps it off the one thread that writes); `take` on the calling thread, chunk after chunk in
// the order of the points; `progress` there too, with the points done so far.
struct SweepSink {
  std::function<void(SweepChunk&)> prepare;
  std::function<void(SweepChunk&&)> take;
  std::function<void(std::int64_t done)> progress;
};

struct SweepRun {
  std::int64_t points = 0, failed = 0;
};

// Runs the shard's points and hands them to `sink`. Throws what a chunk threw (a point's numerical
// failure is its PointResult, not an exception) or what poll threw; the threads are stopped first.
SweepRun run_points(const SweepGrid& grid, const SweepSetup& setup, const SweepSink& sink);

// A sweep as columns: the varied keys' values, then the quantities (named by quantity_name; the
// counts as doubles, NaN where a point failed), one entry per point of the shard in order, and
// each point's failure reason (empty where it did not fail).
struct SweepResult {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  std::vector<std::string> failures;
  std::int64_t points = 0, failed = 0;
};
SweepResult sweep(const SweepGrid& grid, const SweepSetup& setup);
// The same for a Scene a program built and its axes as values: sweep(SweepGrid(scene, axes),
// setup).
SweepResult sweep(const Scene& scene, std::vector<SweepAxis> axes, const SweepSetup& setup);

}  // namespace impact
