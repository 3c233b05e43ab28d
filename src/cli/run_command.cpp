#include "cli/run_command.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "cli/progress.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/run_scene.hpp"
#include "impact/run/scene.hpp"
#include "impact/run/step_events.hpp"
#include "scene/provenance.hpp"
#include "scene/read_scene.hpp"

namespace impact::cli {
namespace {

// Beyond o.max_rows rows or these bytes a run asks for output.every or --force before it starts;
// the events, which cannot be counted before the run, stop it when they pass them.
constexpr double kMaxBytesUnasked = 4e9;

// Steps between two checks of a long run (a full disk, the progress line): 2^16 steps of the
// fastest solver (direct, ~3 ns a step) take 0.2 ms, so the clock is read a few thousand times a
// second, not a billion.
constexpr std::int64_t kCheckEvery = std::int64_t{1} << 16;

// Every output (the rows, the events, the rows' provenance) against the scene and each other, as
// the files they lead to (check_distinct).
void check_paths(const RunOptions& o) {
  std::vector<NamedPath> outputs{{"--out", o.out}};
  if (!o.events.empty())
    outputs.push_back({"--events", o.events, "give the events a file of their own"});
  if (!o.no_provenance)
    if (const std::string sidecar = sidecar_path(o.out); !sidecar.empty())
      outputs.push_back(sidecar_named(sidecar, "--out"));
  check_distinct({{"the scene file", o.scene}}, outputs);
}

// The events file: the CSV of write_event, stopped (OutputError) when it passes the limits above
// without --force.
class EventFile {
 public:
  EventFile(const std::string& path, const RunOptions& o, const Model& model)
      : file(path),
        internal_(event_variables(model).size()),
        unlimited_(o.force),
        max_rows_(o.max_rows) {
    write_event_header(file.stream(), model);
  }
  void write(const Event& e) {
    bytes_ += static_cast<double>(write_event(file.stream(), e, internal_));
    if ((++count_ > max_rows_ || bytes_ > kMaxBytesUnasked) && !unlimited_) [[unlikely]]
      throw OutputError("--events: the run has written " + round_trip(count_) + " events (" +
                            round_trip(std::round(bytes_ / 1e9)) +
                            " GB) by t = " + round_trip(e.t) + " and goes on (the limits are " +
                            round_trip(max_rows_) + " events and " +
                            round_trip(kMaxBytesUnasked / 1e9) +
                            " GB); shorten time.T, or pass --force to write them all",
                        false);
  }
  AtomicFile file;

 private:
  std::size_t internal_;  // the internal variables' columns
  bool unlimited_;
  double max_rows_, count_ = 0, bytes_ = 0;
};

// The summary lines `impact run` prints on standard error (and keeps in the provenance).
std::string summary_text(const Scene& scene, const RunReport& report) {
  const MethodInfo& method = method_info(scene.method);
  char line[512];
  std::snprintf(line, sizeof line, "impact: %s, %lld steps, %lld contact steps", method.name.data(),
                static_cast<long long>(report.summary.steps),
                static_cast<long long>(report.summary.contact_steps));
  std::string text = line;
  if (method.can.iterations_channel) {
    std::snprintf(line, sizeof line, ", %lld iterations (max %d per step)",
                  static_cast<long long>(report.summary.iterations), report.summary.max_iterations);
    text += line;
  }
  std::snprintf(line, sizeof line, ", %.3f s wall\n", report.seconds);
  text += line;
  if (!report.errors) return text;
  const ErrorNorms& e = *report.errors;
  std::snprintf(line, sizeof line,
                "impact: against exact: sup|u - u_exact| = %s, h sum|v - v_exact| = %s, "
                "|E(T) - E_exact(T)| = %s, first impact time error = %s; the reference took "
                "%.3f s wall\n",
                round_trip(e.sup_u).c_str(), round_trip(e.l1_v).c_str(),
                round_trip(e.energy_end).c_str(),
                std::isnan(e.first_impact) ? "none (no impact in one of the two)"
                                           : round_trip(e.first_impact).c_str(),
                report.reference_seconds);
  text += line;
  if (!scene.model.internal.empty() || bonded(scene.model)) {
    std::snprintf(line, sizeof line, "impact: against exact: sup|z - z_exact| = %s\n",
                  round_trip(e.sup_internal).c_str());
    text += line;
  }
  return text;
}

// The provenance of the rows (provenance.hpp).
std::string provenance(const RunOptions& o, const Run& loaded, const RunReport& report) {
  Provenance p;
  p.command = "impact run";
  p.arguments = o.arguments;
  p.scene_path = o.scene;
  p.scene_text = loaded.text;
  p.overrides = o.overrides;
  p.unsets = o.unsets;
  p.scene = &loaded.scene;
  const RunSummary& r = report.summary;
  p.summary = {{"steps", std::to_string(r.steps)},
               {"contact_steps", std::to_string(r.contact_steps)},
               {"iterations", std::to_string(r.iterations)},
               {"max_iterations_per_step", std::to_string(r.max_iterations)},
               {"wall_s", json_number(report.seconds)}};
  if (report.errors) {
    const ErrorNorms& e = *report.errors;
    p.summary.insert(p.summary.end(), {{"err_u_sup", json_number(e.sup_u)},
                                       {"err_v_l1", json_number(e.l1_v)},
                                       {"err_E_T", json_number(e.energy_end)},
                                       {"err_first_impact", json_number(e.first_impact)},
                                       {"reference_s", json_number(report.reference_seconds)}});
  }
  p.summary_line = summary_text(loaded.scene, report);
  return provenance_json(p);
}

}  // namespace

int run_command(const RunOptions& o, bool& in_place) {
  const auto start = Clock::now();
  Run loaded = load_run(o.scene, o.overrides, o.unsets);
  const Scene& scene = loaded.scene;
  if (o.against_exact)
    if (const auto r = reference_refusal(scene.model))
      throw SceneError(o.scene + ": --against exact: " + r->message);
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
  const std::int64_t every = scene.output.every, steps = scene.grid.steps;
  const double rows_due = static_cast<double>(steps / every + 1 + (steps % every != 0));
  const double bytes_due = rows_due * 25.0 * static_cast<double>(scene.output.channels.size() + 1);
  if (!o.force && (rows_due > o.max_rows || bytes_due > kMaxBytesUnasked))
    throw SceneError(o.scene + ": output.every = " + std::to_string(scene.output.every) +
                     ": this run would write " + round_trip(rows_due) + " rows (about " +
                     round_trip(std::round(bytes_due / 1e9)) +
                     " GB); set output.every (e.g. --set output.every=" +
                     std::to_string(static_cast<long long>(
                         std::ceil(static_cast<double>(scene.grid.steps) / 1e6))) +
                     " for 1e6 rows) or pass --force");
  AtomicFile file(o.out);
  in_place = file.in_place();
  std::optional<EventFile> events;
  if (!o.events.empty()) {
    events.emplace(o.events, o, scene.model);
    in_place = in_place || events->file.in_place();
  }
  // The provenance sidecar is opened with the outputs, so that a path it cannot have is refused
  // before the run.
  std::optional<AtomicFile> sidecar;
  if (!o.no_provenance)
    if (const std::string path = sidecar_path(o.out, file.in_place()); !path.empty())
      open_sidecar(sidecar, path, "--out");
  CsvWriter csv(file.stream(), scene.output.channels, scene.model);
  csv.header();
  // Progress only where someone watches it: stderr is a terminal that the CSV does not go to.
  Progress progress(!o.quiet && isatty(2) && !(to_stdout && isatty(1)), scene.grid.steps, start,
                    "impact", "steps");
  RunOutputs outputs;
  outputs.rows = [&](const OutputRow& row) { csv.row(scene.grid.t(row.l), row); };
  if (events) outputs.events = [&](const Event& e) { events->write(e); };
  outputs.against_exact = o.against_exact;
  outputs.check_every = kCheckEvery;
  outputs.check = [&](std::int64_t l) {
    file.check();  // a full disk stops the run here
    if (events) events->file.check();
    progress.update(l);
  };
  const RunReport report = run_scene(scene, loaded.stepper, outputs);
  if (sidecar) std::fputs(provenance(o, loaded, report).c_str(), sidecar->stream());
  // Every output whole before any is put in place: a failed one replaces none.
  file.close();
  if (events) events->file.close();
  if (sidecar) sidecar->close();
  file.commit();
  if (events) events->file.commit();
  if (sidecar) sidecar->commit();
  progress.finish();
  // --quiet drops the summary line, not the errors --against exact was asked to measure.
  const std::string text = summary_text(scene, report);
  std::fputs((o.quiet ? text.substr(text.find('\n') + 1) : text).c_str(), stderr);
  return 0;
}

}  // namespace impact::cli
