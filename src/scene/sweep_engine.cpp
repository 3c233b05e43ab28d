#include "scene/sweep_engine.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <limits>
#include <mutex>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <tuple>

#include "impact/format.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/run/run_result.hpp"
#include "impact/run/summary.hpp"

namespace impact {
namespace {

using Clock = std::chrono::steady_clock;

// Points per chunk, the unit a thread takes: 192 fills the ensemble's padding (ensemble.cpp)
// exactly.
constexpr std::int64_t kChunkPoints = 192;
// The fewest points on one grid that are stepped together: the ensemble steps 192 lanes at once,
// so fewer points would waste most of them (an AVX2 lane-step costs about a third of a scalar
// step, experiments/performance/README.md).
constexpr std::int64_t kMinEnsemble = 64;

// Runs the chunks of a sweep: chunk c is the shard's points c * chunk ... c * chunk + chunk - 1.
class Runner {
 public:
  Runner(const SweepGrid& grid, const SweepSetup& setup)
      : grid_(grid),
        against_(setup.against_exact),
        shard_(setup.shard),
        instruction_set_(setup.instruction_set),
        poll_(setup.poll) {
    const bool against_exact = setup.against_exact;
    const Shard& shard = setup.shard;
    const std::vector<Quantity>& quantities = setup.quantities;
    points_ = shard_points(grid, shard);
    // A point whose model the reference does not follow is refused before any runs, as a run
    // with the errors against the exact solution is: not measured wrong, nor failed point by point.
    if (against_exact)
      grid.require([](const Scene& scene) { return reference_refusal(scene.model); },
                   "the errors against the exact solution (--against exact)");
    // Points on one grid must be close in the order to share a chunk: a sweep whose grid changes
    // every few points runs point by point, in chunks small enough for every thread to get some.
    const bool together = !against_exact && ensemble_kind(grid.base()) &&
                          grid.shared_grid_run() / shard.n >= kMinEnsemble;
    chunk_ = together ? kChunkPoints : std::clamp<std::int64_t>(points_ / 16, 1, kChunkPoints);
    timed_ = std::find(quantities.begin(), quantities.end(), Quantity::wall_s) != quantities.end();
    // The ensemble keeps the per-step summary only for the columns that read it: a sweep of the
    // final state (u_T, v_T, E_T) steps at close to the kernel's rate.
    const bool per_step = std::any_of(quantities.begin(), quantities.end(), [](Quantity q) {
      return q == Quantity::contact_steps || q == Quantity::impacts ||
             q == Quantity::first_impact_time || q == Quantity::rest_time || q == Quantity::max_u;
    });
    depth_ = per_step ? SummaryDepth::per_step : SummaryDepth::final_state;
  }

  std::int64_t points() const { return points_; }
  std::int64_t chunks() const { return (points_ + chunk_ - 1) / chunk_; }
  std::int64_t chunk_size(std::int64_t c) const { return std::min(chunk_, points_ - c * chunk_); }

  SweepChunk run_chunk(std::int64_t c) const {
    const std::int64_t first = c * chunk_, count = chunk_size(c);
    SweepChunk out{first, std::vector<PointResult>(static_cast<std::size_t>(count)), {}, 0};
    std::vector<PointResult>& results = out.results;
    std::vector<Candidate> candidates;
    Scene scene = grid_.base();
    for (std::int64_t p = 0; p < count; ++p) {
      if (poll_.stop && poll_.stop->load(std::memory_order_relaxed)) throw Interrupted{};
      grid_.apply(point(first + p), scene);
      const auto kind = against_ ? std::nullopt : ensemble_kind(scene);
      if (kind)
        candidates.push_back({p, *kind, scene.grid, scene.model, scene.initial});
      else
        run_alone(scene, results[static_cast<std::size_t>(p)]);
    }
    run_together(first, candidates, results);
    for (const PointResult& r : results) out.failed += !r.outcome;
    return out;
  }

 private:
  // A point the ensemble can step, and what decides which others it can be stepped with.
  struct Candidate {
    std::int64_t position;
    EnsembleKind kind;
    Grid grid;
    Model model;
    State initial;
    auto key() const {
      return std::tuple(kind.method, std::bit_cast<std::uint64_t>(kind.theta),
                        std::bit_cast<std::uint64_t>(grid.h), grid.steps);
    }
  };

  std::int64_t point(std::int64_t position) const { return shard_point(shard_, position); }

  void run_alone(const Scene& scene, PointResult& result) const {
    const auto start = timed_ ? Clock::now() : Clock::time_point();
    // A point that fails, whatever the reason (a non-finite step, a force expression or a rate
    // that is not finite where the run evaluates it, a step whose mean force cannot be resolved),
    // is a row saying so; the other points go on. Running out of memory is the process's failure,
    // not the point's: it stops the sweep.
    try {
      result.outcome = summarize(scene, against_, poll_.stop, poll_.poll_steps);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      result.failure = e.what();
    }
    // The method's own time: the reference's is reported apart (reference_s).
    if (timed_)
      result.wall_s =
          seconds_since(start) - (result.outcome ? result.outcome->reference_seconds : 0);
  }

  // Groups the candidates by grid and method; a group of at least kMinEnsemble points is stepped
  // together (bit-identical to one by one, summary.hpp), the others alone.
  void run_together(std::int64_t first, std::vector<Candidate>& candidates,
                    std::vector<PointResult>& results) const {
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.key() < b.key(); });
    Scene scene = grid_.base();
    std::vector<Model> models;
    std::vector<State> initial;
    std::vector<std::optional<PointSummary>> summaries;
    for (auto begin = candidates.begin(); begin != candidates.end();) {
      const auto end = std::find_if(begin, candidates.end(),
                                    [&](const Candidate& c) { return c.key() != begin->key(); });
      if (end - begin < kMinEnsemble) {
        for (auto c = begin; c != end; ++c) {
          grid_.apply(point(first + c->position), scene);
          run_alone(scene, results[static_cast<std::size_t>(c->position)]);
        }
        begin = end;
        continue;
      }
      models.clear();
      initial.clear();
      for (auto c = begin; c != end; ++c) {
        models.push_back(c->model);
        initial.push_back(c->initial);
      }
      summaries.assign(models.size(), std::nullopt);
      const auto start = timed_ ? Clock::now() : Clock::time_point();
      summarize_together(begin->kind, begin->grid, models, initial, summaries, instruction_set_,
                         poll_.stop, poll_.poll_steps, depth_);
      const double share = timed_ ? seconds_since(start) / static_cast<double>(models.size()) : 0;
      for (auto c = begin; c != end; ++c) {
        PointResult& r = results[static_cast<std::size_t>(c->position)];
        if (auto& s = summaries[static_cast<std::size_t>(c - begin)]) {
          r.outcome = PointOutcome{*s, std::nullopt};
          r.wall_s = share;
        } else {
          // A step was not finite: simulate() stops there and says why.
          grid_.apply(point(first + c->position), scene);
          run_alone(scene, r);
        }
      }
      begin = end;
    }
  }

  const SweepGrid& grid_;
  bool against_;
  Shard shard_;
  const std::string& instruction_set_;
  const SweepPoll& poll_;
  std::int64_t points_ = 0, chunk_ = 1;
  bool timed_ = false;
  SummaryDepth depth_ = SummaryDepth::per_step;
};

// At most 4 chunks per thread wait to be written (flat memory).
std::int64_t run_chunks(const Runner& runner, int threads, const SweepSink& sink,
                        const std::function<void()>& poll) {
  const auto progress = [&](std::int64_t done) {
    if (sink.progress) sink.progress(done);
  };
  const std::int64_t chunks = runner.chunks(), window = 4 * static_cast<std::int64_t>(threads);
  std::vector<SweepChunk> slots(static_cast<std::size_t>(window));
  std::vector<char> ready(static_cast<std::size_t>(window), 0);
  std::mutex mutex;
  std::condition_variable changed;
  std::int64_t next = 0, written = 0;
  bool stop = false;
  std::exception_ptr error;
  const auto work = [&] {
    for (;;) {
      std::int64_t c;
      {
        std::unique_lock lock(mutex);
        changed.wait(lock, [&] { return stop || next >= chunks || next < written + window; });
        if (stop || next >= chunks) return;
        c = next++;
      }
      try {
        SweepChunk out = runner.run_chunk(c);
        if (sink.prepare) sink.prepare(out);
        std::lock_guard lock(mutex);
        slots[static_cast<std::size_t>(c % window)] = std::move(out);
        ready[static_cast<std::size_t>(c % window)] = 1;
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
        stop = true;
      }
      changed.notify_all();
    }
  };
  std::vector<std::jthread> pool;
  // Whatever leaves this function (a write error too) stops the threads before they are joined.
  struct Stop {
    std::mutex& mutex;
    std::condition_variable& changed;
    bool& stop;
    ~Stop() {
      {
        std::lock_guard lock(mutex);
        stop = true;
      }
      changed.notify_all();
    }
  };
  for (int t = 0; t < threads; ++t) {
    try {
      pool.emplace_back(work);
    } catch (const std::system_error& e) {
      // Without a thread the sweep cannot go on; say which one and why (the system's words alone,
      // "Resource temporarily unavailable", do not say what was asked).
      throw std::runtime_error(
          "cannot start thread " + std::to_string(t + 1) + " of " + std::to_string(threads) + ": " +
          e.code().message() +
          (t > 0 ? " (the system's limit on memory or processes; try --threads " +
                       std::to_string(t) + ")"
                 : " (the system's limit on memory or processes: each thread needs its stack, "
                   "8 MiB by default; see ulimit -v and ulimit -u)"));
    }
  }
  const Stop stopper{mutex, changed, stop};
  std::int64_t failed = 0, done = 0;
  for (std::int64_t c = 0; c < chunks; ++c) {
    SweepChunk out;
    {
      std::unique_lock lock(mutex);
      const std::size_t slot = static_cast<std::size_t>(c % window);
      const auto tick = std::chrono::milliseconds(poll ? 20 : 500);
      while (!stop && !ready[slot])
        if (changed.wait_for(lock, tick) == std::cv_status::timeout) {
          lock.unlock();
          progress(done);
          if (poll) poll();
          lock.lock();
        }
      if (stop) break;
      out = std::move(slots[slot]);
      ready[slot] = 0;
      written = c + 1;
    }
    changed.notify_all();
    failed += out.failed;
    if (sink.take) sink.take(std::move(out));  // a full disk stops the sweep here
    done += runner.chunk_size(c);
    progress(done);
  }
  if (error) std::rethrow_exception(error);
  return failed;
}

}  // namespace

std::int64_t shard_points(const SweepGrid& grid, const Shard& shard) {
  return grid.size() > shard.k ? (grid.size() - shard.k + shard.n - 1) / shard.n : 0;
}

SweepRun run_points(const SweepGrid& grid, const SweepSetup& setup, const SweepSink& sink) {
  if (setup.threads < 1 || setup.threads > kMaxThreads)
    throw std::invalid_argument("sweep: " + std::to_string(setup.threads) + " threads (1 to " +
                                std::to_string(kMaxThreads) + ")");
  const Runner runner(grid, setup);
  const std::int64_t failed = run_chunks(runner, setup.threads, sink, setup.poll.poll);
  return {runner.points(), failed};
}

SweepResult sweep(const SweepGrid& grid, const SweepSetup& setup) {
  SweepResult out;
  for (const SweepAxis& axis : grid.axes()) out.names.push_back(axis.key());
  for (Quantity q : setup.quantities) out.names.push_back(quantity_name(q, grid.base().model));
  const auto points = static_cast<std::size_t>(shard_points(grid, setup.shard));
  out.columns.assign(out.names.size(), {});
  for (auto& column : out.columns) column.reserve(points);
  out.failures.reserve(points);
  const std::size_t axes = grid.axes().size();
  const auto take = [&](SweepChunk&& chunk) {
    for (std::size_t p = 0; p < chunk.results.size(); ++p) {
      const std::int64_t i = shard_point(setup.shard, chunk.first + static_cast<std::int64_t>(p));
      for (std::size_t k = 0; k < axes; ++k)
        out.columns[k].push_back(grid.axes()[k].value(grid.index(i, k)));
      PointResult& r = chunk.results[p];
      for (std::size_t q = 0; q < setup.quantities.size(); ++q)
        out.columns[axes + q].push_back(
            r.outcome ? visit_quantity(setup.quantities[q], *r.outcome, r.wall_s,
                                       [](auto x) { return static_cast<double>(x); })
                      : std::numeric_limits<double>::quiet_NaN());
      out.failures.push_back(std::move(r.failure));
    }
  };
  const SweepRun run = run_points(grid, setup, {{}, take, {}});
  out.points = run.points;
  out.failed = run.failed;
  return out;
}

SweepResult sweep(const Scene& scene, std::vector<SweepAxis> axes, const SweepSetup& setup) {
  return sweep(SweepGrid(scene, std::move(axes)), setup);
}

}  // namespace impact
