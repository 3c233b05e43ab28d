#include "impact/output.hpp"

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
  const State& s = row.state;
  // At most 1 + 10 fields of 24 characters (-1.2345678901234567e-308) and their separators.
  char buf[256];
  char* p = format_double(buf, buf + sizeof buf, t);
  for (Channel c : channels_) {
    *p++ = ',';
    switch (c) {
      case Channel::u:
        p = format_double(p, buf + sizeof buf, s.u);
        break;
      case Channel::v:
        p = format_double(p, buf + sizeof buf, s.v);
        break;
      case Channel::N:
        p = format_double(p, buf + sizeof buf, row.contact_force);
        break;
      case Channel::E:
        p = format_double(p, buf + sizeof buf, row.energy);
        break;
      case Channel::iterations:
        p = std::to_chars(p, buf + sizeof buf, row.iterations).ptr;
        break;
      default:
        p = format_double(p, buf + sizeof buf, channel_value(row, c));
        break;
    }
  }
  *p++ = '\n';
  std::fwrite(buf, 1, static_cast<std::size_t>(p - buf), out_);
}

}  // namespace impact
