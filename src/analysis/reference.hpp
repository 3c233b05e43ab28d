// An experiment's key numbers against its committed experiments/<name>/reference.toml: one
// comparison for every regression test (and for anyone checking a run by hand).
#pragma once

#include <toml++/toml.h>

#include <string>
#include <string_view>
#include <vector>

namespace impact {

struct ReferenceRule {
  // A number matches when |measured - reference| <= relative * max(1, |reference|): the key
  // numbers are closed forms or converged solves, reproducible to rounding, and 1e-9 leaves room
  // for another compiler's rounding while any change of a scheme moves them by far more.
  double relative = 1e-9;
  // Keys (dotted paths, a prefix ending in '.' for a whole table) not compared: what depends on
  // this machine's timing, or what a test computes on a cheaper grid than the driver.
  std::vector<std::string> skip;
  // Compare only the keys the measured table has (a test that runs part of an experiment).
  bool measured_keys_only = false;
  // An array measured shorter than the reference is compared with the reference's first elements
  // (a test's cheap run over the first of the experiment's step sizes).
  bool measured_prefix = false;
};

// Every difference, one line each ("figure3.no_cor.max_diff_u: measured 1e-08, reference
// 2e-08"), or none. Integers, booleans and strings must be equal; arrays element by element; a
// key in one table and not the other is a difference.
std::vector<std::string> compare_with_reference(const toml::table& measured,
                                                const toml::table& reference,
                                                const ReferenceRule& rule = {});

// experiments/<name>/reference.toml under source_dir.
toml::table read_reference(const std::string& source_dir, std::string_view experiment);

}  // namespace impact
