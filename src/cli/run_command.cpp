#include "cli/run_command.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "impact/error_norms.hpp"
#include "impact/event_log.hpp"
#include "impact/output.hpp"
#include "impact/registry.hpp"
#include "impact/run.hpp"
#include "impact/work_energy.hpp"
#include "scene/read_scene.hpp"

namespace impact::cli {
namespace {

// Beyond these a run asks for output.every or --force before it starts.
constexpr double kMaxRowsUnasked = 1e8, kMaxBytesUnasked = 4e9;

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A progress line on standard error ("impact: 42% of 100000000 steps, 3 s, about 4 s left"),
// redrawn in place, for runs that take more than a couple of seconds. update() is meant to be
// called every kCheckEvery steps, not every step: it reads the clock.
class Progress {
 public:
  Progress(bool enabled, std::int64_t steps, Clock::time_point start)
      : enabled_(enabled), steps_(steps), start_(start) {}

  void update(std::int64_t l) {
    if (!enabled_) return;
    const double elapsed = seconds_since(start_);
    if (elapsed < kQuietSeconds || elapsed < shown_ + kRedrawSeconds) return;
    shown_ = elapsed;
    const double done = static_cast<double>(l) / static_cast<double>(steps_);
    std::fprintf(stderr, "\rimpact: %3.0f%% of %lld steps, %.0f s, about %.0f s left\x1b[K",
                 100.0 * done, static_cast<long long>(steps_), elapsed,
                 elapsed * (1.0 - done) / done);
    drawn_ = true;
  }
  // Erases the line, so that the summary line (or an error message) starts on a clean line.
  void finish() {
    if (drawn_) std::fputs("\r\x1b[K", stderr);
    drawn_ = false;
  }
  ~Progress() { finish(); }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Steps between two update() calls: 2^16 steps of the fastest solver (direct, ~3 ns a step) take
  // 0.2 ms, so the clock is read a few thousand times a second, not a billion.
  static constexpr std::int64_t kCheckEvery = std::int64_t{1} << 16;

 private:
  static constexpr double kQuietSeconds = 2.0;   // nothing is shown for shorter runs
  static constexpr double kRedrawSeconds = 0.5;  // at most two redraws a second
  bool enabled_;
  std::int64_t steps_;
  Clock::time_point start_;
  double shown_ = 0.0;
  bool drawn_ = false;
};

// The output would replace the scene it was computed from (e.g. --out no_cor.toml).
bool same_file(const std::string& a, const std::string& b) {
  struct stat sa, sb;
  return stat(a.c_str(), &sa) == 0 && stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

// A file given as --out or --events may not be the scene itself, and the two may not be one.
void check_paths(const RunOptions& o) {
  const bool out_to_stdout = o.out.empty() || o.out == "-";
  if (!out_to_stdout && same_file(o.out, o.scene))
    throw OutputError(o.out + ": --out names the scene file itself; give another file name", true);
  if (o.events.empty()) return;
  if (o.events != "-" && same_file(o.events, o.scene))
    throw OutputError(o.events + ": --events names the scene file itself; give another file name",
                      true);
  if ((o.events == "-" && out_to_stdout) || o.events == o.out ||
      (!out_to_stdout && o.events != "-" && same_file(o.events, o.out)))
    throw OutputError(o.events + ": --events and --out name the same output (the rows go to " +
                          (out_to_stdout ? std::string("standard output") : o.out) +
                          "); give the events a file of their own",
                      true);
}

// The events of the run: from the stepper itself where it knows them exactly, else read off its
// steps by an EventLog (event_log.hpp).
struct EventOutput {
  AtomicFile file;
  std::optional<EventLog> log;
  EventOutput(const std::string& path, const Scene& scene, AnyStepper& stepper) : file(path) {
    write_event_header(file.stream());
    EventSink sink = [out = file.stream()](const Event& e) { write_event(out, e); };
    if (!attach_event_sink(stepper, sink)) log.emplace(scene.model, scene.grid.h, std::move(sink));
  }
};

}  // namespace

int run_command(const RunOptions& o, bool& in_place) {
  const auto start = Clock::now();
  Run loaded = load_run(o.scene, o.overrides, o.unsets);
  const Scene& scene = loaded.scene;
  // T not a multiple of h: the grid stops short of T (Grid::covering); say so, and which h fits.
  if (!o.quiet && scene.grid.end() < scene.T && scene.T - scene.grid.end() > 1e-12 * scene.T)
    std::fprintf(stderr,
                 "impact: note: T = %s is not a multiple of h = %s: the run ends at t = %s, the "
                 "last grid time before T; h = %s divides T\n",
                 round_trip(scene.T).c_str(), round_trip(scene.grid.h).c_str(),
                 round_trip(scene.grid.end()).c_str(),
                 round_trip(scene.T / static_cast<double>(scene.grid.steps + 1)).c_str());
  check_paths(o);
  const bool to_stdout = o.out.empty() || o.out == "-";
  // A run that would write more than ~1e8 rows (gigabytes) is most likely a missing output.every.
  const std::int64_t every_step = scene.output.every, steps = scene.grid.steps;
  const double rows_due = static_cast<double>(steps / every_step + 1 + (steps % every_step != 0));
  const double bytes_due = rows_due * 25.0 * static_cast<double>(scene.output.channels.size() + 1);
  if (!o.force && (rows_due > kMaxRowsUnasked || bytes_due > kMaxBytesUnasked))
    throw SceneError(o.scene + ": output.every = " + std::to_string(scene.output.every) +
                     ": this run would write " + round_trip(rows_due) + " rows (about " +
                     round_trip(std::round(bytes_due / 1e9)) +
                     " GB); set output.every (e.g. --set output.every=" +
                     std::to_string(static_cast<long long>(
                         std::ceil(static_cast<double>(scene.grid.steps) / 1e6))) +
                     " for 1e6 rows) or pass --force");
  AtomicFile file(o.out);
  in_place = file.in_place();
  std::optional<EventOutput> events;
  if (!o.events.empty()) {
    events.emplace(o.events, scene, loaded.stepper);
    in_place = in_place || events->file.in_place();
  }
  CsvWriter csv(file.stream(), scene.model, scene.output.channels);
  // E with a time-dependent force needs the work of f over every step, not only the written ones.
  std::optional<WorkEnergy> work;
  if (!constant_force(scene.model) && std::ranges::count(scene.output.channels, Channel::E) > 0)
    work.emplace(scene.model, scene.initial, scene.grid.h);
  csv.use_work(work ? &*work : nullptr);
  csv.header();
  RowSchedule rows(scene.output.every, scene.grid.steps);
  // Progress only where someone watches it: stderr is a terminal that the CSV does not go to.
  Progress progress(!o.quiet && isatty(2) && !(to_stdout && isatty(1)), scene.grid.steps, start);
  // The observer's common path is one comparison, so that the step loop keeps its state in
  // registers (run.hpp): the row and the progress check run out of line, on copies of the state,
  // at the next step where one of them may be due (measured with run.hpp's loop: 10.2 -> 2.7 ns
  // per direct step on Figure 3; asking rows.due() at every step instead: 4.5 rather than 3.0 ns
  // on Figure 4 with COR; experiments/performance/README.md).
  const std::int64_t every = scene.output.every, last = scene.grid.steps;
  std::int64_t next_check = Progress::kCheckEvery, next_event = 0;
  const auto event = [&](std::int64_t l, State s, StepInfo info) __attribute__((noinline)) {
    if (rows.due(l)) csv.row(scene.grid.t(l), s, info);
    if (l == next_check) {
      next_check = l + Progress::kCheckEvery;
      file.check();  // a full disk stops the run here
      if (events) events->file.check();
      progress.update(l);
    }
    // Rows are due only at multiples of `every` and at the last step.
    next_event = std::min(every < last - l ? l + every : last, next_check);
  };
  const auto rows_and_progress = [&](std::int64_t l, const State& s, const StepInfo& info) {
    if (l == next_event) [[unlikely]]
      event(l, s, info);
  };
  // What must see every step (the errors against the exact solution, the work of a time-dependent
  // force, the events of a time-stepper) is called out of line, on copies, so that a run without
  // any keeps the plain loop above.
  std::optional<ErrorObserver> errors;
  if (o.against_exact) errors.emplace(scene.model, scene.initial, scene.grid);
  const auto every_step_watch = [&](std::int64_t l, State s, StepInfo info)
      __attribute__((noinline)) {
    if (errors) (*errors)(l, s, info);
    if (work && l > 0) work->step(l, s);
    if (events && events->log) (*events->log)(l, s, info);
  };
  RunSummary summary;
  if (errors || work || (events && events->log)) {
    summary = simulate(loaded.stepper, scene.initial, scene.grid,
                       [&](std::int64_t l, const State& s, const StepInfo& info) {
                         every_step_watch(l, s, info);
                         rows_and_progress(l, s, info);
                       });
  } else {
    summary = simulate(loaded.stepper, scene.initial, scene.grid, rows_and_progress);
  }
  file.commit();
  if (events) events->file.commit();
  progress.finish();
  const double seconds = seconds_since(start);
  if (!o.quiet) {
    const MethodInfo& method = method_info(scene.method);
    std::fprintf(stderr, "impact: %s, %lld steps, %lld contact steps", method.name.data(),
                 static_cast<long long>(summary.steps),
                 static_cast<long long>(summary.contact_steps));
    if (method.has_iterations)
      std::fprintf(stderr, ", %lld iterations (max %d per step)",
                   static_cast<long long>(summary.iterations), summary.max_iterations);
    std::fprintf(stderr, ", %.3f s wall\n", seconds);
  }
  if (errors) {
    const ErrorNorms e = errors->result(summary);
    std::fprintf(stderr,
                 "impact: against exact: sup|u - u_exact| = %s, h sum|v - v_exact| = %s, "
                 "|E(T) - E_exact(T)| = %s, first impact time error = %s, %.3f s wall\n",
                 round_trip(e.sup_u).c_str(), round_trip(e.l1_v).c_str(),
                 round_trip(e.energy_end).c_str(),
                 std::isnan(e.first_impact) ? "none (no impact in one of the two)"
                                            : round_trip(e.first_impact).c_str(),
                 seconds);
  }
  return 0;
}

}  // namespace impact::cli
