// study::integrator_options (<spar/study/integrator_options.hpp>): the shared options of a dynamic
// driver land in the solvers::DynamicOptions fields they name, over the driver's defaults, the
// fields it does not read pass through, and only the options the defaults name are accepted.
#include <spar/study/integrator_options.hpp>

#include <spar/error.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace spar;
using Catch::Contains;

namespace {

/// Reads the integrator options of `args` (without the program name) over `dynamics` and
/// `defaults` and finishes the command line.
study::Integration read(std::vector<std::string> args, const solvers::DynamicOptions& dynamics,
                        const study::IntegratorDefaults& defaults) {
  std::vector<char*> argv{const_cast<char*>("example")};
  for (auto& arg : args) argv.push_back(arg.data());
  study::CommandLine cli(static_cast<int>(argv.size()), argv.data(), "example");
  study::Integration run = study::integrator_options(cli, dynamics, defaults);
  const bool finished = cli.finish();  // throws for the options it refuses
  REQUIRE(finished);
  return run;
}

/// sliding_beam's integrator and defaults.
solvers::DynamicOptions sliding_beam() {
  return {.time_step = 1e-3, .tolerance = 1e-12, .constraint_tolerance = 1e-10, .residual_tolerance = 1e-8};
}
const study::IntegratorDefaults sliding_beam_defaults{.end_time = 3.0, .newton = study::NewtonOptions::tolerance};

}  // namespace

TEST_CASE("integrator_options: the defaults when nothing is given, the other fields passed through", "[study]") {
  const study::Integration run = read({}, sliding_beam(), sliding_beam_defaults);
  CHECK(run.dynamics.time_step == 1e-3);
  CHECK(run.end_time == 3.0);
  CHECK(run.dynamics.spectral_radius == 0.9);  // DynamicOptions' own default
  CHECK(run.dynamics.iteration_matrix == solvers::IterationMatrix::update);
  CHECK(run.strategy == "update");
  CHECK(run.dynamics.tolerance == 1e-12);
  CHECK(run.dynamics.constraint_tolerance == 1e-10);
  CHECK(run.dynamics.residual_tolerance == 1e-8);
}

TEST_CASE("integrator_options: each option in its field", "[study]") {
  const study::Integration run =
      read({"--h", "2e-4", "--t-end", "0.5", "--rho-inf", "0.6", "--strategy", "modified", "--tolerance", "1e-14"},
           sliding_beam(), sliding_beam_defaults);
  CHECK(run.dynamics.time_step == 2e-4);
  CHECK(run.end_time == 0.5);
  CHECK(run.dynamics.spectral_radius == 0.6);
  CHECK(run.dynamics.iteration_matrix == solvers::IterationMatrix::modified);
  CHECK(run.strategy == "modified");
  CHECK(run.dynamics.tolerance == 1e-14);
  CHECK(run.dynamics.constraint_tolerance == 1e-10);

  // Another name for the iteration matrix, its default from the defaults.
  const solvers::DynamicOptions modified{.iteration_matrix = solvers::IterationMatrix::modified};
  const study::IntegratorDefaults renamed{.iteration_matrix_option = "--iteration-matrix"};
  CHECK(read({}, modified, renamed).strategy == "modified");
  CHECK(read({"--iteration-matrix", "frozen"}, modified, renamed).dynamics.iteration_matrix ==
        solvers::IterationMatrix::frozen);
}

TEST_CASE("integrator_options: 003's Newton test, the residual's default the driver's", "[study]") {
  const solvers::DynamicOptions untested{.residual_tolerance = INFINITY};
  const study::IntegratorDefaults truss{.end_time = 30.0, .newton = study::NewtonOptions::test_003};
  const study::Integration run = read({}, untested, truss);
  CHECK(run.dynamics.tolerance == 1e-6);
  CHECK(run.dynamics.constraint_tolerance == 1e-10);
  CHECK(std::isinf(run.dynamics.residual_tolerance));
  const study::Integration given = read({"--constraint-tolerance", "1e-12", "--residual-tolerance", "1e-5"}, untested, truss);
  CHECK(given.dynamics.constraint_tolerance == 1e-12);
  CHECK(given.dynamics.residual_tolerance == 1e-5);
}

TEST_CASE("integrator_options: options the driver does not offer and values out of range are refused", "[study]") {
  const study::IntegratorDefaults plain{.iteration_matrix_option = ""};  // no --strategy, no --tolerance
  CHECK_THROWS_WITH(read({"--strategy", "frozen"}, {}, plain), Contains("unknown option --strategy"));
  CHECK_THROWS_WITH(read({"--tolerance", "1e-9"}, {}, plain), Contains("unknown option --tolerance"));
  CHECK(read({}, {}, plain).dynamics.tolerance == solvers::DynamicOptions{}.tolerance);
  CHECK_THROWS_WITH(read({"--rho-inf", "1.5"}, sliding_beam(), sliding_beam_defaults), Contains("--rho-inf"));
  CHECK_THROWS_WITH(read({"--h", "0"}, sliding_beam(), sliding_beam_defaults), Contains("--h"));
  CHECK_THROWS_WITH(read({"--strategy", "newton"}, sliding_beam(), sliding_beam_defaults), Contains("--strategy"));
}

TEST_CASE("integrator_options: a span of no steps is refused as soon as --h and --t-end are read", "[study]") {
  CHECK_THROWS_WITH(read({"--h", "1e-2", "--t-end", "1e-3"}, sliding_beam(), sliding_beam_defaults),
                    Contains("no step would be taken"));
  CHECK_THROWS_WITH(read({"--h", "1e-9", "--t-end", "100"}, sliding_beam(), sliding_beam_defaults),
                    Contains("steps"));
}
