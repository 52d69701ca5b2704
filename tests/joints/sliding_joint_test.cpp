// SlidingJoint: a point held to a flexible carrier's centerline at its own coordinate ζ (003 §4,
// docs/joints.md §2.5). Its derivatives against finite differences on deformed carriers (inside
// elements, next to knots, beyond a stopped end, locked), the window of control points that
// follows ζ, the end stops and the errors.
#include <spar/core/model.hpp>
#include <spar/elements/beam/beam_centerline.hpp>
#include <spar/error.hpp>
#include <spar/joints/sliding_joint.hpp>
#include <spar/lie/exp.hpp>
#include <spar/iga/straight_line.hpp>
#include <spar/elements/beam/beam.hpp>

#include <Eigen/SVD>

#include <catch2/catch.hpp>

#include "beam_fixtures.hpp"
#include "constraint_checks.hpp"
#include "sliding_carriers.hpp"

using namespace spar;

namespace {

/// A carrier beam (a quarter circle of radius 1.5 with 5 elements) and a free frame for the slider.
struct SlidingFixture {
  core::Model model;
  int slider = -1;

  SlidingFixture(int degree, int continuity) {
    core::add_beam(model, {.centerline = test::quarter_circle_carrier(1.5, 5, degree, continuity),
                    .stiffness = test::generic_stiffness()});
    slider = model.add_frame(Eigen::Vector3d(0.3, -0.2, 0.5), lie::exp(Eigen::Vector3d(0.3, 0.2, -0.4)));
  }

  joints::SlidingJointParameters parameters(double zeta) const {
    return {.slider = {.node = slider, .offset = Eigen::Vector3d(0.1, -0.2, 0.15)},
            .carrier = core::beam_centerline(model, 0), .zeta = zeta, .upper_stop = std::nullopt, .name = "test slider"};
  }
};

/// q with every frame moved and turned at random (a deformed carrier, a slider anywhere).
core::Configuration perturbed(const core::Configuration& q, test::RandomRotations& random) {
  core::Configuration p = q;
  for (int b = 0; b < p.block_count(); ++b)
    if (p.is_frame(b)) {
      p.position[b] += test::random_vector(random, 0.3);
      p.rotation[b] = p.rotation[b] * lie::exp(random.rotation_vector());
    }
  return p;
}

}  // namespace

TEST_CASE("sliding joint: derivatives against finite differences on deformed carriers",
          "[joints][sliding]") {
  test::RandomRotations random(1201);
  for (const int degree : {2, 3})
    for (const int continuity : {0, degree - 1}) {
      SlidingFixture f(degree, continuity);
      const double length = 1.5 * std::numbers::pi / 2;  // the quarter circle's length
      joints::SlidingJoint joint(f.parameters(0.37 * length), f.model);
      CHECK(std::abs(joint.carrier_length() - length) <= 1e-10 * length);
      // Inside elements, and 2e-4 L (3e-4 m) on either side of the element boundary at 0.4 L
      // (C^continuity there): the differences move ζ by at most 1e-6 (configuration) and 1e-4
      // (time, |ζ̇| ≤ 1), so they stay on one side.
      for (const double s : {0.37, 0.4 - 2e-4, 0.4 + 2e-4, 0.5, 0.55}) {
        INFO("degree " << degree << ", C" << continuity << ", zeta = " << s << " L");
        core::Configuration q = perturbed(f.model.state(), random);
        q.vector(joint.zeta_block())(0) = s * length;
        test::check_derivatives(joint, q, 0.2, random);
      }
    }
}

TEST_CASE("sliding joint: the slider on the carrier satisfies Phi; B's zeta column is -dx_B/dzeta",
          "[joints][sliding]") {
  test::RandomRotations random(1202);
  SlidingFixture f(2, 1);
  joints::SlidingJoint joint(f.parameters(1.0), f.model);
  core::Configuration q = perturbed(f.model.state(), random);
  const Eigen::VectorXd no_velocity = Eigen::VectorXd::Zero(q.dof_count());
  std::string description;
  for (const double zeta : {0.0, 0.2, 1.3, joint.carrier_length()}) {
    q.vector(joint.zeta_block())(0) = zeta;
    joint.update_structure(q, no_velocity, 0.0, description);
    // Put the slider's point on the carrier point: p_A = x + R a = x_B.
    const Eigen::Vector3d offset(0.1, -0.2, 0.15);
    q.position[f.slider] = joint.carrier_point(q) - q.rotation[f.slider] * offset;
    // Round-off of x + R a − x_B with |x| ≲ 2.
    CHECK(test::value(joint, q, 0).norm() <= 1e-15 * 10);
    // The frictionless condition (003 eq. 51) is the ζ entry of Bᵀλ: −x_B,ζ·λ, with x_B,ζ the
    // carrier's tangent by finite differences in ζ with step ε = 1e-6: one-sided at the ends,
    // error ε/2·|x_B,ζζ|·|λ| ≲ 2e-6 for |x_B,ζζ| ≲ 2 (curvature of a deformed radius-1.5 arc).
    const Eigen::MatrixXd B = test::jacobian(joint, q, 0);
    const Eigen::Vector3d lambda(0.3, -1.2, 0.7);
    core::Configuration ahead = q, behind = q;
    const double eps = 1e-6;
    ahead.vector(joint.zeta_block())(0) = std::min(zeta + eps, joint.carrier_length());
    behind.vector(joint.zeta_block())(0) = std::max(zeta - eps, 0.0);
    const Eigen::Vector3d tangent = (joint.carrier_point(ahead) - joint.carrier_point(behind)) /
                                    (ahead.vector(joint.zeta_block())(0) - behind.vector(joint.zeta_block())(0));
    CHECK(std::abs((B.transpose() * lambda)(6) + tangent.dot(lambda)) <= 2e-6);
  }
  // The carrier's end points in the reference configuration: ζ = 0 and ζ = L₀.
  core::Configuration q0 = f.model.state();
  q0.vector(joint.zeta_block())(0) = joint.carrier_length();
  joint.update_structure(q0, no_velocity, 0.0, description);
  CHECK((joint.carrier_point(q0) - Eigen::Vector3d(0, 1.5, 0)).norm() <= 1e-14);
  q0.vector(joint.zeta_block())(0) = 0.0;
  joint.update_structure(q0, no_velocity, 0.0, description);
  CHECK((joint.carrier_point(q0) - Eigen::Vector3d(1.5, 0, 0)).norm() <= 1e-14);
}

TEST_CASE("sliding joint: the window of control points follows zeta across elements",
          "[joints][sliding]") {
  SlidingFixture f(2, 1);
  joints::SlidingJoint joint(f.parameters(0.1), f.model);
  const double length = joint.carrier_length();
  // 5 quadratic C¹ elements, 7 control points: element 0's window is elements 0–1, control
  // points 0–3.
  CHECK(joint.window_element() == 0);
  CHECK(joint.blocks().size() == 2 + 4);
  core::Configuration q = f.model.state();
  std::string description;
  CHECK_FALSE(joint.update_structure(q, Eigen::VectorXd::Zero(q.dof_count()), 0.1, description));
  // Into element 1 (0.2 L … 0.4 L): still evaluated, then re-centred: control points 0–4.
  q.vector(joint.zeta_block())(0) = 0.25 * length;
  Eigen::VectorXd phi(3);
  CHECK_NOTHROW(joint.value(q, 0.2, phi));
  CHECK(joint.update_structure(q, Eigen::VectorXd::Zero(q.dof_count()), 0.2, description));
  CHECK(description == "sliding joint 'test slider' entered carrier element 1");
  CHECK(joint.window_element() == 1);
  CHECK(joint.blocks().size() == 2 + 5);
  // Two elements ahead within one step is an evaluation error (the integrator cuts the step).
  q.vector(joint.zeta_block())(0) = 0.85 * length;
  CHECK_THROWS_WITH(joint.value(q, 0.3, phi),
                    Catch::Contains("test slider") && Catch::Contains("reduce the time step"));
}

TEST_CASE("sliding joint: an end stop locks zeta, with derivatives beyond the carrier's end",
          "[joints][sliding]") {
  test::RandomRotations random(1203);
  SlidingFixture f(3, 2);
  joints::SlidingJointParameters p = f.parameters(0.5);
  joints::SlidingJoint probe(p, f.model);
  const double length = probe.carrier_length();
  p.upper_stop = length;
  p.lower_stop = 0.2;
  joints::SlidingJoint joint(p, f.model);
  core::Configuration q = perturbed(f.model.state(), random);
  // A step that overshoots the end: evaluated on the end's tangent line (eq. J29), derivatives
  // exact there too.
  q.vector(joint.zeta_block())(0) = length + 0.03;
  CHECK_THROWS_WITH(joint.value(q, 0.0, Eigen::VectorXd(3).setZero()),
                    Catch::Contains("beyond the neighbours"));  // the window is still at element 1
  std::string description;
  core::Configuration q_window = q;
  q_window.vector(joint.zeta_block())(0) = 0.99 * length;
  for (int e = 0; e < 5 && !joint.locked(); ++e) {
    q_window.vector(joint.zeta_block())(0) = (0.1 + 0.2 * e) * length;
    joint.update_structure(q_window, Eigen::VectorXd::Zero(q.dof_count()), 0.1, description);
  }
  CHECK(joint.window_element() == 4);
  CHECK_FALSE(joint.locked());
  test::check_derivatives(joint, q, 0.0, random);
  const Eigen::Vector3d end = joint.carrier_point(q);
  core::Configuration at_end = q;
  at_end.vector(joint.zeta_block())(0) = length;
  const Eigen::MatrixXd B = test::jacobian(joint, at_end, 0);
  CHECK((end - joint.carrier_point(at_end) + 0.03 * B.col(6)).norm() <= 1e-14);
  // The step ends past the stop: the joint locks at the stop.
  CHECK(joint.update_structure(q, Eigen::VectorXd::Zero(q.dof_count()), 1.25, description));
  CHECK(joint.locked());
  CHECK(joint.equation_count() == 4);
  CHECK(description.find("locked at its upper stop") != std::string::npos);
  CHECK(std::abs(test::value(joint, q, 0)(3) - 0.03) <= 1e-15);
  test::check_derivatives(joint, q, 0.0, random);
  at_end.vector(joint.zeta_block())(0) = 0.7 * length;
  test::check_derivatives(joint, at_end, 0.0, random);
  // Locked is final.
  CHECK_FALSE(joint.update_structure(at_end, Eigen::VectorXd::Zero(q.dof_count()), 2.0, description));
}

TEST_CASE("sliding joint: a slider leaving an end without a stop is an error naming it and the time",
          "[joints][sliding][errors]") {
  SlidingFixture f(2, 1);
  joints::SlidingJoint joint(f.parameters(0.05), f.model);
  core::Configuration q = f.model.state();
  q.vector(joint.zeta_block())(0) = -0.01;
  std::string description;
  CHECK_THROWS_WITH(joint.update_structure(q, Eigen::VectorXd::Zero(q.dof_count()), 0.734, description),
                    Catch::Contains("'test slider'") && Catch::Contains("ran off the start") &&
                        Catch::Contains("t = 0.734") && Catch::Contains("end stop"));
}

TEST_CASE("sliding joint rejects a missing carrier, a slider on the carrier, and coordinates off it",
          "[joints][sliding][errors]") {
  SlidingFixture f(2, 1);
  joints::SlidingJointParameters p = f.parameters(0.5);
  CHECK_THROWS(p.carrier = core::beam_centerline(f.model, 1));
  p.carrier = nullptr;
  CHECK_THROWS(joints::SlidingJoint(p, f.model));
  p = f.parameters(0.5);
  p.slider.node = 2;
  CHECK_THROWS_WITH(joints::SlidingJoint(p, f.model), Catch::Contains("its own carrier"));
  p = f.parameters(0.5);
  p.slider.node = -1;
  CHECK_THROWS_WITH(joints::SlidingJoint(p, f.model), Catch::Contains("ground"));
  p = f.parameters(3.0);
  CHECK_THROWS_WITH(joints::SlidingJoint(p, f.model),
                    Catch::Contains("initial zeta = 3") && Catch::Contains("outside"));
  p = f.parameters(0.5);
  p.upper_stop = 0.4;
  CHECK_THROWS_WITH(joints::SlidingJoint(p, f.model), Catch::Contains("strictly between the stops"));
  p.upper_stop = 2.5;
  CHECK_THROWS_WITH(joints::SlidingJoint(p, f.model), Catch::Contains("the upper stop = 2.5"));
  const int blocks = f.model.block_count();
  p = f.parameters(0.5);
  const joints::SlidingJoint joint(p, f.model);
  CHECK(f.model.block_count() == blocks + 1);
  CHECK(joint.zeta_block() == blocks);
  CHECK(f.model.state().vector(joint.zeta_block())(0) == 0.5);
}

TEST_CASE("sliding joint: zeta in metres keeps the start-up matrix's conditioning independent of the carrier",
          "[joints][sliding]") {
  // The translational start-up system of a 0.5 kg bead on a straight carrier, unknowns (ẍ_A, ζ̈, λ):
  //   [ m I   0    I  ]
  //   [ 0     0   −tᵀ ]     t = x_B,ζ
  //   [ I    −t    0  ]
  // ζ has no mass; the system is regular through t. With ζ the rescaled parameter (eq. J23),
  // |t| = 1 whatever the carrier's length and knot range, so the matrix — and its condition
  // number — is the same for a 2 cm and a 200 m carrier (with the raw parameter u ∈ [0, 1], t
  // would be L times the unit tangent and the condition number would grow like L²).
  std::vector<double> conditions;
  for (const double length : {0.02, 2.0, 200.0}) {
    core::Model model;
    core::add_beam(model, {.centerline = iga::straight_line<3>(Eigen::Vector3d::Zero(), length * Eigen::Vector3d(0.6, 0, -0.8), 5, 2),
                    .stiffness = test::generic_stiffness()});
    const int bead = model.add_frame(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
    const joints::SlidingJoint joint({.slider = {.node = bead}, .carrier = core::beam_centerline(model, 0), .zeta = 0.3 * length}, model);
    const Eigen::MatrixXd B = test::jacobian(joint, model.state(), 0);
    CHECK(std::abs(B.col(6).norm() - 1.0) <= 1e-12);
    Eigen::MatrixXd S = Eigen::MatrixXd::Zero(7, 7);
    S.topLeftCorner<3, 3>() = 0.5 * Eigen::Matrix3d::Identity();
    S.block<3, 3>(4, 0) = B.leftCols<3>();
    S.block<3, 1>(4, 3) = B.col(6);
    S.block<4, 3>(0, 4) = S.block<3, 4>(4, 0).transpose().eval();
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(S);
    conditions.push_back(svd.singularValues()(0) / svd.singularValues()(6));
  }
  // Measured 6.5 for m = 0.5 kg (the spread of m, 1 and the coupling); equal across lengths to
  // round-off.
  CHECK(conditions[0] <= 10);
  CHECK(std::abs(conditions[1] - conditions[0]) <= 1e-10 * conditions[0]);
  CHECK(std::abs(conditions[2] - conditions[0]) <= 1e-10 * conditions[0]);
}

TEST_CASE("sliding joint: a carrier 100 m from the origin behaves as the same one at the origin",
          "[joints][sliding]") {
  // Issue 29: the carrier's reference length (NurbsCurve::arc_length) never returned 100 m away.
  // The same carrier (10 elements: with 5 the old test happened to pass) and slider, once at the
  // origin and once moved by `offset`.
  const Eigen::Vector3d offset(100.0, -40.0, 30.0);
  const iga::NurbsCurve<3> arc = test::quarter_circle_carrier(1.5, 10, 2, 1);
  const auto placed = [&](const Eigen::Vector3d& shift, core::Model& model) {
    core::add_beam(model, {.centerline = iga::NurbsCurve<3>(arc.knots(), arc.control_points().colwise() + shift,
                                                     arc.weights()),
                    .stiffness = test::generic_stiffness()});
    return model.add_frame(shift + Eigen::Vector3d(0.3, -0.2, 0.5), lie::exp(Eigen::Vector3d(0.3, 0.2, -0.4)));
  };
  core::Model near_model, far_model;
  const int slider = placed(Eigen::Vector3d::Zero(), near_model);
  REQUIRE(placed(offset, far_model) == slider);
  joints::SlidingJointParameters p{.slider = {.node = slider, .offset = Eigen::Vector3d(0.1, -0.2, 0.15)},
                                   .carrier = core::beam_centerline(near_model, 0), .zeta = 0.8, .name = "test slider"};
  joints::SlidingJoint near(p, near_model);
  p.carrier = core::beam_centerline(far_model, 0);
  joints::SlidingJoint far(p, far_model);
  // Moving the control points by 100 m rounds them by ≤ √3/2 ulp(100) = 1.2e-14 m, which changes
  // the length by ≤ (π/2 + 2) · 1.2e-14 m; each length is computed to 1e-14: 1e-13 relative.
  CHECK(std::abs(far.carrier_length() - near.carrier_length()) <= 1e-13 * near.carrier_length());
  // Φ, B and ∂(Bᵀλ)/∂Δ at the same deformed configurations, moved by the offset: they depend on
  // differences of positions only. Round-off of sums Σ N_I,ζ x_I with |x_I| ≈ 110 and
  // Σ|N_I,ζ| ≲ 2p/h_ζ ≈ 17 (h_ζ = L₀/10 ≈ 0.24 m): ≈ 1.1e-16 · 110 · 17 ≈ 2e-13 per entry of
  // size ≲ 10; 1e-12 leaves a factor 5.
  test::RandomRotations random(1209);
  std::string description;
  for (const double zeta : {0.1, 0.8, 1.9}) {
    core::Configuration q_near = perturbed(near_model.state(), random);
    q_near.vector(near.zeta_block())(0) = zeta;
    core::Configuration q_far = q_near;
    for (int b = 0; b < q_far.block_count(); ++b)
      if (q_far.is_frame(b)) q_far.position[b] += offset;
    const Eigen::VectorXd no_velocity = Eigen::VectorXd::Zero(q_near.dof_count());
    near.update_structure(q_near, no_velocity, 0.0, description);
    far.update_structure(q_far, no_velocity, 0.0, description);
    INFO("zeta = " << zeta);
    REQUIRE(far.window_element() == near.window_element());
    CHECK(test::relative_error(test::value(far, q_far, 0), test::value(near, q_near, 0)) <= 1e-12);
    CHECK(test::relative_error(test::jacobian(far, q_far, 0), test::jacobian(near, q_near, 0)) <=
          1e-12);
    const Eigen::Vector3d lambda(0.3, -1.2, 0.7);
    const Eigen::Index n = test::local_dofs(near, q_near);
    Eigen::MatrixXd K_near(n, n), K_far(n, n);
    near.multiplier_tangent(q_near, 0, lambda, K_near);
    far.multiplier_tangent(q_far, 0, lambda, K_far);
    CHECK(test::relative_error(K_far, K_near) <= 1e-12);
  }
}
