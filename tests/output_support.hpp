// What `impact run` writes, checked against the library's own trajectory: the library's run of the
// same scene recorded step by step, decimated here by hand (the rule of `impact run --help`, not
// the package's code), and the CSV files read back exactly. Shared by test_output_scale.cpp and
// test_row_schedule.cpp.
#pragma once

#include <bit>
#include <catch2/catch.hpp>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "impact/forces/work_energy.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/error_norms.hpp"
#include "impact/run/row_stream.hpp"
#include "impact/run/scene.hpp"
#include "impact/run/step_events.hpp"
#include "scene/read_scene.hpp"

namespace impact::testing {

// Step l of the library's run: the state at t_l and what the step that ended there reported.
struct Step {
  State s;
  double force = 0;
  std::int64_t iterations = 0;
  double energy = 0;  // E as the E channel defines it (work_energy.hpp)
};

struct LibraryRun {
  Scene scene;
  std::vector<Step> steps;  // l = 0 .. grid.steps
  std::vector<Event> events;
  ErrorNorms errors;
};

// The scene of `impact run path --set ...` run by the library, every step kept; with_errors also
// measures it against the reference as ErrorObserver does (a second run).
inline LibraryRun library_run(const std::string& path, const std::vector<std::string>& sets,
                              bool with_errors) {
  Run loaded = load_run(path, sets);
  LibraryRun run{loaded.scene, {}, {}, {}};
  const Scene& scene = run.scene;
  run.steps.reserve(static_cast<std::size_t>(scene.grid.steps + 1));
  // A method that follows the motion takes a flight's work from its events (work_energy.hpp).
  WorkEnergy work(scene.model, scene.initial, scene.grid.h,
                  method_info(scene.method).can.exact_events);
  const EventSink sink = [&](const Event& e) {
    run.events.push_back(e);
    work.event(e);
  };
  std::optional<StepEvents> log;
  if (!attach_event_sink(loaded.stepper, sink)) log.emplace(scene.model, scene.grid.h, sink);
  simulate(loaded.stepper, scene.initial, scene.grid,
           [&](std::int64_t l, const State& s, const StepInfo& info) {
             if (l > 0) work.step(l, s);
             if (log) (*log)(l, s, info);
             run.steps.push_back({s, info.contact_force, info.iterations, work.energy(s)});
           });
  if (with_errors) {
    // measure_errors(), whose energy error compares v^2/2 - f u at T; with f(t) `impact run`
    // compares E as the channel defines it, the run's last E above against the reference's.
    AnyStepper stepper = make_stepper(scene);
    ErrorObserver errors(scene.model, scene.initial, scene.grid);
    const RunSummary summary = simulate(stepper, scene.initial, scene.grid, errors);
    run.errors = constant_force(scene.model) ? errors.result(summary)
                                             : errors.result(summary, run.steps.back().energy);
  }
  return run;
}

// The rows `impact run` must write for output.every = every, by its rule: l = 0, every, 2 every,
// ..., and the last step; a row's N is the mean of N over the steps since the previous row (the
// step's own N when it is one step), its iterations their sum. Columns: t, u, v, N, E, iterations.
inline std::vector<std::vector<double>> decimate(const LibraryRun& run, std::int64_t every) {
  std::vector<std::vector<double>> rows;
  const std::int64_t last = run.scene.grid.steps;
  std::int64_t previous = 0;
  for (std::int64_t l = 0; l <= last; l = (l == last) ? last + 1 : std::min(l + every, last)) {
    double sum = 0;
    std::int64_t iterations = 0;
    for (std::int64_t j = previous + 1; j <= l; ++j) {
      sum += run.steps[static_cast<std::size_t>(j)].force;
      iterations += run.steps[static_cast<std::size_t>(j)].iterations;
    }
    const Step& at = run.steps[static_cast<std::size_t>(l)];
    const double force = l - previous == 1   ? at.force
                         : l - previous == 0 ? 0.0
                                             : sum / static_cast<double>(l - previous);
    rows.push_back(
        {run.scene.grid.t(l), at.s.u, at.s.v, force, at.energy, static_cast<double>(iterations)});
    previous = l;
  }
  return rows;
}

// A CSV file of numbers read back exactly (std::from_chars); fails the test on a malformed field.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};
inline Table read_table(const std::string& text) {
  Table table;
  std::size_t end = text.find('\n');
  REQUIRE(end != std::string::npos);
  for (std::size_t start = 0, comma; start <= end; start = comma + 1) {
    comma = std::min(text.find(',', start), end);
    table.columns.push_back(text.substr(start, comma - start));
  }
  std::string bad;  // the first malformed line
  for (std::size_t start = end + 1; start < text.size() && bad.empty(); start = end + 1) {
    end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::vector<double> row;
    const char* p = text.data() + start;
    const char* stop = text.data() + end;
    while (p <= stop) {
      double x = 0;
      const auto [next, error] = std::from_chars(p, stop, x);
      if (error != std::errc() || (next != stop && *next != ',')) {
        bad = text.substr(start, end - start);
        break;
      }
      row.push_back(x);
      p = next + 1;
    }
    if (row.size() != table.columns.size() && bad.empty()) bad = text.substr(start, end - start);
    table.rows.push_back(std::move(row));
  }
  INFO("first malformed line: '" << bad << "'");
  REQUIRE(bad.empty());
  REQUIRE(text.back() == '\n');
  return table;
}

// The first difference between the CSV's rows and the expected ones, column by column (bit for
// bit), as text; empty when they are equal.
inline std::string first_difference(const Table& csv, const std::vector<std::vector<double>>& want,
                                    const std::vector<int>& want_columns) {
  if (csv.rows.size() != want.size())
    return "rows: " + std::to_string(csv.rows.size()) + " written, " + std::to_string(want.size()) +
           " due";
  for (std::size_t r = 0; r < want.size(); ++r)
    for (std::size_t c = 0; c < want_columns.size(); ++c) {
      const double got = csv.rows[r][c], due = want[r][static_cast<std::size_t>(want_columns[c])];
      if (std::bit_cast<std::uint64_t>(got) != std::bit_cast<std::uint64_t>(due))
        return "row " + std::to_string(r) + " (t = " + round_trip(want[r][0]) + "), column " +
               csv.columns[c] + ": " + round_trip(got) + " written, " + round_trip(due) + " due";
    }
  return {};
}

}  // namespace impact::testing
