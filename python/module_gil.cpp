#include "module_gil.hpp"

#include <new>
#include <stdexcept>

#include "impact/loop/simulate.hpp"
#include "impact/output/atomic_file.hpp"
#include "scene/scene_error.hpp"

namespace py = pybind11;

namespace impact::python {

void SignalPoll::operator()() const {
  if (raised_.load(std::memory_order_relaxed)) throw impact::Interrupted{};
  if (std::this_thread::get_id() != owner_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now < next_) return;
  next_ = now + kInterval;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) {
    raised_.store(true, std::memory_order_relaxed);
    throw impact::Interrupted{};
  }
}

void raise_failure(std::exception_ptr failure) {
  // A Ctrl-C while a blocking call waited (opening a named pipe) shows as that call's failure
  // (EINTR): the user asked to stop, so KeyboardInterrupt.
  if (PyErr_Occurred() || PyErr_CheckSignals() != 0) throw py::error_already_set();
  try {
    std::rethrow_exception(failure);
  } catch (const impact::Interrupted&) {
    throw std::logic_error("impact: interrupted without a Python error");
  } catch (const SceneError&) {
    throw;
  } catch (const NumericalError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const OutputError&) {  // the module's own memory files
    throw;
  } catch (const std::exception& e) {
    // A force or a rate not finite where it is evaluated, a failed ODE step, ...: `impact run`
    // exits 1 for each, as for a NumericalError.
    throw NumericalError(e.what());
  }
}

}  // namespace impact::python
