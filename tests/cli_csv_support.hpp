// The helpers of the CLI tests, test_cli.cpp and test_cli_run.cpp: reading back the CSV that
// `impact` writes, and a short scene.
#pragma once

#include <stdlib.h>
#include <sys/wait.h>

#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/model/model.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/error_norms.hpp"
#include "scene/read_scene.hpp"

using Catch::Contains;

using namespace impact::testing;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;

struct Csv {
  std::string header;
  std::vector<std::vector<double>> rows;
};

// Reads a CSV written by `impact`; every field must be a whole number as strtod reads it.
inline Csv read_csv(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in);
  Csv csv;
  REQUIRE(std::getline(in, csv.header));
  const auto columns =
      static_cast<std::size_t>(std::count(csv.header.begin(), csv.header.end(), ',') + 1);
  std::string line, bad;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) {
      char* end = nullptr;
      row.push_back(std::strtod(field.c_str(), &end));
      if (bad.empty() && (field.empty() || *end != '\0')) bad = line;
    }
    if (bad.empty() && row.size() != columns) bad = line;
    csv.rows.push_back(std::move(row));
  }
  INFO(path << ": first malformed line: '" << bad << "'");
  REQUIRE(bad.empty());
  return csv;
}

inline std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

const std::string kShortScene =
    "[initial]\nu0 = 0.05\nv0 = -1.0\n"
    "[floor]\ncor = 0.75\n"
    "[force]\nf = -9.80665\n"
    "[time]\nT = 0.1\nh = 0.001\n"
    "[method]\nname = \"direct\"\n"
    "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\"]\n";

}  // namespace
