#include "cli/sweep_csv.hpp"

#include <algorithm>
#include <charconv>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "impact/model/model.hpp"
#include "impact/output/channels.hpp"
#include "impact/output/csv.hpp"
#include "scene/scene_error.hpp"

namespace impact::cli {
namespace {

char* put(char* p, char* end, double x) {
  return format_double(p, end, x);
}

char* put(char* p, char* end, std::int64_t x) {
  return std::to_chars(p, end, x).ptr;
}

// Longest field: a double in round-trip precision, "-1.2345678901234567e-308".
constexpr std::size_t kFieldChars = 32;

}  // namespace

std::string csv_header(const SweepGrid& grid, const std::vector<Quantity>& quantities) {
  std::string header;
  for (const SweepAxis& axis : grid.axes()) header += axis.key() + ",";
  for (Quantity q : quantities) header += quantity_name(q, grid.base().model) + ",";
  return header + "failure\n";
}

RowWriter::RowWriter(const SweepGrid& grid, const std::vector<Quantity>& quantities)
    : grid_(grid),
      quantities_(quantities),
      index_(grid.axes().size(), -1),
      text_(grid.axes().size()) {}

void RowWriter::append(std::string& out, std::int64_t i, const PointResult& result) {
  for (std::size_t k = 0; k < text_.size(); ++k) {
    const std::int64_t j = grid_.index(i, k);
    if (j != index_[k]) {
      index_[k] = j;
      text_[k] = grid_.axes()[k].text(j);
    }
    out += text_[k];
    out += ',';
  }
  const std::size_t start = out.size();
  out.resize(start + quantities_.size() * (kFieldChars + 1));
  char* const begin = out.data() + start;
  char* const end = out.data() + out.size();
  char* p = begin;
  for (Quantity q : quantities_) {
    if (result.outcome)
      p = visit_quantity(q, *result.outcome, result.wall_s, [&](auto x) { return put(p, end, x); });
    *p++ = ',';
  }
  out.resize(start + static_cast<std::size_t>(p - begin));
  if (!result.outcome) {
    // A message is one line; quotes double, as CSV escapes them.
    out += '"';
    for (char c : result.failure) {
      if (c == '"') out += '"';
      out += c == '\n' ? ' ' : c;
    }
    out += '"';
  }
  out += '\n';
}

std::string part_line(std::int64_t k, std::int64_t n, std::int64_t points,
                      const std::string& fingerprint) {
  return "# impact sweep part " + std::to_string(k) + "/" + std::to_string(n) + " of " +
         std::to_string(points) + " points, sweep " + fingerprint + "\n";
}

std::optional<PartLine> parse_part_line(const std::string& line) {
  PartLine p;
  char fingerprint[17] = {};
  int used = 0;
  if (std::sscanf(line.c_str(),
                  "# impact sweep part %" SCNd64 "/%" SCNd64 " of %" SCNd64
                  " points, sweep %16[0-9a-f]%n",
                  &p.k, &p.n, &p.points, fingerprint, &used) != 4 ||
      static_cast<std::size_t>(used) != line.size() || p.n < 1 || p.k < 1 || p.k > p.n ||
      p.points < 0)
    return std::nullopt;
  p.fingerprint = fingerprint;
  return p;
}

std::string sweep_fingerprint(const std::string& scene_text, const std::vector<std::string>& sets,
                              const std::vector<std::string>& varies,
                              const std::vector<Quantity>& quantities, bool against_exact) {
  std::uint64_t hash = 14695981039346656037ull;
  const auto add = [&](std::string_view text) {
    // Each field ends with a byte no field contains, so that "ab","c" and "a","bc" differ.
    for (unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
    hash = (hash ^ 0xffu) * 1099511628211ull;
  };
  add(scene_text);
  for (const auto& s : sets) add(s);
  add("--vary");
  for (const auto& v : varies) add(v);
  add("--summary");
  for (Quantity q : quantities) add(quantity_name(q));
  add(against_exact ? "exact" : "");
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, hash);
  return hex;
}

}  // namespace impact::cli
