#include "impact/ensemble/processor.hpp"

#include <fstream>
#include <string>
#include <thread>

#include "impact/ensemble/ensemble.hpp"

namespace impact {
namespace {

// The value of "key : value" on a line of /proc/cpuinfo, if the line has that key.
bool field(const std::string& line, const std::string& key, std::string& value) {
  if (line.compare(0, key.size(), key) != 0) return false;
  const std::size_t colon = line.find(':', key.size());
  if (colon == std::string::npos || line.find_first_not_of(" \t", key.size()) != colon)
    return false;
  const std::size_t start = line.find_first_not_of(' ', colon + 1);
  value = start == std::string::npos ? "" : line.substr(start);
  return true;
}

}  // namespace

std::string Processor::describe() const {
  return (name.empty() ? std::string("unknown processor") : name) + " (" +
         (vendor.empty() ? "" : vendor + " ") + "family " + std::to_string(family) + " model " +
         std::to_string(model) + ", " + vector_code + ", " + std::to_string(cores) + " cores)";
}

Processor this_processor() {
  Processor p;
  std::ifstream info("/proc/cpuinfo");
  std::string line, value;
  while (std::getline(info, line) && line != "") {  // the first processor's block
    if (field(line, "model name", value))
      p.name = value;
    else if (field(line, "vendor_id", value))
      p.vendor = value;
    else if (field(line, "cpu family", value))
      p.family = std::stoi(value);
    else if (field(line, "model", value))
      p.model = std::stoi(value);
  }
  p.vector_code = std::string(Ensemble::supported_instruction_sets().front());
  p.cores = static_cast<int>(std::thread::hardware_concurrency());
  return p;
}

}  // namespace impact
