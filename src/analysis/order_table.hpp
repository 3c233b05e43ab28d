// The summary.toml form of a fitted order of convergence (fit.hpp), as the convergence and
// Lemma 4 experiments write it.
#pragma once

#include <toml++/toml.h>

#include "analysis/fit.hpp"

namespace impact {

// {order, h_min, h_max, points, max_log_deviation}
toml::table order_fit_table(const OrderFit& fit);

}  // namespace impact
