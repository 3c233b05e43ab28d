// exp_work_precision RESULTS_DIR: the work-precision study
// (src/analysis/work_precision/work_precision_study.hpp), with Siconos's Moreau-Jean (a peer of
// moreau_jean) and its event-driven LSODAR when CMake found Siconos.
#include <cstdio>

#include "analysis/work_precision/work_precision_study.hpp"
#ifdef IMPACT_HAVE_SICONOS
#include "siconos_ball.hpp"
#endif

namespace {

#ifdef IMPACT_HAVE_SICONOS
using namespace impact;

template <SiconosIntegrator kIntegrator>
WorkPrecisionPoint siconos_point(const Scene& scene, double tolerance,
                                 const std::optional<TimingRule>& rule) {
  WorkPrecisionPoint p = measure_point(
      [&] {
        return SiconosBall(scene.model, scene.initial, scene.grid.h, scene.grid.steps, kIntegrator,
                           tolerance);
      },
      scene.model, scene.initial, scene.grid, rule);
  p.tolerance = tolerance;
  return p;
}

// Siconos's Moreau-Jean costs a few microseconds per step: its sweep stops at h = 1e-4 to keep
// `make all` short. LSODAR, the event-driven peer of the scenes with f(t), sweeps its tolerance on
// the grid h = 1e-3, as penalty does, on those scenes only: on Figure 4 with COR 0.75 its event
// loop stops at the Zeno accumulation (Siconos prints its whole model and throws
// "y < -_TOL_ED").
toml::table run_with_siconos(const ExperimentContext& context) {
  WorkPrecisionOptions options;
  options.peers = {
      PeerSolver{"siconos", "moreau_jean", 1e-4, false,
                 &siconos_point<SiconosIntegrator::moreau_jean>},
      PeerSolver{"siconos_lsodar", "", 0.0, true, &siconos_point<SiconosIntegrator::lsodar>}};
  return run_work_precision(context, options);
}

const Experiment kExperiment{kWorkPrecisionExperiment.name, kWorkPrecisionExperiment.description,
                             &run_with_siconos};
#else
const impact::Experiment& kExperiment = impact::work_precision::kWorkPrecisionExperiment;
#endif

}  // namespace

int main(int argc, char** argv) {
  const int status = impact::experiment_main(argc, argv, kExperiment, IMPACT_SOURCE_DIR);
#ifndef IMPACT_HAVE_SICONOS
  if (status == 0)
    std::fprintf(stderr,
                 "work_precision: Siconos was not found when the project was configured, so its "
                 "curves are left out.\n  To include them: apt-get install libsiconos-kernel-dev, "
                 "then rerun make work_precision.\n");
#endif
  return status;
}
