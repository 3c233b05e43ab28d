// What `impact plot` reads: the CSVs of impact run (t,<channels>), of --events
// (t,kind,v_before,v_after[,<internal variables>]) and of impact sweep
// (<keys>,<quantities>,failure), read line by line within fixed bounds, and each curve thinned to
// what a figure can show. (The table of impact work-precision: plot_work_precision.cpp.)
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace impact::cli {

// What plot reads is bounded: a longer line is not a line of these CSVs (a run's row has at most
// six numbers, a sweep's a few dozen and a one-line failure message), and more rows than impact run
// writes without --force are not a run of it.
constexpr std::size_t kMaxLineBytes = 1 << 16;
constexpr std::int64_t kMaxRows = 100'000'000;

// A CSV that is not one plot can draw (exit code 2); the message names the file and the line.
class PlotInputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The lines of a file without their line ends ("\n" or "\r\n"), at most kMaxLineBytes each and at
// most max_rows + 2 of them (a sweep part's first line, the header, the rows), read in blocks.
class CsvLines {
 public:
  // Throws PlotInputError if the file cannot be read.
  explicit CsvLines(const std::string& path, std::int64_t max_rows = kMaxRows);
  CsvLines(const CsvLines&) = delete;
  CsvLines& operator=(const CsvLines&) = delete;
  bool next(std::string& line);
  std::int64_t line_number() const { return line_; }
  const std::string& path() const { return path_; }
  // "<path>, line <n>: <what>", for a PlotInputError.
  [[noreturn]] void reject(const std::string& what) const;

 private:
  std::string path_;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_;
  std::vector<char> block_;
  std::size_t begin_ = 0, end_ = 0;
  std::int64_t line_ = 0, max_rows_;
};

// The fields of a CSV line; a field in double quotes (a sweep's failure message) may hold commas
// and doubled quotes.
std::vector<std::string> split_fields(const std::string& line);
// A number as impact writes it (round-trip decimal, nan, inf); false for anything else.
bool parse_number(const std::string& field, double& x);

struct Point {
  double x = 0, y = 0;
};

// A curve of any length kept in bounded memory: up to 2 kBuckets points are kept as they are;
// past that, consecutive points are grouped in buckets of equal count (doubling as more come) and
// each bucket keeps its first, lowest, highest and last point, in their order. Drawn, that is
// the same figure at any resolution finer than kBuckets columns: every extreme, every jump, every
// impulse of N. Non-finite y are left out (a sweep's rest_time is nan without rest).
class Curve {
 public:
  static constexpr std::size_t kBuckets = 4096;
  void add(double x, double y);
  std::vector<Point> points() const;
  std::int64_t count() const { return count_; }
  bool thinned() const { return per_bucket_ > 1; }
  std::int64_t per_bucket() const { return per_bucket_; }
  bool empty() const { return count_ == 0; }
  double low() const { return low_; }
  double high() const { return high_; }
  double x_low() const { return x_low_; }
  double x_high() const { return x_high_; }

 private:
  struct Kept {
    std::int64_t index;
    Point p;
  };
  struct Bucket {
    Kept first, lowest, highest, last;
  };
  void halve();
  std::vector<Bucket> buckets_;
  std::int64_t per_bucket_ = 1, in_last_ = 0, count_ = 0;
  double low_ = 0, high_ = 0, x_low_ = 0, x_high_ = 0;
};

// A name an internal variable may have (internal.cpp): a letter or '_' followed by letters,
// digits or '_'.
bool is_identifier(const std::string& name);

// A run's CSV: its channels and one curve of each against t. A channel is one of impact's
// (channels.hpp) or an internal variable's name.
struct RunData {
  std::vector<std::string> channels;
  std::vector<bool> internal;  // per channel: an internal variable
  std::vector<Curve> curves;
  std::int64_t rows = 0;
  // From the run's provenance sidecar (CSV.json), when there is one: whether its force depends on
  // t (which energy the E channel is) and its method (a name of the method table), the name of
  // its curves.
  std::optional<bool> force_depends_on_t;
  std::optional<std::string> method;
};
RunData read_run(CsvLines& lines, const std::string& header);

// An events CSV: v_before and v_after against t, one pair of curves per kind (impact, stick,
// lift, and a bonded run's debond, capture, escape: event.hpp), and each internal variable at the
// events, one curve per kind; the t of the kept points mark the events on a run's panels.
struct EventsData {
  static constexpr const char* kKinds[] = {"impact", "stick",   "lift",
                                           "debond", "capture", "escape"};
  static constexpr std::size_t kCount = std::size(kKinds);
  Curve before[kCount], after[kCount];
  std::int64_t count[kCount] = {};
  std::vector<std::string> internal;                       // the internal variables' names
  std::vector<std::array<Curve, kCount>> internal_curves;  // [variable][kind]
};
EventsData read_events(CsvLines& lines, const std::string& header);
bool is_events_header(const std::string& header);

// A sweep's CSV: x is its first varied key, one curve per quantity and per combination of the
// values of the other keys (at most kMaxSweepCurves).
constexpr std::size_t kMaxSweepCurves = 8;
struct SweepData {
  std::vector<std::string> keys, quantities;
  std::vector<std::string> curve_names;    // "time.T = 10, floor.cor = 0.5" (empty: one key)
  std::vector<std::vector<Curve>> curves;  // [quantity][curve]
  std::int64_t points = 0, failed = 0;
};
SweepData read_sweep(CsvLines& lines, const std::string& header);
bool is_sweep_header(const std::string& header);

}  // namespace impact::cli
