// Section resultants of the geometrically exact beam (docs/beam.md B16) against statics that fix
// them exactly: a cantilever's sections carry what is applied beyond them. With a dead force F at
// the tip, R n(S) = F and R m(S) = (x_tip − x(S)) × F in any deformation; with a moment M at the
// tip, R m = M and R n = 0; with a small force, the bending moment of linear beam theory,
// F (L − S). The discrete solution satisfies these only to its discretisation error, so each
// check is a refinement: the error falls with the mesh.
#include <spar/elements/beam/section_resultants.hpp>
#include <spar/elements/loads/loads.hpp>
#include <spar/iga/circular_arc.hpp>
#include <spar/iga/knot_operations.hpp>
#include <spar/lie/lie.hpp>
#include <spar/solvers/static_solver.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "beam_fixtures.hpp"
#include "cantilever.hpp"

using namespace spar;

namespace {

/// The largest errors of the force and the moment over the sections of a cantilever.
struct TipForceErrors {
  double force = 0.0, moment = 0.0;
};

/// Under a dead tip force F, on `elements` cubic elements: the errors over |F| and |F| L.
TipForceErrors tip_force_errors(int elements, const Eigen::Vector3d& F) {
  test::Cantilever c = test::make_cantilever(elements, 3);
  core::add_load(c.model, core::NodalForce{.node = c.tip, .force = F});
  solvers::solve_static(c.model, {.load_steps = 8});
  const core::GeometricallyExactBeam& beam = core::beam(c.model, c.beam);
  const core::SectionResultants r = core::section_resultants(beam, c.model.state());
  const Eigen::Vector3d tip = c.model.state().position[c.tip];
  TipForceErrors errors;
  for (Eigen::Index i = 0; i < r.force.rows(); ++i) {
    const Eigen::Vector3d x = r.position.row(i).transpose();
    errors.force = std::max(errors.force, (r.force.row(i).transpose() - F).norm() / F.norm());
    errors.moment = std::max(errors.moment, (r.moment.row(i).transpose() - (tip - x).cross(F)).norm() / F.norm());
  }
  return errors;
}

/// The errors on three meshes, each twice as fine as the one before, fall by more than 5 (the
/// force) and 10 (the moment) per halving: orders above 2.3 and 3.3.
void check_convergence(const TipForceErrors& coarse, const TipForceErrors& medium, const TipForceErrors& fine) {
  INFO("force errors " << coarse.force << ", " << medium.force << ", " << fine.force);
  INFO("moment errors " << coarse.moment << ", " << medium.moment << ", " << fine.moment);
  CHECK(medium.force < coarse.force / 5);
  CHECK(fine.force < medium.force / 5);
  CHECK(medium.moment < coarse.moment / 10);
  CHECK(fine.moment < medium.moment / 10);
}

}  // namespace

TEST_CASE("section points: the Gauss points of the stiffness, in order, with their arc lengths", "[gebt]") {
  core::Configuration q;
  const core::GeometricallyExactBeam cubic({.centerline = test::straight_centerline(2.0, 3, 3),
                                            .stiffness = test::cantilever_stiffness()}, q);
  const core::SectionPoints at = core::section_points(cubic);
  REQUIRE(at.parameter.size() == 12);  // p + 1 = 4 per element
  for (Eigen::Index i = 0; i < 12; ++i) {
    CHECK(std::abs(at.arc_length(i) - 2.0 * at.parameter(i)) < 1e-14);  // dS/du = 2
    if (i > 0) CHECK(at.arc_length(i) > at.arc_length(i - 1));
    CHECK(at.element[static_cast<std::size_t>(i)] == i / 4);
  }
  // p = 1, selective reduced integration: the two points of everything but the shear.
  core::Configuration q1;
  const core::GeometricallyExactBeam linear({.centerline = test::straight_centerline(1.0, 2, 1),
                                             .stiffness = test::cantilever_stiffness()}, q1);
  const core::SectionPoints at1 = core::section_points(linear);
  REQUIRE(at1.parameter.size() == 4);
  CHECK(std::abs(at1.parameter(0) - 0.25 * (1 - 1 / std::sqrt(3.0))) < 1e-15);
}

TEST_CASE("section resultants vanish in the reference configuration and are objective", "[gebt]") {
  // A curved reference (a quarter circle) is stress-free; a rigid motion of a strained beam keeps
  // n and m in the section frame and turns R n, R m with it.
  core::Configuration q;
  const core::GeometricallyExactBeam beam({.centerline = iga::h_refine(iga::quarter_circle<3>(2.0), 3).curve,
                                           .stiffness = test::generic_stiffness()}, q);
  const core::SectionResultants reference = core::section_resultants(beam, q);
  CHECK(reference.material_force.cwiseAbs().maxCoeff() < 1e-12);
  CHECK(reference.material_moment.cwiseAbs().maxCoeff() < 1e-12);

  core::Configuration strained = q;
  for (int k = 0; k < strained.block_count(); ++k) {
    strained.position[k] += 0.05 * Eigen::Vector3d(std::sin(k), std::cos(2.0 * k), 0.3 * k);
    strained.rotation[k] = strained.rotation[k] * lie::exp(Eigen::Vector3d(0.1 * k, -0.05, 0.2 * std::sin(k)));
  }
  const Eigen::Matrix3d Q = lie::exp(Eigen::Vector3d(0.4, -1.3, 0.8));
  const Eigen::Vector3d shift(1.0, -2.0, 0.5);
  core::Configuration moved = strained;
  for (int k = 0; k < moved.block_count(); ++k) {
    moved.position[k] = Q * moved.position[k] + shift;
    moved.rotation[k] = Q * moved.rotation[k];
  }
  const core::SectionResultants a = core::section_resultants(beam, strained), b = core::section_resultants(beam, moved);
  const double scale = a.material_force.norm() + a.material_moment.norm();
  REQUIRE(scale > 1e-2);
  CHECK((b.material_force - a.material_force).norm() < 1e-12 * scale);
  CHECK((b.material_moment - a.material_moment).norm() < 1e-12 * scale);
  CHECK((b.force.transpose() - Q * a.force.transpose()).norm() < 1e-12 * scale);
  CHECK((b.moment.transpose() - Q * a.moment.transpose()).norm() < 1e-12 * scale);
  CHECK((b.position.transpose() - ((Q * a.position.transpose()).colwise() + shift)).norm() < 1e-12);
}

TEST_CASE("a small tip force gives linear beam theory's bending moment F (L - S)", "[gebt][validation]") {
  // P L²/EI = 1e-4: the rotations are 5e-5 rad, so the nonlinear terms are ~1e-9 of the moment.
  test::Cantilever c = test::make_cantilever(8, 3);
  const double P = 1.0, L = 1.0;
  core::add_load(c.model, core::NodalForce{.node = c.tip, .force = Eigen::Vector3d(0, P, 0)});
  solvers::solve_static(c.model, {.load_steps = 1});
  const core::GeometricallyExactBeam& beam = core::beam(c.model, c.beam);
  const core::SectionPoints at = core::section_points(beam);
  const core::SectionResultants r = core::section_resultants(beam, c.model.state(), at);
  double worst = 0.0;
  for (Eigen::Index i = 0; i < at.arc_length.size(); ++i) {
    // Bending about A₃ = Z: m₃ = EI κ₃ = P (L − S); the shear force along A₂ = Y is P.
    worst = std::max(worst, std::abs(r.material_moment(i, 2) - P * (L - at.arc_length(i))));
    CHECK(std::abs(r.material_force(i, 1) - P) < 1e-6 * P);
  }
  INFO("largest error of M(S) = P (L - S): " << worst << " N m");
  CHECK(worst < 1e-8 * P * L);
}

TEST_CASE("at large deflection the sections carry the tip force and its moment, to the discretisation",
          "[gebt][validation]") {
  // P L²/EI = 3 out of two planes (tip deflection ~0.6 L): the largest errors over all sections,
  // over |F| and |F| L. Measured on 4, 8, 16 elements: force 4.25, 0.64, 0.097 (order 2.7);
  // moment 1.2e-2, 8.7e-4, 4.7e-5 (order 4). The force is EA γ and GA γ: a strain error of the
  // interpolation times a stiffness EA L²/EI = 1e4 times the bending one (docs/beam.md B16), so it
  // converges more slowly than the moment, which equilibrium ties to the tip.
  const Eigen::Vector3d F = 3e4 * Eigen::Vector3d(0.0, 3.0, 1.0).normalized();
  const TipForceErrors fine = tip_force_errors(16, F);
  check_convergence(tip_force_errors(4, F), tip_force_errors(8, F), fine);
  CHECK(fine.force < 0.12);
  CHECK(fine.moment < 6e-5);
}

TEST_CASE("a tip moment rolls the beam up with the moment M at every section and no force", "[gebt][validation]") {
  // M L/EI = π: a half circle; the moment is M along the whole beam and the force zero. The
  // largest errors over all sections, the moment's over M, the force's over M/L. Measured on 8, 16,
  // 32 elements: force 0.55, 6.8e-2, 8.4e-3 (order 3); moment 1.1e-3, 7.4e-5, 5.5e-6 (order 3.8).
  const auto errors = [](int elements) {
    test::Cantilever c = test::make_cantilever(elements, 3);
    const double M = std::numbers::pi * 1e4, L = 1.0;
    core::add_load(c.model, core::NodalMoment{.node = c.tip, .moment = Eigen::Vector3d(0, 0, M)});
    solvers::solve_static(c.model, {.load_steps = 4});
    const core::SectionResultants r = core::section_resultants(core::beam(c.model, c.beam), c.model.state());
    const Eigen::RowVector3d expected(0, 0, M);
    TipForceErrors worst;
    for (Eigen::Index i = 0; i < r.moment.rows(); ++i) {
      worst.moment = std::max(worst.moment, (r.material_moment.row(i) - expected).norm() / M);
      worst.force = std::max(worst.force, r.force.row(i).norm() * L / M);
    }
    return worst;
  };
  const TipForceErrors fine = errors(32);
  check_convergence(errors(8), errors(16), fine);
  CHECK(fine.force < 1e-2);
  CHECK(fine.moment < 6e-6);
}

TEST_CASE("section resultants refuse another model's configuration and foreign points", "[gebt]") {
  core::Configuration q;
  const core::GeometricallyExactBeam beam({.centerline = test::straight_centerline(1.0, 2, 2),
                                           .stiffness = test::cantilever_stiffness()}, q);
  CHECK_THROWS_WITH(core::section_resultants(beam, core::Configuration{}), Catch::Contains("section_resultants"));
  core::SectionPoints points = core::section_points(beam);
  points.element.pop_back();
  CHECK_THROWS_WITH(core::section_resultants(beam, q, points), Catch::Contains("core::section_points(beam)"));
}
