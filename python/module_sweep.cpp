#include "module_sweep.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <string>
#include <thread>
#include <vector>

#include "give_array.hpp"
#include "module_docs.hpp"
#include "module_gil.hpp"
#include "module_scene.hpp"
#include "scene/sweep_engine.hpp"

namespace py = pybind11;

namespace impact::python {
namespace {

// A sweep's columns as NumPy arrays (float64, NaN where a point failed) and its failure reasons
// as a list of str.
py::dict columns(SweepResult&& result) {
  py::dict out;
  for (std::size_t k = 0; k < result.names.size(); ++k)
    out[py::str(result.names[k])] = give(std::move(result.columns[k]));
  py::list failures;
  for (const std::string& failure : result.failures) failures.append(failure);
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
  const std::string allowed = ": 1 to " + std::to_string(kMaxThreads) +
                              " as impact sweep --threads, or None or 0 for one per core";
  if (!py::isinstance<py::int_>(threads) || py::isinstance<py::bool_>(threads))
    throw SceneError("threads = " + text + allowed);
  const py::int_ n = py::reinterpret_borrow<py::int_>(threads);
  if (n < py::int_(0) || n > py::int_(kMaxThreads)) throw SceneError("threads = " + text + allowed);
  return n.cast<int>();
}

py::dict sweep(py::handle scene, py::dict vary, py::handle summary, py::handle set,
               py::handle against, py::handle threads) {
  const SceneSource source = scene_source(scene, set, py::none(), py::none());
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
  int workers = thread_count(threads);
  if (workers == 0) workers = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const SignalPoll poll;
  std::int64_t points = 0;
  // The grid reads the scene file (which may be a named pipe) without the GIL too.
  SweepResult result = without_gil([&] {
    std::vector<SweepAxis> parsed(axes.begin(), axes.end());
    const SweepGrid grid(
        source_name(source), [&](const std::vector<std::string>& all) { return load(source, all); },
        source.overrides, std::move(parsed));
    points = grid.size();
    // The internal variables' columns are the scene's (NAME_T), as for impact sweep.
    SweepSetup setup{parse_summary(list, exact, grid.base().model), exact, Shard{}, workers, "",
                     {[&] { poll(); }, poll.stop(), kPollSteps}};
    return impact::sweep(grid, setup);
  });
  py::dict out = columns(std::move(result));
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
