#include "impact/output/atomic_file.hpp"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <optional>

namespace impact {
namespace {

// The temporary files being written, removed by the signal handler if a signal ends the run (the
// CLI writes at most three at a time: the rows, the events and the rows' provenance). A slot's
// g_temp_set is cleared before its name changes and set after, so that the handler never reads a
// half-copied name.
constexpr int kTempSlots = 3;
char g_temp_path[kTempSlots][PATH_MAX];
volatile std::sig_atomic_t g_temp_set[kTempSlots] = {};

extern "C" void remove_temp_and_reraise(int sig) {
  for (int i = 0; i < kTempSlots; ++i)
    if (g_temp_set[i]) unlink(g_temp_path[i]);
  // With the default action back, the signal ends the process once the handler returns (it is
  // blocked until then), as it would have without the handler: same exit status, core dump.
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigaction(sig, &default_action, nullptr);
  raise(sig);
}

// Every signal whose default action ends the process (signal(7)), so that only SIGKILL, which
// cannot be caught, or a power cut can leave a temporary behind.
constexpr int kFatalSignals[] = {SIGHUP,  SIGINT,  SIGQUIT,   SIGILL,  SIGTRAP, SIGABRT,
                                 SIGBUS,  SIGFPE,  SIGUSR1,   SIGSEGV, SIGUSR2, SIGPIPE,
                                 SIGALRM, SIGTERM, SIGSTKFLT, SIGXCPU, SIGXFSZ, SIGVTALRM,
                                 SIGPROF, SIGIO,   SIGPWR,    SIGSYS};

// Installs the handler where the signal has its default action. An ignored signal stays ignored:
// a script's background job ignores SIGINT, and the user's Ctrl-C is not meant for it; the CLI
// ignores SIGXFSZ. A handler found in place stays too: a sanitizer's for SIGSEGV, or this one,
// installed by an earlier AtomicFile.
void remove_temp_on(int sig) {
  struct sigaction old {};
  if (sigaction(sig, nullptr, &old) != 0 || (old.sa_flags & SA_SIGINFO) ||
      old.sa_handler != SIG_DFL)
    return;
  struct sigaction action {};
  action.sa_handler = remove_temp_and_reraise;
  sigfillset(&action.sa_mask);
  sigaction(sig, &action, nullptr);
}

void remove_temp_on_fatal_signals() {
  for (int sig : kFatalSignals) remove_temp_on(sig);
  for (int sig = SIGRTMIN; sig <= SIGRTMAX; ++sig) remove_temp_on(sig);
}

std::string why() {
  return std::strerror(errno);
}

// Whether this process may write `path` (`info` from stat), and if not, why_not: its mode bits,
// and what access(2) says. The mode bits are checked too because access lets root write anything:
// a file and a directory refuse their owner, and so root, alike.
bool writable(const std::string& path, const struct stat& info, std::string& why_not) {
  const bool allowed = faccessat(AT_FDCWD, path.c_str(), W_OK, AT_EACCESS) == 0;
  if (allowed && (info.st_mode & 0222) != 0) return true;
  char mode[8];
  std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(info.st_mode & 07777));
  why_not = std::string("mode ") + mode + (allowed ? "" : ": " + why());
  return false;
}

// The directory a path's last name is in ("." for a bare name).
std::string directory_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// What the symbolic link `link` names, as a path that reaches it from here (a relative link is
// relative to the link's directory); `link` itself if it cannot be read.
std::string link_target(const std::string& link) {
  std::vector<char> text(PATH_MAX);
  const ssize_t n = readlink(link.c_str(), text.data(), text.size());
  if (n <= 0 || static_cast<std::size_t>(n) == text.size()) return link;
  const std::string target(text.data(), static_cast<std::size_t>(n));
  const std::size_t slash = link.rfind('/');
  if (target.front() == '/' || slash == std::string::npos) return target;
  return link.substr(0, slash + 1) + target;
}

bool same_file(const struct stat& a, const struct stat& b) {
  return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

// Whether the symbolic link `link` is in /proc, where a link (/proc/self/fd/1, which /dev/stdout
// and /dev/fd/1 lead to) stands for an open file rather than for the path it shows.
bool in_proc(const std::string& link) {
  struct stat dir, proc;
  return stat(directory_of(link).c_str(), &dir) == 0 && stat("/proc/self", &proc) == 0 &&
         dir.st_dev == proc.st_dev;
}

// The descriptor of this process that `link` in /proc stands for (/proc/self/fd/N, also reached
// as /proc/<pid>/fd/N), or -1 if it stands for something else.
int own_descriptor(const std::string& link) {
  struct stat dir, own;
  if (stat(directory_of(link).c_str(), &dir) != 0) return -1;
  if (!(stat("/proc/self/fd", &own) == 0 && same_file(dir, own)) &&
      !(stat("/proc/thread-self/fd", &own) == 0 && same_file(dir, own)))
    return -1;
  const std::string name = link.substr(link.rfind('/') + 1);  // npos + 1 == 0
  int fd = -1;
  const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), fd);
  if (error != std::errc() || end != name.data() + name.size() || fcntl(fd, F_GETFD) == -1)
    return -1;
  return fd;
}

// Linux follows at most 40 symbolic links in one path (path_resolution(7)).
constexpr int kMaxLinks = 40;

// Where writing `path` leads: symbolic links followed one at a time, as the kernel would (a
// dangling link leads to the file it names, which the output then creates, as `>` in a shell),
// up to a link in /proc (/dev/stdout, /proc/self/fd/N), which stands for an open file rather
// than for the path it shows. Throws OutputError on a loop of links.
struct Destination {
  std::string target;
  bool proc_link = false;
};
Destination destination(const std::string& path) {
  Destination d{path};
  struct stat info;
  for (int links = 0; lstat(d.target.c_str(), &info) == 0 && S_ISLNK(info.st_mode); ++links) {
    if (in_proc(d.target)) {
      d.proc_link = true;
      return d;
    }
    if (links == kMaxLinks) {
      errno = ELOOP;
      throw OutputError(path + ": cannot open the output file: " + why(), true);
    }
    d.target = link_target(d.target);
  }
  return d;
}

// What a path names, for comparing two of them: the file it reaches (device and inode), or, for
// a file that does not exist yet, the directory it would be created in and its name; standard
// output ("-" or "") is the file that descriptor 1 is open on.
struct Identity {
  dev_t device = 0;
  ino_t inode = 0;
  std::string name;  // the new file's name in that directory; empty for an existing file
  bool operator==(const Identity&) const = default;
};
std::optional<Identity> identity(const std::string& path) {
  struct stat info;
  const auto of = [&](int ok) {
    return ok == 0 ? std::optional<Identity>(Identity{info.st_dev, info.st_ino, {}}) : std::nullopt;
  };
  if (path.empty() || path == "-") return of(fstat(STDOUT_FILENO, &info));
  const Destination d = destination(path);
  if (d.proc_link) {
    const int fd = own_descriptor(d.target);
    return of(fd >= 0 ? fstat(fd, &info) : stat(d.target.c_str(), &info));
  }
  if (stat(d.target.c_str(), &info) == 0) return of(0);
  if (stat(directory_of(d.target).c_str(), &info) != 0) return std::nullopt;
  return Identity{info.st_dev, info.st_ino, d.target.substr(d.target.rfind('/') + 1)};
}

}  // namespace

bool same_output(const std::string& a, const std::string& b) {
  if (a == b) return true;
  const auto x = identity(a), y = identity(b);
  return x && y && *x == *y;
}

bool writes_in_place(const std::string& path) {
  if (path.empty() || path == "-") return true;
  const Destination d = destination(path);
  if (d.proc_link) return true;
  struct stat info;
  return stat(d.target.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode);
}

void check_distinct(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  const auto stream = [](const std::string& path) { return path.empty() || path == "-"; };
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const NamedPath& out = outputs[i];
    const std::string shown = stream(out.path) ? "-" : out.path;
    if (!stream(out.path))
      for (const NamedPath& in : inputs)
        if (same_output(out.path, in.path))
          throw OutputError(shown + ": " + out.what + " names " + in.what + " itself; " + out.fix,
                            true);
    for (std::size_t j = 0; j < i; ++j)
      if (same_output(out.path, outputs[j].path))
        throw OutputError(
            shown + ": " + out.what + " and " + outputs[j].what + " lead to the same output (" +
                (stream(outputs[j].path) ? std::string("standard output") : outputs[j].path) +
                "); " + out.fix,
            true);
  }
}

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
  if (path.empty() || path == "-") {
    stream_ = stdout;
    return;
  }
  // A path the system cannot take would otherwise fail only at the rename, after the whole run.
  if (path.size() >= PATH_MAX)
    throw OutputError(path + ": the path is " + std::to_string(path.size()) +
                          " bytes long; the limit is " + std::to_string(PATH_MAX - 1) +
                          " (PATH_MAX)",
                      true);
  const Destination d = destination(path);
  const std::string& target = d.target;
  // Renaming over the file such a link shows would replace, e.g., the log that standard output
  // is appended to, or write where no descriptor of the caller points.
  if (d.proc_link) {
    open_in_place(target);
    return;
  }
  struct stat info;
  const bool exists = stat(target.c_str(), &info) == 0;
  if (exists && S_ISDIR(info.st_mode))
    throw OutputError(path + ": --out names a directory; give a file name", true);
  // A device or a pipe: written in place (it cannot hold a half-written file anyway).
  if (exists && !S_ISREG(info.st_mode)) {
    open_in_place(target);
    return;
  }
  // Refused, as `>` in a shell would be: the rename would replace the file regardless.
  std::string why_not;
  if (exists && !writable(target, info, why_not))
    throw OutputError(path + ": is read-only (" + why_not + "); not replacing it", true);
  const std::string directory = directory_of(target);
  struct stat dir_info;
  if (stat(directory.c_str(), &dir_info) == 0 && !writable(directory, dir_info, why_not))
    throw OutputError(path + ": cannot create the output file: the directory '" + directory +
                          "' is not writable (" + why_not +
                          "); the output is written to a temporary file beside its target",
                      true);
  // The temporary lives beside the target (rename is atomic only within one file system); its
  // name is the target's, cut so that the suffix still fits in NAME_MAX. The target's name must
  // fit as it is.
  const std::size_t base = target.rfind('/') + 1;  // npos + 1 == 0
  long name_max = pathconf(directory.c_str(), _PC_NAME_MAX);
  if (name_max <= 0) name_max = NAME_MAX;
  if (target.size() - base > static_cast<std::size_t>(name_max))
    throw OutputError(path + ": the file name " + (target == path ? "" : "it leads to ") + "is " +
                          std::to_string(target.size() - base) + " bytes long; the limit is " +
                          std::to_string(name_max) + " (NAME_MAX)",
                      true);
  constexpr std::size_t kSuffix = sizeof ".tmp.XXXXXX" - 1;
  std::string pattern = target.substr(0, base) +
                        target.substr(base, static_cast<std::size_t>(name_max) - kSuffix) +
                        ".tmp.XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  // Everything the object holds is allocated before the temporary exists, so that running out of
  // memory cannot leave it behind (a constructor that throws has no destructor to remove it).
  buffer_.resize(1 << 20);
  temp_.reserve(name.size());
  target_ = target;
  // From mkstemp to the handler knowing the name, signals wait: one that came in between would
  // leave the temporary.
  remove_temp_on_fatal_signals();
  sigset_t all, previous;
  sigfillset(&all);
  sigprocmask(SIG_BLOCK, &all, &previous);
  int fd = mkstemp(name.data());
  const int mkstemp_error = errno;
  for (int i = 0; i < kTempSlots && fd >= 0 && name.size() <= PATH_MAX; ++i) {
    if (g_temp_set[i]) continue;
    std::memcpy(g_temp_path[i], name.data(), name.size());
    g_temp_set[i] = 1;
    slot_ = i;
    break;
  }
  sigprocmask(SIG_SETMASK, &previous, nullptr);
  errno = mkstemp_error;
  if (fd < 0) throw OutputError(path + ": cannot create the output file: " + why(), true);
  temp_.assign(name.data());
  // mkstemp makes the file 0600: keep the mode of the file being replaced, or give a new one the
  // permissions a plain fopen would.
  mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, exists ? info.st_mode & 07777 : 0666 & ~mask);
  stream_ = fdopen(fd, "w");
  if (!stream_) {
    const int error = errno;
    ::close(fd);
    forget_temp();
    errno = error;
    throw OutputError(path + ": cannot open the output file: " + why(), true);
  }
  std::setvbuf(stream_, buffer_.data(), _IOFBF, buffer_.size());
}

void AtomicFile::open_in_place(const std::string& target) {
  // This process's own descriptor (/dev/stdout): written through, not opened again, so that the
  // shell's `>>` appends and commands sharing one `>` write one after the other.
  const int own = own_descriptor(target);
  if (own >= 0) {
    const int fd = dup(own);
    stream_ = fd >= 0 ? fdopen(fd, "w") : nullptr;
    if (!stream_ && fd >= 0) {
      const int error = errno;
      ::close(fd);
      errno = error;
    }
  } else {
    stream_ = std::fopen(target.c_str(), "w");
  }
  if (!stream_) throw OutputError(path_ + ": cannot open the output file: " + why(), true);
}

// Removes the temporary, and then its name from the signal handler's reach.
void AtomicFile::forget_temp() {
  unlink(temp_.c_str());
  if (slot_ >= 0) g_temp_set[slot_] = 0;
  slot_ = -1;
}

AtomicFile::~AtomicFile() {
  if (stream_ == stdout) {
    std::fflush(stream_);
    return;
  }
  if (temp_.empty()) {  // written in place
    if (stream_) std::fclose(stream_);
    return;
  }
  if (!committed_) {
    if (stream_) std::fclose(stream_);
    forget_temp();
  } else if (slot_ >= 0) {
    g_temp_set[slot_] = 0;
  }
}

void AtomicFile::check() const {
  if (stream_ && std::ferror(stream_))
    throw OutputError(
        (stream_ == stdout ? std::string("standard output") : path_) + ": write failed: " + why(),
        false);
}

void AtomicFile::close() {
  if (stream_ == stdout) {
    if (std::fflush(stream_) != 0 || std::ferror(stream_))
      throw OutputError("standard output: write failed: " + why(), false);
    return;
  }
  if (!stream_) return;
  bool failed = std::fflush(stream_) != 0 || std::ferror(stream_);
  int err = errno;
  failed = (std::fclose(stream_) != 0) || failed;
  stream_ = nullptr;
  if (failed) {
    errno = err ? err : errno;
    throw OutputError(path_ + ": write failed: " + why(), false);
  }
}

void AtomicFile::commit() {
  close();
  if (temp_.empty() || committed_) return;  // standard output, or written in place
  if (std::rename(temp_.c_str(), target_.c_str()) != 0)
    throw OutputError(path_ + ": cannot move the output into place: " + why(), false);
  committed_ = true;
}

void write_text_file(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  std::fputs(text.c_str(), file.stream());
  file.commit();
}

}  // namespace impact
