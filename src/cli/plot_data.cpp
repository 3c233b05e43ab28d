#include "cli/plot_data.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <map>

#include "cli/sweep_csv.hpp"
#include "impact/output/channels.hpp"
#include "impact/output/csv.hpp"
#include "scene/toml_text.hpp"

namespace impact::cli {
namespace {

bool is_channel(const std::string& name) {
  return std::ranges::any_of(channels(), [&](const ChannelInfo& c) { return c.name == name; });
}

std::string channel_names() {
  std::string names;
  for (const ChannelInfo& c : channels())
    names += (names.empty() ? "" : ", ") + std::string(c.name);
  return names;
}

// A sweep's quantity, or an internal variable at T (NAME_T).
bool is_quantity(const std::string& name) {
  return is_quantity_name(name) || (name.size() > 2 && name.ends_with("_T") &&
                                    is_identifier(name.substr(0, name.size() - 2)));
}

constexpr const char* kEventsHead = "t,kind,v_before,v_after";

// A scene key as a sweep's header names it: "table.key", letters, digits and '_'.
bool is_key(const std::string& name) {
  const auto dot = name.find('.');
  return dot != std::string::npos && dot > 0 && dot + 1 < name.size() &&
         std::all_of(name.begin(), name.end(), [](char c) {
           return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                  c == '_' || c == '.';
         });
}

std::vector<std::string> header_fields(const CsvLines& lines, const std::string& header) {
  std::vector<std::string> fields = split_fields(header);
  for (const std::string& f : fields)
    if (f.empty()) lines.reject("the header '" + cut(header) + "' has an empty name");
  return fields;
}

std::vector<std::string> row_fields(const CsvLines& lines, const std::string& line,
                                    std::size_t columns) {
  std::vector<std::string> fields = split_fields(line);
  if (fields.size() != columns)
    lines.reject(std::to_string(fields.size()) + " fields where the header has " +
                 std::to_string(columns));
  return fields;
}

double number(const CsvLines& lines, const std::string& field, const std::string& column) {
  double x = 0;
  if (!parse_number(field, x)) lines.reject(column + " = '" + cut(field) + "' is not a number");
  return x;
}

}  // namespace

bool is_identifier(const std::string& name) {
  const auto letter = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
  };
  return !name.empty() && letter(name[0]) && std::all_of(name.begin(), name.end(), [&](char c) {
    return letter(c) || (c >= '0' && c <= '9');
  });
}

CsvLines::CsvLines(const std::string& path, std::int64_t max_rows)
    : path_(path),
      file_(std::fopen(path.c_str(), "rb"), &std::fclose),
      block_(1 << 20),
      max_rows_(max_rows) {
  if (!file_)
    throw PlotInputError(printable(path) + ": cannot read the CSV: " + std::strerror(errno));
  struct stat info;
  if (fstat(fileno(file_.get()), &info) == 0 && S_ISDIR(info.st_mode))
    throw PlotInputError(printable(path) + ": is a directory, not a CSV");
}

void CsvLines::reject(const std::string& what) const {
  throw PlotInputError(printable(path_) + ", line " + std::to_string(line_) + ": " + what);
}

bool CsvLines::next(std::string& line) {
  line.clear();
  bool any = false;
  for (;;) {
    if (begin_ == end_) {
      begin_ = 0;
      end_ = std::fread(block_.data(), 1, block_.size(), file_.get());
      if (end_ == 0) {
        if (std::ferror(file_.get()))
          throw PlotInputError(printable(path_) + ": cannot read the CSV: " + std::strerror(errno));
        if (!any) return false;
        break;  // a last line without its newline
      }
    }
    any = true;
    const char* start = block_.data() + begin_;
    const auto* newline = static_cast<const char*>(std::memchr(start, '\n', end_ - begin_));
    const std::size_t n = newline ? static_cast<std::size_t>(newline - start) : end_ - begin_;
    if (line.size() + n > kMaxLineBytes) {
      ++line_;
      reject("longer than " + std::to_string(kMaxLineBytes) + " bytes: not a CSV of impact");
    }
    line.append(start, n);
    begin_ += n;
    if (newline) {
      ++begin_;
      break;
    }
  }
  ++line_;
  if (!line.empty() && line.back() == '\r') line.pop_back();  // a CSV saved on Windows
  if (line.find('\0') != std::string::npos) reject("a NUL byte: not a text file");
  if (line_ > max_rows_ + 2)
    reject("more than " + std::to_string(max_rows_) +
           " rows, the most impact run writes without --force; write fewer (output.every)");
  return true;
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"')
        fields.back() += c;
      else if (i + 1 < line.size() && line[i + 1] == '"')
        fields.back() += line[++i];
      else
        quoted = false;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

bool parse_number(const std::string& field, double& x) {
  const char* end = field.data() + field.size();
  const auto [stop, error] = std::from_chars(field.data(), end, x);
  return error == std::errc() && stop == end;
}

void Curve::add(double x, double y) {
  if (!std::isfinite(x) || !std::isfinite(y)) return;
  if (count_ == 0) {
    low_ = high_ = y;
    x_low_ = x_high_ = x;
  }
  low_ = std::min(low_, y);
  high_ = std::max(high_, y);
  x_low_ = std::min(x_low_, x);
  x_high_ = std::max(x_high_, x);
  const Kept k{count_++, {x, y}};
  if (buckets_.empty() || in_last_ == per_bucket_) {
    if (buckets_.size() == 2 * kBuckets) halve();
    buckets_.push_back({k, k, k, k});
    in_last_ = 1;
    return;
  }
  Bucket& b = buckets_.back();
  b.last = k;
  if (y < b.lowest.p.y) b.lowest = k;
  if (y > b.highest.p.y) b.highest = k;
  ++in_last_;
}

void Curve::halve() {
  for (std::size_t i = 0; i < kBuckets; ++i) {
    const Bucket& a = buckets_[2 * i];
    const Bucket& b = buckets_[2 * i + 1];
    buckets_[i] = {a.first, b.lowest.p.y < a.lowest.p.y ? b.lowest : a.lowest,
                   b.highest.p.y > a.highest.p.y ? b.highest : a.highest, b.last};
  }
  buckets_.resize(kBuckets);
  per_bucket_ *= 2;
}

std::vector<Point> Curve::points() const {
  std::vector<Point> out;
  out.reserve(buckets_.size() * 4);
  for (const Bucket& b : buckets_) {
    Kept kept[4] = {b.first, b.lowest, b.highest, b.last};
    std::sort(std::begin(kept), std::end(kept),
              [](const Kept& l, const Kept& r) { return l.index < r.index; });
    for (int i = 0; i < 4; ++i)
      if (i == 0 || kept[i].index != kept[i - 1].index) out.push_back(kept[i].p);
  }
  return out;
}

RunData read_run(CsvLines& lines, const std::string& header) {
  RunData run;
  const std::vector<std::string> fields = header_fields(lines, header);
  if (fields.size() < 2 || fields[0] != "t")
    lines.reject("not a CSV of impact run, sweep or --events (its header is '" + cut(header) +
                 "'; a run's is t,<channels>)");
  for (std::size_t c = 1; c < fields.size(); ++c) {
    const bool channel = is_channel(fields[c]);
    if (!channel && (!is_identifier(fields[c]) || fields[c] == "t"))
      lines.reject("unknown channel '" + cut(fields[c]) +
                   "' in the header (a run's channels: " + channel_names() +
                   ", and internal variables by name: a letter or '_' followed by letters, "
                   "digits or '_')");
    if (std::count(fields.begin(), fields.end(), fields[c]) > 1)
      lines.reject("the channel '" + fields[c] + "' is in the header twice");
    run.channels.push_back(fields[c]);
    run.internal.push_back(!channel);
  }
  run.curves.resize(run.channels.size());
  for (std::string line; lines.next(line); ++run.rows) {
    const std::vector<std::string> row = row_fields(lines, line, fields.size());
    const double t = number(lines, row[0], "t");
    for (std::size_t c = 1; c < row.size(); ++c)
      run.curves[c - 1].add(t, number(lines, row[c], fields[c]));
  }
  if (run.rows == 0) lines.reject("no rows after the header");
  return run;
}

bool is_events_header(const std::string& header) {
  const std::string head = kEventsHead;
  return header.starts_with(head) && (header.size() == head.size() || header[head.size()] == ',');
}

EventsData read_events(CsvLines& lines, const std::string& header) {
  if (!is_events_header(header))
    lines.reject("not an events CSV of impact run (its header is '" + cut(header) +
                 "', expected t,kind,v_before,v_after and the internal variables' names)");
  EventsData events;
  const std::vector<std::string> columns = header_fields(lines, header);
  for (std::size_t c = 4; c < columns.size(); ++c) {
    if (!is_identifier(columns[c]) || std::count(columns.begin(), columns.end(), columns[c]) > 1)
      lines.reject("the header's '" + cut(columns[c]) +
                   "' after v_after is not the name of an internal variable (a letter or '_' "
                   "followed by letters, digits or '_', once)");
    events.internal.push_back(columns[c]);
  }
  events.internal_curves.resize(events.internal.size());
  for (std::string line; lines.next(line);) {
    const std::vector<std::string> row = row_fields(lines, line, columns.size());
    const auto kind =
        std::find(std::begin(EventsData::kKinds), std::end(EventsData::kKinds), row[1]) -
        std::begin(EventsData::kKinds);
    if (kind == EventsData::kCount)
      lines.reject("kind = '" + cut(row[1]) +
                   "' (allowed: impact, stick, lift, debond, capture, escape)");
    const double t = number(lines, row[0], "t");
    events.before[kind].add(t, number(lines, row[2], "v_before"));
    events.after[kind].add(t, number(lines, row[3], "v_after"));
    for (std::size_t i = 0; i < events.internal.size(); ++i)
      events.internal_curves[i][kind].add(t, number(lines, row[4 + i], events.internal[i]));
    ++events.count[kind];
  }
  return events;
}

bool is_sweep_header(const std::string& header) {
  const std::string tail = ",failure";
  return header.size() > tail.size() && header.ends_with(tail);
}

SweepData read_sweep(CsvLines& lines, const std::string& header) {
  SweepData sweep;
  const std::vector<std::string> fields = header_fields(lines, header);
  std::size_t c = 0;
  for (; c + 1 < fields.size() && fields[c].find('.') != std::string::npos; ++c) {
    if (!is_key(fields[c]))
      lines.reject("'" + cut(fields[c]) + "' in the header is not a scene key (table.key)");
    sweep.keys.push_back(fields[c]);
  }
  for (; c + 1 < fields.size(); ++c) {
    if (!is_quantity(fields[c]))
      lines.reject("unknown quantity '" + cut(fields[c]) +
                   "' in the header (impact sweep --help lists them; an internal variable at T "
                   "is NAME_T)");
    sweep.quantities.push_back(fields[c]);
  }
  if (sweep.keys.empty() || sweep.quantities.empty())
    lines.reject(
        "a sweep's header has its varied keys, then its quantities, then failure; this "
        "one is '" +
        cut(header) + "'");
  sweep.curves.resize(sweep.quantities.size());
  std::map<std::string, std::size_t> curve_of;
  for (std::string line; lines.next(line); ++sweep.points) {
    const std::vector<std::string> row = row_fields(lines, line, fields.size());
    const double x = number(lines, row[0], sweep.keys[0]);
    std::string name;
    for (std::size_t k = 1; k < sweep.keys.size(); ++k) {
      const double value = number(lines, row[k], sweep.keys[k]);
      name += (k > 1 ? ", " : "") + sweep.keys[k] + " = " + round_trip(value);
    }
    const auto [it, added] = curve_of.emplace(name, curve_of.size());
    if (added) {
      if (curve_of.size() > kMaxSweepCurves)
        lines.reject("more than " + std::to_string(kMaxSweepCurves) + " values of " +
                     sweep.keys[1] + (sweep.keys.size() > 2 ? " and the other keys" : "") +
                     ": plot draws one curve against " + sweep.keys[0] +
                     " for each; sweep fewer, or plot a slice of the rows");
      sweep.curve_names.push_back(name);
      for (auto& curves : sweep.curves) curves.emplace_back();
    }
    for (std::size_t q = 0; q < sweep.quantities.size(); ++q) {
      const std::string& field = row[sweep.keys.size() + q];
      if (!field.empty())
        sweep.curves[q][it->second].add(x, number(lines, field, sweep.quantities[q]));
    }
    sweep.failed += !row.back().empty();
  }
  if (sweep.points == 0) lines.reject("no rows after the header");
  return sweep;
}

}  // namespace impact::cli
