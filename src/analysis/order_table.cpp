#include "analysis/order_table.hpp"

#include <cstdint>

namespace impact {

toml::table order_fit_table(const OrderFit& fit) {
  return toml::table{{"order", fit.order},
                     {"h_min", fit.h_min},
                     {"h_max", fit.h_max},
                     {"points", static_cast<std::int64_t>(fit.points)},
                     {"max_log_deviation", fit.max_log_deviation}};
}

}  // namespace impact
