// How the package writes a number, and reads its clock: one definition of each.
#pragma once

#include <chrono>
#include <string>

namespace impact {

// Appends x in round-trip precision (17 significant digits: the CSV columns) to buf; returns the
// new end.
char* format_double(char* buf, char* end, double x);
// x in round-trip precision, as a string (scenes, summaries and messages written as text).
std::string round_trip(double x);
// The shortest decimal that reads back as x (1e-15, not 1.0000000000000001e-15): for messages.
std::string shortest(double x);

// The wall time since `start`, in seconds.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace impact
