// The processor a number was measured on, as the package names it beside every timing: the CPU's
// model name, its family and model (an Intel and an AMD part differ there), and the widest vector
// code it runs (what the ensemble picks).
#pragma once

#include <string>

namespace impact {

struct Processor {
  std::string name;           // /proc/cpuinfo's "model name", e.g. "Intel(R) Xeon(R) Processor"
  std::string vendor;         // "GenuineIntel", "AuthenticAMD", ...
  int family = 0, model = 0;  // cpuid's (display) family and model
  std::string vector_code;    // "avx512f", "avx2" or "baseline"
  int cores = 0;              // logical processors this process may run on
  // "Intel(R) Xeon(R) Processor (GenuineIntel family 6 model 167, avx512f, 2 cores)".
  std::string describe() const;
};

// This machine's (Linux: /proc/cpuinfo; elsewhere what the compiler's cpuid builtins give).
Processor this_processor();

}  // namespace impact
