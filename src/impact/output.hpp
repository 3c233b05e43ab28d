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

namespace impact {

// The output could not be created or written (exit code 1, or 2 when the path itself is bad).
class OutputError : public std::runtime_error {
 public:
  OutputError(const std::string& what, bool bad_path)
      : std::runtime_error(what), bad_path(bad_path) {}
  bool bad_path;
};

// A file that appears at `path` only on commit(); "-" or "" means standard output.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();  // removes the temporary file unless committed

  std::FILE* stream() { return stream_; }
  void commit();

 private:
  std::string path_, temp_;
  std::FILE* stream_ = nullptr;
  std::vector<char> buffer_;
  bool committed_ = false;
};

// Writes the header `t,<channels>` and one row per written step.
class CsvWriter {
 public:
  CsvWriter(std::FILE* out, const Model& model, std::vector<Channel> channels);
  void header();
  void row(double t, const State& s, const StepInfo& info);

 private:
  std::FILE* out_;
  Model model_;
  std::vector<Channel> channels_;
};

// Appends x in round-trip precision (17 significant digits) to buf; returns the new end.
char* format_double(char* buf, char* end, double x);

}  // namespace impact
