// What the command costs beside what it runs (registered by performance.cpp's main), and the
// ratios `make performance` reports against their targets:
//   sweep_kernel/<method>/<isa>          particle-steps per second of the ensemble alone on a
//                                        sweep's points: figure4/cor075 dropped from u0 = 1..10 m
//                                        (960 points), h = 1e-4, T = 100 s (1e6 steps, so that
//                                        the process's start, about 30 ms, stays near 5%)
//   cli_sweep/<method>/<threads>         `impact sweep` of the same points as a user runs it (a
//                                        process, CSV of the summaries); CPU time of the child (of
//                                        every thread) per particle-step
//   cli_sweep_final/<method>/<threads>   the same with `--summary u_T,v_T,E_T`: the final state
//                                        alone, without the per-step summary
// The ratios (ratio_table): `impact run` over simulate() per phase (performance_phases.hpp;
// target 1.3), `impact sweep` over the ensemble kernel of the widest instruction set (target
// 1.2, the CPU time of one thread and of two), direct with a harmonic force over a constant one
// (stepper/direct/figure3_no_cor{_harmonic,}, target 1.5).
#pragma once

#include <benchmark/benchmark.h>

#include <functional>
#include <string>

namespace impact {

void register_sweep_benchmarks(void (*add_statistics)(benchmark::internal::Benchmark*, bool),
                               const std::string& cli, const std::string& out_dir);

// The markdown table of the ratios; best(name) gives a benchmark's best ns per step (per
// particle-step for cli_sweep) or particle-steps per second (sweep_kernel), NaN when it did not
// run.
std::string ratio_table(const std::function<double(const std::string&)>& best);

}  // namespace impact
