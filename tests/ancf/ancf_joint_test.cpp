// Spherical joints on ANCF beams: the point inside an element against the literal shape functions
// of 001 eqs. (5)/(55), and B against finite differences of Φ.
#include <spar/elements/ancf/ancf_beam.hpp>
#include <spar/elements/loads/vector_load_element.hpp>
#include <spar/error.hpp>
#include <spar/elements/ancf/ancf_points.hpp>
#include <spar/joints/point_joint.hpp>
#include <spar/joints/check_constraint.hpp>

#include <catch2/catch.hpp>

#include <random>

#include "ancf_reference.hpp"

using namespace spar;

namespace {

core::Model deformed_beam(core::AncfElementKind kind, core::AncfBeam& beam) {
  core::Model model;
  beam = core::add_ancf_beam(model, {.end = Eigen::Vector3d(1.2, 0.3, 0), .elements = 3, .kind = kind,
                                     .material = {.young_modulus = 1e3, .poisson_ratio = 0.3, .density = 1},
                                     .section = core::SectionIntegrals::circle(0.05)});
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (int k = 0; k < model.dof_count(); ++k) model.state().values(k) += u(gen);
  return model;
}

template <int transverse>
void check_point(core::AncfElementKind kind) {
  core::AncfBeam beam;
  const core::Model model = deformed_beam(kind, beam);
  const core::Configuration& q = model.state();
  const double xi = 0.37;
  const Eigen::Vector2d yz(0.02, -0.01);
  const core::LinearPoint p = core::ancf_element_point(beam, 1, xi, yz);
  // The literal S(x, y, z) e of 001 on element 1.
  const auto S = test::literal_shape<transverse>(xi * beam.element_length, yz.x(), yz.y(), beam.element_length);
  Eigen::VectorXd e(3 * S.size());
  e.head<12>() = q.vector(beam.nodes[1]);
  e.segment<12>(12) = q.vector(beam.nodes[2]);
  if constexpr (transverse == 3) e.tail<6>() = q.vector(beam.element_blocks[1]);
  Eigen::Vector3d literal = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < S.size(); ++k) literal += S[k] * e.segment<3>(3 * static_cast<Eigen::Index>(k));
  // A few terms of size ≤ 1.5: round-off ≤ 1e-15.
  CHECK((p.position(q) - literal).norm() < 1e-14);
  // The node point is r.
  CHECK(core::ancf_node_point(q, beam.nodes[2]).position(q) == q.vector(beam.nodes[2]).head<3>());
}

}  // namespace

TEST_CASE("ANCF element points follow the paper's shape functions", "[ancf][joints]") {
  check_point<2>(core::AncfElementKind::standard_24);
  check_point<3>(core::AncfElementKind::higher_order_30);
}

TEST_CASE("ANCF spherical joint: B against finite differences, zero tangent and terms", "[ancf][joints]") {
  for (const auto kind : {core::AncfElementKind::standard_24, core::AncfElementKind::higher_order_30}) {
    core::AncfBeam beam;
    const core::Model model = deformed_beam(kind, beam);
    const core::Configuration& q = model.state();
    // A point inside element 1 held at an ANCF node shared with its own element's node B: the
    // shared block enters once.
    const joints::PointJoint joint(core::ancf_element_point(beam, 1, 0.6), core::ancf_node_point(q, beam.nodes[2]), q);
    const int n = core::block_dof_count(q, joint.blocks());
    REQUIRE(static_cast<int>(joint.blocks().size()) == (kind == core::AncfElementKind::standard_24 ? 2 : 3));
    // Φ is linear: central differences of step 1e-6 are exact up to round-off u|Φ|/ε ≈ 1e-10, and B's
    // entries (shape functions) are at most 1 in size, so the errors are absolute (scale floor 1);
    // K_λ and Φ_t have differences of exactly 0. The second difference along the motion is round-off
    // 4u|Φ|/h² ≈ 4e-8, within the default 2e-6.
    const core::DerivativeCheck check = joints::check_constraint(
        joint,
        {.q = q, .velocity = Eigen::VectorXd::Ones(q.dof_count()), .acceleration = Eigen::VectorXd::Zero(q.dof_count()),
         .multipliers = Eigen::Vector3d(1, 2, 3)},
        {.step = 1e-6, .tolerance = 1e-9, .scale_floor = 1.0});
    INFO(check.description());
    CHECK(check.passed());
    Eigen::MatrixXd K(n, n);
    joint.multiplier_tangent(q, 0.0, Eigen::Vector3d(1, 2, 3), K);
    CHECK(K.isZero(0.0));
    Eigen::Vector3d c;
    joint.acceleration_terms(q, Eigen::VectorXd::Ones(q.dof_count()), 0.0, c);
    CHECK(c.isZero(0.0));
    // Held at the ground where the point is: Φ = 0.
    const joints::PointJoint pin(core::ancf_node_point(q, beam.nodes[0]), q.vector(beam.nodes[0]).head<3>(), q);
    Eigen::Vector3d phi;
    pin.value(q, 0.0, phi);
    CHECK(phi.isZero(0.0));
  }
  core::AncfBeam beam;
  const core::Model model = deformed_beam(core::AncfElementKind::standard_24, beam);
  CHECK_THROWS_AS(core::ancf_element_point(beam, 3, 0.5), Error);
  CHECK_THROWS_AS(core::ancf_element_point(beam, 0, 1.5), Error);
  CHECK_THROWS_AS(core::ancf_node_point(model.state(), 99), Error);
}

TEST_CASE("a dead force on an ANCF node: residual, external force, input errors", "[ancf][loads]") {
  core::AncfBeam beam;
  core::Model model = deformed_beam(core::AncfElementKind::standard_24, beam);
  const int index = core::add_ancf_nodal_force(model, beam.nodes[1], Eigen::Vector3d(1, -2, 3), [](double t) { return 2 * t; });
  const core::Element& load = model.element(index);
  const core::ElementRequest request;
  core::ElementOutput out;
  out.reset(12, request);
  load.evaluate({.q = &model.state(), .load_factor = 0.5}, request, out);
  // Statics: −λ f on the position, nothing on the gradients.
  CHECK(out.residual.head<3>() == Eigen::Vector3d(-0.5, 1.0, -1.5));
  CHECK(out.residual.tail<9>().isZero(0.0));
  // Dynamics: history(t) = 2t scales it; on an energy request it reports f for the balance.
  const Eigen::VectorXd v = Eigen::VectorXd::Ones(model.dof_count());
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(model.dof_count());
  core::ElementRequest with_energy;
  with_energy.energy = true;
  out.reset(12, with_energy);
  load.evaluate({.q = &model.state(), .velocity = &v, .acceleration = &a, .time = 0.25}, with_energy, out);
  CHECK(out.residual.head<3>() == Eigen::Vector3d(-0.5, 1.0, -1.5));
  CHECK(out.external_force.head<3>() == Eigen::Vector3d(0.5, -1.0, 1.5));
  CHECK(out.external_force.tail<9>().isZero(0.0));
  CHECK_THROWS_AS(core::VectorLoadElement(model.state(), beam.nodes[0], Eigen::VectorXd::Ones(3), {}, 0), Error);
  const int frame = model.add_frame(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  CHECK_THROWS_AS(core::VectorLoadElement(model.state(), frame, Eigen::VectorXd::Ones(6), {}, 0), Error);
}
