// What the regression tests share: the committed reference.toml of an experiment, typed reads of
// its numbers, and a CHECK with an absolute tolerance that prints both sides in full precision.
#pragma once

#include <toml++/toml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <iomanip>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "check_near.hpp"
#include "impact/model/model.hpp"

namespace impact::testing {

// experiments/<experiment>/reference.toml, parsed once.
inline const toml::table& reference_file(const std::string& experiment) {
  static std::map<std::string, toml::table> cache;
  auto it = cache.find(experiment);
  if (it == cache.end())
    it =
        cache
            .emplace(experiment, toml::parse_file(std::string(IMPACT_SOURCE_DIR) + "/experiments/" +
                                                  experiment + "/reference.toml"))
            .first;
  return it->second;
}

inline std::vector<double> numbers(const toml::node_view<const toml::node>& node) {
  std::vector<double> out;
  if (const toml::array* a = node.as_array())
    for (const toml::node& x : *a) out.push_back(x.value<double>().value());
  return out;
}

inline double number(const toml::node_view<const toml::node>& node) {
  return node.value<double>().value();
}

inline Model model_of(double f, std::optional<double> cor) {
  Model m;
  m.f = f;
  m.cor = cor;
  return m;
}

}  // namespace impact::testing
