#include "cli/plot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <optional>
#include <utility>
#include <vector>

#include "cli/help_format.hpp"
#include "cli/plot_data.hpp"
#include "cli/plot_figure.hpp"
#include "cli/sweep_csv.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/output/csv.hpp"
#include "scene/toml_text.hpp"

extern char** environ;

namespace impact::cli {
namespace {

constexpr int kFailure = 1, kBadInput = 2;

std::string default_out(const std::string& csv) {
  const auto dot = csv.rfind(".csv");
  return csv.substr(0, dot == std::string::npos ? csv.size() : dot) + ".png";
}

std::string figure_format(const std::string& out) {
  const auto dot = out.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : out.substr(dot + 1);
  if (ext != "png" && ext != "pdf" && ext != "svg")
    throw PlotInputError(printable(out) + ": --out must end in .png, .pdf or .svg");
  return ext;
}

// The header, after a sweep part's first line ('# impact sweep part K/N ...') if there is one.
std::string read_header(CsvLines& lines) {
  std::string header;
  if (!lines.next(header)) lines.reject("the file is empty: no CSV header");
  if (parse_part_line(header) && !lines.next(header))
    lines.reject("no CSV header after the part's first line");
  return header;
}

// The first MiB of a regular file; nothing when it is not one (a named pipe would wait for a
// writer, a device never end) or cannot be read.
std::string regular_file_head(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return {};
  struct stat info;
  std::string text;
  if (fstat(fd, &info) == 0 && S_ISREG(info.st_mode)) {
    text.resize(1 << 20);
    std::size_t got = 0;
    for (ssize_t n; got < text.size() && (n = read(fd, text.data() + got, text.size() - got)) != 0;)
      if (n > 0)
        got += static_cast<std::size_t>(n);
      else if (errno != EINTR)
        break;
    text.resize(got);
  }
  close(fd);
  return text;
}

// What the provenance sidecar of a run's CSV (CSV.json, written by impact run) says of its force
// and its method; nothing when there is none, it is not a regular file, or it is not one of ours.
// The method is taken only when it is a name of the method table, and then as the table spells it.
void read_sidecar(const std::string& csv, RunData& run) {
  const std::string text = regular_file_head(csv + ".json");
  for (const bool value : {false, true})
    if (text.find(std::string("\n  \"force_depends_on_t\": ") + (value ? "true" : "false") +
                  ",\n") != std::string::npos)
      run.force_depends_on_t = value;
  const std::string key = "\n  \"method\": \"";
  if (const auto at = text.find(key); at != std::string::npos) {
    const auto begin = at + key.size(), end = text.find('"', begin);
    if (end != std::string::npos)
      if (const MethodInfo* method = find_method(std::string_view(text).substr(begin, end - begin)))
        run.method = std::string(method->name);
  }
}

// The figure may not replace what it draws: --out against the CSV, --against and --events, as
// files (a link, another spelling).
void check_out(const PlotOptions& o, const std::string& out) {
  // The provenance files are read for what the E channel is and which method each run is.
  const std::string sidecar = o.csv + ".json";
  const std::string against_sidecar = o.against.empty() ? "" : o.against + ".json";
  const std::pair<const std::string*, const char*> inputs[] = {
      {&o.csv, "the CSV"},
      {&sidecar, "the CSV's provenance"},
      {&o.against, "--against"},
      {&against_sidecar, "the provenance of --against"},
      {&o.events, "--events"}};
  for (const auto& [input, what] : inputs)
    if (!input->empty() && same_output(out, *input))
      throw PlotInputError(printable(out) + ": --out names " + what + " (" + printable(*input) +
                           "), an input of the figure; give the figure another file name");
}

Figure read_figure(const PlotOptions& o) {
  CsvLines lines(o.csv);
  const std::string header = read_header(lines);
  if (is_work_precision_header(header)) {
    if (!o.against.empty() || !o.events.empty())
      throw PlotInputError(printable(o.csv) +
                           ": --against and --events go with the CSV of a run, not of "
                           "impact work-precision");
    return read_work_precision_figure(lines, header);
  }
  const bool extras = !o.against.empty() || !o.events.empty();
  if (extras && (is_sweep_header(header) || is_events_header(header)))
    throw PlotInputError(printable(o.csv) + ": --against and --events go with the CSV of a run, " +
                         "not of a " + (is_sweep_header(header) ? "sweep" : "run's events"));
  if (is_sweep_header(header)) return sweep_figure(read_sweep(lines, header));
  if (is_events_header(header)) return events_figure(read_events(lines, header));
  RunData run = read_run(lines, header);
  read_sidecar(o.csv, run);
  std::optional<RunData> reference;
  if (!o.against.empty()) {
    CsvLines ref_lines(o.against);
    reference = read_run(ref_lines, read_header(ref_lines));
    read_sidecar(o.against, *reference);
    bool shared = false;
    for (const std::string& c : reference->channels)
      shared =
          shared || std::find(run.channels.begin(), run.channels.end(), c) != run.channels.end();
    if (!shared)
      throw PlotInputError(printable(o.against) + ": --against has none of the channels of " +
                           printable(o.csv));
  }
  std::optional<EventsData> events;
  if (!o.events.empty()) {
    CsvLines event_lines(o.events);
    events = read_events(event_lines, read_header(event_lines));
  }
  return run_figure(run, reference ? &*reference : nullptr, events ? &*events : nullptr);
}

std::string describe(int status) {
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status))
    return "was killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
           strsignal(WTERMSIG(status)) + ")";
  return "ended with wait status " + std::to_string(status);
}

}  // namespace

void run_gnuplot(const std::string& script, const std::vector<std::string>& names,
                 AtomicFile& out) {
  std::fflush(out.stream());
  int script_pipe[2];
  if (pipe2(script_pipe, O_CLOEXEC) != 0)
    throw GnuplotError(std::string("cannot start gnuplot: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, script_pipe[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fileno(out.stream()), STDOUT_FILENO);
  // This process ignores SIGPIPE (a gnuplot that stops reading early is reported by its exit
  // status); gnuplot gets the default action back.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  std::vector<std::string> args = {"gnuplot", "-c", "/dev/stdin"};
  args.insert(args.end(), names.begin(), names.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int error = posix_spawnp(&pid, "gnuplot", &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  close(script_pipe[0]);
  if (error != 0) {
    close(script_pipe[1]);
    throw GnuplotError(std::string("cannot start gnuplot: ") + std::strerror(error) +
                       " (is it installed and on PATH? Debian: apt install gnuplot-nox)");
  }
  for (std::size_t done = 0; done < script.size();) {
    const ssize_t n = write(script_pipe[1], script.data() + done, script.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // gnuplot stopped reading: its status says why
    done += static_cast<std::size_t>(n);
  }
  close(script_pipe[1]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR)
      throw GnuplotError(std::string("waiting for gnuplot: ") + std::strerror(errno));
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw GnuplotError("gnuplot " + describe(status));
  struct stat drawn;
  if (!out.in_place() && fstat(fileno(out.stream()), &drawn) == 0 && drawn.st_size == 0)
    throw GnuplotError("gnuplot exited normally but drew nothing");
}

CLI::App* add_plot_command(CLI::App& app, PlotOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "plot",
      "Draw a CSV of impact run, its --events, impact sweep or impact work-precision with "
      "gnuplot: one panel per channel, internal variable or quantity.");
  cmd->add_option("CSV", o.csv,
                  "A CSV written by impact run, run --events, sweep or work-precision")
      ->required();
  cmd->add_option("--out,-o", o.out,
                  "The figure: .png, .pdf or .svg (default: the CSV's name with .png). Written to "
                  "a temporary file and renamed when gnuplot succeeds; never one of the files it "
                  "draws (the CSV, its .json, --against, --events), whatever the spelling or "
                  "link.");
  cmd->add_option("--against", o.against,
                  "Overlay a reference run's channels, dashed: a CSV of impact run, e.g. of the "
                  "exact solution: impact run SCENE --set method.name=exact -o ref.csv");
  cmd->add_option("--events", o.events,
                  "Mark the run's events (impact run --events ev.csv) on every panel, one dotted "
                  "line per event, coloured by kind");
  cmd->footer(wrap(
      "A run's E channel is v^2/2 - f u (kinetic plus potential energy per unit mass, the "
      "paper's (3-1)) for a constant force and v^2/2 - f(0) u(0) - W(t), W the work of f since "
      "t = 0, for a force f(t); the figure says which, from the run's provenance file CSV.json "
      "(both without one). A run's curves are named by its method, from the same file (without "
      "one, by the CSV's name); every panel has the same margins, so the t axes line up, and "
      "the axes span the data. A sweep with more than one varied key gets one curve "
      "per combination of the other keys' values (at most 8). Each curve of more than 8192 "
      "points is drawn through the first, lowest, highest and last value of every group of "
      "consecutive rows (4096 to 8192 groups), which keeps every extreme and every impulse; the "
      "figure says so. Lines longer than 65536 bytes or more than 1e8 rows are refused.",
      kHelpWidth));
  return cmd;
}

int plot_command(const PlotOptions& o) {
  std::signal(SIGPIPE, SIG_IGN);
  try {
    const std::string out = o.out.empty() ? default_out(o.csv) : o.out;
    const std::string format = figure_format(out);
    check_out(o, out);
    const std::string script = gnuplot_script(read_figure(o), format);
    AtomicFile file(out);
    try {
      run_gnuplot(script, {o.csv, o.against, o.events}, file);
    } catch (const GnuplotError& e) {
      throw GnuplotError(printable(o.csv) + ": " + e.what() + "; " +
                         (file.in_place() ? "the figure may be incomplete"
                                          : printable(out) + " is left as it was"));
    }
    file.commit();
    return 0;
  } catch (const PlotInputError& e) {
    std::fprintf(stderr, "impact: error: %s\n", e.what());
    return kBadInput;
  } catch (const OutputError& e) {
    std::fprintf(stderr, "impact: error: %s\n", e.what());
    return e.bad_path ? kBadInput : kFailure;
  } catch (const std::exception& e) {  // gnuplot's failure, or out of memory: after unwinding,
    std::fprintf(stderr, "impact: error: %s\n", e.what());  // so no temporary is left
    return kFailure;
  }
}

}  // namespace impact::cli
