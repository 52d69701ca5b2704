// The curves a sliding joint grips (core::Curve, issue 30): each family's — a beam's centerline,
// a RANCF cable's, a rigid body's rail — against central differences of its own position: x_ζ
// and x_ζζ in ζ, ∂x/∂Δ in the blocks' increments (through q ⊕ Δ), and the multiplier tangent
// ∂((∂x/∂(ζ, Δ))ᵀf)/∂(ζ, Δ); inside segments, on both sides of a segment boundary and beyond the
// ends. Then the sliding joint on each curve by the installed joints::check_constraint (B, K_λ
// and the acceleration terms).
#include <spar/core/curve.hpp>
#include <spar/core/model.hpp>
#include <spar/elements/beam/beam.hpp>
#include <spar/elements/beam/beam_centerline.hpp>
#include <spar/elements/cable/cable_centerline.hpp>
#include <spar/elements/cable/rancf_cable_element.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/elements/rigid_body/rigid_rail.hpp>
#include <spar/iga/circular_arc.hpp>
#include <spar/joints/sliding_joint.hpp>
#include <spar/lie/exp.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "beam_fixtures.hpp"
#include "constraint_checks.hpp"
#include "sliding_carriers.hpp"

using namespace spar;

namespace {

/// A model holding a carrier curve, a free frame for a slider, and the curve.
struct CarrierModel {
  core::Model model;
  std::shared_ptr<const core::Curve> curve;
  int slider = -1;
  std::string name;
};

/// A GEBT beam on a rational quarter circle of radius 1.5 (5 elements of degree 3, C²).
void build_beam(CarrierModel& c) {
  const int b = core::add_beam(c.model, {.centerline = test::quarter_circle_carrier(1.5, 5, 3, 2),
                                         .stiffness = test::generic_stiffness()});
  c.curve = core::beam_centerline(c.model, b);
  c.name = "beam centerline";
}

/// A spatial RANCF cable of 4 elements of 0.4 m along +X with rational weights (so that the
/// weights' quotient rule is exercised); its nodes are perturbed below.
void build_cable(CarrierModel& c) {
  std::vector<int> nodes, elements;
  for (int i = 0; i <= 4; ++i) {
    Eigen::VectorXd node = Eigen::VectorXd::Zero(6);
    node(0) = 0.4 * i;
    node(3) = 1.0;
    nodes.push_back(c.model.add_vector(node));
  }
  for (int i = 0; i < 4; ++i)
    elements.push_back(c.model.add_element(std::make_unique<core::RancfCableElement<3>>(core::RancfCableParameters{
        .node_a = nodes[i], .node_b = nodes[i + 1], .length = 0.4,
        .section = {.axial_stiffness = 1e3, .bending_stiffness = 1.0, .mass_per_length = 2.0},
        .weights = Eigen::Vector4d(1.0, 0.8 + 0.1 * i, 1.3, 1.0)})));
  c.curve = core::cable_centerline(c.model, elements);
  c.name = "cable centerline";
}

/// A rail on a rigid body: an exact circular arc of radius 0.8 over 270° (three rational pieces)
/// in the body's X–Z plane, about a centre 0.2 m off the centre of mass.
void build_rail(CarrierModel& c) {
  const int body = core::add_rigid_body(c.model, {.center_of_mass = Eigen::Vector3d(0.3, -0.1, 0.2),
                                                  .rotation = lie::exp(Eigen::Vector3d(0.4, -0.3, 0.2)),
                                                  .mass = 2.0, .inertia = Eigen::Matrix3d::Identity()});
  const iga::NurbsCurve<3> arc = iga::circular_arc<3>({.center = Eigen::Vector3d(0.2, 0.0, 0.0),
                                                       .x_axis = -Eigen::Vector3d::UnitZ(),
                                                       .y_axis = Eigen::Vector3d::UnitX(), .radius = 0.8,
                                                       .start_angle = -0.75 * std::numbers::pi,
                                                       .sweep = 1.5 * std::numbers::pi});
  c.curve = core::rigid_body_rail(c.model, body, arc);
  c.name = "rigid rail";
}

/// Every frame moved and turned at random, every vector coordinate perturbed by ±0.1.
void perturb(core::Configuration& q, test::RandomRotations& random) {
  for (int b = 0; b < q.block_count(); ++b)
    if (q.is_frame(b)) {
      q.position[b] += test::random_vector(random, 0.3);
      q.rotation[b] = q.rotation[b] * lie::exp(random.rotation_vector());
    }
  for (Eigen::Index k = 0; k < q.values.size(); ++k) q.values(k) += random.uniform(-0.1, 0.1);
}

/// The model blocks of point p, and its local increments in the global layout.
std::vector<int> point_blocks(const core::Curve& curve, const core::CurvePoint& p) {
  std::vector<int> blocks;
  for (int j = 0; j < p.block_count; ++j) blocks.push_back(curve.block(p.first_block + j));
  return blocks;
}

/// q ⊕ (step e_i) for the global increment index i.
core::Configuration moved(const core::Configuration& q, int dof, double step) {
  core::Configuration r = q;
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(q.dof_count());
  delta(dof) = step;
  r.apply_increment(delta);
  return r;
}

/// The derivatives at ζ against central differences. Steps ε = 1e-6 in ζ and in the increments:
/// truncation ε²/6·|x‴| ≲ 1e-12·|x‴| (|x‴| ≲ 50 for these curves of unit size) and round-off
/// u·|x|/ε ≲ 1e-9 for |x| ≲ 3: 1e-7 relative to max(1, |derivative|) leaves two orders over both.
void check_curve(const core::Curve& curve, const core::Configuration& q, double zeta, test::RandomRotations& random) {
  constexpr double eps = 1e-6, tolerance = 1e-7;
  const core::CurvePoint p = curve.point(q, zeta, 2);
  const auto position = [&](const core::Configuration& r, double z) { return curve.point(r, z, 0).x[0]; };
  // ζ-derivatives.
  const Eigen::Vector3d x_zeta = (position(q, zeta + eps) - position(q, zeta - eps)) / (2 * eps);
  CHECK(test::relative_error(p.x[1], x_zeta) <= tolerance);
  const Eigen::Vector3d x_zeta_zeta = (curve.point(q, zeta + eps, 1).x[1] - curve.point(q, zeta - eps, 1).x[1]) / (2 * eps);
  CHECK(test::relative_error(p.x[2], x_zeta_zeta) <= tolerance);
  // The point alone is the point with its derivatives (to the round-off of a different order).
  CHECK((position(q, zeta) - p.x[0]).norm() <= 1e-15 * std::max(1.0, p.x[0].norm()));
  // ∂x/∂Δ, through W = I.
  const std::vector<int> blocks = point_blocks(curve, p);
  const std::vector<int> dofs = core::block_dofs(q, blocks);
  const int n = static_cast<int>(dofs.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(3, n), B_fd(3, n);
  curve.add_jacobian(q, p, Eigen::Matrix3d::Identity(), B, 0, 0);
  for (int i = 0; i < n; ++i)
    B_fd.col(i) = (position(moved(q, dofs[i], eps), zeta) - position(moved(q, dofs[i], -eps), zeta)) / (2 * eps);
  CHECK(test::relative_error(B, B_fd) <= tolerance);
  // The multiplier tangent: the derivative of g = [x_ζ·f; (∂x/∂Δ)ᵀf] in (ζ, Δ), ζ first.
  const Eigen::Vector3d f = test::random_vector(random, 2.0);
  const auto g = [&](const core::Configuration& r, double z) {
    const core::CurvePoint point = curve.point(r, z, 1);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(3, n);
    curve.add_jacobian(r, point, Eigen::Matrix3d::Identity(), J, 0, 0);
    Eigen::VectorXd out(n + 1);
    out(0) = point.x[1].dot(f);
    out.tail(n) = J.transpose() * f;
    return out;
  };
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + 1, n + 1), K_fd(n + 1, n + 1);
  curve.add_multiplier_tangent(q, p, f, K, 0, 1);
  K_fd.col(0) = (g(q, zeta + eps) - g(q, zeta - eps)) / (2 * eps);
  for (int i = 0; i < n; ++i) K_fd.col(i + 1) = (g(moved(q, dofs[i], eps), zeta) - g(moved(q, dofs[i], -eps), zeta)) / (2 * eps);
  CHECK(test::relative_error(K, K_fd) <= tolerance);
}

using Builder = std::function<void(CarrierModel&)>;

}  // namespace

TEST_CASE("curves of every family: derivatives in zeta and in the blocks against finite differences",
          "[sliding][curves]") {
  test::RandomRotations random(3001);
  for (const Builder& build : std::vector<Builder>{build_beam, build_cable, build_rail}) {
    CarrierModel c;
    build(c);
    const double L = c.curve->length();
    core::Configuration q = c.model.state();
    perturb(q, random);
    // Inside segments, 2e-4 L on both sides of the beam's and the cable's boundaries at 0.4 L and
    // 0.5 L (and of the rail's knot at 1/3 L, where the rational pieces meet), and 2 % beyond
    // either end (the tangent line, eq. J29). The differences move ζ by 1e-6 and stay on one side.
    for (const double s : {0.13, 0.4 - 2e-4, 0.4 + 2e-4, 1.0 / 3 + 2e-4, 0.5 - 2e-4, 0.5 + 2e-4, 0.77, -0.02, 1.02}) {
      INFO(c.name << " at zeta = " << s << " L");
      check_curve(*c.curve, q, s * L, random);
    }
  }
}

TEST_CASE("curves of every family: segments and their blocks", "[sliding][curves]") {
  CarrierModel beam, cable, rail;
  build_beam(beam);
  build_cable(cable);
  build_rail(rail);
  // The beam: 5 cubic C² elements, 8 control points; element e depends on control points e … e + 3.
  CHECK(beam.curve->segment_count() == 5);
  CHECK(beam.curve->block_count() == 8);
  CHECK(beam.curve->segment_at(0.41 * beam.curve->length()) == 2);
  CHECK(beam.curve->segment_at(beam.curve->length()) == 4);
  CHECK(beam.curve->segment_blocks(1, 3).first == 1);
  CHECK(beam.curve->segment_blocks(1, 3).last == 6);
  // The cable: 4 elements of 0.4 m, 5 nodes; ζ is the material coordinate.
  CHECK(cable.curve->length() == Approx(1.6).epsilon(1e-15));
  CHECK(cable.curve->segment_count() == 4);
  CHECK(cable.curve->segment_at(0.8) == 2);  // a node belongs to the element after it
  CHECK(cable.curve->segment_at(1.6) == 3);
  CHECK(cable.curve->segment_blocks(0, 1).last == 2);
  // At a node the point is the node's r (the rational weights change the speed, not the ends).
  const core::CurvePoint p = cable.curve->point(cable.model.state(), 0.8, 0);
  CHECK((p.x[0] - Eigen::Vector3d(0.8, 0, 0)).norm() <= 1e-15);
  // The rail: one segment on the body's frame; its length is the arc's, 0.8 · 3π/2.
  CHECK(rail.curve->segment_count() == 1);
  CHECK(rail.curve->block_count() == 1);
  CHECK(rail.curve->length() == Approx(0.8 * 1.5 * std::numbers::pi).epsilon(1e-13));
}

TEST_CASE("the sliding joint on every family's curve: B, K_lambda and the acceleration terms",
          "[sliding][joints]") {
  test::RandomRotations random(3002);
  for (const Builder& build : std::vector<Builder>{build_beam, build_cable, build_rail}) {
    CarrierModel c;
    build(c);
    c.slider = c.model.add_frame(Eigen::Vector3d(0.3, -0.2, 0.5), lie::exp(Eigen::Vector3d(0.3, 0.2, -0.4)));
    const double L = c.curve->length();
    joints::SlidingJoint joint({.slider = {.node = c.slider, .offset = Eigen::Vector3d(0.1, -0.2, 0.15)},
                                .carrier = c.curve, .zeta = 0.45 * L, .name = c.name},
                               c.model);
    for (const double s : {0.37, 0.45, 0.52}) {
      INFO(c.name << " at zeta = " << s << " L");
      core::Configuration q = c.model.state();
      perturb(q, random);
      q.vector(joint.zeta_block())(0) = s * L;
      test::check_derivatives(joint, q, 0.2, random);
    }
  }
}

TEST_CASE("curves of every family refuse what they cannot be built from", "[sliding][curves][errors]") {
  CarrierModel c;
  build_cable(c);
  CHECK_THROWS_AS(core::cable_centerline(c.model, {}), Error);
  CHECK_THROWS_WITH(core::cable_centerline(c.model, {0, 2}), Catch::Contains("previous one ends"));
  const int beam = core::add_beam(c.model, {.centerline = test::quarter_circle_carrier(1.0, 2, 2, 1),
                                            .stiffness = test::generic_stiffness()});
  CHECK_THROWS_WITH(core::cable_centerline(c.model, {c.model.element_count() - 1}),
                    Catch::Contains("not a spatial fixed-length RANCF"));
  CHECK_THROWS_AS(core::beam_centerline(c.model, beam + 1), Error);
  CHECK_THROWS_AS(core::rigid_body_rail(c.model, 0, iga::quarter_circle<3>(1.0)), Error);
  CHECK_THROWS_WITH(core::RigidRail(c.model, 0, iga::quarter_circle<3>(1.0)), Catch::Contains("frame"));  // a cable node
  const core::CurvePoint p = c.curve->point(c.model.state(), 0.1, 0);
  CHECK_THROWS_AS(c.curve->point(c.model.state(), std::numeric_limits<double>::quiet_NaN(), 0), Error);
  CHECK_THROWS_AS(c.curve->point(c.model.state(), 0.1, 3), Error);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(13, 13);
  CHECK_THROWS_AS(c.curve->add_multiplier_tangent(c.model.state(), p, Eigen::Vector3d::Ones(), K, 0, 1), Error);
}
