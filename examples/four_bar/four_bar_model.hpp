#pragma once
// The spatial four-bar of issue 14 (two flexible steel rods, a rigid coupler, four revolute
// joints about Z, a driven crank, gravity) and the rigid four-bar it is checked against: shared by
// the example and its tests.
#include <spar/spar.hpp>
#include <spar/joints/joints.hpp>

#include <cmath>
#include <memory>
#include <numbers>

namespace spar::examples {

/// The link lengths [m], the drive and the rods' stiffness.
struct FourBarGeometry {
  double ground = 0.4;   ///< A = (0, 0, 0) to D = (ground, 0, 0)
  double crank = 0.1;    ///< A to B
  double coupler = 0.35; ///< B to C
  double rocker = 0.3;   ///< D to C
  double initial_crank_angle = std::numbers::pi / 3;  ///< θ(0) from +X [rad]
  double crank_rate = 10.0;                           ///< θ̇ [rad/s]
  double young_modulus = 210e9;                       ///< the rods' E [Pa] (steel)
};

/// The rigid four-bar's closure: for a crank angle θ, B = crank (cos θ, sin θ) and C the
/// intersection of the circles |C − B| = coupler and |C − D| = rocker on the branch with C to
/// the left of the line B → D (the one of the mechanism at θ(0) = 60°, C above the ground link;
/// a Grashof crank-rocker, 0.1 + 0.4 ≤ 0.35 + 0.3, stays on it for every θ).
struct RigidFourBar {
  FourBarGeometry g;

  Eigen::Vector3d b(double theta) const { return g.crank * Eigen::Vector3d(std::cos(theta), std::sin(theta), 0); }
  Eigen::Vector3d c(double theta) const {
    const Eigen::Vector3d B = b(theta), D(g.ground, 0, 0);
    const double d = (D - B).norm();
    const Eigen::Vector3d e = (D - B) / d, normal(-e.y(), e.x(), 0);
    const double along = (d * d + g.coupler * g.coupler - g.rocker * g.rocker) / (2 * d);
    return B + along * e + std::sqrt(g.coupler * g.coupler - along * along) * normal;
  }
  /// The rocker's angle ψ from +X (direction D → C) [rad].
  double rocker_angle(double theta) const {
    const Eigen::Vector3d C = c(theta);
    return std::atan2(C.y(), C.x() - g.ground);
  }
  /// θ(t) of the drive.
  double crank_angle(double t) const { return g.initial_crank_angle + g.crank_rate * t; }
};

/// The mechanism: model, joints (pivots A, B, C, D, then the drive) and where things are.
struct FourBar {
  core::Model model;
  solvers::ConstraintList joints;
  int crank = 0, rocker = 0;  ///< beam indices
  int coupler_node = 0;       ///< the coupler's frame block (at its centre of mass)
  int crank_root = 0, crank_tip = 0, rocker_root = 0, rocker_tip = 0;
  RigidFourBar rigid;

  /// The flexible rocker's angle: the direction of its chord D → tip from +X [rad].
  double rocker_angle(const core::Configuration& q) const {
    const Eigen::Vector3d chord = q.position[rocker_tip] - q.position[rocker_root];
    return std::atan2(chord.y(), chord.x());
  }
};

/// Issue 14's four-bar: ground pivots A = (0, 0, 0) and D = (0.4, 0, 0); crank A → B and rocker
/// D → C steel rods of circular section, radius 5 mm (E = 210 GPa, ν = 0.3, ρ = 7850 kg/m³),
/// `elements` cubic C² NURBS elements each; the coupler B → C a rigid body of 0.5 kg at its
/// midpoint with the inertia of a slender rod (m L²/12 across it; along it that of a 5 mm-radius
/// solid rod, m r²/2 — the issue gives the mass only); revolute joints about Z at A, B, C, D;
/// the crank's root section turned about Z at `crank_rate` from θ(0) by an AngleDriver; gravity
/// 9.81 m/s² along −Y. The state is the rigid four-bar's at θ(0), at rest (the integrator's
/// initial assembly gives the velocities the drive imposes).
inline FourBar build_four_bar(int elements, const FourBarGeometry& geometry = {}) {
  FourBar f;
  f.rigid.g = geometry;
  const double theta0 = geometry.initial_crank_angle;
  const Eigen::Vector3d A(0, 0, 0), B = f.rigid.b(theta0), C = f.rigid.c(theta0), D(geometry.ground, 0, 0);
  const core::Material steel{.young_modulus = geometry.young_modulus, .poisson_ratio = 0.3, .density = 7850};
  const core::CrossSection rod = core::CrossSection::circle(0.010, steel.poisson_ratio);
  const core::SectionStiffness stiffness = core::SectionStiffness::from(steel, rod);
  const core::SectionInertia inertia = core::SectionInertia::from(steel, rod);
  f.crank = core::add_beam(f.model, {.centerline = iga::straight_line<3>(A, B, elements, 3),
                              .stiffness = stiffness, .inertia = inertia});
  f.rocker = core::add_beam(f.model, {.centerline = iga::straight_line<3>(D, C, elements, 3),
                               .stiffness = stiffness, .inertia = inertia});
  const core::GeometricallyExactBeam& crank = core::beam(f.model, f.crank);
  const core::GeometricallyExactBeam& rocker = core::beam(f.model, f.rocker);
  f.crank_root = crank.node(0);
  f.crank_tip = crank.node(crank.control_point_count() - 1);
  f.rocker_root = rocker.node(0);
  f.rocker_tip = rocker.node(rocker.control_point_count() - 1);

  // The coupler's body frame: X along B → C, Z along the pivots' axis (the results draw it as a
  // bar along its X).
  const double mass = 0.5, radius = 0.005;
  const Eigen::Vector3d along = (C - B).normalized();
  Eigen::Matrix3d frame;
  frame << along, Eigen::Vector3d::UnitZ().cross(along), Eigen::Vector3d::UnitZ();
  const double across = mass * geometry.coupler * geometry.coupler / 12, axial = mass * radius * radius / 2;
  f.coupler_node = core::rigid_body(f.model, core::add_rigid_body(f.model,
      {.center_of_mass = 0.5 * (B + C), .rotation = frame, .mass = mass,
       .inertia = Eigen::Vector3d(axial, across, across).asDiagonal().toDenseMatrix()})).node;
  f.model.set_gravity(Eigen::Vector3d(0, -9.81, 0));

  const core::Configuration& q0 = f.model.state();
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  using joints::Attachment;
  using joints::RevoluteJoint;
  f.joints.push_back(std::make_unique<RevoluteJoint>(Attachment{f.crank_root}, Attachment{-1, A}, z, q0));
  f.joints.push_back(std::make_unique<RevoluteJoint>(Attachment{f.crank_tip},
                                                     joints::attach_at(f.coupler_node, B, q0), z, q0));
  f.joints.push_back(std::make_unique<RevoluteJoint>(joints::attach_at(f.coupler_node, C, q0),
                                                     Attachment{f.rocker_tip}, z, q0));
  f.joints.push_back(std::make_unique<RevoluteJoint>(Attachment{f.rocker_root}, Attachment{-1, D}, z, q0));
  f.joints.push_back(std::make_unique<joints::AngleDriver>(
      f.crank_root, z, joints::TimeFunction::linear(geometry.crank_rate), q0));
  return f;
}

}  // namespace spar::examples
