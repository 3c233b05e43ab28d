// The Python module `impact`: a scene run by the library's own paths (the scene reader, run_scene,
// the reference solution, the sweep engine of `impact sweep`), its rows handed over as NumPy arrays
// that hold the same doubles `impact run` writes to CSV. The GIL is released while a run steps.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "give_array.hpp"
#include "impact/channels.hpp"
#include "impact/error_norms.hpp"
#include "impact/format.hpp"
#include "impact/registry.hpp"
#include "impact/run.hpp"
#include "impact/run_scene.hpp"
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

// The summary of `impact run` under the names of its provenance sidecar (OUT.json).
py::dict summary(const RunReport& report) {
  py::dict out;
  const RunSummary& r = report.summary;
  out["steps"] = r.steps;
  out["contact_steps"] = r.contact_steps;
  out["iterations"] = r.iterations;
  out["max_iterations_per_step"] = r.max_iterations;
  out["wall_s"] = report.seconds;
  if (!report.errors) return out;
  const ErrorNorms& e = *report.errors;
  out["err_u_sup"] = e.sup_u;
  out["err_v_l1"] = e.l1_v;
  out["err_E_T"] = e.energy_end;
  out["err_first_impact"] = e.first_impact;
  out["reference_s"] = report.reference_seconds;
  return out;
}

py::dict run(py::handle scene, py::handle set, py::handle method, py::handle every,
             py::handle against) {
  const bool exact = against_exact(against);
  Run loaded = load(scene_source(scene, set, method, every));
  const Scene& s = loaded.scene;
  const py::ssize_t rows = row_count(s);
  // The arrays are made here, with the GIL, and filled in place while the run steps without it.
  py::array_t<double> t(rows);
  std::vector<py::array> columns;
  std::vector<void*> data;
  for (Channel c : s.output.channels) {
    if (c == Channel::iterations)
      columns.push_back(py::array_t<std::int64_t>(rows));
    else
      columns.push_back(py::array_t<double>(rows));
    data.push_back(columns.back().mutable_data());
  }
  double* times = t.mutable_data();
  py::ssize_t next = 0;
  RunOutputs outputs;
  outputs.rows = [&](const OutputRow& row) {
    if (next == rows) throw std::logic_error("impact: more rows than RowSchedule gives");
    times[next] = s.grid.t(row.l);
    for (std::size_t k = 0; k < s.output.channels.size(); ++k) {
      auto* x = static_cast<double*>(data[k]);
      switch (s.output.channels[k]) {
        case Channel::u:
          x[next] = row.state.u;
          break;
        case Channel::v:
          x[next] = row.state.v;
          break;
        case Channel::N:
          x[next] = row.contact_force;
          break;
        case Channel::E:
          x[next] = row.energy;
          break;
        case Channel::iterations:
          static_cast<std::int64_t*>(data[k])[next] = row.iterations;
          break;
      }
    }
    ++next;
  };
  outputs.against_exact = exact;
  RunReport report;
  {
    py::gil_scoped_release release;
    report = run_scene(s, loaded.stepper, outputs);
  }
  if (next != rows) throw std::logic_error("impact: fewer rows than RowSchedule gives");
  py::dict out;
  out["t"] = t;
  for (std::size_t k = 0; k < columns.size(); ++k)
    out[py::str(std::string(channel_name(s.output.channels[k])))] = columns[k];
  out["method"] = std::string(method_info(s.method).name);
  out["summary"] = summary(report);
  return out;
}

py::dict events(py::handle scene, py::handle set, py::handle method) {
  Run loaded = load(scene_source(scene, set, method, py::none()));
  std::vector<double> t, before, after;
  std::vector<EventKind> kinds;
  RunOutputs outputs;
  outputs.events = [&](const Event& e) {
    t.push_back(e.t);
    kinds.push_back(e.kind);
    before.push_back(e.v_before);
    after.push_back(e.v_after);
  };
  {
    py::gil_scoped_release release;
    run_scene(loaded.scene, loaded.stepper, outputs);
  }
  py::list names;
  for (EventKind k : kinds) names.append(std::string(event_name(k)));
  py::dict out;
  out["t"] = give(std::move(t));
  out["kind"] = py::module_::import("numpy").attr("array")(names, "U6");
  out["v_before"] = give(std::move(before));
  out["v_after"] = give(std::move(after));
  return out;
}

py::dict exact(py::handle scene, py::array_t<double, py::array::c_style | py::array::forcecast> t,
               py::handle set) {
  Run loaded = load(scene_source(scene, set, py::none(), py::none()));
  const Scene& s = loaded.scene;
  const py::ssize_t n = t.size();
  const double* times = t.data();
  for (py::ssize_t i = 0; i < n; ++i)
    if (!std::isfinite(times[i]))
      throw py::value_error("t[" + std::to_string(i) + "] = " + round_trip(times[i]) +
                            ": the times must be finite");
  py::array_t<double> u(n), v(n);
  double *us = u.mutable_data(), *vs = v.mutable_data();
  {
    py::gil_scoped_release release;
    // The reference follows its events forward in time: the times in increasing order.
    std::vector<py::ssize_t> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), py::ssize_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](py::ssize_t a, py::ssize_t b) { return times[a] < times[b]; });
    const double end = n > 0 ? std::max(times[order.back()], s.T) : s.T;
    ReferenceSolution reference(s.model, s.initial, end);
    for (py::ssize_t i : order) {
      const State at = reference.at(times[i]);
      us[i] = at.u;
      vs[i] = at.v;
    }
  }
  py::dict out;
  out["t"] = py::array_t<double>(n, times);
  out["u"] = u;
  out["v"] = v;
  return out;
}

}  // namespace
}  // namespace impact::python

PYBIND11_MODULE(impact, m) {
  using namespace impact::python;
  m.doc() =
      "impact: a particle falling onto a rigid floor (Ahn and Wolf, Dynamic impact of a "
      "particle, 2013). Scenes are TOML files, TOML text or dicts, read and checked as `impact "
      "run` reads them.";
  py::register_exception<impact::SceneError>(m, "SceneError", PyExc_ValueError);
  py::register_exception<impact::NumericalError>(m, "NumericalError", PyExc_ArithmeticError);
  m.def("run", &run, py::arg("scene"), py::kw_only(), py::arg("set") = py::none(),
        py::arg("method") = py::none(), py::arg("every") = py::none(),
        py::arg("against") = py::none(),
        "Runs a scene as `impact run` does. Returns a dict: 't' and the scene's output channels "
        "(u, v, N, E: float64; iterations: int64) as NumPy arrays holding the doubles of the "
        "CSV rows, 'method', and 'summary': a dict of steps, contact_steps, iterations, "
        "max_iterations_per_step, wall_s and with against='exact' the errors err_u_sup, "
        "err_v_l1, err_E_T, err_first_impact, reference_s (the names of impact run's OUT.json). "
        "set: {'table.key': value} as "
        "--set; method: method.name; every: output.every. A bad scene raises SceneError (a "
        "ValueError) with the reader's message.");
  m.def("events", &events, py::arg("scene"), py::kw_only(), py::arg("set") = py::none(),
        py::arg("method") = py::none(),
        "The impacts, sticks and lifts of a run, as `impact run --events` writes them: a dict "
        "of arrays t, kind ('impact', 'stick', 'lift'), v_before, v_after.");
  m.def("exact", &exact, py::arg("scene"), py::arg("t"), py::kw_only(), py::arg("set") = py::none(),
        "The exact solution of the scene's problem (the reference of against='exact') at the "
        "times t, in any order: a dict of arrays t, u, v.");
  add_sweep(m);
}
