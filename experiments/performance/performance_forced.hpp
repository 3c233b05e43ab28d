// The benchmarks of the time-dependent body force f(t) (registered by performance.cpp's main):
//   impacts/exact/<scene>                  ns per impact of `exact` with a harmonic force: one
//                                          solve over a long horizon in a single grid step, so
//                                          that only its event tracking is timed
//   stepper/exact/table_period1            ns per sample of an event-driven solution sampled
//                                          sequentially on a grid, harmonic f (constant f with
//                                          COR: performance.cpp's stepper/exact/figure4_cor075)
//   stepper/event_driven/expression        the same for an expression force
//   stepper/direct/table_period1, .../table_period1_constant_f, .../figure3_no_cor_harmonic,
//   .../figure4_cor075_harmonic            ns per step of `direct` with a harmonic force, to set
//                                          beside the same scene with a constant force
#pragma once

#include <benchmark/benchmark.h>

namespace impact {

// add_statistics: the repetitions and statistics every benchmark of exp_performance uses.
void register_forced_benchmarks(void (*add_statistics)(benchmark::internal::Benchmark*, bool));

}  // namespace impact
