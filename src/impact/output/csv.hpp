// Output: the CSV rows of a run in round-trip precision (format.hpp), written through an AtomicFile
// (atomic_file.hpp), so a failed run leaves no half-written file.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "impact/format.hpp"
#include "impact/model/model.hpp"
#include "impact/output/atomic_file.hpp"
#include "impact/output/channels.hpp"
#include "impact/output/row.hpp"

namespace impact {

// Writes the header `t,<channels>` and one row per written step.
class CsvWriter {
 public:
  // model: the names of its internal variables' channels.
  CsvWriter(std::FILE* out, std::vector<Channel> channels, const Model& model = {});
  void header();
  // The row at t = row.l h (row.hpp), its E as run_scene() filled it in.
  void row(double t, const OutputRow& row);

 private:
  std::FILE* out_;
  std::vector<Channel> channels_;
  std::vector<std::string> names_;  // the header's names of the channels
};

}  // namespace impact
