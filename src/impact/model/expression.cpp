#include "impact/model/expression.hpp"

#include <muParser.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string_view>

#include "impact/format.hpp"

namespace impact {

namespace {

std::atomic<std::size_t> parses{0};

// A token muparser could not read that starts as a number does ("9.8e", "2.5e+").
bool starts_number(const std::string& token) {
  return !token.empty() && (std::isdigit(static_cast<unsigned char>(token[0])) || token[0] == '.');
}

// The number that starts at `position` of the text: digits, '.', an exponent and its sign.
std::string number_at(const std::string& text, std::size_t position) {
  std::size_t end = position;
  while (end < text.size()) {
    const char c = text[end];
    const bool sign =
        (c == '+' || c == '-') && end > position && (text[end - 1] == 'e' || text[end - 1] == 'E');
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || sign)) break;
    ++end;
  }
  return text.substr(position, end - position);
}

// What a force expression and a rate may not be, checked on the text before muparser sees it:
// an assignment with '=' (muparser's "t = 1" sets t; "+=", "-=", ... too), which would change a
// variable that the force and the other rates read. `reads` says what the expression may read.
void refuse_assignment(const std::string& text, const std::string& reads) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '=') continue;
    const bool comparison =
        (i > 0 && std::string_view("=!<>").find(text[i - 1]) != std::string_view::npos) ||
        (i + 1 < text.size() && text[i + 1] == '=');
    if (comparison) continue;
    // The name assigned to: the word before the '=' (or the operator, "+=").
    std::size_t end = i;
    if (end > 0 && std::string_view("+-*/").find(text[end - 1]) != std::string_view::npos) --end;
    while (end > 0 && text[end - 1] == ' ') --end;
    std::size_t start = end;
    while (start > 0 &&
           (std::isalnum(static_cast<unsigned char>(text[start - 1])) || text[start - 1] == '_'))
      --start;
    const std::string name = start < end ? text.substr(start, end - start) : "a value";
    throw std::invalid_argument("the expression assigns to " + name + " with '=' at position " +
                                std::to_string(i + 1) + "; " + reads + " (to compare, write '==')");
  }
}

// After the first Eval: several comma-separated values ("1,2"), of which muparser keeps the last.
void refuse_value_list(mu::Parser& parser) {
  if (const int values = parser.GetNumResults(); values > 1)
    throw std::invalid_argument("the expression has " + std::to_string(values) +
                                " values separated by commas, of which muparser would keep the "
                                "last; give one (a comma only separates arguments)");
}

}  // namespace

struct Expression::Facts {
  std::string text;
  bool compiled = false;
  bool state = false;             // reads u, v or an internal variable
  ExpressionVariables variables;  // z[0..m) of an evaluation
};

// The variables are bound by address: the parser and its variables stay together on the heap.
struct Expression::Parser {
  explicit Parser(const Facts& facts) : count(facts.variables.names.size()) {
    parser.DefineVar("t", &t);
    parser.DefineVar("u", &u);
    parser.DefineVar("v", &v);
    for (std::size_t i = 0; i < count; ++i) parser.DefineVar(facts.variables.names[i], &z[i]);
    parser.DefineConst("pi", std::numbers::pi);
    parser.SetExpr(facts.text);
    ++parses;  // muparser parses the text at the first Eval
  }
  double eval() {
    try {
      return parser.Eval();
    } catch (const mu::Parser::exception_type& e) {
      throw std::runtime_error(e.GetMsg());
    }
  }
  mu::Parser parser;
  double t = 0.0, u = 0.0, v = 0.0;
  std::array<double, kMaxInternal> z{};
  std::size_t count;
};

Expression::Expression(std::string text) {
  if (text.empty()) return;
  auto facts = std::make_shared<Facts>();
  facts->text = std::move(text);
  facts_ = std::move(facts);
}

Expression::Expression() = default;

Expression::Expression(const char* text) : Expression(std::string(text)) {}

Expression::Expression(std::string text, ExpressionVariables variables, std::string_view rate_of,
                       Compile) {
  auto facts = std::make_shared<Facts>();
  facts->text = std::move(text);
  facts->compiled = true;
  facts->variables = std::move(variables);
  const std::string named = variables_named(facts->variables.names);
  const std::string& text_ = facts->text;
  if (!rate_of.empty()) {
    const std::string name(rate_of);
    const std::string what = "the rate of internal variable \"" + name + "\"";
    if (text_.find_first_not_of(" \t") == std::string::npos)
      throw std::invalid_argument(what + " is empty; give g in " + name + "' = g(" + named + ")");
    try {
      refuse_assignment(text_, "a rate only reads " + named);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(what + ": " + e.what());
    }
    std::unique_ptr<Parser> parser;
    try {
      parser = std::make_unique<Parser>(*facts);
      std::copy(facts->variables.initial.begin(), facts->variables.initial.end(),
                parser->z.begin());
      // The first Eval parses: an unknown name or a malformed expression fails here, and the
      // values it gives are counted. Its value (at t = 0, u = v = 0) is not checked: the scene
      // reader evaluates the rates at the initial state.
      parser->parser.Eval();
      refuse_value_list(parser->parser);
    } catch (const mu::Parser::exception_type& e) {
      throw std::invalid_argument(what + " does not parse: " + e.GetMsg() + " (the variables are " +
                                  named + ")");
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(what + ": " + e.what());
    }
    facts_ = std::move(facts);
    parser_ = std::move(parser);
    return;
  }
  if (text_.size() > kMaxExpressionLength)
    throw std::invalid_argument("the expression has " + std::to_string(text_.size()) +
                                " characters; at most " + std::to_string(kMaxExpressionLength) +
                                " are allowed");
  if (text_.find_first_not_of(" \t") == std::string::npos)
    throw std::invalid_argument("the expression is empty; give a function of t (and u, v)");
  refuse_assignment(text_, "a force only reads " + named);
  std::unique_ptr<Parser> parser;
  try {
    parser = std::make_unique<Parser>(*facts);
    std::copy(facts->variables.initial.begin(), facts->variables.initial.end(), parser->z.begin());
    const double f0 = parser->parser.Eval();
    // muparser records the variables it read as the first Eval parses (GetUsedVar parses again,
    // and so does the next Eval).
    const auto& used = parser->parser.GetUsedVar();
    facts->state = used.count("u") > 0 || used.count("v") > 0;
    for (const std::string& name : facts->variables.names)
      facts->state = facts->state || used.count(name) > 0;
    refuse_value_list(parser->parser);
    // A force of t alone must be finite where every run starts; one of the state is probed at
    // the scene's initial state by the scene reader (check_force), and elsewhere where the run
    // evaluates it.
    if (!std::isfinite(f0) && !facts->state)
      throw std::invalid_argument("the expression is " + round_trip(f0) +
                                  " at t = 0; it must be finite");
  } catch (const mu::Parser::exception_type& e) {
    // Positions are counted from 1 here; muparser's own message counts from 0, so it is left
    // out where the position is all it adds.
    const std::string at = " at position " + std::to_string(e.GetPos() + 1);
    if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN && starts_number(e.GetToken()))
      throw std::invalid_argument("the number \"" + number_at(text_, e.GetPos()) + "\"" + at +
                                  " is malformed (a number is digits with an optional fraction "
                                  "and exponent, as 9.8, .5 or 2.5e-3)");
    if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN)
      throw std::invalid_argument("the expression uses \"" + e.GetToken() + "\"" + at +
                                  ", which is no variable or function muparser knows (the "
                                  "variables are " +
                                  named + "; pi is defined)");
    throw std::invalid_argument("the expression does not parse" + at + ": " + e.GetMsg() +
                                " (the variables are " + named + "; pi is defined)");
  }
  facts_ = std::move(facts);
  parser_ = std::move(parser);
}

// A copy shares the facts and makes its own parser when it first evaluates.
Expression::Expression(const Expression& other) : facts_(other.facts_) {}

Expression& Expression::operator=(const Expression& other) {
  if (this != &other) {
    facts_ = other.facts_;
    parser_.reset();
  }
  return *this;
}

Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;
Expression::~Expression() = default;

const std::string& Expression::text() const {
  static const std::string none;
  return facts_ ? facts_->text : none;
}

bool Expression::is_compiled() const {
  return facts_ && facts_->compiled;
}

Expression Expression::compiled(const ExpressionVariables& variables, std::string_view rate_of,
                                Compile) const {
  if (is_compiled() && facts_->variables.names == variables.names) return *this;
  return Expression(text(), variables, rate_of, Compile{});
}

bool Expression::reads_state() const {
  return facts_ && facts_->state;
}

Expression::Parser& Expression::parser() const {
  if (!parser_) {
    if (!is_compiled())
      throw std::logic_error("Expression: \"" + text() + "\" is evaluated before it is compiled");
    parser_ = std::make_unique<Parser>(*facts_);
  }
  return *parser_;
}

double Expression::operator()(double t) const {
  Parser& p = parser_ ? *parser_ : parser();  // made at the first evaluation
  p.t = t;
  return p.eval();
}

double Expression::operator()(double t, double u, double v, const double* z) const {
  Parser& p = parser_ ? *parser_ : parser();  // made at the first evaluation
  p.t = t;
  p.u = u;
  p.v = v;
  for (std::size_t i = 0; i < p.count; ++i) p.z[i] = z[i];
  return p.eval();
}

std::string variables_named(const std::vector<std::string>& names) {
  if (names.empty()) return "t, u and v";
  std::string listed;
  for (std::size_t i = 0; i < names.size(); ++i)
    listed += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return "t, u, v and the internal variable" + std::string(names.size() > 1 ? "s " : " ") + listed;
}

std::size_t expression_parses() {
  return parses.load();
}

}  // namespace impact
