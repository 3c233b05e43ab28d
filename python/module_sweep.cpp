#include "module_sweep.hpp"

#include <pybind11/numpy.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <limits>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "cli/sweep_csv.hpp"
#include "cli/sweep_runner.hpp"
#include "give_array.hpp"
#include "impact/atomic_file.hpp"
#include "module_docs.hpp"
#include "module_gil.hpp"
#include "module_scene.hpp"

namespace py = pybind11;

namespace impact::python {
namespace {

// A file in memory, for the scene text of a sweep given as text or a dict (SweepGrid reads a
// path) and for the rows the engine writes (to an AtomicFile, here /dev/fd/N written in place).
class MemoryFile {
 public:
  explicit MemoryFile(const char* name) : fd_(memfd_create(name, MFD_CLOEXEC)) {
    if (fd_ < 0) throw std::system_error(errno, std::generic_category(), "memfd_create");
  }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;
  ~MemoryFile() { close(fd_); }
  std::string path() const { return "/dev/fd/" + std::to_string(fd_); }
  void write(const std::string& text) const {
    if (::write(fd_, text.data(), text.size()) != static_cast<ssize_t>(text.size()))
      throw std::system_error(errno, std::generic_category(), "write to a memory file");
  }
  std::string read() const {
    std::string text;
    char buffer[1 << 16];
    for (off_t at = 0;;) {
      const ssize_t n = pread(fd_, buffer, sizeof buffer, at);
      if (n < 0) throw std::system_error(errno, std::generic_category(), "read a memory file");
      if (n == 0) return text;
      text.append(buffer, static_cast<std::size_t>(n));
      at += n;
    }
  }

 private:
  int fd_;
};

// The CSV of `impact sweep` as columns: the numbers as float64 (NaN where a point failed), the
// failure reasons as a list of str.
py::dict columns(const std::string& csv) {
  std::vector<std::string> names;
  std::size_t at = 0;
  const std::size_t header_end = csv.find('\n');
  for (std::size_t comma; (comma = csv.find(',', at)) < header_end; at = comma + 1)
    names.push_back(csv.substr(at, comma - at));
  std::vector<std::vector<double>> values(names.size());
  py::list failures;
  for (at = header_end + 1; at < csv.size();) {
    for (auto& column : values) {
      const std::size_t comma = csv.find(',', at);
      double x = std::numeric_limits<double>::quiet_NaN();
      if (comma > at) std::from_chars(csv.data() + at, csv.data() + comma, x);
      column.push_back(x);
      at = comma + 1;
    }
    const std::size_t line_end = csv.find('\n', at);
    std::string failure;
    if (line_end > at)  // "...", with "" for a quote
      for (std::size_t i = at + 1; i + 1 < line_end; ++i)
        if (failure += csv[i]; csv[i] == '"') ++i;
    failures.append(failure);
    at = line_end + 1;
  }
  py::dict out;
  for (std::size_t k = 0; k < names.size(); ++k)
    out[py::str(names[k])] = give(std::move(values[k]));
  out["failure"] = failures;
  return out;
}

// vary's value for one key as --vary's SPEC: a str as it is, a sequence of numbers comma-joined.
std::string axis_spec(const std::string& key, py::handle spec) {
  if (py::isinstance<py::str>(spec)) return spec.cast<std::string>();
  if (!py::isinstance<py::sequence>(spec) && !py::hasattr(spec, "__array__"))
    throw SceneError("vary['" + key + "'] = " + py::repr(spec).cast<std::string>() +
                     ": give 'a:b:n', 'a:b:n:log', 'v1,v2,...' or a sequence of numbers");
  std::string text;
  for (py::handle value : spec) {  // a NumPy scalar as the Python number it holds (set_value)
    if (!text.empty()) text += ',';
    text += set_value(value, "vary['" + key + "']");
  }
  return text;
}

// summary: one str as --summary takes it, or a sequence of names.
std::string summary_list(py::handle summary) {
  if (summary.is_none()) return "";
  if (py::isinstance<py::str>(summary)) return summary.cast<std::string>();
  std::string list;
  for (py::handle name : summary) {
    if (!py::isinstance<py::str>(name))
      throw SceneError("summary: " + py::repr(name).cast<std::string>() +
                       " is not a quantity's name (a str)");
    if (!list.empty()) list += ',';
    list += name.cast<std::string>();
  }
  return list;
}

// threads as --threads takes it (1 to kMaxThreads), None or 0 for one per core.
int thread_count(py::handle threads) {
  if (threads.is_none()) return 0;
  const std::string text = py::repr(threads).cast<std::string>();
  const std::string allowed = ": 1 to " + std::to_string(cli::kMaxThreads) +
                              " as impact sweep --threads, or None or 0 for one per core";
  if (!py::isinstance<py::int_>(threads) || py::isinstance<py::bool_>(threads))
    throw SceneError("threads = " + text + allowed);
  const py::int_ n = py::reinterpret_borrow<py::int_>(threads);
  if (n < py::int_(0) || n > py::int_(cli::kMaxThreads))
    throw SceneError("threads = " + text + allowed);
  return n.cast<int>();
}

py::dict sweep(py::handle scene, py::dict vary, py::handle summary, py::handle set,
               py::handle against, py::handle threads) {
  SceneSource source = scene_source(scene, set, py::none(), py::none());
  MemoryFile scene_file("impact-scene");
  if (source.path.empty()) {
    scene_file.write(source.text);
    source.path = scene_file.path();
  }
  std::vector<std::string> axes;
  for (auto [key, spec] : vary) {
    const std::string name = py::str(key).cast<std::string>();
    axes.push_back(name + "=" + axis_spec(name, spec));
  }
  const std::string list = summary_list(summary);
  const bool exact = !against.is_none();
  if (exact && py::str(against).cast<std::string>() != "exact")
    throw SceneError("against = " + py::str(against).cast<std::string>() +
                     ": the only reference is 'exact' (or None)");
  const std::vector<cli::Quantity> quantities = cli::parse_summary(list, exact);
  int workers = thread_count(threads);
  if (workers == 0) workers = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const SignalPoll poll;
  MemoryFile rows("impact-sweep");
  // The grid reads the scene file (which may be a named pipe) without the GIL too.
  const std::int64_t points = without_gil([&] {
    std::vector<SweepAxis> parsed(axes.begin(), axes.end());
    const SweepGrid grid(source.path, source.overrides, std::move(parsed));
    AtomicFile file(rows.path());
    std::fputs(cli::csv_header(grid, quantities).c_str(), file.stream());
    cli::run_points(grid, quantities, exact, cli::Shard{}, workers, "", file, false,
                    {[&] { poll(); }, poll.stop(), kPollSteps});
    file.commit();
    return grid.size();
  });
  py::dict out = columns(rows.read());
  out["points"] = points;
  return out;
}

}  // namespace

void add_sweep(py::module_& m) {
  m.def("sweep", &sweep, py::arg("scene"), py::kw_only(), py::arg("vary"),
        py::arg("summary") = py::none(), py::arg("set") = py::none(),
        py::arg("against") = py::none(), py::arg("threads") = py::none(), kSweepDoc);
}

}  // namespace impact::python
