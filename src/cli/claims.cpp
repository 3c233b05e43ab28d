// `impact-claims`: prints the verdict table of paper_notes/claims.md with the numbers of the latest
// experiment results. A ledger row cites its measured numbers as `experiment:key`; the value is
// read from results/<experiment>/summary.toml, so the table shows what the last run measured.
#include <toml++/toml.h>

#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

// The cells of a Markdown table row; "\|" is a literal bar inside a cell.
std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::string cell;
  bool started = false;
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size() && row[i + 1] == '|') {
      cell += '|';
      ++i;
    } else if (row[i] == '|') {
      if (started) {
        const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
        out.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
      }
      started = true;
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  return out;
}

std::string latest(const std::string& results, const std::string& experiment,
                   const std::string& key, std::map<std::string, toml::table>& cache) {
  auto it = cache.find(experiment);
  if (it == cache.end()) {
    toml::table summary;
    try {
      summary = toml::parse_file(results + "/" + experiment + "/summary.toml");
    } catch (const toml::parse_error&) {
      return "(no results: make " + experiment + ")";
    }
    it = cache.emplace(experiment, std::move(summary)).first;
  }
  const toml::node_view<const toml::node> node = std::as_const(it->second).at_path(key);
  if (!node) return "(" + key + " missing)";
  std::ostringstream value;
  node.node()->visit([&](auto&& v) { value << v; });
  return value.str();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string ledger = argc > 1 ? argv[1] : "paper_notes/claims.md";
  const std::string results = argc > 2 ? argv[2] : "results";
  std::ifstream in(ledger);
  if (!in) {
    std::cerr << "impact-claims: cannot read " << ledger << "\n";
    return 2;
  }
  const std::regex reference("`([A-Za-z0-9_]+):([A-Za-z0-9_.\\-]+)`");
  std::map<std::string, toml::table> cache;
  std::string line;
  int rows = 0;
  while (std::getline(in, line)) {
    if (line.rfind("| C", 0) != 0) continue;
    const std::vector<std::string> c = cells(line);
    if (c.size() < 6) continue;
    // Columns: id | where | claim | experiment / test | measured | verdict
    std::string measured;
    for (std::sregex_iterator m(c[4].begin(), c[4].end(), reference), end; m != end; ++m)
      measured += (measured.empty() ? "" : "; ") + (*m)[1].str() + ":" + (*m)[2].str() + " = " +
                  latest(results, (*m)[1].str(), (*m)[2].str(), cache);
    std::cout << c[0] << " | " << c[1] << " | " << c[5] << " | "
              << (measured.empty() ? c[4] : measured) << "\n";
    ++rows;
  }
  if (rows == 0) {
    std::cerr << "impact-claims: no claim rows (| C...) in " << ledger << "\n";
    return 1;
  }
  return 0;
}
