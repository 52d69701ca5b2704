#pragma once
/// \file
/// The options every dynamic driver reads with the same words: the time step --h, the end time
/// --t-end, the spectral radius --rho-inf, the iteration matrix (--strategy) and the Newton test
/// (--tolerance, or 003's three tests), read from a study::CommandLine into the
/// solvers::DynamicOptions the integrator takes, over the driver's own defaults:
///
///     study::CommandLine cli(argc, argv, "my_study: what it computes");
///     const study::Integration run =
///         study::integrator_options(cli, {.time_step = 1e-3, .constraint_tolerance = 1e-12}, {.end_time = 2.0});
///     if (!cli.finish()) return 0;
///     solvers::GeneralizedAlpha integrator(model, std::move(joints), run.dynamics);

#include <spar/solvers/generalized_alpha.hpp>
#include <spar/study/command_line.hpp>
#include <spar/study/run_limits.hpp>

#include <string>

namespace spar::study {

/// Which Newton tolerances integrator_options reads.
enum class NewtonOptions {
  none,       ///< none: the driver's tolerances as given
  tolerance,  ///< --tolerance (the squared increment ‖[Δq, h²βΔλ]‖²), its default the driver's
  test_003,   ///< newton_test_options: --tolerance, --constraint-tolerance, --residual-tolerance
              ///< at 003's test (1e-6, 1e-10 m), the residual's default the driver's residual_tolerance
};

/// What integrator_options reads beside --h and --rho-inf, and the driver's words and defaults
/// that are not solvers::DynamicOptions fields.
struct IntegratorDefaults {
  std::string time_step_help = "time step [s]";
  double end_time = 1.0;  ///< --t-end's default [s]
  std::string end_time_help = "end time [s]";
  /// The option naming the iteration matrix (update | frozen | modified): "--strategy", another
  /// name (ancf_double_pendulum: "--iteration-matrix"), or "" for none (the driver's as given).
  std::string iteration_matrix_option = "--strategy";
  NewtonOptions newton = NewtonOptions::none;
};

/// A dynamic run's integrator options and its span, as the command line gave them.
struct Integration {
  solvers::DynamicOptions dynamics;  ///< the driver's with the options read
  double end_time = 0.0;             ///< --t-end [s]
  std::string strategy;              ///< the iteration matrix's name: update | frozen | modified
};

/// Reads --h (> 0), --t-end (> 0), --rho-inf (in [0, 1]), the iteration-matrix option and the
/// Newton options `defaults` names, in that order, over `dynamics`: its time_step, spectral_radius,
/// iteration_matrix and tolerances are the options' defaults, its other fields pass through as
/// given. A span the run cannot take (time_steps: a step longer than the span, or more than
/// max_time_steps steps) is refused here, as soon as --h and --t-end are read.
Integration integrator_options(CommandLine& cli, const solvers::DynamicOptions& dynamics,
                               const IntegratorDefaults& defaults = {});

}  // namespace spar::study
