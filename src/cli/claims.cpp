// `impact-claims`: the claims ledger with its numbers. paper_notes/claims_source.md is the ledger
// as written: each row cites its measured numbers as `experiment:key`. This tool
//   table SOURCE [RESULTS] [REFERENCES]   prints the verdicts in the terminal with the numbers of
//                                         the latest run (RESULTS/<experiment>/summary.toml, else
//                                         the committed REFERENCES/<experiment>/reference.toml);
//   markdown SOURCE REFERENCES [OUT]      writes paper_notes/claims.md: the same ledger with the
//                                         committed numbers in place of the keys, and a tally;
//   check SOURCE REFERENCES COMMITTED     exits 1 when COMMITTED is not what `markdown` writes.
// A row's verdict must start with one of the six verdicts of `kVerdicts`; a row that does not, or
// that cites a key the references lack, or names no test, is an error (exit 1, naming the row). A
// key may end in an array index, `experiment:table.key[2]`.
#include <toml++/toml.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

// The fixed vocabulary, longest first where one is a prefix of another. "beyond the paper": a
// question the paper does not treat, or one of its statements carried past the hypotheses the
// paper states for it; measured, but neither for nor against the paper.
constexpr std::array<const char*, 6> kVerdicts = {"reproduced under a stated condition",
                                                  "holds by construction",
                                                  "not reproduced",
                                                  "error in the paper",
                                                  "beyond the paper",
                                                  "reproduced"};
constexpr std::array<std::size_t, 6> kTallyOrder = {5, 0, 1,
                                                    2, 3, 4};  // reading order of the tally
constexpr std::size_t kError = 3, kBeyond = 4;  // "error in the paper", "beyond the paper"
// What kind of error in the paper a row finds, in parentheses right after the verdict: a misprint
// the surrounding text corrects, a statement false as printed that one constant or factor mends,
// a formula with a term or sign wrong, a statement false that no constant mends, a true statement
// whose proof fails.
constexpr std::array<const char*, 5> kErrorKinds = {"typo", "wrong constant", "wrong formula",
                                                    "false statement", "flawed proof"};

struct Row {
  std::vector<std::string> cells;  // id | where | claim | experiment / test | measured | verdict
  std::size_t verdict = 0;         // index into kVerdicts
  std::size_t kind = 0;            // index into kErrorKinds, for an error in the paper
  std::size_t verdict_words = 0;   // the length of the verdict (and kind) at the cell's start
};

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

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

std::string escape_bars(const std::string& cell) {
  std::string out;
  for (const char c : cell) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

bool is_row(const std::string& line) {
  return line.rfind("| C", 0) == 0;
}

Row parse_row(const std::string& line) {
  Row row{cells(line), 0};
  if (row.cells.size() != 6)
    throw Error("row has " + std::to_string(row.cells.size()) + " cells, not 6: " + line);
  const std::string& id = row.cells[0];
  const std::string& verdict = row.cells[5];
  std::size_t k = 0;
  for (; k < kVerdicts.size(); ++k) {
    const std::string v = kVerdicts[k];
    if (verdict.rfind(v, 0) == 0 &&
        (verdict.size() == v.size() ||
         std::string(" :;,(").find(verdict[v.size()]) != std::string::npos))
      break;
  }
  if (k == kVerdicts.size())
    throw Error(id + ": the verdict \"" + verdict.substr(0, 40) +
                "...\" does not start with reproduced / reproduced under a stated condition / "
                "holds by construction / not reproduced / error in the paper / beyond the paper");
  if (row.cells[3].find("test_") == std::string::npos)
    throw Error(id + ": the experiment / test cell names no test (test_<file>)");
  row.verdict = k;
  row.verdict_words = std::string(kVerdicts[k]).size();
  if (k == kError) {
    for (; row.kind < kErrorKinds.size(); ++row.kind)
      if (verdict.rfind(std::string("error in the paper (") + kErrorKinds[row.kind] + ")", 0) == 0)
        break;
    if (row.kind == kErrorKinds.size())
      throw Error(id +
                  ": an error in the paper names its kind next, \"error in the paper (KIND)\", " +
                  "KIND one of typo / wrong constant / wrong formula / false statement / flawed "
                  "proof");
    row.verdict_words += std::string(kErrorKinds[row.kind]).size() + 3;
  }
  return row;
}

// Significant digits: 4 for a float ("5.801", "1.066e-14"), an integer as it is.
std::string format(const toml::node& node) {
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  if (const auto* f = node.as_floating_point()) {
    std::array<char, 32> text{};
    std::snprintf(text.data(), text.size(), "%.4g", f->get());
    std::string s = text.data();
    const auto e = s.find('e');  // 1.066e-14 stays, 1e+06 -> 1e6, 1e-05 -> 1e-5
    if (e != std::string::npos) {
      std::string exponent = s.substr(e + 1);
      const std::string sign = exponent[0] == '-' ? "-" : "";
      exponent.erase(0, exponent.find_first_not_of("+-0"));
      s = s.substr(0, e) + "e" + sign + exponent;
    }
    return s;
  }
  std::ostringstream value;
  node.visit([&](auto&& v) { value << v; });
  return value.str();
}

// The TOML files of the experiments, read once each.
class Numbers {
 public:
  Numbers(std::string results, std::string references)
      : results_(std::move(results)), references_(std::move(references)) {}

  // The value of `key` in the experiment's summary (if a results folder is given and has it),
  // else in its reference; nullopt when neither has it. `from_results` tells which was used.
  std::optional<std::string> get(const std::string& experiment, const std::string& key,
                                 bool* from_results = nullptr) {
    if (!results_.empty()) {
      if (const toml::node* n = find(results_ + "/" + experiment + "/summary.toml", key)) {
        if (from_results) *from_results = true;
        return format(*n);
      }
    }
    if (from_results) *from_results = false;
    if (const toml::node* n = find(references_ + "/" + experiment + "/reference.toml", key))
      return format(*n);
    return std::nullopt;
  }

 private:
  const toml::node* find(const std::string& path, const std::string& key) {
    auto it = files_.find(path);
    if (it == files_.end()) {
      std::optional<toml::table> table;
      try {
        table = toml::parse_file(path);
      } catch (const toml::parse_error&) {
      }
      it = files_.emplace(path, std::move(table)).first;
    }
    if (!it->second) return nullptr;
    return it->second->at_path(key).node();
  }
  std::string results_, references_;
  std::map<std::string, std::optional<toml::table>> files_;
};

const std::regex& reference_pattern() {
  static const std::regex pattern("`([A-Za-z0-9_]+):([A-Za-z0-9_.\\-]+(?:\\[[0-9]+\\])?)`");
  return pattern;
}

// The measured cell with each `experiment:key` replaced by its committed value.
std::string substitute(const Row& row, Numbers& numbers) {
  const std::string& cell = row.cells[4];
  std::string out;
  auto last = cell.cbegin();
  for (std::sregex_iterator m(cell.begin(), cell.end(), reference_pattern()), end; m != end; ++m) {
    const auto value = numbers.get((*m)[1].str(), (*m)[2].str());
    if (!value)
      throw Error(row.cells[0] + ": " + (*m)[0].str() + " is not in experiments/" + (*m)[1].str() +
                  "/reference.toml");
    out.append(last, (*m)[0].first);
    out += "**" + *value + "**";
    last = (*m)[0].second;
  }
  out.append(last, cell.cend());
  return out;
}

std::vector<std::string> read_lines(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot read " + path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The count line (the claims on the paper's statements, then those beyond it) and the table of
// verdicts, an error in the paper with its kind.
std::string tally(const std::vector<Row>& rows) {
  std::array<std::vector<std::string>, kVerdicts.size()> ids;
  for (const Row& row : rows)
    ids[row.verdict].push_back(row.cells[0] + (row.verdict == kError
                                                   ? std::string(" (") + kErrorKinds[row.kind] + ")"
                                                   : std::string()));
  std::ostringstream out;
  out << "**" << rows.size() << " claims: " << rows.size() - ids[kBeyond].size()
      << " on the paper's own statements (";
  for (std::size_t i = 0; i < kTallyOrder.size(); ++i)
    if (kTallyOrder[i] != kBeyond)
      out << (i ? ", " : "") << ids[kTallyOrder[i]].size() << " " << kVerdicts[kTallyOrder[i]];
  out << ") and " << ids[kBeyond].size()
      << " beyond the paper.**\n\n| verdict | claims |\n| --- | --- |\n";
  for (const std::size_t k : kTallyOrder) {
    out << "| " << kVerdicts[k] << " (" << ids[k].size() << ") |";
    for (std::size_t i = 0; i < ids[k].size(); ++i) out << (i ? ", " : " ") << ids[k][i];
    out << " |\n";
  }
  return out.str();
}

// paper_notes/claims.md from the source ledger: a notice, the source's title, the tally, then the
// source with every row's keys replaced by numbers and its verdict's leading words in bold.
std::string markdown(const std::string& source, const std::string& references) {
  const std::vector<std::string> lines = read_lines(source);
  std::vector<Row> rows;
  for (const std::string& line : lines)
    if (is_row(line)) rows.push_back(parse_row(line));
  if (rows.empty()) throw Error("no claim rows (| C...) in " + source);
  Numbers numbers("", references);
  std::ostringstream out;
  out << "<!-- Generated by impact-claims (make claims-md) from claims_source.md and the committed "
         "experiments/*/reference.toml: edit those, not this file. -->\n";
  std::size_t r = 0, i = 0;
  if (!lines.empty() && lines[0].rfind("# ", 0) == 0) out << lines[i++] << "\n\n" << tally(rows);
  for (; i < lines.size(); ++i) {
    if (!is_row(lines[i])) {
      out << lines[i] << "\n";
      continue;
    }
    const Row& row = rows[r++];
    std::vector<std::string> c = row.cells;
    c[4] = substitute(row, numbers);
    const std::size_t n = row.verdict_words;
    c[5] = "**" + c[5].substr(0, n) + "**" + c[5].substr(n);
    out << "|";
    for (const std::string& cell : c) out << " " << escape_bars(cell) << " |";
    out << "\n";
  }
  return out.str();
}

// The terminal table: claim, verdict and test on one line, then each measured number on a line of
// its own as key = value (latest run, else the reference), so that a number says what it is.
void table(const std::string& source, const std::string& results, const std::string& references) {
  Numbers numbers(results, references);
  bool any_reference = false;
  std::printf("%-4s  %-35s  %s\n", "id", "verdict", "test");
  for (const std::string& line : read_lines(source)) {
    if (!is_row(line)) continue;
    const Row row = parse_row(line);
    const std::string& test = row.cells[3];
    const auto slash = test.find(" / ");
    std::printf("%-4s  %-35s  %s\n", row.cells[0].c_str(), kVerdicts[row.verdict],
                (slash == std::string::npos ? test : test.substr(slash + 3)).c_str());
    const std::string& cell = row.cells[4];
    for (std::sregex_iterator m(cell.begin(), cell.end(), reference_pattern()), end; m != end;
         ++m) {
      bool from_results = false;
      const auto value = numbers.get((*m)[1].str(), (*m)[2].str(), &from_results);
      if (!from_results) any_reference = true;
      std::printf("      %s:%s = %s%s\n", (*m)[1].str().c_str(), (*m)[2].str().c_str(),
                  value.value_or("(missing)").c_str(), from_results ? "" : "*");
    }
  }
  if (any_reference)
    std::printf("* no result of the latest run: the committed reference.toml value\n");
}

int usage() {
  std::cerr << "usage: impact-claims table SOURCE [RESULTS] [REFERENCES]\n"
               "       impact-claims markdown SOURCE REFERENCES [OUT]\n"
               "       impact-claims check SOURCE REFERENCES COMMITTED\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() < 2) return usage();
  try {
    const std::string& mode = args[0];
    if (mode == "table") {
      table(args[1], args.size() > 2 ? args[2] : "results",
            args.size() > 3 ? args[3] : "experiments");
      return 0;
    }
    if (args.size() < 3) return usage();
    const std::string generated = markdown(args[1], args[2]);
    if (mode == "markdown") {
      if (args.size() < 4) {
        std::cout << generated;
        return 0;
      }
      std::ofstream out(args[3], std::ios::binary);
      if (!(out << generated) || !out.flush()) throw Error("cannot write " + args[3]);
      return 0;
    }
    if (mode == "check" && args.size() == 4) {
      std::ifstream in(args[3], std::ios::binary);
      const std::string committed{std::istreambuf_iterator<char>(in), {}};
      if (committed == generated) return 0;
      std::cerr << "impact-claims: " << args[3] << " is stale: run `make claims-md`\n";
      return 1;
    }
    return usage();
  } catch (const Error& e) {
    std::cerr << "impact-claims: " << e.what() << "\n";
    return 1;
  }
}
