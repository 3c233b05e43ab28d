#include "cli/sweep.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <optional>
#include <thread>

#include "cli/progress.hpp"
#include "cli/sweep_csv.hpp"
#include "impact/ensemble/ensemble.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/scene.hpp"
#include "scene/provenance.hpp"
#include "scene/sweep_engine.hpp"
#include "scene/sweep_grid.hpp"

namespace impact::cli {
namespace {

Shard parse_shard(const std::string& text) {
  Shard s;
  if (text.empty()) return s;
  const auto slash = text.find('/');
  std::int64_t k = 0, n = 0;
  const auto whole = [](std::string_view t, std::int64_t& x) {
    const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), x);
    return !t.empty() && error == std::errc() && end == t.data() + t.size();
  };
  if (slash == std::string::npos || !whole(std::string_view(text).substr(0, slash), k) ||
      !whole(std::string_view(text).substr(slash + 1), n) || n < 1 || k < 1 || k > n)
    throw SceneError("--shard " + text + ": expected K/N with 1 <= K <= N, e.g. 3/8");
  return {k - 1, n, true};
}

}  // namespace

CLI::App* add_sweep_command(CLI::App& app, SweepOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Run one scene over a grid of parameters on every core: one CSV row of summary quantities "
      "per point. Also: impact sweep --merge PART... --out FILE.");
  cmd->add_option("SCENE", o.scene, "Scene file (TOML); see docs/scenes.md");
  cmd->add_option("--vary", o.varies,
                  "table.key=SPEC: the values of one key (repeatable; the product is swept, the "
                  "last --vary varying fastest), e.g. --vary time.h=1e-4:1e-2:41:log")
      ->allow_extra_args(false);
  cmd->add_option("--set", o.sets, "Override or add a scene key for every point, as for run")
      ->allow_extra_args(false);
  cmd->add_option("--summary", o.summary,
                  "Quantities to write, comma-separated, in this order (default: all but wall_s, "
                  "and the err_* ones with --against exact)");
  cmd->add_option("--against", o.against,
                  "exact: add the error measures against the exact solution (err_*); with "
                  "--summary, that list must name one of them (exit 2 otherwise: the reference "
                  "would run for nothing)");
  cmd->add_option("--threads", o.threads, "Threads (default: one per core)")
      ->check(CLI::Range(1, kMaxThreads));
  cmd->add_option("--shard", o.shard,
                  "K/N: run only points K-1, K-1+N, K-1+2N, ... (1 <= K <= N) and write a part "
                  "for --merge");
  cmd->add_option("--merge", o.merge,
                  "Join the parts of a sharded sweep into the file one run would have written")
      ->allow_extra_args(true);
  cmd->add_option("--instruction-set", o.instruction_set,
                  "The ensemble's vector code: avx512f, avx2 or baseline (default: the widest this "
                  "processor has); all give the same bytes");
  cmd->add_option("--out,-o", o.out,
                  "Output CSV file (default: standard output), renamed into place when complete");
  cmd->add_flag("--quiet,-q", o.quiet, "Do not print the progress and summary lines");
  cmd->add_flag("--no-provenance", o.no_provenance,
                "Do not write OUT.json, the provenance of the rows, beside --out");
  std::string keys;
  for (const std::string& k : sweep_keys()) keys += (keys.empty() ? "" : ", ") + k;
  cmd->footer(
      "SPEC: a:b:n      n values from a to b, evenly spaced, both ends included\n"
      "      a:b:n:log  n values evenly spaced in log10 (a, b > 0)\n"
      "      v1,v2,...  the numbers given\n"
      "Keys: " +
      keys +
      ".\nEvery point is checked as a scene before any runs (exit 2 names the point and the key).\n"
      "\nCSV: the varied values (17 digits: --set key=<that text> gives the point to impact run),\n"
      "the quantities, and 'failure' (empty, or why the point failed, quoted). Rows are in the\n"
      "order of the points, the last --vary fastest, whatever --threads is. Quantities:\n" +
      quantities_help() +
      "\ndirect (closed-form free flight) and moreau_jean points that share h are stepped\n"
      "together in the vectorised ensemble, bit-identical to impact run; other methods run\n"
      "point by point; all on --threads threads. A part (--shard) starts with a line\n"
      "'# impact sweep part K/N ...'; --merge checks that the parts belong together.\n"
      "\nExit codes: 0 ok, 1 a point failed numerically (its row says why) or a write error,\n"
      "2 bad input.\n"
      "Example: impact sweep experiments/figure4/no_cor.toml --vary time.h=1e-4:1e-2:41:log \\\n"
      "           --summary rest_time,E_T --out h_sweep.csv");
  return cmd;
}

int run_sweep(const SweepOptions& o) {
  if (!o.merge.empty()) {
    if (!o.scene.empty() || !o.varies.empty() || !o.sets.empty() || !o.shard.empty() ||
        !o.summary.empty() || !o.against.empty() || !o.instruction_set.empty())
      throw SceneError("--merge takes only the parts and --out: no SCENE, --vary, --set, ...");
    return merge_parts(o.merge, o.out);
  }
  if (o.scene.empty()) throw SceneError("SCENE is required (or --merge PART...)");
  const auto start = Clock::now();
  if (!o.against.empty() && o.against != "exact")
    throw SceneError("--against " + o.against + ": the only reference is 'exact'");
  const bool against = !o.against.empty();
  const Shard shard = parse_shard(o.shard);
  if (!o.instruction_set.empty()) {
    const auto supported = Ensemble::supported_instruction_sets();
    if (std::find(supported.begin(), supported.end(), o.instruction_set) == supported.end()) {
      std::string names;
      for (auto n : supported) names += (names.empty() ? "" : ", ") + std::string(n);
      throw SceneError("--instruction-set " + o.instruction_set +
                       ": not one this processor runs (" + names + ")");
    }
  }
  const int threads = o.threads > 0
                          ? o.threads
                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::vector<SweepAxis> axes;
  for (const std::string& vary : o.varies) axes.emplace_back(vary);
  const SweepGrid grid(o.scene, o.sets, std::move(axes));
  // The internal variables' columns are the scene's (z_T named after them).
  const std::vector<Quantity> quantities = parse_summary(o.summary, against, grid.base().model);

  const bool to_stdout = o.out.empty() || o.out == "-";
  std::vector<NamedPath> outputs{{"--out", o.out}};
  if (!o.no_provenance)
    if (const std::string path = sidecar_path(o.out); !path.empty())
      outputs.push_back(sidecar_named(path, "--out"));
  check_distinct({{"the scene file", o.scene}}, outputs);
  AtomicFile file(o.out);
  std::optional<AtomicFile> sidecar;  // opened before the run: a bad path is refused at once
  if (!o.no_provenance)
    if (const std::string path = sidecar_path(o.out, file.in_place()); !path.empty())
      open_sidecar(sidecar, path, "--out");
  std::string head;
  if (shard.given)
    head = part_line(shard.k + 1, shard.n, grid.size(),
                     sweep_fingerprint(grid.scene_text(), o.sets, o.varies, quantities, against));
  head += csv_header(grid, quantities);
  std::fputs(head.c_str(), file.stream());

  // Progress only where someone watches it: stderr is a terminal that the CSV does not go to.
  Progress shown(!o.quiet && isatty(2) && !(to_stdout && isatty(1)), shard_points(grid, shard),
                 Clock::now(), "impact sweep", "points", true);
  const auto rows = [&](SweepChunk& chunk) {
    RowWriter writer(grid, quantities);
    for (std::size_t p = 0; p < chunk.results.size(); ++p)
      writer.append(chunk.text, shard_point(shard, chunk.first + static_cast<std::int64_t>(p)),
                    chunk.results[p]);
  };
  const auto write = [&](SweepChunk&& chunk) {
    std::fwrite(chunk.text.data(), 1, chunk.text.size(), file.stream());
    file.check();  // a full disk stops the sweep here
  };
  const SweepRun run =
      run_points(grid, {quantities, against, shard, threads, o.instruction_set, {}},
                 {rows, write, [&](std::int64_t done) { shown.update(done); }});
  shown.finish();
  const double seconds = seconds_since(start);
  char line[256];
  std::snprintf(
      line, sizeof line, "impact sweep: %lld points, %lld failed, %d threads, %.3f s wall\n",
      static_cast<long long>(run.points), static_cast<long long>(run.failed), threads, seconds);
  if (sidecar) {
    Provenance p{"impact sweep", o.arguments, o.scene, grid.scene_text(), o.sets, {},
                 &grid.base(),   {},          line};
    p.summary = {{"points", std::to_string(run.points)},
                 {"failed", std::to_string(run.failed)},
                 {"threads", std::to_string(threads)},
                 {"wall_s", json_number(seconds)}};
    std::fputs(provenance_json(p).c_str(), sidecar->stream());
    sidecar->close();
  }
  file.commit();
  if (sidecar) sidecar->commit();
  if (!o.quiet) std::fputs(line, stderr);
  return run.failed > 0 ? 1 : 0;
}

}  // namespace impact::cli
