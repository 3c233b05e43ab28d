// The figure check: reads a gnuplot script (experiments/*/plot.gp) as gnuplot would, statement by
// statement, and at each `plot` asks what a reader of the panel gets: a title, axis labels with a
// unit in brackets ("[m]", "[1]" for a pure number), a key placed outside the data, and axis
// ranges that come from the data. The script is read in text order: loops run once, both branches
// of an `if` are read, macros (@name) and `;` are expanded, so that the settings in force at a
// `plot` are those of its first pass.
//
// What counts as "from the data": autoscale (`*` or no range), or a bound whose expression names a
// variable that stats, a results file (load), value() or system() gave, or a variable computed
// from one. A bound of literal numbers (directly, or through variables assigned literals) is fixed.
// A variable assigned from the data once stays so (both branches of an `if` are read).
// A fixed range or a key inside the plot is accepted with a stated reason, a comment on its line
// or in the comment block just above it: "fixed range: <reason>", "key inside: <reason>"; an axis
// without a label with "no xlabel: <reason>" / "no ylabel: <reason>". A reason has 3 words or more.
// A panel whose border is unset (a strip that only holds a key) is not a data panel.
#pragma once

#include <cctype>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace figure_check {

struct Statement {
  std::string text;
  int line = 0;
  std::string comment;  // the line's comment and the comment block just above it
};

// The position just after the string literal starting at s[i] (' or ").
inline std::size_t skip_string(const std::string& s, std::size_t i) {
  const char q = s[i];
  for (++i; i < s.size(); ++i) {
    if (q == '"' && s[i] == '\\')
      ++i;
    else if (s[i] == q)
      return i + 1;
  }
  return s.size();
}

// Splits a line of code into statements at `;`, `{` and `}` outside strings.
inline void split_statements(const std::string& code, int line, const std::string& comment,
                             std::vector<Statement>& out) {
  std::string current;
  auto flush = [&] {
    const auto b = current.find_first_not_of(" \t");
    if (b != std::string::npos) out.push_back({current.substr(b), line, comment});
    current.clear();
  };
  for (std::size_t i = 0; i < code.size();) {
    const char c = code[i];
    if (c == '"' || c == '\'') {
      const auto j = skip_string(code, i);
      current += code.substr(i, j - i);
      i = j;
    } else if (c == ';' || c == '{' || c == '}') {
      flush();
      ++i;
    } else {
      current += c;
      ++i;
    }
  }
  flush();
}

// The statements of a script: continuation lines joined, comments kept beside their statements.
inline std::vector<Statement> read_statements(const std::string& script) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= script.size()) {
    const auto end = script.find('\n', start);
    lines.push_back(
        script.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  std::vector<Statement> out;
  std::string above;  // the comment block just above the current line
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const int first_line = static_cast<int>(n) + 1;
    std::string logical = lines[n];
    while (!logical.empty() && logical.back() == '\\' && n + 1 < lines.size()) {
      logical.pop_back();
      logical += lines[++n];
    }
    std::string code, comment;
    for (std::size_t i = 0; i < logical.size();) {
      if (logical[i] == '"' || logical[i] == '\'') {
        const auto j = skip_string(logical, i);
        code += logical.substr(i, j - i);
        i = j;
      } else if (logical[i] == '#') {
        comment = logical.substr(i + 1);
        break;
      } else {
        code += logical[i++];
      }
    }
    if (code.find_first_not_of(" \t") == std::string::npos) {
      above =
          comment.empty() && logical.find('#') == std::string::npos ? "" : above + " " + comment;
      continue;
    }
    split_statements(code, first_line, above + " " + comment, out);
    above.clear();
  }
  return out;
}

// The text of a double- or single-quoted literal.
inline std::string unquote(const std::string& literal) {
  std::string out;
  const char q = literal.front();
  for (std::size_t i = 1; i + 1 < literal.size(); ++i) {
    if (q == '"' && literal[i] == '\\' && i + 2 < literal.size()) {
      const char e = literal[++i];
      out += e == 'n' ? '\n' : e;
    } else if (q == '\'' && literal[i] == '\'' && i + 2 < literal.size()) {
      out += literal[++i];
    } else {
      out += literal[i];
    }
  }
  return out;
}

struct Token {
  enum Kind { kIdent, kString, kNumber, kOther } kind;
  std::string text;
  bool call = false;  // an identifier followed by '('
};

inline std::vector<Token> tokens(const std::string& s) {
  std::vector<Token> out;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c == '\'') {
      const auto j = skip_string(s, i);
      out.push_back({Token::kString, s.substr(i, j - i)});
      i = j;
    } else if (std::isdigit(c) || (c == '.' && i + 1 < s.size() && std::isdigit(s[i + 1]))) {
      std::size_t j = i;
      while (j < s.size() &&
             (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '.' ||
              ((s[j] == '-' || s[j] == '+') && (s[j - 1] == 'e' || s[j - 1] == 'E'))))
        ++j;
      out.push_back({Token::kNumber, s.substr(i, j - i)});
      i = j;
    } else if (std::isalpha(c) || c == '_') {
      std::size_t j = i;
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
      Token t{Token::kIdent, s.substr(i, j - i)};
      std::size_t k = j;
      while (k < s.size() && s[k] == ' ') ++k;
      t.call = k < s.size() && s[k] == '(';
      out.push_back(t);
      i = j;
    } else {
      if (!std::isspace(c)) out.push_back({Token::kOther, std::string(1, s[i])});
      ++i;
    }
  }
  return out;
}

// A reason of at least 3 words after "<key>:" in a comment.
inline bool has_reason(const std::string& comment, const std::string& key) {
  const auto at = comment.find(key + ":");
  if (at == std::string::npos) return false;
  static const std::regex three_words(R"(^\s*\S+\s+\S+\s+\S+)");
  return std::regex_search(comment.substr(at + key.size() + 1), three_words);
}

class Checker {
 public:
  explicit Checker(std::string name) : name_(std::move(name)) { reset(); }

  void run(const std::string& script) {
    for (const auto& s : read_statements(script)) statement(s, 0);
  }
  const std::vector<std::string>& problems() const { return problems_; }
  int plots() const { return plots_; }

 private:
  struct Axis {
    bool fixed = false;
    int line = 0;
  };
  std::string name_;
  std::vector<std::string> problems_;
  int plots_ = 0;
  std::map<std::string, std::string> definitions_;  // variable or function -> expression
  std::map<std::string, std::string> strings_;      // variable -> literal value (for macros)
  std::string title_, xlabel_, ylabel_;
  bool xlabel_waived_ = false, ylabel_waived_ = false, border_ = true;
  bool key_on_ = true, key_inside_ = true, key_reasoned_ = false;
  int key_line_ = 0;
  std::map<char, Axis> axes_;

  void reset() {
    title_.clear();
    xlabel_.clear();
    ylabel_.clear();
    xlabel_waived_ = ylabel_waived_ = false;
    border_ = key_on_ = key_inside_ = true;
    key_reasoned_ = false;
    axes_.clear();
  }
  void problem(int line, const std::string& what) {
    problems_.push_back(name_ + ":" + std::to_string(line) + ": " + what);
  }

  // Whether an expression's value comes from the data (see the header).
  bool derived(const std::string& expr, int depth = 0) const {
    static const std::set<std::string> literal_names = {"pi", "NaN", "x", "y", "eq", "ne"};
    if (depth > 20) return false;
    for (const auto& t : tokens(expr)) {
      if (t.kind != Token::kIdent) continue;
      if (t.text.rfind("STATS_", 0) == 0 || t.text.rfind("GPVAL_", 0) == 0) return true;
      if (t.call && (t.text == "value" || t.text == "system")) return true;
      if (literal_names.count(t.text)) continue;
      const auto d = definitions_.find(t.text);
      if (d == definitions_.end()) {
        if (!t.call) return true;  // not assigned here: loaded from a results file
        continue;                  // a built-in function: its arguments decide
      }
      if (derived(d->second, depth + 1)) return true;
    }
    return false;
  }

  // The literals a label expression can show (comparisons, fonts and colours left out), with the
  // literals of the user functions and variables it names.
  void label_literals(const std::string& expr, std::vector<std::string>& out, int depth = 0) const {
    if (depth > 10) return;
    const auto t = tokens(expr);
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i].kind == Token::kString) {
        const auto prev = i > 0 ? t[i - 1].text : "";
        const auto next = i + 1 < t.size() ? t[i + 1].text : "";
        if (prev == "eq" || prev == "ne" || next == "eq" || next == "ne" || prev == "font" ||
            prev == "rgb" || prev == "textcolor" || prev == "tc")
          continue;
        out.push_back(unquote(t[i].text));
      } else if (t[i].kind == Token::kIdent) {
        const auto d = definitions_.find(t[i].text);
        if (d != definitions_.end()) label_literals(d->second, out, depth + 1);
      }
    }
  }

  void check_label(const std::string& axis, const std::string& expr, bool waived, int line) {
    static const std::regex unit(R"(\[[^\]]+\])");
    if (waived) return;
    if (expr.empty()) return problem(line, "a panel without an " + axis + "label");
    std::vector<std::string> literals;
    label_literals(expr, literals);
    if (literals.empty()) return;  // built at run time: nothing to read here
    if (expr.find('?') == std::string::npos) {
      std::string joined;
      for (const auto& l : literals) joined += l;
      if (!std::regex_search(joined, unit))
        problem(line, axis + "label without a unit in brackets: " + joined);
      return;
    }
    for (const auto& l : literals)
      if (!std::regex_search(l, unit))
        problem(line, axis + "label without a unit in brackets: " + l);
  }

  void set_range(char axis, const std::string& rest, const Statement& s) {
    const auto open = rest.find('['), close = rest.rfind(']');
    if (open == std::string::npos || close == std::string::npos) return;
    const auto inside = rest.substr(open + 1, close - open - 1);
    // The colon between the bounds: the first one outside parentheses.
    int depth = 0;
    std::size_t colon = std::string::npos;
    for (std::size_t i = 0; i < inside.size() && colon == std::string::npos; ++i) {
      if (inside[i] == '(')
        ++depth;
      else if (inside[i] == ')')
        --depth;
      else if (inside[i] == '"' || inside[i] == '\'')
        i = skip_string(inside, i) - 1;
      else if (inside[i] == ':' && depth == 0)
        colon = i;
    }
    const std::string bounds[2] = {inside.substr(0, colon),
                                   colon == std::string::npos ? "" : inside.substr(colon + 1)};
    bool fixed = false;
    for (const auto& b : bounds) {
      const auto trimmed = std::regex_replace(b, std::regex(R"(\s+)"), "");
      if (trimmed.empty() || trimmed == "*") continue;
      if (!derived(b)) fixed = true;
    }
    axes_[axis] = {fixed && !has_reason(s.comment, "fixed range"), s.line};
  }

  void set_key(const std::string& rest, const Statement& s) {
    static const std::regex off(R"(^\s*off\b)");
    static const std::regex placement(
        R"(\b(inside|outside|below|above|over|under|top|bottom|left|right|center|at|tmargin|bmargin|lmargin|rmargin|default)\b)");
    static const std::regex outside(
        R"(\b(outside|below|above|over|under|tmargin|bmargin|lmargin|rmargin)\b|\bat\s+screen\b)");
    if (std::regex_search(rest, off)) {
      key_on_ = false;
      return;
    }
    key_on_ = true;
    if (!std::regex_search(rest, placement)) return;  // style only: the placement stays
    key_inside_ = !std::regex_search(rest, outside);
    key_reasoned_ = has_reason(s.comment, "key inside");
    key_line_ = s.line;
  }

  static bool draws_key(const std::string& plot) {
    // Elements separated by top-level commas; one without notitle / title "" is in the key.
    std::vector<std::string> elements(1);
    int depth = 0;
    for (std::size_t i = 0; i < plot.size(); ++i) {
      const char c = plot[i];
      if (c == '"' || c == '\'') {
        const auto j = skip_string(plot, i);
        elements.back() += plot.substr(i, j - i);
        i = j - 1;
        continue;
      }
      if (c == '(' || c == '[') ++depth;
      if (c == ')' || c == ']') --depth;
      if (c == ',' && depth == 0)
        elements.emplace_back();
      else
        elements.back() += c;
    }
    static const std::regex untitled(R"(\bnotitle\b|\b(title|t)\s*(""|''))");
    for (const auto& e : elements)
      if (!std::regex_search(e, untitled)) return true;
    return false;
  }

  void plot(const Statement& s) {
    if (!border_) return;  // a strip that holds only a key
    ++plots_;
    if (title_.empty()) problem(s.line, "a panel without a title");
    check_label("x", xlabel_, xlabel_waived_, s.line);
    check_label("y", ylabel_, ylabel_waived_, s.line);
    if (key_on_ && key_inside_ && !key_reasoned_ && draws_key(s.text))
      problem(s.line, "a key inside the plot without a reason (set key at line " +
                          std::to_string(key_line_) + ")");
    for (const auto& [axis, state] : axes_)
      if (state.fixed)
        problem(s.line, std::string("a fixed ") + axis + " range without a reason (set at line " +
                            std::to_string(state.line) + ")");
  }

  void statement(const Statement& s, int depth) {
    static const std::regex macro(R"(@([A-Za-z_]\w*))");
    std::smatch m;
    if (depth < 10 && std::regex_search(s.text, m, macro) && strings_.count(m[1])) {
      const auto expanded = std::regex_replace(s.text, macro, strings_[m[1]],
                                               std::regex_constants::format_first_only);
      std::vector<Statement> parts;
      split_statements(expanded, s.line, s.comment, parts);
      for (const auto& p : parts) statement(p, depth + 1);
      return;
    }
    static const std::regex assignment(R"(^([A-Za-z_]\w*)\s*(\([^()]*\))?\s*=([^=].*)$)");
    if (std::regex_match(s.text, m, assignment)) {
      const std::string name = m[1], expr = m[3];
      // Both branches of an `if` are read: a variable the data set once stays from the data.
      const auto old = definitions_.find(name);
      const bool was_derived = old != definitions_.end() && derived(old->second);
      definitions_[name] = was_derived ? old->second + " + " + expr : expr;
      const auto t = tokens(expr);
      if (t.size() == 1 && t[0].kind == Token::kString) strings_[name] = unquote(t[0].text);
      return;
    }
    static const std::regex command(R"(^(set|unset)\s+(\w+)\s*(.*)$)");
    if (std::regex_match(s.text, m, command)) {
      const bool set = m[1] == "set";
      const std::string what = m[2], rest = m[3];
      const auto waive = [&](const std::string& axis, bool& waived) {
        waived = has_reason(s.comment, "no " + axis + "label");
      };
      if (what == "title")
        title_ = set ? rest : "";
      else if (what == "xlabel")
        xlabel_ = set ? rest : "", waive("x", xlabel_waived_);
      else if (what == "ylabel")
        ylabel_ = set ? rest : "", waive("y", ylabel_waived_);
      else if (what == "key")
        set ? set_key(rest, s) : void(key_on_ = false);
      else if (what == "border")
        border_ = set;
      else if (what.size() >= 6 && what.substr(what.size() - 5) == "range")
        set ? set_range(what[0], rest, s) : void(axes_.erase(what[0]));
      else if (what == "autoscale") {
        if (rest.empty()) axes_.clear();
        for (const char a : std::string("xyz"))
          (rest.find(a) != std::string::npos) && axes_.erase(a);
      } else if (what == "multiplot" && set && rest.find("title") == std::string::npos)
        problem(s.line, "a figure (multiplot) without a title");
      return;
    }
    if (s.text == "reset") return reset();
    static const std::regex plot_command(R"(^(plot|splot|replot)\b)");
    if (std::regex_search(s.text, plot_command)) plot(s);
  }
};

}  // namespace figure_check
