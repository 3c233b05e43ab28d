// Numbers in the Markdown tables people read (results/*/table.md, orders.md): 3 significant
// digits. Data files and summaries use round_trip (impact/output/csv.hpp), which reads back
// exactly.
#pragma once

#include <string>

namespace impact {

std::string short_number(double x);

}  // namespace impact
