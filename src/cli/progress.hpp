// A progress line on standard error for the runs and sweeps that take more than a couple of
// seconds ("impact: 42% of 100000000 steps, 3 s, about 4 s left"), redrawn in place: nothing for
// the first 2 s, then at most twice a second. Shown only where someone watches it (the caller
// decides: standard error a terminal that the output does not go to).
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

#include "impact/format.hpp"

namespace impact::cli {

using Clock = std::chrono::steady_clock;

class Progress {
 public:
  // `what` names the command and the unit: {"impact", "steps"}, {"impact sweep", "points"};
  // with_rate adds "N points/s".
  Progress(bool enabled, std::int64_t total, Clock::time_point start, std::string command,
           std::string unit, bool with_rate = false)
      : enabled_(enabled),
        total_(total),
        start_(start),
        command_(std::move(command)),
        unit_(std::move(unit)),
        with_rate_(with_rate) {}
  ~Progress() { finish(); }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // `done` of the total are done; reads the clock, so it is meant for every few thousand steps.
  void update(std::int64_t done) {
    if (!enabled_ || done <= 0) return;
    const double elapsed = seconds_since(start_);
    if (elapsed < kQuietSeconds || elapsed < shown_ + kRedrawSeconds) return;
    shown_ = elapsed;
    const double fraction = static_cast<double>(done) / static_cast<double>(total_);
    std::string rate;
    if (with_rate_)
      rate = ", " + std::to_string(static_cast<long long>(static_cast<double>(done) / elapsed)) +
             " " + unit_ + "/s";
    std::fprintf(stderr, "\r%s: %3.0f%% of %lld %s%s, %.0f s, about %.0f s left\x1b[K",
                 command_.c_str(), 100.0 * fraction, static_cast<long long>(total_), unit_.c_str(),
                 rate.c_str(), elapsed, elapsed * (1.0 - fraction) / fraction);
    drawn_ = true;
  }
  // Erases the line, so that the summary line (or an error message) starts on a clean line.
  void finish() {
    if (drawn_) std::fputs("\r\x1b[K", stderr);
    drawn_ = false;
  }

 private:
  static constexpr double kQuietSeconds = 2.0;   // nothing is shown for shorter runs
  static constexpr double kRedrawSeconds = 0.5;  // at most two redraws a second
  bool enabled_;
  std::int64_t total_;
  Clock::time_point start_;
  std::string command_, unit_;
  bool with_rate_;
  double shown_ = 0.0;
  bool drawn_ = false;
};

}  // namespace impact::cli
