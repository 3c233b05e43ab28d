// The cost of a step in each phase of a motion (registered by performance.cpp's main), for
// direct, moreau_jean and fb_newton, each phase one run of 1e8 steps (fb_newton 1e7):
//   phase/<method>/<phase>   ns per step through simulate() (as `impact run` calls it), output off
//   bare/direct/<phase>      ns per step of the scheme (5-1) alone: direct_step on one particle in
//   a
//                            plain loop, without the stepper, the run loop or its checks
//   cli/<method>/<phase>     ns per step of `impact run` on the same run (a process, a scene
//                            file, CSV decimated to 1e4 rows; CPU time of the child)
// The phases, from the paper's scenes:
//   free_flight   figure3/no_cor over 10 s (f = 0: one impact, then free flight)
//   bouncing      figure4/cor075 over its first 6 s (impacts, before the rest at ~7.0 s)
//   chatter       figure4/no_cor for 10 s from the method's state at t = 10 s (direct and
//                 fb_newton: their period-2 chatter on the floor; moreau_jean without COR
//                 bounces elastically)
//   rest          figure4/cor075 for 10 s from the method's state at t = 10 s (at rest)
// The later phases start from the state after the last contact step the method took before
// t = 10 s: the step's free flight starts there (direct.hpp), so the run goes on bit for bit as
// the scene's own run would have (moreau_jean: see phase_scene).
#pragma once

#include <benchmark/benchmark.h>

#include <functional>
#include <string>

namespace impact {

// add_statistics: the repetitions and statistics every benchmark of exp_performance uses; run_cli
// runs `impact` with these arguments and returns the child's CPU seconds; `out_dir` takes the CSV.
void register_phase_benchmarks(void (*add_statistics)(benchmark::internal::Benchmark*, bool),
                               const std::string& cli, const std::string& out_dir);

// For plot.gp: per method and phase, the best ns per step of the bare loop (direct), simulate()
// and `impact run`, and the targets: 1.5 x simulate()'s free-flight cost, and for `impact run`
// 1.5 x the bare loop; `best` gives a benchmark's best ns per step (NaN when it did not run).
std::string phase_plot_data(const std::function<double(const std::string&)>& best);

// The processor this runs on, as /proc/cpuinfo names it ("Intel(R) Xeon(R) Processor, family 6
// model 167"), for the tables and the figure.
std::string processor_name();

}  // namespace impact
