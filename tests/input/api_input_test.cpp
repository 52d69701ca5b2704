// The public API refuses the bad input of issue 15's audit with a spar::Error naming it: each
// case is a call and a word its message must hold. Crashes (a configuration of the wrong size),
// hangs (100 000 Gauss points), std::bad_alloc (2^31 elements) and silent NaN (a NaN point,
// Poisson ratio, load history, tolerance, results scalar, matrix) are all among them.
#include <spar/core/core.hpp>
#include <spar/elements/elements.hpp>
#include <spar/output/output.hpp>
#include <spar/iga/iga.hpp>
#include <spar/joints/joints.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/solvers/linear_solver.hpp>
#include <spar/solvers/static_solver.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/elements/loads/loads.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include "cantilever.hpp"
#include "error_cases.hpp"

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

using namespace spar;

namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double infinite = std::numeric_limits<double>::infinity();

/// A steel cantilever of 4 cubic elements along +X, clamped at the root, with inertia.
test::Cantilever steel_cantilever() { return test::make_steel_cantilever(4); }

core::RigidBodyParameters top() {
  return {.center_of_mass = Eigen::Vector3d(0, 1, 0), .mass = 15.0,
          .inertia = Eigen::Vector3d(0.234375, 0.46875, 0.234375).asDiagonal()};
}

/// Evaluates the cantilever's first element (a beam element) at the input `change` makes of a
/// good static one: Element::evaluate checks its input at this boundary.
void evaluate_element(const std::function<void(core::ElementInput&)>& change) {
  test::Cantilever c = steel_cantilever();
  core::ElementInput in{.q = &c.model.state(), .gravity = Eigen::Vector3d(0, 0, -9.81)};
  change(in);
  const core::Element& element = c.model.element(0);
  core::ElementOutput out;
  out.reset(core::frame_dofs * static_cast<int>(element.blocks().size()), {.residual = true});
  element.evaluate(in, {.residual = true}, out);
}

/// A few dynamic steps of the cantilever under `options` with a tip force of the given history.
void run_dynamics(const solvers::DynamicOptions& options, core::LoadHistory history = {}) {
  test::Cantilever c = steel_cantilever();
  core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(0, 10, 0)}, std::move(history));
  solvers::GeneralizedAlpha integrator(c.model, {}, options);
  integrator.initialize();
  for (int i = 0; i < 3; ++i) integrator.step();
}

}  // namespace

TEST_CASE("every bad API input of the audit ends in a spar::Error naming it", "[input]") {
  const std::vector<test::ErrorCase> cases = {
      {"position_at with an empty configuration (SIGSEGV)",
       [] { test::Cantilever c = steel_cantilever(); core::beam(c.model, c.beam).position_at(core::Configuration{}, 0.5); }, "frame nodes"},
      {"rotation_at with an empty configuration",
       [] { test::Cantilever c = steel_cantilever(); core::beam(c.model, c.beam).rotation_at(core::Configuration{}, 0.5); }, "frame nodes"},
      {"sample_centerline with an empty configuration",
       [] { test::Cantilever c = steel_cantilever(); core::beam(c.model, c.beam).sample_centerline(core::Configuration{}, 3); }, "frame nodes"},
      {"beam element 99 (read out of bounds)",
       [] { test::Cantilever c = steel_cantilever(); core::beam(c.model, c.beam).element(99); }, "element 99 does not exist"},
      {"100 000 Gauss points (hung)",
       [] {
         core::Model model;
         core::add_beam(model, {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 1, 3),
                         .stiffness = core::SectionStiffness::from({.young_modulus = 1e9, .poisson_ratio = 0.3},
                                                                   core::CrossSection::circle(0.01, 0.3)),
                         .quadrature_points = 100000});
       },
       "quadrature_points"},
      {"a Gauss rule of 100 000 points", [] { iga::gauss_legendre(100000); }, "1 to 64 points"},
      {"open_uniform with 2^31 - 1 elements (std::bad_alloc)",
       [] { iga::KnotVector::open_uniform(2147483647, 1, 0); }, "elements"},
      {"open_uniform of degree 2^31 - 1", [] { iga::KnotVector::open_uniform(1, 2147483647, 0); }, "degree"},
      {"a rigid body with a NaN centre of mass",
       [] { core::Model m; auto p = top(); p.center_of_mass.x() = not_a_number; core::add_rigid_body(m, p); }, "centre of mass"},
      {"a rigid body with an infinite centre of mass",
       [] { core::Model m; auto p = top(); p.center_of_mass.y() = infinite; core::add_rigid_body(m, p); }, "centre of mass"},
      {"an inertia diag(1, 1, 5) that breaks the triangle inequality",
       [] { core::Model m; auto p = top(); p.inertia = Eigen::Vector3d(1, 1, 5).asDiagonal(); core::add_rigid_body(m, p); },
       "triangle inequality"},
      {"an inertia with I3 = -1e-9 prints its value",
       [] { core::Model m; auto p = top(); p.inertia = Eigen::Vector3d(1, 1, -1e-9).asDiagonal(); core::add_rigid_body(m, p); },
       "positive definite"},
      {"attach_at a NaN point",
       [] { test::Cantilever c = steel_cantilever(); joints::attach_at(c.tip, Eigen::Vector3d(not_a_number, 0, 0), c.model.state()); }, "attachment point"},
      {"a NaN joint offset",
       [] {
         test::Cantilever c = steel_cantilever();
         joints::SphericalJoint(joints::Attachment{.node = c.tip, .offset = Eigen::Vector3d(0, not_a_number, 0)},
                                joints::Attachment{.node = -1, .offset = Eigen::Vector3d::Zero()}, c.model.state());
       },
       "offset of attachment a"},
      {"a NaN prismatic line point",
       [] {
         test::Cantilever c = steel_cantilever();
         joints::PrismaticJoint(joints::Attachment{.node = c.tip, .offset = Eigen::Vector3d::Zero()},
                                Eigen::Vector3d(not_a_number, 0, 0), Eigen::Vector3d::UnitX(), false, c.model.state());
       },
       "line point"},
      {"Poisson's ratio NaN in CrossSection::rectangle", [] { core::CrossSection::rectangle(0.01, 0.01, not_a_number); },
       "Poisson"},
      {"Poisson's ratio NaN in CrossSection::circle", [] { core::CrossSection::circle(0.01, not_a_number); }, "Poisson"},
      {"a NaN force in add_load",
       [] { test::Cantilever c = steel_cantilever(); core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(not_a_number, 0, 0)}); },
       "force"},
      {"a NaN follower moment",
       [] {
         test::Cantilever c = steel_cantilever();
         core::add_load(c.model, core::NodalMoment{.node = c.tip, .moment = Eigen::Vector3d(0, 0, not_a_number),
                                            .frame = core::MomentFrame::material});
       },
       "moment"},
      {"set_gravity(NaN)", [] { core::Model m; m.set_gravity(Eigen::Vector3d(0, 0, not_a_number)); }, "gravity"},
      {"static residual_tolerance = -1", [] { test::Cantilever c = steel_cantilever(); solvers::solve_static(c.model, {.residual_tolerance = -1}); },
       "tolerance"},
      {"static increment_tolerance = NaN",
       [] { test::Cantilever c = steel_cantilever(); solvers::solve_static(c.model, {.increment_tolerance = not_a_number}); }, "tolerance"},
      {"dynamic tolerance = NaN", [] { run_dynamics({.tolerance = not_a_number}); }, "tolerance must be positive"},
      {"dynamic residual_tolerance = -1", [] { run_dynamics({.residual_tolerance = -1}); }, "residual_tolerance = -1"},
      {"dynamic residual_tolerance = NaN", [] { run_dynamics({.residual_tolerance = not_a_number}); }, "residual_tolerance = nan"},
      {"dynamic constraint_tolerance = NaN", [] { run_dynamics({.constraint_tolerance = not_a_number}); },
       "constraint_tolerance = nan"},
      {"modified_newton_contraction = NaN", [] { run_dynamics({.modified_newton_contraction = not_a_number}); },
       "modified_newton_contraction"},
      {"a spectral radius of 1.5", [] { run_dynamics({.spectral_radius = 1.5}); }, "1.5 is outside [0, 1]"},
      {"a NaN load history in dynamics", [] { run_dynamics({}, [](double t) { return t > 0.0015 ? not_a_number : 1.0; }); },
       "the load history gives nan at t = 0.002"},
      {"set_velocity(NaN)",
       [] {
         test::Cantilever c = steel_cantilever();
         solvers::GeneralizedAlpha integrator(c.model, {}, {});
         integrator.set_velocity(c.tip, Eigen::Vector3d(not_a_number, 0, 0), Eigen::Vector3d::Zero());
       },
       "NaN"},
      {"an element evaluated at a NaN load factor",
       [] { evaluate_element([](core::ElementInput& in) { in.load_factor = not_a_number; }); },
       "the load factor is nan"},
      {"an element evaluated at an infinite time",
       [] { evaluate_element([](core::ElementInput& in) { in.time = infinite; }); },
       "the time is inf"},
      {"an element evaluated with a NaN gravity",
       [] { evaluate_element([](core::ElementInput& in) { in.gravity.y() = not_a_number; }); },
       "gravity has a non-finite component"},
      {"an element evaluated without a configuration",
       [] { evaluate_element([](core::ElementInput& in) { in.q = nullptr; }); },
       "ElementInput::q is null"},
      {"an element evaluated in another model's configuration",
       [] {
         static const core::Configuration other;
         evaluate_element([](core::ElementInput& in) { in.q = &other; });
       },
       "is not in the configuration (0 blocks)"},
      {"an element evaluated with a velocity and no acceleration",
       [] {
         static const Eigen::VectorXd v;
         evaluate_element([](core::ElementInput& in) { in.velocity = &v; });
       },
       "only one of velocity and acceleration"},
      {"an element evaluated with a velocity of the wrong size",
       [] {
         static const Eigen::VectorXd v = Eigen::VectorXd::Zero(5);
         evaluate_element([](core::ElementInput& in) { in.velocity = in.acceleration = &v; });
       },
       "the velocity has 5 and the acceleration 5 entries"},
      // Found by the fuzz test (tests/input/fuzz_test.cpp).
      {"degree elevation across a discontinuity (read past its arrays)",
       [] { iga::degree_elevation_operator(iga::KnotVector({0, 0, 0.5, 0.5, 1, 1}, 1), 1); }, "multiplicity p + 1"},
      {"degree elevation by INT_MAX (overflowed past the check)",
       [] { iga::degree_elevation_operator(iga::KnotVector::open_uniform(2, 2, 1), 2147483647); }, "by 2147483647"},
      {"knot insertion INT_MAX times (overflowed past the check)",
       [] { iga::knot_insertion_operator(iga::KnotVector::open_uniform(2, 2, 1), 0.25, 2147483647); },
       "2147483647 times"},
      {"h-refinement into INT_MAX parts", [] { iga::uniform_refinement_knots(iga::KnotVector::open_uniform(2, 2, 1), 2147483647); },
       "iga::max_knots"},
      // Found by libFuzzer (fuzz/model_fuzzer, under UBSan).
      {"straight_line of degree INT_MIN (degree - 1 overflowed)",
       [] { iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 2, -2147483647 - 1); },
       "degree -2147483648 is outside 1"},
      {"a knot span of 5e-324 (refined to a curve 13 % away)",
       [] { iga::KnotVector({0, 0, 0, 0, 4.9406564584124654e-324, 0.5, 1, 1, 1, 1}, 3); }, "differ by less than"},
      {"a weight of 5e-324 next to 1 (its derivatives overflowed; refused since issue 29)",
       [] {
         const iga::KnotVector U = iga::KnotVector::open_uniform(1, 2, 1);
         Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Ones(3, 3);
         iga::NurbsCurve<3>(U, points, Eigen::Vector3d(4.9406564584124654e-324, 1, 1));
       },
       "below machine epsilon times the largest weight"},
      {"curve derivatives that overflow (control points of ±1e308)",
       [] {
         const iga::KnotVector U = iga::KnotVector::open_uniform(1, 2, 1);
         Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Ones(3, 3);
         points.col(1) *= -1;
         iga::NurbsCurve<3>(U, 1e308 * points).derivatives(0.0, 2);
       },
       "overflow at u = 0"},
      {"a body whose gravity potential overflows (1e300 kg at z = -1e300 m)",
       [] {
         core::Model m;
         auto p = top();
         p.mass = 1e300;
         p.center_of_mass.z() = -1e300;
         m.fix(core::rigid_body(m, core::add_rigid_body(m, p)).node);
         m.set_gravity(Eigen::Vector3d(0, 0, -9.81));
         solvers::GeneralizedAlpha(m, {}, {}).initialize();
       },
       "mechanical energy at t = 0 is not finite"},
      {"a rotation with 1e-7 noise prints the size of the noise",
       [] {
         Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
         R(0, 1) = 1e-7;
         core::Model m;
         m.add_frame(Eigen::Vector3d::Zero(), R);
       },
       "1e-07"},
  };
  test::check_error_cases(cases);
}

TEST_CASE("every linear solver refuses a NaN matrix and names the entry", "[input]") {
  Eigen::SparseMatrix<double> A(2, 2);
  A.insert(0, 0) = 1.0;
  A.insert(1, 1) = 1.0;
  A.insert(0, 1) = 0.5;
  A.makeCompressed();
  for (const auto kind : {solvers::LinearSolverKind::klu, solvers::LinearSolverKind::umfpack,
                          solvers::LinearSolverKind::eigen_lu}) {
    auto solver = solvers::make_linear_solver(kind);
    solver->analyze(A);
    A.coeffRef(1, 1) = not_a_number;
    CHECK_THROWS_WITH(solver->factorize(A), Catch::Contains("non-finite entry nan at (1, 1)"));
    A.coeffRef(1, 1) = 1.0;
    solver->factorize(A);  // and works again with finite values
  }
}

TEST_CASE("ResultsWriter refuses a NaN scalar unless it is declared may_be_undefined", "[input]") {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("spar_input_results_" + std::to_string(getpid()) + ".h5");
  output::ResultsLayout layout;
  layout.velocities = false;
  layout.scalars = {{.name = "energy", .unit = "J", .description = "energy"},
                    {.name = "material_coordinate", .unit = "m", .description = "undefined once released",
                     .may_be_undefined = true}};
  {
    output::ResultsWriter writer(file.string(), layout);
    writer.append({.time = 0.0, .scalars = {1.0, not_a_number}});  // NaN where declared: accepted
    CHECK_THROWS_WITH(writer.append({.time = 1.0, .scalars = {not_a_number, 0.0}}), Catch::Contains("(energy) = nan"));
    CHECK_THROWS_WITH(writer.append({.time = 1.0, .scalars = {1.0, infinite}}), Catch::Contains("is not finite"));
  }
  std::filesystem::remove(file);
  std::filesystem::remove(std::filesystem::path(file).replace_extension(".xmf"));
}

TEST_CASE("a NaN load history stops the run at its first evaluation, without cut-backs", "[input]") {
  // Before: the history's error was taken for a Newton failure, the step was halved 8 times and
  // the final message advised reducing the time step.
  test::Cantilever c = steel_cantilever();
  core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(0, 10, 0)},
                   [](double t) { return t > 0.0015 ? not_a_number : 1.0; });
  solvers::GeneralizedAlpha integrator(c.model, {}, {});
  integrator.initialize();
  integrator.step();
  const core::Configuration before = c.model.state();
  try {
    integrator.step();
    FAIL("the NaN history was accepted");
  } catch (const InputError& error) {
    CHECK(std::string(error.what()).find("the load history gives nan at t = 0.002") != std::string::npos);
    CHECK(error.fix() == "give a history that is finite at every time of the run");
  }
  CHECK(integrator.counters().cutbacks == 0);
  CHECK(integrator.time() == 0.001);  // the failed step is undone, the converged one kept
  CHECK(c.model.state().position == before.position);
}
