// The stability of a static equilibrium (StaticReport::unstable_directions, issue 15): a
// perfectly straight column converges on its straight branch at any load; above its Euler loads
// that branch is unstable, and the report counts the buckling modes below the load.
#include <spar/core/core.hpp>
#include <spar/elements/elements.hpp>
#include <spar/iga/iga.hpp>
#include <spar/joints/joints.hpp>
#include <spar/solvers/static_solver.hpp>
#include <spar/elements/loads/loads.hpp>
#include <spar/elements/beam/beam.hpp>

#include <catch2/catch.hpp>

#include <numbers>

using namespace spar;

namespace {

/// A 1 m steel column of square section along +X from the origin, 16 cubic elements, under a
/// dead compressive tip force factor · P₁, P₁ = π²EI/(4L²) the first Euler load of a cantilever
/// (P_n = (2n − 1)² P₁). Clamped by a Dirichlet condition or by a clamp joint (6 multipliers).
solvers::StaticReport compress_column(double factor, bool clamp_by_joint) {
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  const double width = 0.01, length = 1.0;
  const core::SectionStiffness C =
      core::SectionStiffness::from(steel, core::CrossSection::rectangle(width, width, steel.poisson_ratio));
  core::Model model;
  const int b = core::add_beam(model, {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(),
                                                                    Eigen::Vector3d(length, 0, 0), 16, 3),
                                .stiffness = C});
  const core::GeometricallyExactBeam& beam = core::beam(model, b);
  const int root = beam.node(0), tip = beam.node(beam.control_point_count() - 1);
  const double euler = std::numbers::pi * std::numbers::pi * C.bending_2 / (4 * length * length);
  core::add_load(model, core::NodalForce{.node = tip, .force = Eigen::Vector3d(-factor * euler, 0, 0)});
  if (!clamp_by_joint) {
    model.fix(root);
    return solvers::solve_static(model, {.load_steps = 7});
  }
  joints::ClampJoint clamp(joints::Attachment{.node = root, .offset = Eigen::Vector3d::Zero()},
                           joints::Attachment{.node = -1, .offset = Eigen::Vector3d::Zero()}, model.state());
  return solvers::solve_static(model, {.load_steps = 7}, {&clamp});
}

}  // namespace

TEST_CASE("a straight column is stable below its Euler load and counts its buckling modes above it",
          "[statics][stability]") {
  // The square section buckles alike in both planes: each Euler load P_n below the applied load
  // is two negative eigenvalues. The loads sit between the P_n (1, 9, 25 × P₁), where 16 cubic
  // elements resolve the first modes to far better than the margin.
  for (const bool joint : {false, true}) {
    INFO((joint ? "clamp joint" : "Dirichlet clamp"));
    CHECK(compress_column(0.5, joint).unstable_directions == 0);
    CHECK(compress_column(3.0, joint).unstable_directions == 2);
    CHECK(compress_column(10.0, joint).unstable_directions == 4);
  }
}

TEST_CASE("the stability of a state under a moment load is not assessed", "[statics][stability]") {
  // A moment of fixed material (or inertial) components has no potential for 3D rotations: the
  // energy criterion does not apply, though the tangent of the roll-up is symmetric.
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  core::Model model;
  const int b = core::add_beam(model,
      {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0, 0), 8, 3),
       .stiffness = core::SectionStiffness::from(steel, core::CrossSection::rectangle(0.01, 0.01, 0.3))});
  const core::GeometricallyExactBeam& beam = core::beam(model, b);
  model.fix(beam.node(0));
  core::add_load(model, core::NodalMoment{.node = beam.node(beam.control_point_count() - 1),
                                   .moment = Eigen::Vector3d(0, 0, 100.0), .frame = core::MomentFrame::material});
  CHECK(solvers::solve_static(model).unstable_directions == -1);
}
