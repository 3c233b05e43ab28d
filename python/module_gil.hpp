// How the module runs the library: without the GIL from the opening of the scene file (a named
// pipe may keep it waiting) to the last step, taking the GIL back for a moment every few
// milliseconds so that Python's signal handlers run: Ctrl-C stops a run or a sweep within about
// 0.1 s with KeyboardInterrupt, and nothing half-made is returned. A failure of the run itself
// is impact.NumericalError, as `impact run` exits 1 for it.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <functional>
#include <thread>
#include <utility>

namespace impact::python {

// Steps between two calls of a SignalPoll inside a run: at ~3 ns a step (direct) a call every
// 3 us, one clock read each; at the slowest steppers' tens of microseconds, 10 to 100 ms.
inline constexpr std::int64_t kPollSteps = 1024;

// Made on the calling thread, which holds the GIL. Called from any thread during the work: on
// the calling thread it runs Python's signal handlers (PyErr_CheckSignals, with the GIL) at most
// every kInterval; once a handler raised (the Python error is set), it sets stop() and every call
// on every thread throws impact::Interrupted (simulate.hpp), as the library does where it reads
// stop().
class SignalPoll {
 public:
  static constexpr std::chrono::milliseconds kInterval{10};
  SignalPoll() : owner_(std::this_thread::get_id()) {}
  SignalPoll(const SignalPoll&) = delete;
  SignalPoll& operator=(const SignalPoll&) = delete;
  void operator()() const;
  // The poll as the library's periodic check (RowStream::Check).
  std::function<void(std::int64_t)> check() const {
    return [this](std::int64_t) { (*this)(); };
  }
  // Set once a signal handler raised: what the library's threads read (RunOutputs::stop).
  const std::atomic<bool>* stop() const { return &raised_; }

 private:
  std::thread::id owner_;
  mutable std::atomic<bool> raised_{false};
  mutable std::chrono::steady_clock::time_point next_{};
};

// After the GIL is taken back: the exception of the work as the module raises it. A signal
// handler's exception (KeyboardInterrupt) wins over any; SceneError, NumericalError, OutputError
// (the module's memory files) and std::bad_alloc stay what they are; any other failure of the
// library is a NumericalError.
[[noreturn]] void raise_failure(std::exception_ptr failure);

// work() without the GIL; its exceptions as raise_failure() makes them.
template <class Work>
auto without_gil(Work&& work) -> decltype(work()) {
  std::exception_ptr failure;
  {
    pybind11::gil_scoped_release release;
    try {
      return std::forward<Work>(work)();
    } catch (...) {
      failure = std::current_exception();
    }
  }
  raise_failure(failure);
}

}  // namespace impact::python
