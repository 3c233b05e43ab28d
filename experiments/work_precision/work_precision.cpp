// exp_work_precision RESULTS_DIR: the work-precision study (src/analysis/work_precision_study.hpp),
// with Siconos's Moreau-Jean as a peer of moreau_jean when CMake found Siconos.
#include <cstdio>

#include "analysis/work_precision_study.hpp"
#ifdef IMPACT_HAVE_SICONOS
#include "siconos_ball.hpp"
#endif

namespace {

#ifdef IMPACT_HAVE_SICONOS
using namespace impact;

WorkPrecisionPoint siconos_point(const Scene& scene, const std::optional<TimingRule>& rule) {
  return measure_point(
      [&] { return SiconosBall(scene.model, scene.initial, scene.grid.h, scene.grid.steps); },
      scene.model, scene.initial, scene.grid, rule);
}

// Siconos costs about a microsecond per step: its sweep stops at h = 1e-4 to keep `make all`
// short.
toml::table run_with_siconos(const ExperimentContext& context) {
  WorkPrecisionOptions options;
  options.peer = PeerSolver{"siconos", "moreau_jean", 1e-4, &siconos_point};
  return run_work_precision(context, options);
}

const Experiment kExperiment{kWorkPrecisionExperiment.name, kWorkPrecisionExperiment.description,
                             &run_with_siconos};
#else
const impact::Experiment& kExperiment = impact::kWorkPrecisionExperiment;
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
