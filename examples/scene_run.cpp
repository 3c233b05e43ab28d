// A scene run as `impact run` runs it: the README's quick-start ball (docs/library.md shows this
// program), dropped from 1 m under gravity onto a floor with COR 0.8, stepped by "direct" over 4 s
// with h = 1e-3, with the rows of the channels u, v, N, E every 500 steps, its impacts, and its
// errors against the exact solution, through run_scene(), the function behind the command and the
// Python module.
#include <cstdio>
#include <impact/impact.hpp>

int main() {
  impact::Model model;
  model.f = -9.80665;
  model.cor = 0.8;
  impact::Scene scene =
      impact::make_scene(model, impact::State{1.0, 0.0}, 4.0, 1e-3, impact::DirectParams{});
  scene.output.channels = {impact::Channel::u, impact::Channel::v, impact::Channel::N,
                           impact::Channel::E};
  scene.output.every = 500;

  impact::RunOutputs outputs;
  outputs.rows = [&](const impact::OutputRow& row) {
    std::printf("t = %4.2f  u = %9.6f  v = %10.6f  N = %10.4f  E = %8.5f\n", scene.grid.t(row.l),
                row.state.u, row.state.v, row.contact_force, row.energy);
  };
  int impacts = 0;
  outputs.events = [&](const impact::Event& event) {
    if (event.kind == impact::EventKind::impact && ++impacts <= 3)
      std::printf("impact at t = %.17g, v from %g to %g\n", event.t, event.v_before, event.v_after);
  };
  outputs.against_exact = true;

  impact::AnyStepper stepper = impact::make_stepper(scene);
  const impact::RunReport report = impact::run_scene(scene, stepper, outputs);
  std::printf(
      "%lld steps, %lld in contact, %d impacts; against the exact solution: "
      "sup |u - u_exact| = %.3g m\n",
      static_cast<long long>(report.summary.steps),
      static_cast<long long>(report.summary.contact_steps), impacts, report.errors->sup_u);
  return 0;
}
