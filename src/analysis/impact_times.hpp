// Where an exact solution is not smooth: its impact times and the start of its rest. The sup
// distance of two exact solutions is attained at such a time or an end point (path_distance.hpp),
// and the quadratures of the weak formulation (weak_solution.hpp) split their integrals there.
#pragma once

#include <vector>

#include "impact/references/exact.hpp"

namespace impact {

// The impact times in (0, T] and the time the particle comes to rest, if it does: where u has kinks
// and the cumulative impulse jumps. Before a Zeno accumulation the impact times crowd together;
// one closer than 1e-9 max(1, T) to the previous kept time is dropped (its jump, at most
// (1 + e) e^k V1, falls below the quadrature tolerance long before the spacing does, and GSL
// cannot subdivide intervals a few ulp wide). At most the first 400 impacts.
std::vector<double> impact_times(const ExactSolution& x, double T);

}  // namespace impact
