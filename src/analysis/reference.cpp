#include "analysis/reference.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "impact/output/csv.hpp"

namespace impact {
namespace {

bool skipped(const std::string& key, const ReferenceRule& rule) {
  return std::any_of(rule.skip.begin(), rule.skip.end(), [&](const std::string& s) {
    return key == s || (!s.empty() && s.back() == '.' && key.rfind(s, 0) == 0);
  });
}

std::string shown(const toml::node& node) {
  if (const auto x = node.value<double>(); x && !node.is_string()) return round_trip(*x);
  std::ostringstream text;
  node.visit([&](auto&& v) { text << v; });
  return text.str();
}

void compare(const std::string& key, const toml::node& measured, const toml::node& reference,
             const ReferenceRule& rule, std::vector<std::string>& out);

void compare_tables(const std::string& prefix, const toml::table& measured,
                    const toml::table& reference, const ReferenceRule& rule,
                    std::vector<std::string>& out) {
  for (auto&& [k, node] : reference) {
    const std::string key = prefix + std::string(k.str());
    if (skipped(key, rule)) continue;
    if (const toml::node* m = measured.get(k.str()))
      compare(key, *m, node, rule, out);
    else if (!rule.measured_keys_only)
      out.push_back(key + ": in the reference, not measured");
  }
  for (auto&& [k, node] : measured) {
    const std::string key = prefix + std::string(k.str());
    if (!skipped(key, rule) && !reference.get(k.str()))
      out.push_back(key + ": measured " + shown(node) + ", not in the reference");
  }
}

void compare(const std::string& key, const toml::node& measured, const toml::node& reference,
             const ReferenceRule& rule, std::vector<std::string>& out) {
  const auto mismatch = [&] {
    out.push_back(key + ": measured " + shown(measured) + ", reference " + shown(reference));
  };
  if (reference.is_table()) {
    if (!measured.is_table()) return mismatch();
    return compare_tables(key + ".", *measured.as_table(), *reference.as_table(), rule, out);
  }
  if (reference.is_array()) {
    const toml::array* m = measured.as_array();
    const toml::array& r = *reference.as_array();
    const bool prefix = m && rule.measured_prefix && m->size() < r.size();
    if (!m || (m->size() != r.size() && !prefix)) {
      out.push_back(key + ": measured " + (m ? std::to_string(m->size()) : "no") +
                    " elements, reference " + std::to_string(r.size()));
      return;
    }
    for (std::size_t i = 0; i < m->size(); ++i)
      compare(key + "[" + std::to_string(i) + "]", *m->get(i), *r.get(i), rule, out);
    return;
  }
  if (reference.is_floating_point() || (reference.is_integer() && measured.is_floating_point())) {
    const auto m = measured.value<double>();
    const double r = *reference.value<double>();
    if (!m || measured.is_string()) return mismatch();
    const bool both_nan = std::isnan(*m) && std::isnan(r);
    if (!both_nan && !(std::fabs(*m - r) <= rule.relative * std::fmax(1.0, std::fabs(r))) &&
        *m != r)  // equal infinities
      mismatch();
    return;
  }
  if (measured.type() != reference.type() || shown(measured) != shown(reference)) mismatch();
}

}  // namespace

std::vector<std::string> compare_with_reference(const toml::table& measured,
                                                const toml::table& reference,
                                                const ReferenceRule& rule) {
  std::vector<std::string> out;
  compare_tables("", measured, reference, rule, out);
  return out;
}

toml::table read_reference(const std::string& source_dir, std::string_view experiment) {
  return toml::parse_file(source_dir + "/experiments/" + std::string(experiment) +
                          "/reference.toml");
}

}  // namespace impact
