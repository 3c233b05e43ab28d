// Figure 2 (Section 5.1): the spline approximation S_eps of the displacement around an impact at
// t* = 5 with eps = 1e-3 (the caption's values), from the paper's formulas and, independently, from
// GSL's natural cubic spline through the same data (spline_contact.hpp).
#pragma once

#include <toml++/toml.h>

#include "analysis/experiment.hpp"

namespace impact::figure2 {

// Returns {figure2 = {...}}: the continuity jumps of the printed and the corrected S_2 at the knots
// and the GSL-vs-formula differences (the keys of experiments/figure2/reference.toml). Writes
//   pieces.csv      t, piece (3, 1, 2, 4), u = S, v = S', N = S'' from the (corrected) formulas,
//                   and the same from the 3-knot and the 5-knot GSL natural splines;
//   s2_printed.csv  t, u, v, N of S_2 as printed, on [t*, t* + eps].
toml::table run_figure2(const ExperimentContext& context);

extern const Experiment kFigure2Experiment;

}  // namespace impact::figure2
