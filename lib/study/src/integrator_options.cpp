#include <spar/study/integrator_options.hpp>

namespace spar::study {

Integration integrator_options(CommandLine& cli, const solvers::DynamicOptions& dynamics,
                               const IntegratorDefaults& defaults) {
  Integration run{.dynamics = dynamics};
  solvers::DynamicOptions& o = run.dynamics;
  o.time_step = cli.number("--h", o.time_step, defaults.time_step_help, Range::positive());
  run.end_time = cli.number("--t-end", defaults.end_time, defaults.end_time_help, Range::positive());
  time_steps(o.time_step, run.end_time);  // a span of no steps or of too many is refused
  o.spectral_radius =
      cli.number("--rho-inf", o.spectral_radius, "spectral radius at infinity (1: no dissipation)", Range::between(0, 1));
  run.strategy = std::string(solvers::to_string(o.iteration_matrix));
  if (!defaults.iteration_matrix_option.empty()) {
    run.strategy = cli.text(defaults.iteration_matrix_option, run.strategy, "iteration matrix: update | frozen | modified",
                            {"update", "frozen", "modified"});
    o.iteration_matrix = solvers::iteration_matrix_from_string(run.strategy);
  }
  if (defaults.newton == NewtonOptions::tolerance)
    o.tolerance = cli.number("--tolerance", o.tolerance, "Newton: |[dq, h^2 beta dlambda]|^2 (squared, m and rad)",
                             newton_tolerances);
  if (defaults.newton == NewtonOptions::test_003) {
    const NewtonTest test = newton_test_options(cli, o.residual_tolerance);
    o.tolerance = test.tolerance;
    o.constraint_tolerance = test.constraint_tolerance;
    o.residual_tolerance = test.residual_tolerance;
  }
  return run;
}

}  // namespace spar::study
