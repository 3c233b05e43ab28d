// The Python module `impact`: a scene run by the library's own paths (the scene reader, run_scene,
// the reference solution, the sweep engine of `impact sweep`), its rows handed over as NumPy arrays
// that hold the same doubles `impact run` writes to CSV, under the same names (an internal
// variable's as the scene names it). The GIL is released while a scene is read and run
// (module_gil.hpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "give_array.hpp"
#include "impact/format.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/output/channels.hpp"
#include "impact/run/error_norms.hpp"
#include "impact/run/run_scene.hpp"
#include "impact/run/step_events.hpp"
#include "impact/version.hpp"
#include "module_docs.hpp"
#include "module_gil.hpp"
#include "module_scene.hpp"
#include "module_sweep.hpp"

namespace py = pybind11;

namespace impact::python {
namespace {

bool against_exact(py::handle against) {
  if (against.is_none()) return false;
  const std::string name = py::str(against).cast<std::string>();
  if (name != "exact")
    throw SceneError("against = " + name + ": the only reference is 'exact' (or None)");
  return true;
}

// The rows `impact run` writes (RowSchedule): t_0, every `every`-th step and the last one.
py::ssize_t row_count(const Scene& scene) {
  const std::int64_t steps = scene.grid.steps, every = scene.output.every;
  return static_cast<py::ssize_t>(steps / every + 1 + (steps % every != 0));
}

// A float64 column of a row, as the CSV writer (csv.cpp) writes it. A channel without a
// column here is refused before the run, never returned unfilled.
double row_value(const OutputRow& row, Channel channel) {
  if (channel == Channel::iterations)
    throw std::logic_error("impact: the Python module has no float64 column for the channel " +
                           std::string(channel_name(channel)));
  return channel_value(row, channel);
}

std::string name_of(const Model& model, std::size_t i) {
  return model.internal[i].name;
}

// The summary of `impact run` under the names of its provenance sidecar (OUT.json), with each
// internal variable at T (NAME_T) and, against the reference, their largest error.
py::dict summary(const RunReport& report, const Model& model,
                 const std::array<double, kMaxInternal>& internal_T) {
  py::dict out;
  const RunSummary& r = report.summary;
  out["steps"] = r.steps;
  out["contact_steps"] = r.contact_steps;
  out["iterations"] = r.iterations;
  out["max_iterations_per_step"] = r.max_iterations;
  out["wall_s"] = report.seconds;
  for (std::size_t i = 0; i < model.internal.size(); ++i)
    out[py::str(name_of(model, i) + "_T")] = internal_T[i];
  if (!report.errors) return out;
  const ErrorNorms& e = *report.errors;
  out["err_u_sup"] = e.sup_u;
  out["err_v_l1"] = e.l1_v;
  out["err_E_T"] = e.energy_end;
  out["err_first_impact"] = e.first_impact;
  if (!model.internal.empty() || bonded(model)) out["err_internal_sup"] = e.sup_internal;
  out["reference_s"] = report.reference_seconds;
  return out;
}

py::dict run(py::handle scene, py::handle set, py::handle method, py::handle every,
             py::handle against) {
  const bool exact = against_exact(against);
  const SceneSource source = scene_source(scene, set, method, every);
  const SignalPoll poll;
  Run loaded = without_gil([&] { return load(source); });
  const Scene& s = loaded.scene;
  const py::ssize_t rows = row_count(s);
  OutputRow probe;
  for (Channel c : s.output.channels)
    if (c != Channel::iterations) row_value(probe, c);
  // The arrays are made here, with the GIL, and filled in place while the run steps without it.
  py::array_t<double> t = zeros<double>(rows);
  std::vector<py::array> columns;
  std::vector<void*> data;
  for (Channel c : s.output.channels) {
    if (c == Channel::iterations)
      columns.push_back(zeros<std::int64_t>(rows));
    else
      columns.push_back(zeros<double>(rows));
    data.push_back(columns.back().mutable_data());
  }
  double* times = t.mutable_data();
  py::ssize_t next = 0;
  std::array<double, kMaxInternal> internal_T{};
  RunOutputs outputs;
  outputs.rows = [&](const OutputRow& row) {
    if (next == rows) throw std::logic_error("impact: more rows than RowSchedule gives");
    times[next] = s.grid.t(row.l);
    for (std::size_t k = 0; k < s.output.channels.size(); ++k) {
      const Channel c = s.output.channels[k];
      if (c == Channel::iterations)
        static_cast<std::int64_t*>(data[k])[next] = row.iterations;
      else
        static_cast<double*>(data[k])[next] = row_value(row, c);
    }
    internal_T = row.internal;  // the last row is t_n
    ++next;
  };
  outputs.against_exact = exact;
  outputs.check_every = kPollSteps;
  outputs.check = poll.check();
  const RunReport report = without_gil([&] { return run_scene(s, loaded.stepper, outputs); });
  if (next != rows) throw std::logic_error("impact: fewer rows than RowSchedule gives");
  py::dict out;
  out["t"] = t;
  for (std::size_t k = 0; k < columns.size(); ++k)
    out[py::str(std::string(channel_name(s.output.channels[k], s.model)))] = columns[k];
  out["method"] = std::string(method_info(s.method).name);
  out["summary"] = summary(report, s.model, internal_T);
  return out;
}

py::dict events(py::handle scene, py::handle set, py::handle method) {
  const SceneSource source = scene_source(scene, set, method, py::none());
  const SignalPoll poll;
  Run loaded = without_gil([&] { return load(source); });
  const Model& model = loaded.scene.model;
  std::vector<double> t, before, after;
  const std::vector<std::string> variables = event_variables(model);
  std::vector<std::vector<double>> internal(variables.size());
  std::vector<EventKind> kinds;
  RunOutputs outputs;
  outputs.events = [&](const Event& e) {
    t.push_back(e.t);
    kinds.push_back(e.kind);
    before.push_back(e.v_before);
    after.push_back(e.v_after);
    for (std::size_t i = 0; i < internal.size(); ++i) internal[i].push_back(e.internal[i]);
  };
  outputs.check_every = kPollSteps;
  outputs.check = poll.check();
  without_gil([&] { run_scene(loaded.scene, loaded.stepper, outputs); });
  py::list names;
  for (EventKind k : kinds) names.append(std::string(event_name(k)));
  py::dict out;
  out["t"] = give(std::move(t));
  // U7: the longest kind's name, capture
  out["kind"] = py::module_::import("numpy").attr("array")(names, "U7");
  out["v_before"] = give(std::move(before));
  out["v_after"] = give(std::move(after));
  for (std::size_t i = 0; i < internal.size(); ++i)
    out[py::str(variables[i])] = give(std::move(internal[i]));
  return out;
}

py::dict exact(py::handle scene, py::array_t<double, py::array::c_style | py::array::forcecast> t,
               py::handle set) {
  const SceneSource source = scene_source(scene, set, py::none(), py::none());
  const SignalPoll poll;
  Run loaded = without_gil([&] { return load(source); });
  const Scene& s = loaded.scene;
  if (const auto r = reference_refusal(s.model)) throw SceneError("exact(): " + r->message);
  const py::ssize_t n = t.size();
  const double* times = t.data();
  for (py::ssize_t i = 0; i < n; ++i)
    if (!std::isfinite(times[i]))
      throw py::value_error("t[" + std::to_string(i) + "] = " + round_trip(times[i]) +
                            ": the times must be finite");
  // The internal variables, or a bonded model's beta and D, as the reference carries them.
  const std::vector<std::string> variables = event_variables(s.model);
  const std::size_t m = variables.size();
  py::array_t<double> u = zeros<double>(n), v = zeros<double>(n);
  std::vector<py::array_t<double>> z;
  std::vector<double*> zs;
  for (std::size_t i = 0; i < m; ++i) {
    z.push_back(zeros<double>(n));
    zs.push_back(z.back().mutable_data());
  }
  double *us = u.mutable_data(), *vs = v.mutable_data();
  without_gil([&] {
    // The reference follows its events forward in time: the times in increasing order.
    std::vector<py::ssize_t> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), py::ssize_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](py::ssize_t a, py::ssize_t b) { return times[a] < times[b]; });
    const double end = n > 0 ? std::max(times[order.back()], s.T) : s.T;
    ReferenceSolution reference(s.model, s.initial, end);
    const auto initial_z = with_internal(s.model, s.initial).z;
    for (std::size_t k = 0; k < order.size(); ++k) {
      if (k % kPollSteps == 0) poll();
      const py::ssize_t i = order[k];
      const State at = reference.at(times[i]);
      us[i] = at.u;
      vs[i] = at.v;
      if (m == 0) continue;
      // As the errors against the reference take it (error_norms.hpp): z(0) at t <= 0.
      const auto zi = times[i] > 0 ? reference.internal_at(times[i]) : initial_z;
      for (std::size_t j = 0; j < m; ++j) zs[j][i] = zi[j];
    }
  });
  py::dict out;
  out["t"] = py::array_t<double>(n, times);
  out["u"] = u;
  out["v"] = v;
  for (std::size_t j = 0; j < m; ++j) out[py::str(variables[j])] = z[j];
  return out;
}

}  // namespace
}  // namespace impact::python

PYBIND11_MODULE(impact, m) {
  using namespace impact::python;
  // The signatures are written in the docstrings (module_docs.hpp), with the types they take.
  py::options options;
  options.disable_function_signatures();
  m.doc() = kModuleDoc;
  m.attr("__version__") = std::string(impact::version());
  py::register_exception<impact::SceneError>(m, "SceneError", PyExc_ValueError);
  py::register_exception<impact::NumericalError>(m, "NumericalError", PyExc_ArithmeticError);
  m.def("run", &run, py::arg("scene"), py::kw_only(), py::arg("set") = py::none(),
        py::arg("method") = py::none(), py::arg("every") = py::none(),
        py::arg("against") = py::none(), kRunDoc);
  m.def("events", &events, py::arg("scene"), py::kw_only(), py::arg("set") = py::none(),
        py::arg("method") = py::none(), kEventsDoc);
  m.def("exact", &exact, py::arg("scene"), py::arg("t"), py::kw_only(), py::arg("set") = py::none(),
        kExactDoc);
  add_sweep(m);
}
