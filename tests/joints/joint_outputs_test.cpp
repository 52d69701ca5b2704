// Joint-level outputs (docs/joints.md §5): a revolute joint's reaction against hand-computed
// static and dynamic reactions, its relative angle and rate under a driver, a prismatic joint's
// stroke; the attachment's offset initialization. The body: mass m, inertia J about its centre
// of mass C = (L, 0, 0), hinged about Z at the origin.
#include <spar/joints/angle_driver.hpp>
#include <spar/joints/prismatic_joint.hpp>
#include <spar/joints/reaction.hpp>
#include <spar/joints/revolute_joint.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>
#include <new>
#include <numbers>

using namespace spar;

namespace {

constexpr double mass = 2.0, inertia_z = 0.05, arm = 0.5, g = 9.81;  // kg, kg m², m, m/s²

struct Hinged {
  core::Model model;
  solvers::ConstraintList joints;
  int body = 0;
};

/// The body hinged at the origin; `body_first`: the body is the joint's a (else the ground is).
Hinged hinged(const Eigen::Vector3d& gravity, bool body_first, double drive_rate = 0.0) {
  Hinged h;
  h.body = core::rigid_body(h.model, core::add_rigid_body(h.model,
      {.center_of_mass = Eigen::Vector3d(arm, 0, 0), .mass = mass,
       .inertia = Eigen::Vector3d(0.04, 0.03, inertia_z).asDiagonal()})).node;
  h.model.set_gravity(gravity);
  const joints::Attachment body = joints::attach_at(h.body, Eigen::Vector3d::Zero(), h.model.state());
  const joints::Attachment ground{-1};
  h.joints.push_back(std::make_unique<joints::RevoluteJoint>(body_first ? body : ground, body_first ? ground : body,
                                                             Eigen::Vector3d::UnitZ(), h.model.state()));
  if (drive_rate != 0.0)
    h.joints.push_back(std::make_unique<joints::AngleDriver>(
        h.body, Eigen::Vector3d::UnitZ(), joints::TimeFunction::linear(drive_rate), h.model.state()));
  return h;
}

solvers::DynamicOptions options() { return {.time_step = 1e-3, .tolerance = 1e-20, .constraint_tolerance = 1e-13}; }

}  // namespace

TEST_CASE("revolute reaction: a body held by its hinge against gravity along the axis",
          "[joints][validation]") {
  // Gravity −g e_z along the hinge: the body rests (nothing turns it about Z), and the hinge
  // carries its weight, F = (0, 0, m g) on the body, and the moment of the weight about the
  // hinge, M = −(L e_x) × (−m g e_z) = (0, −m g L, 0). Round-off of the 11 × 11 solve: 1e-12 of
  // m g L.
  for (const bool body_first : {true, false}) {
    Hinged h = hinged(Eigen::Vector3d(0, 0, -g), body_first);
    solvers::GeneralizedAlpha integrator(h.model, std::move(h.joints), options());
    integrator.initialize();
    const auto& joint = dynamic_cast<const joints::RevoluteJoint&>(integrator.constraint(0));
    const core::Configuration& q = h.model.state();
    const joints::Wrench local = joint.reaction_in_frame(q, 0.0, integrator.multipliers(0));
    const Eigen::Matrix3d frame = joint.frame(q);
    const double sign = body_first ? 1.0 : -1.0;  // the reaction on a: on the ground, minus that on the body
    const double scale = 1e-12 * mass * g * arm;
    INFO((body_first ? "a = body" : "a = ground") << ": force " << (frame * local.force).transpose() << ", moment "
                                                   << (frame * local.moment).transpose());
    CHECK((frame * local.force - sign * Eigen::Vector3d(0, 0, mass * g)).norm() <= scale);
    CHECK((frame * local.moment - sign * Eigen::Vector3d(0, -mass * g * arm, 0)).norm() <= scale);
    CHECK(std::abs(local.moment.z()) <= scale);  // frictionless about its axis
    // The generic reaction on the body agrees, whichever side it is on.
    const joints::Wrench on_body = joints::reaction(joint, q, 0.0, integrator.multipliers(0), h.body, joint.point(q));
    CHECK((on_body.force - Eigen::Vector3d(0, 0, mass * g)).norm() <= scale);
    // It stays at rest: the same reaction after steps.
    for (int n = 0; n < 5; ++n) integrator.step();
    CHECK((frame * joint.reaction_in_frame(q, integrator.time(), integrator.multipliers(0)).force -
           sign * Eigen::Vector3d(0, 0, mass * g)).norm() <= scale);
  }
}

TEST_CASE("revolute reaction: a horizontal pendulum released at rest", "[joints][validation]") {
  // Gravity −g e_y, the body horizontal at rest: at t = 0 it turns with α = −m g L/(J + m L²)
  // about Z, its centre accelerates by α L along Y, and the hinge pushes it up with
  // F_y = m (α L + g) = m g J/(J + m L²) (no force along X: no velocity yet).
  Hinged h = hinged(Eigen::Vector3d(0, -g, 0), true);
  solvers::GeneralizedAlpha integrator(h.model, std::move(h.joints), options());
  integrator.initialize();
  const auto& joint = dynamic_cast<const joints::RevoluteJoint&>(integrator.constraint(0));
  const core::Configuration& q = h.model.state();
  const joints::Wrench local = joint.reaction_in_frame(q, 0.0, integrator.multipliers(0));
  const Eigen::Vector3d force = joint.frame(q) * local.force;
  const double expected = mass * g * inertia_z / (inertia_z + mass * arm * arm);
  INFO("force " << force.transpose() << " N, expected (0, " << expected << ", 0)");
  CHECK((force - Eigen::Vector3d(0, expected, 0)).norm() <= 1e-12 * mass * g);
}

TEST_CASE("revolute coordinates: relative angle and rate under a driver", "[joints]") {
  // Driven at ω about Z from rest (the initial assembly gives the velocity): φ = ω t, φ̇ = ω, to
  // the Newton tolerance (increments ≤ 1e-10 rad) and the constraint tolerance.
  const double omega = 10.0;
  Hinged h = hinged(Eigen::Vector3d(0, -g, 0), true, omega);
  solvers::GeneralizedAlpha integrator(h.model, std::move(h.joints), options());
  const auto& joint = dynamic_cast<const joints::RevoluteJoint&>(integrator.constraint(0));
  for (int n = 0; n < 100; ++n) integrator.step();  // 0.1 s: 1 rad
  const double t = integrator.time();
  CHECK(joint.relative_angle(h.model.state()) == Approx(omega * t).epsilon(1e-10));
  CHECK(joint.relative_rate(h.model.state(), integrator.velocity()) == Approx(omega).epsilon(1e-8));
}

TEST_CASE("prismatic coordinates: stroke and its rate", "[joints]") {
  // A point at offset a = (0, 0.1, 0) on a node at x turned by 90° about Z: p = x + R a.
  core::Configuration q;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  q.add_frame(Eigen::Vector3d(1.0, 2.0, 3.0), R);
  const Eigen::Vector3d line_point(0.5, 0, 0), direction(1, 1, 0);
  const joints::PrismaticJoint joint(joints::Attachment{0, Eigen::Vector3d(0, 0.1, 0)}, line_point, direction, false, q);
  const Eigen::Vector3d d = direction.normalized(), p = q.position[0] + R * Eigen::Vector3d(0, 0.1, 0);
  CHECK(joint.stroke(q) == Approx((p - line_point).dot(d)).epsilon(1e-15));
  Eigen::VectorXd v(6);
  v << 0.3, -0.2, 0.1, 0.0, 0.0, 2.0;  // ẋ, Ω (material)
  const Eigen::Vector3d p_dot = v.head<3>() + R * Eigen::Vector3d(0, 0, 2.0).cross(Eigen::Vector3d(0, 0.1, 0));
  CHECK(joint.stroke_rate(q, v) == Approx(p_dot.dot(d)).epsilon(1e-15));
}

TEST_CASE("attachment: Attachment{node, {}} has a zero offset, whatever the memory held", "[joints]") {
  // Built over bytes 0xFF (NaN as doubles): with an Eigen::Vector3d offset, `{}` ran Eigen's
  // default constructor, which leaves the entries as they were (NaN here). The bytes are written
  // through a volatile pointer: a memset before the object's lifetime is a dead store the
  // optimizer removes.
  alignas(joints::Attachment) unsigned char memory[sizeof(joints::Attachment)];
  volatile unsigned char* bytes = memory;
  for (std::size_t i = 0; i < sizeof memory; ++i) bytes[i] = 0xFF;
  const auto* attachment = new (memory) joints::Attachment{3, {}};
  CHECK(attachment->node == 3);
  CHECK(attachment->offset == Eigen::Vector3d::Zero());
  const joints::Attachment given{-1, Eigen::Vector3d(1, 2, 3)};
  CHECK(given.offset == Eigen::Vector3d(1, 2, 3));
}
