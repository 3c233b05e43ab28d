#include "impact/output.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstdlib>
#include <cstring>

namespace impact {
namespace {

// The temporary file being written, removed by the signal handler if the user interrupts a run
// (one per process: the CLI writes one output at a time).
char g_temp_path[4096];

extern "C" void remove_temp_and_exit(int sig) {
  if (g_temp_path[0] != '\0') unlink(g_temp_path);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

std::string why() {
  return std::strerror(errno);
}

}  // namespace

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
  if (path.empty() || path == "-") {
    stream_ = stdout;
    return;
  }
  struct stat info;
  if (stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    throw OutputError(path + ": --out names a directory; give a file name", true);
  std::string pattern = path + ".tmp.XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  int fd = mkstemp(name.data());
  if (fd < 0) throw OutputError(path + ": cannot create the output file: " + why(), true);
  temp_ = name.data();
  // mkstemp makes the file 0600; give it the permissions a plain fopen would.
  mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  stream_ = fdopen(fd, "w");
  if (!stream_) {
    close(fd);
    unlink(temp_.c_str());
    throw OutputError(path + ": cannot open the output file: " + why(), true);
  }
  buffer_.resize(1 << 20);
  std::setvbuf(stream_, buffer_.data(), _IOFBF, buffer_.size());
  if (temp_.size() < sizeof g_temp_path) {
    std::memcpy(g_temp_path, temp_.c_str(), temp_.size() + 1);
    std::signal(SIGINT, remove_temp_and_exit);
    std::signal(SIGTERM, remove_temp_and_exit);
  }
}

AtomicFile::~AtomicFile() {
  if (temp_.empty()) {
    if (stream_) std::fflush(stream_);
    return;
  }
  if (!committed_) {
    if (stream_) std::fclose(stream_);
    unlink(temp_.c_str());
  }
  g_temp_path[0] = '\0';
}

void AtomicFile::commit() {
  if (temp_.empty()) {
    if (std::fflush(stream_) != 0 || std::ferror(stream_))
      throw OutputError("standard output: write failed: " + why(), false);
    return;
  }
  bool failed = std::fflush(stream_) != 0 || std::ferror(stream_);
  int err = errno;
  failed = (std::fclose(stream_) != 0) || failed;
  stream_ = nullptr;
  if (failed) {
    errno = err ? err : errno;
    throw OutputError(path_ + ": write failed: " + why(), false);
  }
  if (std::rename(temp_.c_str(), path_.c_str()) != 0)
    throw OutputError(path_ + ": cannot move the output into place: " + why(), false);
  committed_ = true;
}

char* format_double(char* buf, char* end, double x) {
  return std::to_chars(buf, end, x, std::chars_format::general, 17).ptr;
}

CsvWriter::CsvWriter(std::FILE* out, const Model& model, std::vector<Channel> channels)
    : out_(out), model_(model), channels_(std::move(channels)) {}

void CsvWriter::header() {
  std::string line = "t";
  for (Channel c : channels_) {
    line += ',';
    line += channel_name(c);
  }
  line += "\n";
  std::fputs(line.c_str(), out_);
}

void CsvWriter::row(double t, const State& s, const StepInfo& info) {
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
        p = format_double(p, buf + sizeof buf, info.contact_force);
        break;
      case Channel::E:
        p = format_double(p, buf + sizeof buf, energy(model_, s));
        break;
      case Channel::iterations:
        p = std::to_chars(p, buf + sizeof buf, info.iterations).ptr;
        break;
    }
  }
  *p++ = '\n';
  std::fwrite(buf, 1, static_cast<std::size_t>(p - buf), out_);
}

}  // namespace impact
