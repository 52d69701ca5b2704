// Every spar::Error thrown by GeneralizedAlpha (solvers/src/generalized_alpha.cpp and the files
// of its jobs: integrator, newton_step, iteration_matrix_strategy, initial_assembly,
// structure_changes), by the assembly it builds (solvers/src/system_assembly.cpp) and by solve_static's options
// (solvers/src/static_solver.cpp), reached through the public API, with the words of its what,
// where and fix (issue 16; docs/errors.md, "Solvers"). The failures inside a step and their
// cut-backs are in newton_failures_test.cpp; elsewhere, with the same throw reached by another
// input: a beam without section inertia (tests/dynamics/dynamics_errors_test.cpp), NaN tolerances
// and velocities, a NaN load history and an overflowing gravity potential
// (tests/input/api_input_test.cpp), increment units of the wrong size and a dof count changed
// without remap (tests/model/structure_change_test.cpp, increment_units_test.cpp).
#include <spar/core/model.hpp>
#include <spar/error.hpp>
#include <spar/joints/revolute_joint.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/solvers/static_solver.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>

#include <catch2/catch.hpp>

#include <atomic>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "non_finite_iterate.hpp"

using namespace spar;

namespace {

/// A sound mass on a spring (non_finite_iterate.hpp with no failures) on block 0 of 1 coordinate.
struct Spring {
  core::Model model;
  explicit Spring(const test::NonFiniteIterateParameters& p = {}) {
    model.add_vector(Eigen::VectorXd::Zero(1));
    model.add_element(std::make_unique<test::NonFiniteIterate>(p, std::make_shared<std::atomic<int>>(0)));
  }
};

void construct(const solvers::DynamicOptions& options) {
  Spring s;
  solvers::GeneralizedAlpha integrator(s.model, {}, options);
}

/// A rigid body of 2 kg, J = diag(0.04, 0.03, 0.05) kg m² about its centre C = (0.5, 0, 0) m,
/// hinged about Z at the origin (`hinges` times: more than once is redundant), its centre moved by
/// `offset` from there.
struct Pendulum {
  core::Model model;
  solvers::ConstraintList joints;
  Pendulum(const Eigen::Vector3d& offset, int hinges = 1) {
    const int body = core::rigid_body(model, core::add_rigid_body(model,
        {.center_of_mass = Eigen::Vector3d(0.5, 0, 0), .mass = 2.0,
         .inertia = Eigen::Vector3d(0.04, 0.03, 0.05).asDiagonal()})).node;
    for (int i = 0; i < hinges; ++i)
      joints.push_back(std::make_unique<joints::RevoluteJoint>(
          joints::attach_at(body, Eigen::Vector3d::Zero(), model.state()), joints::Attachment{-1},
          Eigen::Vector3d::UnitZ(), model.state()));
    model.state().position[body] += offset;
  }
};

void initialize(Pendulum&& p, const solvers::DynamicOptions& options = {}) {
  solvers::GeneralizedAlpha integrator(p.model, std::move(p.joints), options);
  integrator.initialize();
}

struct Case {
  std::string name;
  std::function<void()> call;
  std::string what, where, fix;  // words each part of the message must hold
};

}  // namespace

TEST_CASE("every error of the integrator and of the static solver's options names what, where and the fix",
          "[model][errors]") {
  constexpr double infinite = std::numeric_limits<double>::infinity();
  const std::string ga = "solvers::GeneralizedAlpha";
  const std::vector<Case> cases = {
      // Options (generalized_alpha.cpp and integrator.cpp, iteration_matrix_from_string, from_spectral_radius,
      // validated_parameters, check_units).
      {"an unknown strategy", [] { solvers::iteration_matrix_from_string("newton"); },
       "unknown iteration-matrix strategy 'newton'", "solvers::iteration_matrix_from_string",
       "use update, frozen or modified"},
      {"rho_infinity = -0.1", [] { solvers::GeneralizedAlphaParameters::from_spectral_radius(-0.1); },
       "spectral radius rho_infinity = -0.1 is outside [0, 1]", "solvers::GeneralizedAlphaParameters",
       "give 0 <= rho_infinity <= 1"},
      {"a negative initial_assembly_tolerance", [] { construct({.initial_assembly_tolerance = -1.0}); },
       "initial_assembly_tolerance and initial_velocity_stiffness_time must be >= 0 and finite", ga,
       "fix the DynamicOptions"},
      {"an infinite initial_velocity_stiffness_time", [=] { construct({.initial_velocity_stiffness_time = infinite}); },
       "initial_assembly_tolerance and initial_velocity_stiffness_time must be >= 0 and finite", ga,
       "fix the DynamicOptions"},
      {"time_step = 0", [] { construct({.time_step = 0.0}); }, "time step must be positive and finite", ga,
       "give DynamicOptions::time_step > 0"},
      {"max_iterations = 0", [] { construct({.max_iterations = 0}); },
       "tolerance must be positive and finite, max_iterations >= 1, max_cutbacks >= 0", ga, "fix the DynamicOptions"},
      {"max_cutbacks = -1", [] { construct({.max_cutbacks = -1}); },
       "tolerance must be positive and finite, max_iterations >= 1, max_cutbacks >= 0", ga, "fix the DynamicOptions"},
      {"constraint_tolerance = 0", [] { construct({.constraint_tolerance = 0.0}); },
       "constraint_tolerance = 0 and residual_tolerance = 1e-06 must be positive (+inf: the test is off)", ga,
       "fix the DynamicOptions' tolerances (NaN and values <= 0 are refused)"},
      {"modified_newton_contraction = 1.5", [] { construct({.modified_newton_contraction = 1.5}); },
       "modified_newton_contraction = 1.5 is outside (0, 1]", ga, "e.g. 0.5"},
      {"a negative increment unit", [] { construct({.increment_units = Eigen::VectorXd::Constant(1, -1.0)}); },
       "increment_units has 1 entries for 1 dofs, or a non-positive entry", ga,
       "give one positive unit per dof, or none"},
      // The assembly (system_assembly.cpp).
      {"a null constraint",
       [] {
         Spring s;
         solvers::ConstraintList constraints;
         constraints.push_back(nullptr);
         solvers::GeneralizedAlpha integrator(s.model, std::move(constraints), {});
       },
       "null constraint", "solvers::SystemAssembly", "pass joint objects"},
      {"a joint built on another model",
       [] {
         Pendulum p(Eigen::Vector3d::Zero());
         core::Model other;
         solvers::GeneralizedAlpha integrator(other, std::move(p.joints), {});
       },
       "constraint 0 refers to block 0, which the model does not have", "solvers::SystemAssembly",
       "build joints on the model they constrain"},
      // Initialization (initialize, consistent_accelerations, project_positions,
      // assemble_initial_state, factorize).
      {"the same hinge twice", [] { initialize(Pendulum(Eigen::Vector3d::Zero(), 2)); },
       "the iteration matrix is singular at t = 0 (step 1)", ga, "check for a redundant constraint"},
      {"an acceleration that overflows (1e302 N on 1e-300 kg)",
       [] {
         Spring s({.mass = 1e-300, .anchor = 1e300});
         solvers::GeneralizedAlpha(s.model, {}, {}).initialize();
       },
       "the consistent accelerations are not finite at t = 0", ga,
       "check the model's masses, loads and velocities for NaN or infinite values"},
      {"a kinetic energy that overflows (1 kg at 1e160 m/s)",
       [] {
         Spring s;
         solvers::GeneralizedAlpha integrator(s.model, {}, {});
         integrator.set_velocity(0, Eigen::VectorXd::Constant(1, 1e160));
         integrator.initialize();
       },
       "the mechanical energy at t = 0 is not finite", "solvers::GeneralizedAlpha::initialize",
       "check the model's masses, positions, velocities and gravity for absurd magnitudes"},
      {"a hinge 0.5 mm off that one Gauss-Newton iteration cannot close",
       [] { initialize(Pendulum(Eigen::Vector3d(0, 5e-4, 0)), {.constraint_tolerance = 1e-12, .max_iterations = 1}); },
       "the configuration could not be projected onto the constraints by the initial assembly at t = 0", ga,
       "check that the constraints can hold together at this state"},
      {"a hinge 2 mm off, beyond the 1 mm tolerance", [] { initialize(Pendulum(Eigen::Vector3d(0, 0, 2e-3))); },
       "the initial assembly would move block 0 by 0.002 (|Phi| = 0.002 as given), more than "
       "initial_assembly_tolerance = 0.001",
       "solvers::GeneralizedAlpha::initialize", "or raise DynamicOptions::initial_assembly_tolerance"},
      // Between steps and the accessors.
      {"a block added without remap",
       [] {
         Spring s;
         solvers::GeneralizedAlpha integrator(s.model, {}, {});
         integrator.step();
         s.model.add_vector(Eigen::VectorXd::Zero(2));
         integrator.step();
       },
       "the model now has 3 dofs, the integrator's state 1", "solvers::GeneralizedAlpha::step",
       "call remap(P) with P of (new dofs) x (old dofs)"},
      {"set_velocity of block 5",
       [] {
         Spring s;
         solvers::GeneralizedAlpha(s.model, {}, {}).set_velocity(5, Eigen::VectorXd::Zero(1));
       },
       "block 5 does not exist", "solvers::GeneralizedAlpha::set_velocity", "give a block of the model"},
      {"set_velocity after the first step",
       [] {
         Spring s;
         solvers::GeneralizedAlpha integrator(s.model, {}, {});
         integrator.step();
         integrator.set_velocity(0, Eigen::VectorXd::Zero(1));
       },
       "initial velocities must be set before the first step", "solvers::GeneralizedAlpha::set_velocity",
       "call set_velocity before initialize() and step()"},
      {"a frame's velocity for a vector block",
       [] {
         Spring s;
         solvers::GeneralizedAlpha(s.model, {}, {}).set_velocity(0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
       },
       "block 0 is a vector block", "solvers::GeneralizedAlpha::set_velocity",
       "give a vector block's velocity as one Eigen::VectorXd"},
      {"an infinite angular velocity",
       [=] {
         Pendulum p(Eigen::Vector3d::Zero());
         solvers::GeneralizedAlpha(p.model, {}, {}).set_velocity(0, Eigen::Vector3d::Zero(),
                                                                 Eigen::Vector3d(0, 0, infinite));
       },
       "the velocity has a NaN or infinite entry", "solvers::GeneralizedAlpha::set_velocity", "give finite velocities"},
      {"three velocities for a block of one",
       [] {
         Spring s;
         solvers::GeneralizedAlpha(s.model, {}, {}).set_velocity(0, Eigen::VectorXd::Zero(3));
       },
       "block 0 takes 1 finite velocity entries, got 3", "solvers::GeneralizedAlpha::set_velocity",
       "give one finite entry per increment of the block"},
      {"a 2 x 2 map for 1 dof",
       [] {
         Spring s;
         solvers::GeneralizedAlpha(s.model, {}, {}).remap(Eigen::MatrixXd::Identity(2, 2));
       },
       "the map is 2x2, expected 1x1 with finite entries", "solvers::GeneralizedAlpha::remap",
       "give P as (new dofs) x (old dofs), after Model::replace_state"},
      {"constraint 3 of none",
       [] {
         Spring s;
         solvers::GeneralizedAlpha(s.model, {}, {}).constraint(3);
       },
       "constraint 3 does not exist (0 constraints)", "solvers::GeneralizedAlpha::constraint",
       "give an index into the constructor's constraint list"},
      // solve_static's options (static_solver.cpp, check_options).
      {"load_steps = 0", [] { Spring s; solvers::solve_static(s.model, {.load_steps = 0}); },
       "load_steps and max_iterations must be at least 1, max_cutbacks at least 0", "solvers::solve_static",
       "fix the StaticOptions"},
      {"max_cutbacks = -1", [] { Spring s; solvers::solve_static(s.model, {.max_cutbacks = -1}); },
       "load_steps and max_iterations must be at least 1, max_cutbacks at least 0", "solvers::solve_static",
       "fix the StaticOptions"},
      {"constraint_tolerance = 0", [] { Spring s; solvers::solve_static(s.model, {.constraint_tolerance = 0.0}); },
       "the tolerances must be positive numbers", "solvers::solve_static",
       "fix the StaticOptions' tolerances (NaN and values <= 0 are refused)"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    std::string what, where, fix;
    try {
      c.call();
    } catch (const Error& error) {
      what = error.what();
      where = error.where();
      fix = error.fix();
    }
    CHECK_THAT(what, Catch::Contains(c.what));
    CHECK(where == c.where);
    CHECK_THAT(fix, Catch::Contains(c.fix));
  }
}
