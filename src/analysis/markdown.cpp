#include "analysis/markdown.hpp"

#include <cstdio>

namespace impact {

std::string short_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

}  // namespace impact
