#pragma once
// The heavy top's reference solution: an independent integration of its equations of motion in
// unit quaternions with the classical fourth-order Runge–Kutta method and a small step. It shares
// nothing with spar's solver (no constraint, no Lie-group update, no Newton): the fixed point is
// eliminated and the body turns about it.
//
//   J_O Ω̇ = −Ω × J_O Ω + X × (m Rᵀ g),   J_O = J + m (XᵀX I − X Xᵀ)   (Euler about the fixed point)
//   q̇ = ½ q ⊗ (0, Ω)                                                   (R = R(q), body → inertial)
//
// Ω is the material angular velocity, X the centre of mass in the body frame measured from the
// fixed point, J the inertia about the centre of mass; the centre of mass is at x = R X and moves
// with ẋ = R (Ω × X). Used by examples/heavy_top and tests/dynamics/heavy_top_test.cpp.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace spar::examples::heavy_top {

/// A top with a fixed point at the inertial origin.
struct TopParameters {
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();          ///< about the centre of mass, body frame
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();   ///< X, body frame, from the fixed point
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
};

/// The classic set of Brüls, Cardona & Arnold (2012, §5.1; also Brüls & Cardona 2010):
/// m = 15 kg, J = diag(0.234375, 0.46875, 0.234375) kg m², X = (0, 1, 0) m, g = (0, 0, −9.81).
/// With Ω(0) = (0, 150, −4.61538) rad/s and R(0) = I.
inline TopParameters classic_top() {
  return {.mass = 15.0,
          .inertia = Eigen::Vector3d(0.234375, 0.46875, 0.234375).asDiagonal(),
          .center_of_mass = Eigen::Vector3d(0.0, 1.0, 0.0),
          .gravity = Eigen::Vector3d(0.0, 0.0, -9.81)};
}

/// The state of the reduced (fixed-point) system.
struct TopState {
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< Ω, material

  Eigen::Matrix3d rotation_matrix() const { return rotation.normalized().toRotationMatrix(); }
};

class TopReference {
  using Vector7d = Eigen::Matrix<double, 7, 1>;

public:
  explicit TopReference(const TopParameters& top)
      : top_(top),
        inertia_about_point_(top.inertia + top.mass * (top.center_of_mass.squaredNorm() * Eigen::Matrix3d::Identity() -
                                                       top.center_of_mass * top.center_of_mass.transpose())),
        inverse_(inertia_about_point_.inverse()) {}

  /// Advances `state` by `duration` in `steps` RK4 steps.
  void advance(TopState& state, double duration, long steps) const {
    const double h = duration / static_cast<double>(steps);
    Vector7d y = pack(state);
    for (long k = 0; k < steps; ++k) {
      const Vector7d k1 = rate(y);
      const Vector7d k2 = rate(y + 0.5 * h * k1);
      const Vector7d k3 = rate(y + 0.5 * h * k2);
      const Vector7d k4 = rate(y + h * k3);
      y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    unpack(y, state);
  }

  /// The centre of mass x = R X.
  Eigen::Vector3d center_of_mass(const TopState& state) const {
    return state.rotation_matrix() * top_.center_of_mass;
  }
  /// Its velocity ẋ = R (Ω × X).
  Eigen::Vector3d center_of_mass_velocity(const TopState& state) const {
    return state.rotation_matrix() * state.angular_velocity.cross(top_.center_of_mass);
  }
  /// ½ Ωᵀ J_O Ω − m g·x: the conserved total energy.
  double energy(const TopState& state) const {
    return 0.5 * state.angular_velocity.dot(inertia_about_point_ * state.angular_velocity) -
           top_.mass * top_.gravity.dot(center_of_mass(state));
  }

private:
  static Vector7d pack(const TopState& s) {
    Vector7d y;
    y << s.rotation.w(), s.rotation.x(), s.rotation.y(), s.rotation.z(), s.angular_velocity;
    return y;
  }
  static void unpack(const Vector7d& y, TopState& s) {
    s.rotation = Eigen::Quaterniond(y(0), y(1), y(2), y(3));
    s.angular_velocity = y.tail<3>();
  }

  /// (q̇, Ω̇). The quaternion is normalized inside R(q) only, so the unit-norm drift of RK4
  /// (O(h⁴) per unit time) does not feed back into the dynamics.
  Vector7d rate(const Vector7d& y) const {
    const Eigen::Quaterniond q(y(0), y(1), y(2), y(3));
    const Eigen::Vector3d omega = y.tail<3>();
    const Eigen::Quaterniond qdot = q * Eigen::Quaterniond(0.0, omega.x(), omega.y(), omega.z());
    const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
    const Eigen::Vector3d moment = top_.center_of_mass.cross(top_.mass * (R.transpose() * top_.gravity));
    Vector7d out;
    out << 0.5 * qdot.w(), 0.5 * qdot.x(), 0.5 * qdot.y(), 0.5 * qdot.z(),
        inverse_ * (moment - omega.cross(inertia_about_point_ * omega));
    return out;
  }

  TopParameters top_;
  Eigen::Matrix3d inertia_about_point_;
  Eigen::Matrix3d inverse_;
};

}  // namespace spar::examples::heavy_top
