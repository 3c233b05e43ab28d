#include "cli/work_precision_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "analysis/markdown.hpp"
#include "analysis/work_precision_lyapunov.hpp"
#include "cli/help_format.hpp"
#include "cli/plot.hpp"
#include "cli/progress.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/scene.hpp"
#include "scene/provenance.hpp"
#include "scene/read_scene.hpp"
#include "scene/sweep_grid.hpp"

namespace impact::cli {
namespace {

// The references part when their distance passes this fraction of an error: beyond, the error
// is the reference's as much as the method's.
constexpr double kPartingFraction = 1e-3;
// Two references delta0 = 1e-10 apart in v0 (estimate_lyapunov), sampled on the experiment's
// step 1e-3 (T / 100 for a shorter T), and at most kPartingSamples times (a longer T).
constexpr double kPartingStep = 1e-3, kPartingSamples = 1e6;

// The time-steppers swept over h: not the references, not penalty (which sweeps a tolerance).
bool steps_over_h(const MethodInfo& m) {
  return !m.can.reference && !std::holds_alternative<PenaltyParams>(m.defaults);
}

std::string swept_method_names() {
  std::string names;
  for (const MethodInfo& m : methods())
    if (steps_over_h(m)) names += (names.empty() ? "" : ", ") + std::string(m.name);
  return names;
}

std::vector<std::string> parse_methods(const std::string& text, const Model& model) {
  std::vector<std::string> names;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    const std::string name = text.substr(begin, comma - begin);
    const MethodInfo* info = find_method(name);
    if (!info || !steps_over_h(*info))
      throw SceneError("--methods " + text + ": '" + name +
                       "' is not a time-stepper swept over h; the methods are " +
                       swept_method_names() + ", comma-separated");
    if (const std::string why = refusal_reason(*info, model); !why.empty())
      throw SceneError("--methods " + text + ": " + name + " cannot run this scene: " + why +
                       " (impact run --help lists what each method honours)");
    if (std::find(names.begin(), names.end(), name) != names.end())
      throw SceneError("--methods " + text + ": " + name + " is named twice");
    names.push_back(name);
    begin = comma + 1;
  }
  return names;
}

// Without --methods: those of the default list that can run the scene, the others named on
// standard error with the reason (unless --quiet); none left is bad input.
std::vector<std::string> default_methods(const Model& model, bool quiet) {
  std::vector<std::string> names;
  std::string left_out;
  const std::string list = kDefaultMethods;
  for (std::size_t begin = 0; begin <= list.size();) {
    const std::size_t comma = std::min(list.find(',', begin), list.size());
    const std::string name = list.substr(begin, comma - begin);
    begin = comma + 1;
    const std::string why = refusal_reason(*find_method(name), model);
    if (why.empty())
      names.push_back(name);
    else
      left_out +=
          "impact work-precision: " + name + " left out of the default methods: " + why + "\n";
  }
  if (names.empty())
    throw SceneError(std::string("--methods (default ") + kDefaultMethods +
                     "): none of them can run this scene; name the methods to sweep, from " +
                     swept_method_names());
  if (!quiet) std::fputs(left_out.c_str(), stderr);
  return names;
}

// --h SPEC as impact sweep's --vary reads it, each h in (0, T].
std::vector<double> parse_steps(const std::string& spec, double T) {
  if (spec.empty()) return swept_steps();
  const std::string prefix = "--vary time.h=" + spec + ": ";
  std::vector<double> steps;
  try {
    const SweepAxis axis("time.h=" + spec);
    for (std::int64_t j = 0; j < axis.size(); ++j) steps.push_back(axis.value(j));
  } catch (const SceneError& e) {
    const std::string why = e.what();
    throw SceneError("--h " + spec + ": " +
                     (why.rfind(prefix, 0) == 0 ? why.substr(prefix.size()) : why));
  }
  for (const double h : steps)
    if (!(h > 0 && h <= T))
      throw SceneError("--h " + spec + ": h = " + round_trip(h) +
                       " is out of range: every h must be in (0, T] = (0, " + round_trip(T) + "]");
  std::sort(steps.begin(), steps.end(), std::greater<>());
  if (std::adjacent_find(steps.begin(), steps.end()) != steps.end() || steps.size() < 2)
    throw SceneError("--h " + spec + ": an order needs at least 2 different steps h");
  return steps;
}

std::string check_against(const std::string& against, const Model& model) {
  const std::string reference(reference_for(model).name);
  if (!against.empty() && against != reference)
    throw SceneError(
        "--against " + against + ": this scene's force " +
        (model.expression.empty() ? "has a closed-form reference" : "is an expression") +
        ", measured against " + reference + "; the allowed value is " + reference);
  return reference;
}

// Every output (the table, its provenance, the figure) against the scene and each other.
void check_paths(const WorkPrecisionCommandOptions& o) {
  std::vector<NamedPath> outputs{{"--out", o.out}};
  if (!o.no_provenance)
    if (const std::string path = sidecar_path(o.out); !path.empty())
      outputs.push_back(sidecar_named(path, "--out"));
  if (!o.plot.empty()) {
    const auto dot = o.plot.rfind('.');
    const std::string ext = dot == std::string::npos ? "" : o.plot.substr(dot + 1);
    if (ext != "png" && ext != "pdf" && ext != "svg")
      throw SceneError("--plot " + o.plot + ": the figure's name must end in .png, .pdf or .svg");
    outputs.push_back({"--plot", o.plot});
  }
  check_distinct({{"the scene file", o.scene}}, outputs);
}

// Per row: where the two references part by more than kPartingFraction of its sup-norm error.
using Partings = std::vector<std::vector<std::optional<double>>>;

Partings partings(const std::vector<impact::Curve>& curves, const LyapunovEstimate& spread) {
  Partings out;
  for (const impact::Curve& c : curves) {
    out.emplace_back();
    for (const WorkPrecisionPoint& p : c.points)
      out.back().push_back(parting_time(spread, kPartingFraction * p.errors.sup_u));
  }
  return out;
}

std::string table(const std::vector<impact::Curve>& curves, const Partings& parted) {
  std::string text =
      "method,h,steps,sup_u,l1_v,energy_end,first_impact,cpu_s,cpu_median_s,repetitions,batch,"
      "reference_s,reference_parts_at\n";
  for (std::size_t i = 0; i < curves.size(); ++i)
    for (std::size_t j = 0; j < curves[i].points.size(); ++j) {
      const WorkPrecisionPoint& p = curves[i].points[j];
      text += curves[i].name + "," + round_trip(p.h) + "," + std::to_string(p.steps);
      for (const ErrorMeasure m : kErrorMeasures) {
        const double e = error_of(p.errors, m);
        text += ",";
        text += std::isfinite(e) ? round_trip(e) : "";  // no impact in the run or the reference
      }
      text += "," + round_trip(p.cost.min) + "," + round_trip(p.cost.median) + "," +
              std::to_string(p.cost.repetitions) + "," + std::to_string(p.cost.batch) + "," +
              round_trip(p.reference_seconds) + ",";
      if (parted[i][j]) text += round_trip(*parted[i][j]);
      text += "\n";
    }
  return text;
}

// The orders (stderr and the sidecar's summary) and the warnings on the reference's horizon.
struct Report {
  std::string lines;
  std::vector<std::pair<std::string, std::string>> summary;
};

Report report(const std::vector<impact::Curve>& curves, const Partings& parted,
              const LyapunovEstimate& spread, double T) {
  Report r;
  double reference_seconds = 0;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const impact::Curve& c = curves[i];
    r.lines += "impact work-precision: " + c.name + ": order";
    for (const ErrorMeasure m : kErrorMeasures) {
      const OrderFit fit = curve_order(c, m);
      const std::string name(measure_name(m));
      r.lines += " " + name + " " + (fit.points >= 2 ? short_number(fit.order) : "-");
      r.summary.emplace_back(c.name + "." + name + "_order", json_number(fit.order));
    }
    const WorkPrecisionPoint& finest = *std::min_element(
        c.points.begin(), c.points.end(), [](const auto& a, const auto& b) { return a.h < b.h; });
    r.lines += "; at h = " + short_number(finest.h) + ": sup_u " +
               short_number(finest.errors.sup_u) + " in " + short_number(finest.cost.min) +
               " s CPU\n";
    r.summary.emplace_back(c.name + ".cpu_s_at_h_min", json_number(finest.cost.min));
    for (const WorkPrecisionPoint& p : c.points) reference_seconds += p.reference_seconds;
    const auto at = parted[i][static_cast<std::size_t>(&finest - c.points.data())];
    if (at)
      r.lines += "impact work-precision: warning: " + c.name + " at h = " + short_number(finest.h) +
                 ": two references 1e-10 apart in v0 part by more than 1e-3 of its error (" +
                 short_number(finest.errors.sup_u) + ") at t = " + short_number(*at) +
                 " s, before T = " + short_number(T) +
                 " s: the motion is sensitive to its start (Lyapunov exponent about " +
                 short_number(spread.lambda) +
                 " 1/s); its errors measure the reference as much as the method (rows with "
                 "reference_parts_at)\n";
  }
  r.lines += "impact work-precision: the reference took " + short_number(reference_seconds) +
             " s wall over all points (not in cpu_s)\n";
  r.summary.emplace_back("reference_s", json_number(reference_seconds));
  return r;
}

}  // namespace

CLI::App* add_work_precision_command(CLI::App& app, WorkPrecisionCommandOptions& o) {
  CLI::App* cmd =
      app.add_subcommand("work-precision", "Errors, CPU time and orders over a sweep of h.");
  cmd->add_option("SCENE", o.scene, "Scene file (TOML); see docs/scenes.md")->required();
  cmd->add_option("--methods", o.methods,
                  "The time-steppers, comma-separated, each with its default parameters (the "
                  "scene's [method] table is not used): " +
                      swept_method_names() +
                      ", e.g. --methods direct,moreau_jean (default: " + kDefaultMethods +
                      ", those of them that can run the scene; standard error names the others "
                      "and why)");
  cmd->add_option("--h", o.steps,
                  "The steps h, as impact sweep's --vary SPEC: a:b:n, a:b:n:log or v1,v2,..., "
                  "each in (0, T], at least 2 different ones, e.g. --h 1e-2:1e-5:10:log "
                  "(default: 1, 2 and 5 times the powers of ten from 0.1 down to 1e-5, as the "
                  "experiment)");
  cmd->add_option("--against", o.against,
                  "The reference the errors are measured against: exact (a constant or harmonic "
                  "force) or event_driven (an expression force); default and only allowed value: "
                  "the scene's own")
      ->check(CLI::IsMember({"exact", "event_driven"}));
  cmd->add_option("--repeat", o.repeat,
                  "Time each solve this many times and keep the fastest (the median is written "
                  "too); solves shorter than 0.2 ms are timed in batches")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--set", o.sets, "Override or add a scene key, as for run, e.g. --set time.T=2")
      ->allow_extra_args(false);
  cmd->add_option("--out,-o", o.out,
                  "The table, CSV (default: standard output); written to a temporary file and "
                  "renamed when complete");
  cmd->add_option("--plot", o.plot,
                  "Also draw the figure with gnuplot: .png, .pdf or .svg, every error measure "
                  "against CPU time and against h, log-log, one curve per method");
  cmd->add_option("--max-steps", o.max_steps,
                  "The most grid steps T/h one run may take (the finest h decides); beyond, the "
                  "command refuses to start unless --force")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--force", o.force, "Run however many steps the finest h asks for");
  cmd->add_flag("--quiet,-q", o.quiet, "Do not print the progress, the orders and the warnings");
  cmd->add_flag("--no-provenance", o.no_provenance,
                "Do not write OUT.json, the provenance of the table with the orders, beside --out");
  cmd->footer(wrap(
      "CSV: one row per method and h: method, h, steps, the errors sup_u (max_l |u^l - u(t_l)|, "
      "m), l1_v (h sum_l |v^l - v(t_l)|, m), energy_end (|E^n - E(T)|, m^2/s^2), first_impact "
      "(|t_1,h - t_1|, s; empty without an impact), cpu_s (CPU seconds of the solve alone, the "
      "fastest of --repeat; the reference is not in it), cpu_median_s, repetitions, batch, "
      "reference_s (wall seconds of the reference's work in the run that measured the errors) "
      "and reference_parts_at. The orders are the least-squares slopes of log error against "
      "log h over the errors above 1e-10; they go to standard error and the sidecar.\nA motion "
      "sensitive to its start (a chaotic one): two references 1e-10 apart in v0 are run over "
      "[0, T]; a row's reference_parts_at is the time where their distance passes 1e-3 of its "
      "sup_u error (empty: it does not before T). At the finest h that gives a warning: the "
      "error there measures the reference as much as the method.\nExit codes: 0 ok, 1 a "
      "numerical failure or a write error, 2 bad input.\nExample: impact work-precision "
      "experiments/figure4/cor075.toml --methods direct,moreau_jean --h 1e-2:1e-5:10:log "
      "--repeat 5 --out wp.csv --plot wp.png",
      kHelpWidth));
  return cmd;
}

int run_work_precision_command(const WorkPrecisionCommandOptions& o) {
  const auto start = Clock::now();
  const Run loaded = load_run(o.scene, o.sets, {});
  const Scene& scene = loaded.scene;
  // Its time-steppers and its reference do not follow a bonding field yet.
  if (bonded(scene.model))
    throw SceneError(o.scene +
                     ": [bonding]: work-precision sweeps time-steppers over h against a "
                     "reference, and neither takes a bonding field yet (exact and event_driven "
                     "run it with impact run)");
  const std::vector<std::string> names = o.methods.empty() ? default_methods(scene.model, o.quiet)
                                                           : parse_methods(o.methods, scene.model);
  const std::vector<double> steps = parse_steps(o.steps, scene.T);
  // Each method runs every h --repeat times and once more against the reference: a step count
  // past what a run can do in hours is most likely a mistyped h.
  if (const double finest = scene.T / steps.back(); !o.force && finest > o.max_steps)
    throw SceneError("--h " + (o.steps.empty() ? std::string("(default)") : o.steps) +
                     ": the finest h = " + round_trip(steps.back()) +
                     " takes T/h = " + round_trip(std::floor(finest)) +
                     " steps per run, more than --max-steps = " + round_trip(o.max_steps) +
                     " (each of " + std::to_string(names.size()) + " methods runs it " +
                     std::to_string(o.repeat + 1) + " times); give a larger h, or pass --force");
  const std::string reference = check_against(o.against, scene.model);
  check_paths(o);
  AtomicFile file(o.out);
  std::optional<AtomicFile> sidecar, figure;  // opened before the run: a bad path is refused now
  if (!o.no_provenance)
    if (const std::string path = sidecar_path(o.out, file.in_place()); !path.empty())
      open_sidecar(sidecar, path, "--out");
  if (!o.plot.empty()) figure.emplace(o.plot);

  const bool to_stdout = o.out.empty() || o.out == "-";
  Progress progress(!o.quiet && isatty(2) && !(to_stdout && isatty(1)),
                    static_cast<std::int64_t>(names.size() * steps.size()), start,
                    "impact work-precision", "points");
  const TimingRule rule{o.repeat, o.repeat, 0.0, TimingRule{}.min_sample_seconds};
  const std::vector<impact::Curve> curves = step_curves(
      scene, names, steps, rule, [&](std::size_t done) { progress.update(std::int64_t(done)); });
  const LyapunovEstimate spread = estimate_lyapunov(
      scene, scene.T, std::max(std::min(kPartingStep, scene.T / 100), scene.T / kPartingSamples));
  const Partings parted = partings(curves, spread);
  progress.finish();
  const Report r = report(curves, parted, spread, scene.T);

  if (figure) {  // before the table, which may go to standard output as it is written
    try {
      run_gnuplot(gnuplot_script(work_precision_figure(curves, reference, o.repeat),
                                 o.plot.substr(o.plot.rfind('.') + 1)),
                  {o.scene}, *figure);
    } catch (const GnuplotError& e) {
      throw OutputError(o.plot + ": " + e.what() + "; no output written", false);
    }
  }
  std::fputs(table(curves, parted).c_str(), file.stream());
  if (sidecar) {
    Provenance p{"impact work-precision",
                 o.arguments,
                 o.scene,
                 loaded.text,
                 o.sets,
                 {},
                 &scene,
                 r.summary,
                 r.lines};
    p.summary.emplace_back("wall_s", json_number(seconds_since(start)));
    std::fputs(provenance_json(p).c_str(), sidecar->stream());
  }
  // Every output whole before any is put in place: a failed one replaces none.
  file.close();
  if (sidecar) sidecar->close();
  if (figure) figure->close();
  file.commit();
  if (sidecar) sidecar->commit();
  if (figure) figure->commit();
  if (!o.quiet) std::fputs(r.lines.c_str(), stderr);
  return 0;
}

}  // namespace impact::cli
