#include "impact/output/csv.hpp"

#include <charconv>

namespace impact {

CsvWriter::CsvWriter(std::FILE* out, std::vector<Channel> channels, const Model& model)
    : out_(out), channels_(std::move(channels)) {
  for (Channel c : channels_) names_.emplace_back(channel_name(c, model));
}

void CsvWriter::header() {
  std::string line = "t";
  for (const std::string& name : names_) {
    line += ',';
    line += name;
  }
  line += "\n";
  std::fputs(line.c_str(), out_);
}

void CsvWriter::row(double t, const OutputRow& row) {
  // At most 1 + 10 fields of 24 characters (-1.2345678901234567e-308) and their separators.
  char buf[256];
  char* p = format_double(buf, buf + sizeof buf, t);
  for (Channel c : channels_) {
    *p++ = ',';
    // The iterations are a count, written as an integer; every other channel a double.
    p = c == Channel::iterations ? std::to_chars(p, buf + sizeof buf, row.iterations).ptr
                                 : format_double(p, buf + sizeof buf, channel_value(row, c));
  }
  *p++ = '\n';
  std::fwrite(buf, 1, static_cast<std::size_t>(p - buf), out_);
}

}  // namespace impact
