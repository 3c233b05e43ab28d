// The CSV of `impact sweep`: one row per point (its quantities: scene/sweep_quantities.hpp), and
// the first line that marks a shard's part so that `impact sweep --merge` can check and join parts.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/sweep_grid.hpp"
#include "scene/sweep_quantities.hpp"

namespace impact::cli {

// "time.h,rest_time,E_T,failure\n": the varied keys, the quantities, the failure reason.
std::string csv_header(const SweepGrid& grid, const std::vector<Quantity>& quantities);
// Writes rows. Point i's row: its values as round_trip writes them (the --set text that gives them
// back), the quantities (empty where the point failed; nan for a time that does not exist), and
// the failure reason in double quotes (empty where it did not fail).
class RowWriter {
 public:
  RowWriter(const SweepGrid& grid, const std::vector<Quantity>& quantities);
  void append(std::string& out, std::int64_t i, const PointResult& result);

 private:
  const SweepGrid& grid_;
  const std::vector<Quantity>& quantities_;
  // Each axis's value in the row before and its text: only the axes that changed are formatted
  // again (one of two in a 1000 x 1000 sweep; a number in round-trip precision costs ~100 ns).
  std::vector<std::int64_t> index_;
  std::vector<std::string> text_;
};

// The first line of shard K of N (1-based) of a sweep of `points` points with this fingerprint.
std::string part_line(std::int64_t k, std::int64_t n, std::int64_t points,
                      const std::string& fingerprint);
struct PartLine {
  std::int64_t k = 0, n = 0, points = 0;
  std::string fingerprint;
};
std::optional<PartLine> parse_part_line(const std::string& line);

// A hash (FNV-1a, 64 bits, in hex) of everything that decides a sweep's rows: the scene file's
// bytes, the --set and --vary strings, the quantities and --against.
std::string sweep_fingerprint(const std::string& scene_text, const std::vector<std::string>& sets,
                              const std::vector<std::string>& varies,
                              const std::vector<Quantity>& quantities, bool against_exact);

}  // namespace impact::cli
