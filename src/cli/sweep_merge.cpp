// `impact sweep --merge PART... --out FILE`: the parts of a sharded sweep joined into the file one
// machine would have written. Shard K of N holds points K-1, K-1+N, ... in order, so the merged
// rows take one line from each part in turn; every part is read as it streams (O(1) memory).
#include <sys/resource.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "cli/sweep.hpp"
#include "cli/sweep_csv.hpp"
#include "impact/output/csv.hpp"
#include "scene/scene_error.hpp"
#include "scene/toml_text.hpp"

namespace impact::cli {
namespace {

struct Part {
  std::string path;
  std::unique_ptr<std::ifstream> in;
  PartLine line;
  std::string header;
};

[[noreturn]] void reject(const std::string& path, const std::string& why) {
  throw SceneError("--merge: " + printable(path) + ": " + why);
}

// Why a part cannot be opened, and what was likely meant: --merge takes every word up to the next
// option as a part, and an option right after it as one too.
std::string cannot_open(const std::string& path, int error) {
  std::string why = std::string("cannot open the part: ") + std::strerror(error);
  if (path.starts_with("-"))
    why +=
        " (this looks like an option: give the parts right after --merge, e.g. --merge "
        "p1.csv p2.csv -o all.csv)";
  else if (error == ENOENT && path.find(',') != std::string::npos)
    why += " (parts are separated by spaces, not commas)";
  return why;
}

// A whole line, or false at the end of the file; a last line without its newline is a part cut
// short (a copy that did not finish), not a row.
bool read_line(Part& part, std::string& line) {
  if (!std::getline(*part.in, line)) return false;
  if (part.in->eof()) reject(part.path, "the last line has no newline: the part is cut short");
  return true;
}

// Every part open at once: raise the soft limit on open files to the hard one for many shards.
void allow_open_files(std::size_t count) {
  rlimit limit{};
  if (getrlimit(RLIMIT_NOFILE, &limit) == 0 && limit.rlim_cur < count + 16) {
    limit.rlim_cur = limit.rlim_max;
    setrlimit(RLIMIT_NOFILE, &limit);
  }
}

}  // namespace

int merge_parts(const std::vector<std::string>& paths, const std::string& out) {
  allow_open_files(paths.size());
  std::vector<Part> parts;
  for (const std::string& path : paths) {
    Part part{path, std::make_unique<std::ifstream>(path, std::ios::binary), {}, {}};
    if (!*part.in) reject(path, cannot_open(path, errno));
    std::string first;
    const auto line = read_line(part, first) ? parse_part_line(first) : std::nullopt;
    if (!line) reject(path, "not a part of a sweep (its first line is not '# impact sweep part')");
    part.line = *line;
    if (!read_line(part, part.header)) reject(path, "no CSV header after the first line");
    parts.push_back(std::move(part));
  }
  std::sort(parts.begin(), parts.end(),
            [](const Part& a, const Part& b) { return a.line.k < b.line.k; });
  const PartLine& first = parts.front().line;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Part& p = parts[i];
    if (p.line.n != first.n || p.line.points != first.points ||
        p.line.fingerprint != first.fingerprint || p.header != parts.front().header)
      reject(p.path, "belongs to another sweep than " + parts.front().path +
                         " (its scene, --set, --vary, --summary, --against or shard count differ)");
    if (p.line.k != static_cast<std::int64_t>(i) + 1)
      reject(p.path, p.line.k == static_cast<std::int64_t>(i)
                         ? "shard " + std::to_string(p.line.k) + " is given twice"
                         : "shard " + std::to_string(i + 1) + " of " + std::to_string(first.n) +
                               " is missing");
  }
  if (static_cast<std::int64_t>(parts.size()) != first.n)
    reject(parts.back().path, "shard " + std::to_string(parts.size() + 1) + " of " +
                                  std::to_string(first.n) + " is missing");

  // The merged file may not replace a part (as files: a link to one is one).
  std::vector<NamedPath> inputs;
  for (const std::string& path : paths) inputs.push_back({"the part " + path, path});
  check_distinct(inputs, {{"--out", out}});
  AtomicFile file(out);
  std::fputs((parts.front().header + "\n").c_str(), file.stream());
  std::string row;
  std::int64_t failed = 0;
  for (std::int64_t i = 0; i < first.points; ++i) {
    Part& part = parts[static_cast<std::size_t>(i % first.n)];
    if (!read_line(part, row))
      reject(part.path, "ends before point " + std::to_string(i + 1) + " of " +
                            std::to_string(first.points) + ": the part is incomplete");
    failed += row.empty() || row.back() != ',';  // a failed point ends with its reason
    row += '\n';
    std::fwrite(row.data(), 1, row.size(), file.stream());
    if (i % 65536 == 0) file.check();
  }
  for (Part& part : parts)
    if (read_line(part, row)) reject(part.path, "has more rows than its shard's points");
  file.commit();
  return failed > 0 ? 1 : 0;
}

}  // namespace impact::cli
