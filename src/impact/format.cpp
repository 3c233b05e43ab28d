#include "impact/format.hpp"

#include <charconv>

namespace impact {

char* format_double(char* buf, char* end, double x) {
  return std::to_chars(buf, end, x, std::chars_format::general, 17).ptr;
}

std::string round_trip(double x) {
  char buf[32];
  return std::string(buf, format_double(buf, buf + sizeof buf, x));
}

std::string shortest(double x) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

}  // namespace impact
