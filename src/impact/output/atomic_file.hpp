// Output files written whole or not at all: a temporary file beside the target, renamed into place
// only when everything was written, so that a failed run leaves no half-written file.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

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
  // Flushes and closes the file; throws OutputError if anything written so far failed. The
  // output is not in place yet: a caller that writes several files closes them all, then
  // commits them, so that a failure of one replaces none.
  void close();
  // close() if not done, then renames the temporary over the target.
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
  int slot_ = -1;  // the signal handler's slot for temp_ (csv.cpp), -1 for none
  bool committed_ = false;
};

// Whether two paths (given as outputs, or an output and an input) lead to the same file: the same
// file reached (symbolic links followed, /dev/stdout and /dev/fd/N as the descriptor they stand
// for, "-" as standard output), or, for a file not there yet, the same name in the same directory
// (so ./new.csv, sub/../new.csv and an absolute spelling are one).
bool same_output(const std::string& a, const std::string& b);

// Whether AtomicFile(path) writes in place (standard output, a device, a pipe, /dev/stdout, ...),
// where no file is created, so that nothing (a provenance sidecar) has a place beside it. Throws
// OutputError for a loop of symbolic links.
bool writes_in_place(const std::string& path);

// A file a command reads or writes, as its messages name it: what it is ("--out", "the scene
// file", "the provenance file of --out (o.csv.json)"), its path, and how to give it another
// ("give another file name").
struct NamedPath {
  std::string what, path, fix = "give another file name";
};
// Every output of a command against every input and every other output, as the files they lead
// to (same_output): throws OutputError (a bad path, exit 2) naming both where one output would
// replace an input ("--out names the scene file itself") or two outputs are one file or one stream
// ("--events and --out lead to the same output"). An output to standard output ("-" or "") is a
// stream, compared with the other outputs only.
void check_distinct(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

// Writes `text` to `path` through an AtomicFile: the file appears whole or not at all.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace impact
