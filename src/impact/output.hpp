// Output: CSV rows in round-trip precision, written to a temporary file beside the target and
// renamed into place only when the run succeeded, so a failed run leaves no half-written file.
#pragma once

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "impact/model.hpp"
#include "impact/scene.hpp"
#include "impact/work_energy.hpp"

namespace impact {

// The output could not be created or written (exit code 1, or 2 when the path itself is bad).
class OutputError : public std::runtime_error {
 public:
  OutputError(const std::string& what, bool bad_path)
      : std::runtime_error(what), bad_path(bad_path) {}
  bool bad_path;
};

// A file that appears at `path` only on commit(); "-" or "" means standard output. Symbolic links
// are followed, and stay: the file a link names is replaced, or created if the link dangles. What
// is not a regular file is written in place, as it stands: a device or a named pipe (renaming over
// it would replace the node itself), and an open descriptor such as /dev/stdout, /dev/fd/N or
// /proc/self/fd/N (written through the caller's descriptor, so that `>>` appends, even when it is
// redirected to a regular file). Refused before any work, as bad paths: a read-only file, a
// directory that is not writable (checked by mode bits too, so also for root), a name longer than
// NAME_MAX or a path longer than PATH_MAX. Every signal whose default action ends the process
// removes the temporary first.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();  // removes the temporary file unless committed

  std::FILE* stream() { return stream_; }
  // Throws OutputError if a write has failed so far (e.g. the disk is full), so that a long run
  // can stop early instead of computing output that cannot be stored.
  void check() const;
  void commit();
  // Written as it goes (standard output, a device, a pipe, a descriptor), not through a temporary.
  bool in_place() const { return temp_.empty(); }

 private:
  void open_in_place(const std::string& target);
  void forget_temp();

  std::string path_;    // as given, for messages
  std::string target_;  // the file that commit() replaces: path_ with symbolic links followed
  std::string temp_;
  std::FILE* stream_ = nullptr;
  std::vector<char> buffer_;
  int slot_ = -1;  // the signal handler's slot for temp_ (output.cpp), -1 for none
  bool committed_ = false;
};

// Which steps get a row: l = 0, every, 2 every, ... and always the last step. Comparing l with the
// next row's index instead of computing l % every keeps the division out of the step loop; every is
// capped at `last` so that the next index cannot overflow (output.every may be up to 2^63 - 1).
class RowSchedule {
 public:
  RowSchedule(std::int64_t every, std::int64_t last)
      : every_(every < last ? every : (last > 0 ? last : 1)), last_(last) {}
  bool due(std::int64_t l) {
    if (l != next_ && l != last_) return false;
    next_ = l + every_;
    return true;
  }

 private:
  std::int64_t every_, last_, next_ = 0;
};

// Writes the header `t,<channels>` and one row per written step.
class CsvWriter {
 public:
  CsvWriter(std::FILE* out, const Model& model, std::vector<Channel> channels);
  // The E channel of a time-dependent force: v^2/2 - f(0) u(0) - W(t) from `work`, which the
  // caller feeds every step (work_energy.hpp); without it, E is (3-1), v^2/2 - f u.
  void use_work(const WorkEnergy* work) { work_ = work; }
  void header();
  // Throws NumericalError if the energy channel overflows (u and v finite, E not).
  void row(double t, const State& s, const StepInfo& info);

 private:
  std::FILE* out_;
  Model model_;
  std::vector<Channel> channels_;
  const WorkEnergy* work_ = nullptr;
};

// Appends x in round-trip precision (17 significant digits) to buf; returns the new end.
char* format_double(char* buf, char* end, double x);
// x in round-trip precision, as a string (for scenes, summaries and messages written as text).
std::string round_trip(double x);
// Writes `text` to `path` through an AtomicFile: the file appears whole or not at all.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace impact
